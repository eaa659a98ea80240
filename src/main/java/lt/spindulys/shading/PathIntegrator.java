package lt.spindulys.shading;

import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.light.EnvironmentSource;
import lt.spindulys.light.Light;
import lt.spindulys.light.LightSample;
import lt.spindulys.light.Lights;
import lt.spindulys.light.MeshEmitter;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.sampling.PaddedStrata;
import lt.spindulys.sampling.Rng;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TracedObject;

/**
 * Unidirectional path tracing (global illumination), iterative, as pbrt-v4's {@code PathIntegrator}
 * does it. At every surface a path reaches, one light is picked uniformly and sampled
 * ({@link Light#sampleLi}, next-event estimation), and the surface's BSDF draws the next
 * direction; light found along that direction (an area light, the environment) is weighted
 * against the light's own density by multiple importance sampling with the power heuristic, and
 * a point light, which no direction finds, takes the whole weight. Paths end after
 * {@code maxdepth} bounces (0: direct light only, as Cycles' {@code max_bounces}), or earlier by
 * Russian roulette from the third bounce on, with the survival probability the path's throughput
 * (undoing the radiance scaling of refraction, so paths inside glass survive).
 *
 * <p>Materials: a principled material scatters by {@link PrincipledBsdf} with its base colour,
 * metallic, roughness and transmission after textures; Whitted materials by the documented mapping of {@link WhittedMaterialBsdf}
 * (kd and colour a Lambert lobe, ks and shininess a GGX lobe, kr a mirror, kt refraction); the
 * ambient term is not used, since indirect light replaces it. Emission (a material's, or an OBJ
 * {@code Ke}) is found by the paths that hit it, and an emissive mesh that holds still is also
 * sampled as a light ({@link lt.spindulys.light.MeshEmitter}). Rays that leave the scene see the environment, or
 * the background colour, which therefore lights the scene as a uniform sky.
 *
 * <p>Media as in the Whitted tracer: a path that refracts into a solid enters its medium, whose
 * index of refraction and attenuation (Beer's law) apply until it leaves the same solid; the
 * index of refraction at a surface is that of the side entered over that of the side left. Every
 * surface blocks a shadow ray: light through glass is found by the paths that refract.
 *
 * <p>Every random number of a path comes from one generator seeded from the global seed, the
 * pixel and the sample index, so the image is the same for any thread count or tile split; the
 * light samples and scattering at the first two surfaces are stratified over the pixel's samples
 * ({@link PaddedStrata}; progressive over them when the pixel's count is open, under adaptive sampling).
 * Immutable; all per-path state lives in the thread's {@link TracerScratch}.
 */
public final class PathIntegrator implements Integrator {
    /** Distinguishes a path's random numbers from the pixel sampler's and the lights' streams. */
    private static final long PATH_STREAM = 0x70617468L;
    /**
     * Surfaces of a path (counted from the camera's) whose light sample and scattering take
     * stratified numbers ({@link PaddedStrata}); deeper ones take independent numbers, where
     * strata no longer pay: the light there is already averaged over many paths.
     */
    private static final int STRATIFIED_SURFACES = 2;
    /** Bounces after which Russian roulette may end a path. */
    private static final int ROULETTE_BOUNCES = 3;

    private final Scene scene;
    private final RenderSettings settings;
    private final Light[] lightArray;
    private final Lights lights;
    /** The probability of picking each light for a path vertex's light sample (uniform). */
    private final double pick;
    /** What rays that hit nothing see, or null for the background colour. */
    private final Environment environment;
    /** The environment as a light, or null when it is not one (then paths find it by BSDF sampling alone). */
    private final Light environmentLight;
    private final FirstHits firstHits;
    private final int maxDepth;
    private final double clamp;
    /**
     * Whether a ray can find light by hitting something: an area light, a glowing surface, an
     * environment or a background that is not black. Without any, the last bounce is not traced.
     */
    private final boolean findable;

    /**
     * A path tracer for {@code scene}, reading its settings' {@code maxdepth} and {@code clamp}.
     *
     * @param scene the frozen scene
     */
    public PathIntegrator(Scene scene) {
        this.scene = scene;
        this.settings = scene.settings();
        this.lights = Lights.withEmissiveMeshes(scene);
        this.lightArray = lights.all();
        this.pick = lightArray.length == 0 ? 0 : 1.0 / lightArray.length;
        this.environment = scene.environment();
        Light env = null;
        for (Light l : lightArray) if (l instanceof EnvironmentSource) env = l;
        this.environmentLight = env;
        this.firstHits = new FirstHits(scene);
        this.maxDepth = settings.maxDepth();
        this.clamp = settings.clamp();
        this.findable = lights.hasSurfaces() || environment != null || !settings.background().isBlack() || glows(scene);
    }

    /** Whether some surface of the scene emits light (a material's emission, or an emission texture). */
    private static boolean glows(Scene scene) {
        boolean[] any = {false};
        for (lt.spindulys.scene.GObject o : scene.objects()) {
            o.forEachMaterial(m -> any[0] |= !m.emission().isBlack() || m.texture(lt.spindulys.texture.Channel.EMISSION) != null);
        }
        return any[0];
    }

    @Override
    public TracerScratch newScratch(HeapBudget.Reservation reservation) {
        TracerScratch s = new TracerScratch(0);
        reservation.release(scratchBytes(settings.samplesPerPixel()));
        return s;
    }

    /** The scratch does not grow with the input: a path keeps one vertex and the next ray whatever its length. */
    @Override
    public long scratchBytes(int samplesPerPixel) {
        return HeapBudget.sum(WhittedIntegrator.FIXED_SCRATCH_BYTES, HeapBudget.product(2, WhittedIntegrator.VERTEX_BYTES));
    }

    @Override
    public String scratchSizedBy(int samplesPerPixel) { return "path tracing"; }

    @Override
    public int traceFirstHit(Ray ray, TracerScratch s, double[] out) { return firstHits.trace(ray, s, out); }

    @Override
    public void traceCamera(Ray camera, TracerScratch s, double[] out) {
        s.cameraRays++;
        s.mediaCount = 0;
        Rng rng = s.pathRng.seed(s.seed ^ PATH_STREAM, s.pixelX, s.pixelY, s.sample);
        PaddedStrata strata = s.strata;
        if (s.progressive) strata.startProgressive(s.seed ^ PATH_STREAM, s.pixelX, s.pixelY, s.sample);
        else strata.start(s.seed ^ PATH_STREAM, s.pixelX, s.pixelY, s.sample, s.samplesPerPixel);
        double[] square = s.square;
        double[] beta = s.throughput, sum = s.pathSum, c = s.contribution, f = s.bsdfValue;
        beta[0] = beta[1] = beta[2] = 1;
        sum[0] = sum[1] = sum[2] = 0;
        // Indirect light is summed apart when clamped, so that the clamp bounds the sample's total of it.
        double[] late = clamp > 0 ? s.indirectSum : sum;
        late[0] = late[1] = late[2] = 0;
        double etaScale = 1, travelled = 0, bsdfPdf = 0;
        boolean specular = false;
        // The vertex the current segment left (where light densities are measured from).
        double qx = 0, qy = 0, qz = 0;
        TracerScratch.PathVertex v = s.path[0];
        Hit hit = v.hit;
        ShadingData sd = v.shading;
        SurfaceBsdf bsdf = s.bsdf;
        BsdfSample bs = s.bsdfSample;
        double[] frame = s.frame;
        Ray ray = camera;
        // Segment 0 is the camera ray; segment k leaves the path's k-th surface.
        for (int segment = 0; ; segment++) {
            if (TraversalScratch.COUNTING) s.ctx.rayKind = segment == 0 ? TraversalScratch.CAMERA : TraversalScratch.SECONDARY;
            boolean found = scene.intersect(ray, hit, s.ctx);
            double dlen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
            double dx = ray.dx / dlen, dy = ray.dy / dlen, dz = ray.dz / dlen;
            Material medium = s.innermost();
            // Light found along the segment: direct when it reaches the camera off at most one surface.
            boolean indirect = segment >= 2;
            boolean weighed = segment > 0 && !specular; // the light could have been sampled from the vertex left
            if (lights.hasSurfaces()) {
                double[] seen = s.lightSeen;
                int li = lights.nearestSurface(ray, found ? hit.t : Double.POSITIVE_INFINITY, seen);
                if (li >= 0) {
                    double w = weighed ? powerHeuristic(bsdfPdf, pick * lightArray[li].pdfLi(qx, qy, qz, dx, dy, dz)) : 1;
                    c[0] = seen[0] * w; c[1] = seen[1] * w; c[2] = seen[2] * w;
                    if (medium != null) WhittedIntegrator.attenuate(medium, seen[3] * dlen, c);
                    add(beta, c, indirect ? late : sum);
                    if (segment == 0) FirstHits.recordNothing(s);
                    break;
                }
            }
            if (!found) {
                if (segment == 0) FirstHits.recordNothing(s);
                // Camera rays see the environment as its camera view says; later segments see the map.
                if (environment != null && segment == 0) environment.lookupFromCamera(dx, dy, dz, settings.background(), c);
                else if (environment != null) environment.lookup(dx, dy, dz, c);
                else { Color bg = settings.background(); c[0] = bg.r(); c[1] = bg.g(); c[2] = bg.b(); }
                if (weighed && environmentLight != null) {
                    double w = powerHeuristic(bsdfPdf, pick * environmentLight.pdfLi(qx, qy, qz, dx, dy, dz));
                    c[0] *= w; c[1] *= w; c[2] *= w;
                }
                if (medium != null) WhittedIntegrator.attenuate(medium, Double.POSITIVE_INFINITY, c);
                add(beta, c, indirect ? late : sum);
                break;
            }
            if (segment == 0 && hit.object instanceof lt.spindulys.scene.AdaptiveSubdivisionSurface) s.adaptiveCameraHits++;
            hit.object.shade(ray, hit, sd);
            Material m = sd.material;
            travelled += hit.t * dlen;
            TextureShading.evaluate(m, sd, m.isTextured() ? firstHits.footprint(sd, travelled, dx, dy, dz) : 0, s, v);
            if (segment == 0) FirstHits.recordHit(s, v, sd, dx, dy, dz, travelled);
            if (medium != null && medium.attenuates()) {
                WhittedIntegrator.attenuate(medium, hit.t * dlen, beta);
                if (beta[0] <= 0 && beta[1] <= 0 && beta[2] <= 0) break;
            }
            if (v.emissionR > 0 || v.emissionG > 0 || v.emissionB > 0) {
                double w = 1;
                MeshEmitter emitter = weighed ? lights.emitterOf(hit.object) : null;
                if (emitter != null && emitter.samples(m)) { // a light the vertex left could have sampled
                    double d = hit.t * dlen, cos = Math.abs(sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz);
                    double brightness = (v.emissionR + v.emissionG + v.emissionB) / 3;
                    w = cos > 0 ? powerHeuristic(bsdfPdf, pick * emitter.pdfAt(brightness, d * d, cos)) : 1;
                }
                c[0] = v.emissionR * w; c[1] = v.emissionG * w; c[2] = v.emissionB * w;
                add(beta, c, indirect ? late : sum);
            }
            if (segment > maxDepth) break; // the last segment only looks for light

            // The frame: geometric and shading normals turned towards the incoming ray.
            boolean entering = sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz < 0;
            double sign = entering ? 1 : -1;
            double nfx = sign * sd.ng[0], nfy = sign * sd.ng[1], nfz = sign * sd.ng[2];
            double snx = sign * sd.ns[0], sny = sign * sd.ns[1], snz = sign * sd.ns[2];
            if (snx * dx + sny * dy + snz * dz >= 0) { snx = nfx; sny = nfy; snz = nfz; }
            double px = sd.p[0], py = sd.p[1], pz = sd.p[2];
            double eps = 1e-9 * Math.max(1, Math.max(Math.abs(px), Math.max(Math.abs(py), Math.abs(pz)))) + 1e-9 * hit.t * dlen;
            tangentFrame(snx, sny, snz, frame);
            double tx = frame[0], ty = frame[1], tz = frame[2], bx = frame[3], by = frame[4], bz = frame[5];
            double wox = -(dx * tx + dy * ty + dz * tz), woy = -(dx * bx + dy * by + dz * bz), woz = -(dx * snx + dy * sny + dz * snz);

            // Indices of refraction on both sides, as the Whitted tracer finds them from the media entered.
            TracedObject solid = hit.object.solid();
            boolean leavesInnermost = !entering && (s.innermostSolid() == solid || s.innermost() == m);
            double n1, n2;
            if (entering) {
                n1 = WhittedIntegrator.ior(s.innermost());
                n2 = m.ior();
            } else {
                n1 = leavesInnermost ? s.innermost().ior() : m.ior();
                n2 = WhittedIntegrator.ior(leavesInnermost ? s.outer() : s.innermost());
            }
            double eta = n2 / n1;
            // An untextured material seen again with the same indices needs no new set-up (a
            // path bounces between a few materials): the BSDF is this thread's, set only here.
            if (m.isTextured() || m != s.configuredMaterial || eta != s.configuredEta) {
                configure(bsdf, m, v, eta);
                s.configuredMaterial = m.isTextured() ? null : m;
                s.configuredEta = eta;
            }

            // Next-event estimation: one light, picked uniformly.
            if (pick > 0 && !bsdf.isSpecular()) {
                boolean padded = segment < STRATIFIED_SURFACES;
                double pickU = padded ? strata.get1D(4 * segment, rng) : rng.nextDouble();
                int li = Math.min((int) (pickU * lightArray.length), lightArray.length - 1);
                if (padded) strata.get2D(4 * segment + 1, rng, square);
                else { square[0] = rng.nextDouble(); square[1] = rng.nextDouble(); }
                double u1 = square[0], u2 = square[1];
                Light light = lightArray[li];
                LightSample ls = s.lightSample;
                if (light.sampleLi(px, py, pz, u1, u2, ls)) {
                    double ux = ls.wx, uy = ls.wy, uz = ls.wz;
                    double cosG = ux * nfx + uy * nfy + uz * nfz, cosS = ux * snx + uy * sny + uz * snz;
                    // A smooth triangle's shadow ray starts on the curved surface its vertex normals
                    // describe when the ray came from outside and the shading normal faces the light
                    // (ShadingData#shadowOrigin): that ray, not the flat facet's normal, then decides.
                    boolean lifted = sd.lifted && entering && cosS > 0;
                    // Otherwise both normals must agree on the side the light is on, or shading normals leak light.
                    if (cosG * cosS > 0 || lifted) {
                        double wix = ux * tx + uy * ty + uz * tz, wiy = ux * bx + uy * by + uz * bz;
                        bsdf.eval(wox, woy, woz, wix, wiy, cosS, f);
                        if (f[0] > 0 || f[1] > 0 || f[2] > 0) {
                            boolean outside = cosG > 0 || lifted;
                            double side = outside ? eps : -eps;
                            double ox = px, oy = py, oz = pz;
                            if (lifted) { ox = sd.shadowOrigin[0]; oy = sd.shadowOrigin[1]; oz = sd.shadowOrigin[2]; }
                            ox += nfx * side; oy += nfy * side; oz += nfz * side;
                            boolean infinite = ls.distance == Double.POSITIVE_INFINITY;
                            Ray shadow = infinite ? s.shadowRay.set(ox, oy, oz, ux, uy, uz, 0, Double.POSITIVE_INFINITY)
                                    : s.shadowRay.set(ox, oy, oz, ls.x - ox, ls.y - oy, ls.z - oz, 0, ls.shadowTMax);
                            shadow.time = ray.time;
                            s.shadowRays++;
                            if (TraversalScratch.COUNTING) s.ctx.rayKind = TraversalScratch.SHADOW;
                            s.ctx.occluderSlot = li & OCCLUDER_MASK;
                            s.ctx.shadowReceiver = cosG > 0 && hit.object.flat() ? hit.object : null;
                            boolean blocked = scene.occluded(shadow, s.ctx);
                            s.ctx.shadowReceiver = null;
                            // A path ends at an area light it reaches, so another light's surface hides this sample
                            // too: else light samples and BSDF samples would see different scenes and MIS mix them.
                            if (!blocked && lights.hasSurfaces()) {
                                int nearer = lights.nearestSurface(shadow, Double.POSITIVE_INFINITY, s.lightSeen);
                                blocked = nearer >= 0 && nearer != li;
                            }
                            if (!blocked) {
                                double lightPdf = pick * ls.pdf;
                                double w = ls.delta ? 1 : powerHeuristic(lightPdf, bsdf.pdf(wox, woy, woz, wix, wiy, cosS));
                                double k = Math.abs(cosS) * w / lightPdf;
                                c[0] = f[0] * ls.r * k; c[1] = f[1] * ls.g * k; c[2] = f[2] * ls.b * k;
                                // The shadow ray crosses the medium on the light's side: the ray's own, or the one behind the surface.
                                Material across = outside ? medium : entering ? m : leavesInnermost ? s.outer() : medium;
                                if (across != null) WhittedIntegrator.attenuate(across, ls.distance, c);
                                add(beta, c, segment >= 1 ? late : sum);
                            }
                        }
                    }
                }
            }

            // The next direction, from the BSDF; at the last bounce it only looks for light, which
            // is pointless when nothing a ray can reach gives any (point lights and a black sky).
            if (segment == maxDepth && !findable) break;
            boolean padded = segment < STRATIFIED_SURFACES;
            double uc = padded ? strata.get1D(4 * segment + 2, rng) : rng.nextDouble();
            if (padded) strata.get2D(4 * segment + 3, rng, square);
            else { square[0] = rng.nextDouble(); square[1] = rng.nextDouble(); }
            double u1 = square[0], u2 = square[1];
            if (!bsdf.sample(wox, woy, woz, uc, u1, u2, bs) || !(bs.pdf > 0)) break;
            double wx = bs.wix * tx + bs.wiy * bx + bs.wiz * snx;
            double wy = bs.wix * ty + bs.wiy * by + bs.wiz * sny;
            double wz = bs.wix * tz + bs.wiy * bz + bs.wiz * snz;
            boolean transmitted = bs.wiz < 0;
            double cosG = wx * nfx + wy * nfy + wz * nfz;
            if (transmitted ? cosG >= 0 : cosG <= 0) break; // the shading normal sent it to the wrong side
            double k = Math.abs(bs.wiz) / bs.pdf;
            beta[0] *= bs.f[0] * k; beta[1] *= bs.f[1] * k; beta[2] *= bs.f[2] * k;
            if (!(beta[0] > 0 || beta[1] > 0 || beta[2] > 0)) break;
            specular = bs.specular;
            bsdfPdf = bs.pdf;
            if (transmitted) {
                etaScale *= bs.eta * bs.eta;
                if (entering) s.pushMedium(m, solid);
                else if (leavesInnermost) s.mediaCount--;
                s.refractionRays++;
            } else {
                s.reflectionRays++;
            }
            qx = px; qy = py; qz = pz;
            double side = transmitted ? -eps : eps;
            Ray next = s.path[1].ray;
            next.set(px + nfx * side, py + nfy * side, pz + nfz * side, wx, wy, wz, 0, Double.POSITIVE_INFINITY);
            next.time = ray.time;
            ray = next;
            if (segment + 1 >= ROULETTE_BOUNCES) {
                double survive = Math.max(beta[0], Math.max(beta[1], beta[2])) * etaScale;
                if (survive < 1) {
                    if (rng.nextDouble() >= survive) break;
                    beta[0] /= survive; beta[1] /= survive; beta[2] /= survive;
                }
            }
        }
        if (late != sum) {
            double max = Math.max(late[0], Math.max(late[1], late[2]));
            double k = max > clamp ? clamp / max : 1;
            sum[0] += late[0] * k; sum[1] += late[1] * k; sum[2] += late[2] * k;
        }
        out[0] = sum[0]; out[1] = sum[1]; out[2] = sum[2];
    }

    /** Slots of the thread's occluder cache, less one: a mask. */
    private static final int OCCLUDER_MASK = lt.spindulys.trace.TraceContext.OCCLUDER_SLOTS - 1;

    /** Sets the thread's BSDF to the surface at vertex v (material m, after textures), eta the index entered over the index left. */
    private static void configure(SurfaceBsdf bsdf, Material m, TracerScratch.PathVertex v, double eta) {
        if (m.model() == Material.Model.PRINCIPLED) {
            bsdf.setPrincipled(v.colourR, v.colourG, v.colourB, v.metallic, v.roughness, eta, v.transmission);
            return;
        }
        Color filter = m.filter();
        bsdf.setWhitted(v.colourR, v.colourG, v.colourB, m.kd(), v.ks, m.shininess(), v.kr, v.kt, eta,
                filter.r(), filter.g(), filter.b(), m.fresnel());
    }

    /**
     * Adds throughput times c to {@code sum}: the path's, or with a clamp the sum of its light that
     * reached the camera off more than one surface, which the end of the path scales down, keeping
     * its hue, so that no channel of it exceeds the clamp. A contribution that is not finite (a
     * degenerate sample) is dropped.
     */
    private static void add(double[] beta, double[] c, double[] sum) {
        double r = beta[0] * c[0], g = beta[1] * c[1], b = beta[2] * c[2];
        if (!(Double.isFinite(r) && Double.isFinite(g) && Double.isFinite(b))) return;
        sum[0] += r; sum[1] += g; sum[2] += b;
    }

    /**
     * The power heuristic's weight (beta 2) of a sample drawn with density a, against another
     * strategy's density b for the same direction; 1 where b is 0, and for an infinite a.
     */
    static double powerHeuristic(double a, double b) {
        if (!(b > 0)) return 1;
        if (a == Double.POSITIVE_INFINITY) return 1;
        double a2 = a * a, b2 = b * b;
        double w = a2 / (a2 + b2);
        return w == w ? w : 0; // both overflowing: no information, give the other strategy the weight
    }

    /**
     * Two unit tangents perpendicular to the unit normal n, written to out[0..2] and out[3..5]:
     * Duff et al.'s branchless orthonormal basis (JCGT 2017), continuous except at n.z = -0 / +0.
     */
    static void tangentFrame(double nx, double ny, double nz, double[] out) {
        double sign = Math.copySign(1.0, nz);
        double a = -1 / (sign + nz), b = nx * ny * a;
        out[0] = 1 + sign * nx * nx * a; out[1] = sign * b; out[2] = -sign * nx;
        out[3] = b; out[4] = sign + ny * ny * a; out[5] = -ny;
    }

}
