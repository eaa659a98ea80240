package lt.spindulys.shading;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.TracedObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.material.Material;
import lt.spindulys.sampling.Rng;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.EnvironmentLight;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.texture.Channel;

/**
 * Recursive Whitted ray tracing, the thesis's model: at the nearest hit, ambient plus diffuse and
 * Blinn-Phong specular from every point light that a shadow ray reaches, plus reflection and
 * refraction traced recursively, all attenuated by e^(-beta d) over the distance travelled inside
 * a medium. Transparent occluders tint shadows by kt*filter per surface crossing (and by the
 * medium's attenuation) instead of blocking. Immutable; all per-ray state lives in the caller's
 * {@link TracerScratch}.
 *
 * <p>Media are entered and left per solid ({@link lt.spindulys.scene.GObject#solid()}): a CSG
 * result is one solid, so a ray that enters it through one leaf and leaves through another (of
 * another material) leaves the medium it entered, whose material gives the inside's index of
 * refraction and attenuation; the exit surface's material still gives that surface's kt and filter.
 *
 * <p>Area lights ({@link AreaLight}): each shaded point sends {@link AreaLight#samples()} shadow
 * rays per pixel sample to points on the light, drawn from strata of the light shared by the
 * pixel's samples (seeded from the pass seed, pixel, sample and light, as set by
 * {@link TracerScratch#setSample}), through the same transmission walk as point lights' shadow
 * rays; rays that reach a light before any surface see its radiance.
 *
 * <p>An environment that is a light ({@link EnvironmentLight}) is sampled the same way, as one
 * more sampled light after the area lights (its own strata and seeds): {@link Environment#samples()}
 * directions per pixel sample drawn in proportion to the map's brightness, each a shadow ray to
 * infinity that brings the radiance seen along it, weighted by the solid angle it stands for.
 *
 * <p>Textures ({@link TextureShading}): a material's bound channels are evaluated at each shaded
 * hit before lighting (colour, ks, kr, kt, emission, bumped shading normal), with a footprint from
 * the path length and the camera's pixel angle; shadow rays evaluate transparency textures.
 *
 * <p>A ray that hits nothing sees the scene's {@link Environment} along its direction if it has
 * one (so mirrors and glass show it), else the background colour.
 */
public final class WhittedIntegrator {
    /** Surfaces a shadow ray may cross before the light counts as blocked. */
    private static final int MAX_SHADOW_CROSSINGS = 64;

    private final Scene scene;
    private final RenderSettings settings;
    private final PointLight[] lights;
    private final AreaLight[] areaLights;
    /** What rays that hit nothing see, or null for the background colour. */
    private final Environment environment;
    /** The environment as a light, or null; sampled as light index areaLights.length. */
    private final EnvironmentLight environmentLight;
    /** Area lights plus the environment light if any: the lights that take strata. */
    private final int sampledLights;
    /** The area lights' samples per pixel sample together (the occluder cache's slots after theirs are the environment's). */
    private final int areaSamples;
    private final boolean transparentShadows;
    /** Angle between the primary rays of neighbouring pixels at the image centre, radians (texture footprints). */
    private final double pixelAngle;
    /**
     * Smallest squared distance an inverse-square light's falloff divides by: the one at which
     * all of them together could deliver {@link Ranges#MAX_IRRADIANCE}. A point (nearly) on a
     * light would otherwise receive an unbounded amount; for lights of everyday intensities this
     * distance is below 1e-12 and changes nothing.
     */
    private final double minDistance2;

    public WhittedIntegrator(Scene scene) {
        this.scene = scene;
        this.settings = scene.settings();
        this.lights = scene.lightArray();
        this.areaLights = scene.areaLightArray();
        this.environment = scene.environment();
        this.environmentLight = scene.environmentLight();
        this.sampledLights = areaLights.length + (environmentLight != null ? 1 : 0);
        int samples = 0;
        for (AreaLight l : areaLights) samples += l.samples(); // each at most AreaLight.MAX_SAMPLES
        this.areaSamples = samples;
        this.transparentShadows = scene.hasTransparentObjects();
        this.pixelAngle = pixelAngle(scene);
        double power = 0;
        for (PointLight l : lights) if (l.falloff() == PointLight.Falloff.INVERSE_SQUARE) power += l.power();
        this.minDistance2 = power / Ranges.MAX_IRRADIANCE;
    }

    /**
     * The camera's angle per pixel, measured between the rays through the two pixels at the
     * image centre (any camera model); the footprint of a texture lookup is this angle times the
     * path length. Away from the centre a pinhole's pixels subtend slightly less: the
     * approximation errs on the blurrier side there.
     */
    static double pixelAngle(Scene scene) {
        if (scene.camera() == null) return 0;
        int w = scene.settings().width(), h = scene.settings().height();
        double aspect = (double) w / h;
        Ray a = new Ray(), b = new Ray();
        scene.camera().generateRay(0.5, 0.5, aspect, 0, 0, 0, a); // from the lens centre
        scene.camera().generateRay(0.5 + 1.0 / w, 0.5, aspect, 0, 0, 0, b);
        double la = Math.sqrt(a.dx * a.dx + a.dy * a.dy + a.dz * a.dz), lb = Math.sqrt(b.dx * b.dx + b.dy * b.dy + b.dz * b.dz);
        double cos = (a.dx * b.dx + a.dy * b.dy + a.dz * b.dz) / (la * lb);
        double angle = Math.acos(Math.max(-1, Math.min(1, cos)));
        return Double.isFinite(angle) ? angle : 0;
    }

    /** Smallest incidence cosine used to widen a texture footprint on surfaces seen at a grazing angle. */
    private static final double MIN_FOOTPRINT_COSINE = 1 / lt.spindulys.texture.Mapping.MAX_ANISOTROPY;

    /**
     * A scratch sized for this scene's recursion depth and lights, for one thread: its heap
     * ({@link #scratchBytes}) is checked and reserved first, so threads that make theirs at once
     * cannot all pass the check and then all allocate.
     *
     * @throws lt.spindulys.limits.InsufficientMemoryException if the heap cannot hold it
     */
    public TracerScratch newScratch() {
        String what = environmentLight == null ? "the area lights' sample strata of one render thread"
                : "the area and environment lights' sample strata of one render thread";
        try (HeapBudget.Reservation r = HeapBudget.reserve(scratchBytes(settings.samplesPerPixel()), what)) {
            return newScratch(r);
        }
    }

    /**
     * A scratch made under a reservation the caller holds, which must cover
     * {@link #scratchBytes scratchBytes(samplesPerPixel)} (the renderer reserves every thread's at
     * once, before it starts them); that much of it is released once the scratch is made.
     *
     * @param reservation heap reserved for this scratch among others
     * @return the scratch
     */
    public TracerScratch newScratch(HeapBudget.Reservation reservation) {
        TracerScratch s = new TracerScratch(settings.maxDepth());
        s.lightStrata = new int[sampledLights][];
        s.lightStrataGeneration = new int[sampledLights];
        s.lightStrataCols = new int[sampledLights];
        // Each light's strata (pixel samples times its samples, both from the input) are kept per thread.
        int spp = settings.samplesPerPixel();
        for (int i = 0; i < sampledLights; i++) {
            int n = spp * samples(i);
            s.lightStrata[i] = new int[n];
            s.lightStrataCols[i] = strataCols(n);
        }
        reservation.release(scratchBytes(spp));
        return s;
    }

    /**
     * Heap one thread's scratch holds at {@code samplesPerPixel} pixel samples: 4 bytes per pixel
     * sample and light sample of every sampled light (its strata, the one part sized by input),
     * and the fixed rest (path vertices per recursion depth, the occluder cache, traversal stacks).
     *
     * @param samplesPerPixel the pixel samples of a pass
     * @return bytes, saturating
     */
    public long scratchBytes(int samplesPerPixel) {
        long bytes = HeapBudget.sum(FIXED_SCRATCH_BYTES, HeapBudget.product(settings.maxDepth() + 2, VERTEX_BYTES));
        for (int i = 0; i < sampledLights; i++) bytes = HeapBudget.sum(bytes, 16, HeapBudget.product(4, samplesPerPixel, samples(i)));
        return bytes;
    }

    /** Heap of a scratch that does not grow with the input: the trace context, its occluder cache and stacks, with a margin. */
    static final long FIXED_SCRATCH_BYTES = 32L << 10;

    /** Heap of one recursion depth's path vertex (ray, hit, shading record, colours), with a margin. */
    static final long VERTEX_BYTES = 1L << 10;

    /**
     * What makes the scratch large, for a message: "samples 65536 of the settings x samples 1024
     * of the environment", naming each sampled light's {@code samples} (a sum when there are several).
     *
     * @param samplesPerPixel the pixel samples of a pass
     * @return the phrase, or the pixel samples alone when no light is sampled
     */
    public String scratchSizedBy(int samplesPerPixel) {
        String pixel = "samples " + samplesPerPixel + " of the settings";
        if (sampledLights == 0) return pixel;
        if (sampledLights > 4) {
            long sum = 0;
            for (int i = 0; i < sampledLights; i++) sum += samples(i);
            return pixel + " x samples " + sum + " of " + sampledLights + " lights together";
        }
        StringBuilder counts = new StringBuilder(), names = new StringBuilder();
        for (int i = 0; i < sampledLights; i++) {
            counts.append(i == 0 ? "" : " + ").append(samples(i));
            names.append(i == 0 ? "" : ", ").append(lightName(i));
        }
        return pixel + " x samples " + counts + " of the " + names;
    }

    /** The statement of sampled light i: rectlight, disclight, spherelight or environment. */
    private String lightName(int i) {
        if (i >= areaLights.length) return "environment";
        return switch (areaLights[i].shape()) {
            case RECTANGLE -> "rectlight";
            case DISC -> "disclight";
            case SPHERE -> "spherelight";
        };
    }

    /** Shadow rays per pixel sample of sampled light i: an area light, or the environment after them. */
    private int samples(int i) {
        return i < areaLights.length ? areaLights[i].samples() : environmentLight.environment().samples();
    }

    /** Colour seen along a camera ray, written to out[0..2]. */
    public void traceCamera(Ray ray, TracerScratch s, double[] out) {
        s.cameraRays++;
        s.mediaCount = 0;
        s.path[0].travelled = 0;
        trace(ray, 0, 1, s, out);
    }

    /**
     * What a render pass sees along {@code ray}: its first hit only, with no lights, shadows or
     * secondary rays. Writes to out[0] the distance along the ray's direction made unit
     * (+Infinity if nothing is hit) and to out[1..3] the unit world-space shading normal turned to
     * face the ray, by the same rule as shading uses (0 0 0 if nothing is hit).
     *
     * @return the {@link lt.spindulys.scene.GObject#id()} of the object hit, or -1
     */
    public int traceFirstHit(Ray ray, TracerScratch s, double[] out) {
        s.cameraRays++;
        TracerScratch.PathVertex v = s.path[0];
        Hit hit = v.hit;
        if (!scene.intersect(ray, hit, s.ctx)) {
            out[0] = Double.POSITIVE_INFINITY;
            out[1] = out[2] = out[3] = 0;
            return -1;
        }
        ShadingData sd = v.shading;
        hit.object.shade(ray, hit, sd);
        double dlen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        double dx = ray.dx / dlen, dy = ray.dy / dlen, dz = ray.dz / dlen;
        // The normal pass shows the bumped normal that shading uses.
        if (sd.material.texture(Channel.BUMP) != null) TextureShading.evaluate(sd.material, sd, footprint(sd, hit.t * dlen, dx, dy, dz), s, v);
        // As in trace: flip both normals towards the ray by the geometric one, and fall back to
        // the geometric normal where the interpolated one still faces away.
        double sign = sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz < 0 ? 1 : -1;
        double nx = sign * sd.ns[0], ny = sign * sd.ns[1], nz = sign * sd.ns[2];
        if (nx * dx + ny * dy + nz * dz >= 0) { nx = sign * sd.ng[0]; ny = sign * sd.ng[1]; nz = sign * sd.ng[2]; }
        out[0] = hit.t * dlen;
        out[1] = nx; out[2] = ny; out[3] = nz;
        return hit.object.id();
    }

    /** World-space width of the pixel's footprint at a hit a path of this length reaches along unit direction d. */
    private double footprint(ShadingData sd, double travelled, double dx, double dy, double dz) {
        double cos = Math.abs(sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz);
        return travelled * pixelAngle / Math.max(cos, MIN_FOOTPRINT_COSINE);
    }

    /** Colour seen along {@code ray}, traced at recursion depth {@code depth}, written to out[0..2]. */
    private void trace(Ray ray, int depth, double weight, TracerScratch s, double[] out) {
        TracerScratch.PathVertex v = s.path[depth];
        Hit hit = v.hit;
        Material medium = s.innermost();
        double dlen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        boolean found = scene.intersect(ray, hit, s.ctx);
        if (areaLights.length > 0) {
            double tLight = seesAreaLight(ray, found ? hit.t : Double.POSITIVE_INFINITY, out);
            if (tLight == tLight) { // not NaN: a light is nearer than any surface
                if (medium != null) attenuate(medium, tLight * dlen, out);
                return;
            }
        }
        if (!found) {
            if (environment != null) {
                environment.lookup(ray.dx / dlen, ray.dy / dlen, ray.dz / dlen, out);
            } else {
                Color bg = settings.background();
                out[0] = bg.r(); out[1] = bg.g(); out[2] = bg.b();
            }
            if (medium != null) attenuate(medium, Double.POSITIVE_INFINITY, out);
            return;
        }
        ShadingData sd = v.shading;
        hit.object.shade(ray, hit, sd);
        Material m = sd.material;
        v.weight = weight;
        v.time = ray.time;
        double dx = ray.dx / dlen, dy = ray.dy / dlen, dz = ray.dz / dlen;
        v.dx = dx; v.dy = dy; v.dz = dz;
        double travelled = v.travelled + hit.t * dlen;

        // Textured surface terms (colour, ks, kr, kt, emission) and the bumped shading normal.
        TextureShading.evaluate(m, sd, m.isTextured() ? footprint(sd, travelled, dx, dy, dz) : 0, s, v);

        // Normals facing the incoming ray: nf geometric, sn shading (kept on nf's side).
        v.entering = sd.ng[0] * dx + sd.ng[1] * dy + sd.ng[2] * dz < 0;
        double sign = v.entering ? 1 : -1;
        v.nfx = sign * sd.ng[0]; v.nfy = sign * sd.ng[1]; v.nfz = sign * sd.ng[2];
        v.snx = sign * sd.ns[0]; v.sny = sign * sd.ns[1]; v.snz = sign * sd.ns[2];
        if (v.snx * dx + v.sny * dy + v.snz * dz >= 0) { v.snx = v.nfx; v.sny = v.nfy; v.snz = v.nfz; }
        double px = sd.p[0], py = sd.p[1], pz = sd.p[2];
        v.px = px; v.py = py; v.pz = pz;
        v.eps = 1e-9 * Math.max(1, Math.max(Math.abs(px), Math.max(Math.abs(py), Math.abs(pz)))) + 1e-9 * hit.t * dlen;

        localIllumination(m, v, s, out);
        out[0] += v.emissionR; out[1] += v.emissionG; out[2] += v.emissionB;

        if (depth < settings.maxDepth() && (v.kr > 0 || v.kt > 0)) {
            s.path[depth + 1].travelled = travelled;
            secondary(m, hit.object.solid(), depth, s, out);
        }
        if (medium != null) attenuate(medium, hit.t * dlen, out);
    }

    /** Ambient, diffuse and specular light at vertex v, whose surface has material m. */
    private void localIllumination(Material m, TracerScratch.PathVertex v, TracerScratch s, double[] out) {
        Color ia = settings.ambient();
        double ka = m.ka();
        out[0] = ka * ia.r() * v.colourR; out[1] = ka * ia.g() * v.colourG; out[2] = ka * ia.b() * v.colourB;
        if (!(m.kd() > 0 || v.ks > 0)) return;
        // A flat receiver cannot shadow itself: its shadow rays skip it (opaque shadows only).
        s.ctx.shadowReceiver = v.hit.object.flat() ? v.hit.object : null;
        pointIllumination(m, v, s, out);
        if (areaLights.length > 0) areaIllumination(m, v, s, out);
        if (environmentLight != null) environmentIllumination(m, v, s, out);
        s.ctx.shadowReceiver = null;
    }

    /** Adds to out[0..2] the diffuse and Blinn-Phong specular light from every point light at vertex v (material m). */
    private void pointIllumination(Material m, TracerScratch.PathVertex v, TracerScratch s, double[] out) {
        double kd = m.kd(), ks = v.ks, shininess = m.shininess();
        double px = v.px, py = v.py, pz = v.pz;
        double nfx = v.nfx, nfy = v.nfy, nfz = v.nfz, snx = v.snx, sny = v.sny, snz = v.snz;
        double ox = px + nfx * v.eps, oy = py + nfy * v.eps, oz = pz + nfz * v.eps;
        for (int li = 0; li < lights.length; li++) {
            PointLight light = lights[li];
            // Shading uses the true point; only the shadow ray starts off the surface.
            double lx = light.position().x() - px, ly = light.position().y() - py, lz = light.position().z() - pz;
            double dist2 = lx * lx + ly * ly + lz * lz, dist = Math.sqrt(dist2);
            if (!(dist > 0)) continue;
            double ux = lx / dist, uy = ly / dist, uz = lz / dist;
            if (ux * nfx + uy * nfy + uz * nfz <= 0) continue; // light behind the surface
            double ndotl = ux * snx + uy * sny + uz * snz;
            if (ndotl <= 0) continue;
            Ray shadow = s.shadowRay.set(ox, oy, oz, light.position().x() - ox, light.position().y() - oy, light.position().z() - oz, 0, 1);
            shadow.time = v.time; // a moving object casts its shadow where it is at the shaded ray's time
            s.ctx.occluderSlot = li & OCCLUDER_MASK;
            if (!shadowTransmission(shadow, dist, s)) continue;
            double[] t = s.transmission;
            double scale = light.intensity();
            if (light.falloff() == PointLight.Falloff.INVERSE_SQUARE) scale /= Math.max(dist2, minDistance2);
            Color lc = light.color();
            addLight(v, kd, ks, shininess, ux, uy, uz, ndotl, lc.r() * scale * t[0], lc.g() * scale * t[1], lc.b() * scale * t[2], out);
        }
    }

    /** Slots of the thread's occluder cache (TraceContext#occluders), less one: a mask. */
    private static final int OCCLUDER_MASK = lt.spindulys.trace.TraceContext.OCCLUDER_SLOTS - 1;

    /** Distinguishes the area-light strata's shuffle from the per-sample jitter and the pixel sampler's streams. */
    private static final long STRATA_STREAM = 0x61726561L, JITTER_STREAM = 0x6a697474L;

    /**
     * Adds to out[0..2] the diffuse and Blinn-Phong specular light from every area light at
     * vertex v (material m): each of a light's samples takes the stratum of the pixel's shuffled
     * strata that its pixel sample and index within the light select, jittered within it.
     */
    private void areaIllumination(Material m, TracerScratch.PathVertex v, TracerScratch s, double[] out) {
        double kd = m.kd(), ks = v.ks, shininess = m.shininess();
        double px = v.px, py = v.py, pz = v.pz;
        double nfx = v.nfx, nfy = v.nfy, nfz = v.nfz, snx = v.snx, sny = v.sny, snz = v.snz;
        double ox = px + nfx * v.eps, oy = py + nfy * v.eps, oz = pz + nfz * v.eps;
        double[] ls = s.lightSample;
        int slots = lights.length; // the occluder cache's slots: the point lights', then each light's strata
        for (int li = 0; li < areaLights.length; li++) {
            AreaLight light = areaLights[li];
            int k = light.samples(), n = s.samplesPerPixel * k;
            int[] strata = strata(li, n, s);
            int cols = s.lightStrataCols[li], rows = n / cols;
            int firstSlot = slots;
            slots += n;
            Rng rng = s.lightRng.seed(s.seed ^ JITTER_STREAM * (li + 1), s.pixelX, s.pixelY, s.sample);
            Color lc = light.color();
            double scale = light.intensity() / k;
            double lr = lc.r() * scale, lg = lc.g() * scale, lb = lc.b() * scale;
            for (int j = 0; j < k; j++) {
                int at = s.sample * k + j; // below n for a sample index below the pixel's count
                int st = strata[at < n ? at : at % n], row = st / cols;
                double su = (st - row * cols + rng.nextDouble()) / cols, sv = (row + rng.nextDouble()) / rows;
                if (!sampleLight(light, su, sv, px, py, pz, ls)) continue;
                double lx = ls[0] - px, ly = ls[1] - py, lz = ls[2] - pz;
                double dist = ls[4];
                if (!(dist > 0)) continue;
                double ux = lx / dist, uy = ly / dist, uz = lz / dist;
                if (ux * nfx + uy * nfy + uz * nfz <= 0) continue; // light behind the surface
                double ndotl = ux * snx + uy * sny + uz * snz;
                if (ndotl <= 0) continue;
                // The shadow ray stops just short of the light's surface, so that geometry the light
                // lies on (a disc on a ceiling) does not block it.
                Ray shadow = s.shadowRay.set(ox, oy, oz, ls[0] - ox, ls[1] - oy, ls[2] - oz, 0, 1 - 1e-7);
                shadow.time = v.time;
                s.ctx.occluderSlot = (firstSlot + st) & OCCLUDER_MASK;
                double weight = ls[3];
                if (!shadowTransmission(shadow, dist, s)) continue;
                double[] t = s.transmission;
                addLight(v, kd, ks, shininess, ux, uy, uz, ndotl, lr * weight * t[0], lg * weight * t[1], lb * weight * t[2], out);
            }
        }
    }

    /**
     * Adds to out[0..2] the diffuse and Blinn-Phong specular light from the environment at vertex
     * v (material m), as {@link #areaIllumination} does for an area light: its strata and seeds
     * are light index areaLights.length's, each stratum's jittered point becomes a direction
     * drawn by brightness, and a shadow ray to infinity along it brings the radiance seen there
     * times the solid angle the sample stands for, over the light's sample count.
     */
    private void environmentIllumination(Material m, TracerScratch.PathVertex v, TracerScratch s, double[] out) {
        double kd = m.kd(), ks = v.ks, shininess = m.shininess();
        double nfx = v.nfx, nfy = v.nfy, nfz = v.nfz, snx = v.snx, sny = v.sny, snz = v.snz;
        double ox = v.px + nfx * v.eps, oy = v.py + nfy * v.eps, oz = v.pz + nfz * v.eps;
        double[] ls = s.lightSample;
        int li = areaLights.length;
        int k = environmentLight.environment().samples(), n = s.samplesPerPixel * k;
        int[] strata = strata(li, n, s);
        int cols = s.lightStrataCols[li], rows = n / cols;
        int firstSlot = lights.length + s.samplesPerPixel * areaSamples; // after the point and area lights' slots
        Rng rng = s.lightRng.seed(s.seed ^ JITTER_STREAM * (li + 1), s.pixelX, s.pixelY, s.sample);
        for (int j = 0; j < k; j++) {
            int at = s.sample * k + j; // below n for a sample index below the pixel's count
            int st = strata[at < n ? at : at % n], row = st / cols;
            double su = (st - row * cols + rng.nextDouble()) / cols, sv = (row + rng.nextDouble()) / rows;
            environmentLight.sample(sv, su, ls);
            double ux = ls[0], uy = ls[1], uz = ls[2];
            if (ux * nfx + uy * nfy + uz * nfz <= 0) continue; // below the surface
            double ndotl = ux * snx + uy * sny + uz * snz;
            if (ndotl <= 0) continue;
            Ray shadow = s.shadowRay.set(ox, oy, oz, ux, uy, uz, 0, Double.POSITIVE_INFINITY);
            shadow.time = v.time;
            double weight = ls[3] / k, lr = ls[4] * weight, lg = ls[5] * weight, lb = ls[6] * weight;
            s.ctx.occluderSlot = (firstSlot + st) & OCCLUDER_MASK;
            if (!shadowTransmission(shadow, 1, s)) continue;
            double[] t = s.transmission;
            addLight(v, kd, ks, shininess, ux, uy, uz, ndotl, lr * t[0], lg * t[1], lb * t[2], out);
        }
    }

    /**
     * Adds to out[0..2] the diffuse and Blinn-Phong specular reflection at v of light (ir, ig, ib)
     * arriving from unit direction (ux, uy, uz), whose cosine with the shading normal is ndotl:
     * a point light, or one sample of an area light or of the environment.
     */
    private static void addLight(TracerScratch.PathVertex v, double kd, double ks, double shininess,
                                 double ux, double uy, double uz, double ndotl, double ir, double ig, double ib, double[] out) {
        double diff = kd * ndotl;
        out[0] += diff * v.colourR * ir; out[1] += diff * v.colourG * ig; out[2] += diff * v.colourB * ib;
        if (ks > 0) {
            double hx = ux - v.dx, hy = uy - v.dy, hz = uz - v.dz;
            double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
            double nh = hl > 0 ? (hx * v.snx + hy * v.sny + hz * v.snz) / hl : 0;
            if (nh > 0) {
                double spec = ks * Math.pow(nh, shininess);
                out[0] += spec * ir; out[1] += spec * ig; out[2] += spec * ib;
            }
        }
    }

    /**
     * The order in which the pixel's samples take area light li's n strata: a shuffle seeded from
     * the pass seed, pixel and light, drawn once per pixel and thread.
     */
    private int[] strata(int li, int n, TracerScratch s) {
        if (s.lightStrata.length < sampledLights) { // a scratch not made by newScratch
            s.lightStrata = new int[sampledLights][];
            s.lightStrataGeneration = new int[sampledLights];
            s.lightStrataCols = new int[sampledLights];
        }
        int[] p = s.lightStrata[li];
        if (p != null && p.length == n && s.lightStrataGeneration[li] == s.pixelGeneration) return p;
        if (p == null || p.length != n) {
            p = s.lightStrata[li] = new int[n];
            s.lightStrataCols[li] = strataCols(n);
        }
        for (int i = 0; i < n; i++) p[i] = i;
        Rng rng = s.lightRng.seed(s.seed ^ STRATA_STREAM * (li + 1), s.pixelX, s.pixelY, li);
        for (int i = n - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            int t = p[i]; p[i] = p[j]; p[j] = t;
        }
        s.lightStrataGeneration[li] = s.pixelGeneration;
        return p;
    }

    /** Columns of the grid of n strata over a light's unit square, as square as n allows (n = rows x cols, rows <= cols). */
    private static int strataCols(int n) {
        int rows = (int) Math.floor(Math.sqrt(n));
        while (n % rows != 0) rows--;
        return n / rows;
    }

    /**
     * A point on {@code light} for the unit-square sample (su, sv), seen from (px, py, pz): writes
     * it to out[0..2], its distance from (px, py, pz) to out[4] and to out[3] the weight that turns radiance into this sample's irradiance
     * share before the receiver's cosine (the solid angle per sample: cos at the light * area / d^2
     * for a rectangle or disc sampled by area, the cone's solid angle for a sphere sampled within
     * the cone it fills).
     *
     * @return false if the sample gives nothing (the light's back, or the point inside a sphere)
     */
    static boolean sampleLight(AreaLight light, double su, double sv, double px, double py, double pz, double[] out) {
        lt.spindulys.math.Vec3 c = light.center(), u = light.halfU(), w = light.halfV();
        if (light.shape() == AreaLight.Shape.SPHERE) {
            double wx = c.x() - px, wy = c.y() - py, wz = c.z() - pz;
            double d2 = wx * wx + wy * wy + wz * wz, r = light.radius();
            if (!(d2 > r * r)) return false;
            double d = Math.sqrt(d2);
            wx /= d; wy /= d; wz /= d;
            double x = r * r / d2;
            double oneMinusCosMax = x / (1 + Math.sqrt(1 - x)); // 1 - sqrt(1 - x) without cancellation
            double cos = 1 - su * oneMinusCosMax, sin = Math.sqrt(Math.max(0, 1 - cos * cos));
            double phi = 2 * Math.PI * sv;
            // A frame about the direction to the centre.
            double ax = Math.abs(wx) < 0.9 ? 1 : 0, ay = ax == 1 ? 0 : 1;
            double tx = ay * wz, ty = -ax * wz, tz = ax * wy - ay * wx; // (a x w)
            double tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
            tx /= tl; ty /= tl; tz /= tl;
            double bx = wy * tz - wz * ty, by = wz * tx - wx * tz, bz = wx * ty - wy * tx;
            double cp = Math.cos(phi) * sin, sp = Math.sin(phi) * sin;
            double dx = wx * cos + tx * cp + bx * sp, dy = wy * cos + ty * cp + by * sp, dz = wz * cos + tz * cp + bz * sp;
            // The nearer crossing of the sphere along that direction.
            double t = d * cos - Math.sqrt(Math.max(0, r * r - d2 * sin * sin));
            out[0] = px + t * dx; out[1] = py + t * dy; out[2] = pz + t * dz;
            out[3] = 2 * Math.PI * oneMinusCosMax;
            double lx = out[0] - px, ly = out[1] - py, lz = out[2] - pz;
            out[4] = Math.sqrt(lx * lx + ly * ly + lz * lz);
            return true;
        }
        double a = 2 * su - 1, b = 2 * sv - 1;
        if (light.shape() == AreaLight.Shape.DISC) {
            // Shirley and Chiu's concentric map, as for lens samples: strata stay equal in area.
            double rr, phi;
            if (a == 0 && b == 0) { rr = 0; phi = 0; }
            else if (Math.abs(a) > Math.abs(b)) { rr = a; phi = Math.PI / 4 * (b / a); }
            else { rr = b; phi = Math.PI / 2 - Math.PI / 4 * (a / b); }
            a = rr * Math.cos(phi);
            b = rr * Math.sin(phi);
        }
        double x = c.x() + a * u.x() + b * w.x(), y = c.y() + a * u.y() + b * w.y(), z = c.z() + a * u.z() + b * w.z();
        double lx = px - x, ly = py - y, lz = pz - z;
        double d2 = lx * lx + ly * ly + lz * lz;
        if (!(d2 > 0)) return false;
        lt.spindulys.math.Vec3 n = light.normal();
        double d = Math.sqrt(d2);
        double cos = (lx * n.x() + ly * n.y() + lz * n.z()) / d;
        if (light.oneSided() ? cos <= 0 : cos == 0) return false;
        out[0] = x; out[1] = y; out[2] = z;
        out[3] = Math.abs(cos) * light.area() / d2;
        out[4] = d; // the same as from the point to the sample: (px - x)^2 = (x - px)^2 exactly
        return true;
    }

    /**
     * If {@code ray} reaches an area light before {@code tBound}, writes the radiance it sees there
     * to out[0..2] (black from a one-sided light's back) and returns the ray parameter of the
     * crossing; else returns NaN and leaves out alone.
     */
    private double seesAreaLight(Ray ray, double tBound, double[] out) {
        double best = Math.min(tBound, ray.tMax);
        AreaLight seen = null;
        boolean front = false;
        double ox = ray.ox, oy = ray.oy, oz = ray.oz, dx = ray.dx, dy = ray.dy, dz = ray.dz;
        for (AreaLight light : areaLights) {
            lt.spindulys.math.Vec3 c = light.center();
            double cx = c.x() - ox, cy = c.y() - oy, cz = c.z() - oz;
            if (light.shape() == AreaLight.Shape.SPHERE) {
                double r = light.radius();
                double a = dx * dx + dy * dy + dz * dz, hb = dx * cx + dy * cy + dz * cz;
                double disc = hb * hb - a * (cx * cx + cy * cy + cz * cz - r * r);
                if (disc < 0) continue;
                double sq = Math.sqrt(disc);
                double t = (hb - sq) / a;
                if (!(t > ray.tMin)) t = (hb + sq) / a;
                if (t > ray.tMin && t < best) { best = t; seen = light; front = true; }
                continue;
            }
            lt.spindulys.math.Vec3 n = light.normal(), u = light.halfU(), w = light.halfV();
            double denom = n.x() * dx + n.y() * dy + n.z() * dz;
            if (denom == 0) continue;
            double t = (n.x() * cx + n.y() * cy + n.z() * cz) / denom;
            if (!(t > ray.tMin && t < best)) continue;
            double qx = ox + t * dx - c.x(), qy = oy + t * dy - c.y(), qz = oz + t * dz - c.z();
            double a = (qx * u.x() + qy * u.y() + qz * u.z()) / (u.x() * u.x() + u.y() * u.y() + u.z() * u.z());
            double b = (qx * w.x() + qy * w.y() + qz * w.z()) / (w.x() * w.x() + w.y() * w.y() + w.z() * w.z());
            boolean inside = light.shape() == AreaLight.Shape.DISC ? a * a + b * b <= 1 : Math.abs(a) <= 1 && Math.abs(b) <= 1;
            if (!inside) continue;
            best = t;
            seen = light;
            front = denom < 0 || !light.oneSided();
        }
        if (seen == null) return Double.NaN;
        Color lc = seen.color();
        double i = front ? seen.intensity() : 0;
        out[0] = lc.r() * i; out[1] = lc.g() * i; out[2] = lc.b() * i;
        return best;
    }

    /**
     * Fraction of a light's colour that reaches the origin of {@code ray}, the scratch's shadow
     * ray (t = 1 at the light, which is {@code dist} away; or, with tMax infinite, a ray with a
     * unit direction and {@code dist} 1 towards the environment), written to s.transmission;
     * false if nothing arrives.
     */
    private boolean shadowTransmission(Ray ray, double dist, TracerScratch s) {
        s.shadowRays++;
        double[] t = s.transmission;
        t[0] = t[1] = t[2] = 1;
        if (!transparentShadows) return !scene.occluded(ray, s.ctx);
        Hit hit = s.shadowHit;
        ShadingData sd = s.shadowShading;
        // Walk through the surfaces between the point and the light; media entered along the way
        // attenuate from their entry, a medium left without an entry did so from the origin. A
        // medium is left through any surface of the solid it was entered by (a CSG result's exit
        // may be another leaf, with another material); the entry's material attenuates.
        Material inside = null;
        TracedObject insideSolid = null;
        double enteredAt = 0;
        // Where the light is, in t: a medium still entered there attenuates up to it (an
        // environment is infinitely far: only the medium's channels with beta 0 pass).
        double end = ray.tMax == Double.POSITIVE_INFINITY ? Double.POSITIVE_INFINITY : 1;
        for (int crossing = 0; crossing < MAX_SHADOW_CROSSINGS; crossing++) {
            if (!scene.intersect(ray, hit, s.ctx)) {
                if (inside != null) attenuate(inside, (end - enteredAt) * dist, t);
                return t[0] > 0 || t[1] > 0 || t[2] > 0;
            }
            Material m = hit.material;
            if (m.kt() <= 0) return false;
            // A transparency texture needs the hit's shading data; shade once and reuse it below.
            boolean shaded = m.texture(Channel.TRANSPARENCY) != null;
            double kt = m.kt();
            if (shaded) {
                hit.object.shade(ray, hit, sd);
                kt = TextureShading.shadowKt(m, sd, s);
            }
            Color f = m.filter();
            t[0] *= kt * f.r(); t[1] *= kt * f.g(); t[2] *= kt * f.b();
            if (m.attenuates() || inside != null) {
                if (!shaded) hit.object.shade(ray, hit, sd);
                boolean entering = sd.ng[0] * ray.dx + sd.ng[1] * ray.dy + sd.ng[2] * ray.dz < 0;
                TracedObject solid = hit.object.solid();
                if (entering) {
                    if (m.attenuates()) {
                        inside = m;
                        insideSolid = solid;
                        enteredAt = hit.t;
                    }
                } else if (inside != null && (insideSolid == solid || inside == m)) {
                    attenuate(inside, (hit.t - enteredAt) * dist, t);
                    inside = null;
                    insideSolid = null;
                } else if (m.attenuates()) {
                    attenuate(m, hit.t * dist, t);
                    inside = null;
                    insideSolid = null;
                }
            }
            if (t[0] <= 0 && t[1] <= 0 && t[2] <= 0) return false;
            ray.tMin = hit.t + 1e-9;
        }
        return false;
    }

    /**
     * Adds to out the reflected and refracted light at vertex {@code depth}, whose surface (of
     * material m, part of {@code solid}) reflects or transmits, traced one depth deeper.
     */
    private void secondary(Material m, TracedObject solid, int depth, TracerScratch s, double[] out) {
        TracerScratch.PathVertex v = s.path[depth];
        double dx = v.dx, dy = v.dy, dz = v.dz;
        double nfx = v.nfx, nfy = v.nfy, nfz = v.nfz, snx = v.snx, sny = v.sny, snz = v.snz;
        double kr = v.kr, kt = v.kt;
        double reflW = kr, refrW = kt;
        double[] dir = s.dir;
        double tx = 0, ty = 0, tz = 0; // the refracted direction, kept for after the reflection
        boolean canRefract = false;
        double n1 = 1, n2 = 1;
        // Leaving the medium the ray is in: the innermost one was entered through a surface of
        // this solid (for a CSG result possibly another leaf with another material) or is the
        // same material. Its material is then the inside's index, not the exit surface's.
        boolean leavesInnermost = !v.entering && (s.innermostSolid() == solid || s.innermost() == m);
        if (kt > 0) {
            // Indices on both sides: entering goes from the current medium into m; leaving goes
            // from the medium left into whatever encloses it on the medium stack.
            if (v.entering) {
                n1 = ior(s.innermost());
                n2 = m.ior();
            } else {
                n1 = leavesInnermost ? s.innermost().ior() : m.ior();
                n2 = ior(leavesInnermost ? s.outer() : s.innermost());
            }
            canRefract = Optics.refract(dx, dy, dz, snx, sny, snz, n1, n2, dir);
            if (canRefract && dir[0] * nfx + dir[1] * nfy + dir[2] * nfz >= 0) {
                canRefract = Optics.refract(dx, dy, dz, nfx, nfy, nfz, n1, n2, dir);
            }
            tx = dir[0]; ty = dir[1]; tz = dir[2];
            if (m.fresnel()) {
                double fr = Optics.schlick(-(dx * snx + dy * sny + dz * snz), n1, n2);
                reflW = kr + kt * fr;
                refrW = kt * (1 - fr);
            }
            if (!canRefract) { // total internal reflection: the transmitted share is reflected
                reflW += refrW;
                refrW = 0;
            }
        }
        TracerScratch.PathVertex next = s.path[depth + 1];
        double[] c = next.seen;
        Ray ray = next.ray;
        ray.time = v.time;
        double px = v.px, py = v.py, pz = v.pz, eps = v.eps, weight = v.weight;
        if (reflW > 0 && reflW * weight >= settings.minContribution()) {
            Optics.reflect(dx, dy, dz, snx, sny, snz, dir);
            if (dir[0] * nfx + dir[1] * nfy + dir[2] * nfz <= 0) Optics.reflect(dx, dy, dz, nfx, nfy, nfz, dir);
            ray.set(px + nfx * eps, py + nfy * eps, pz + nfz * eps, dir[0], dir[1], dir[2], 0, Double.POSITIVE_INFINITY);
            s.reflectionRays++;
            trace(ray, depth + 1, weight * reflW, s, c);
            out[0] += reflW * c[0]; out[1] += reflW * c[1]; out[2] += reflW * c[2];
        }
        Color f = m.filter();
        if (refrW > 0 && refrW * f.max() * weight >= settings.minContribution()) {
            ray.set(px - nfx * eps, py - nfy * eps, pz - nfz * eps, tx, ty, tz, 0, Double.POSITIVE_INFINITY);
            s.refractionRays++;
            if (v.entering) {
                s.pushMedium(m, solid);
                trace(ray, depth + 1, weight * refrW * f.max(), s, c);
                s.mediaCount--;
            } else if (leavesInnermost) {
                Material left = s.innermost();
                TracedObject leftSolid = s.innermostSolid();
                s.mediaCount--;
                trace(ray, depth + 1, weight * refrW * f.max(), s, c);
                s.pushMedium(left, leftSolid);
            } else {
                trace(ray, depth + 1, weight * refrW * f.max(), s, c);
            }
            out[0] += refrW * f.r() * c[0]; out[1] += refrW * f.g() * c[1]; out[2] += refrW * f.b() * c[2];
        }
    }

    private static double ior(Material m) { return m == null ? 1 : m.ior(); }

    /** Multiplies rgb by e^(-beta d) of the medium; an infinite distance leaves only channels with beta 0. */
    private static void attenuate(Material medium, double distance, double[] rgb) {
        if (!medium.attenuates()) return;
        Color beta = medium.beta();
        rgb[0] *= beta.r() == 0 ? 1 : Math.exp(-beta.r() * distance);
        rgb[1] *= beta.g() == 0 ? 1 : Math.exp(-beta.g() * distance);
        rgb[2] *= beta.b() == 0 ? 1 : Math.exp(-beta.b() * distance);
    }
}
