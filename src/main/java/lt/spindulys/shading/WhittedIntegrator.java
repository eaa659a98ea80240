package lt.spindulys.shading;

import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.TracedObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.light.Light;
import lt.spindulys.light.LightSample;
import lt.spindulys.light.Lights;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.material.Material;
import lt.spindulys.sampling.ProgressiveSequence;
import lt.spindulys.sampling.Rng;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.EnvironmentLight;
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
 * <p>Lights ({@link Lights}: the point lights, the {@link AreaLight area lights}, and the
 * environment if it is an {@link EnvironmentLight}) are shaded in one loop, each light drawing
 * its own samples ({@link Light#sampleLi}) into the scratch's {@link LightSample}. A point light
 * takes one; every other light takes {@link Light#samples()} per pixel sample at points of the
 * unit square drawn from strata of the light shared by the pixel's samples (seeded from the pass
 * seed, pixel, sample and light, as set by {@link TracerScratch#setSample}), or, for a pixel
 * whose count is open (adaptive sampling), from the light's progressive sequence over the pixel's
 * samples ({@link TracerScratch#setProgressiveSample}). Each sample's shadow
 * ray goes through the same transmission walk, to the sampled point or, for the environment, to
 * infinity, and brings the sample's weighted radiance. Rays that reach an area light before any
 * surface see its radiance.
 *
 * <p>Textures ({@link TextureShading}): a material's bound channels are evaluated at each shaded
 * hit before lighting (colour, ks, kr, kt, emission, bumped shading normal), with a footprint from
 * the path length and the camera's pixel angle; shadow rays evaluate transparency textures.
 *
 * <p>A ray that hits nothing sees the scene's {@link Environment} along its direction if it has
 * one (so mirrors and glass show it), else the background colour; a camera ray (depth 0) sees the
 * environment's camera view ({@link Environment#lookupFromCamera}).
 */
public final class WhittedIntegrator implements Integrator {
    /** Surfaces a shadow ray may cross before the light counts as blocked. */
    private static final int MAX_SHADOW_CROSSINGS = 64;

    private final Scene scene;
    private final RenderSettings settings;
    /** The scene's lights: the point lights, the area lights, the environment if it is a light. */
    private final Lights lights;
    private final Light[] lightArray;
    /** The lights that take strata (all but the point lights), counted. */
    private final int stratifiedLights;
    /** What rays that hit nothing see, or null for the background colour. */
    private final Environment environment;
    private final boolean transparentShadows;
    /** What render passes see, and the footprints of texture lookups. */
    private final FirstHits firstHits;

    public WhittedIntegrator(Scene scene) {
        this.scene = scene;
        this.settings = scene.settings();
        this.lights = Lights.of(scene);
        this.lightArray = lights.all();
        this.stratifiedLights = lights.stratified();
        this.environment = scene.environment();
        this.transparentShadows = scene.hasTransparentObjects();
        this.firstHits = new FirstHits(scene);
    }

    /**
     * A scratch sized for this scene's recursion depth and lights, for one thread: its heap
     * ({@link #scratchBytes}) is checked and reserved first, so threads that make theirs at once
     * cannot all pass the check and then all allocate.
     *
     * @throws lt.spindulys.limits.InsufficientMemoryException if the heap cannot hold it
     */
    public TracerScratch newScratch() {
        String what = scene.environmentLight() == null ? "the area lights' sample strata of one render thread"
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
    @Override
    public TracerScratch newScratch(HeapBudget.Reservation reservation) {
        TracerScratch s = new TracerScratch(settings.maxDepth());
        s.lightStrata = new int[stratifiedLights][];
        s.lightStrataGeneration = new int[stratifiedLights];
        s.lightStrataCols = new int[stratifiedLights];
        // Each light's strata (pixel samples times its samples, both from the input) are kept per thread.
        int spp = settings.samplesPerPixel();
        int i = 0;
        for (Light l : lightArray) {
            if (l.isDelta()) continue;
            int n = spp * l.samples();
            s.lightStrata[i] = new int[n];
            s.lightStrataCols[i++] = strataCols(n);
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
    @Override
    public long scratchBytes(int samplesPerPixel) {
        long bytes = HeapBudget.sum(FIXED_SCRATCH_BYTES, HeapBudget.product(settings.maxDepth() + 2, VERTEX_BYTES));
        for (Light l : lightArray) if (!l.isDelta()) bytes = HeapBudget.sum(bytes, 16, HeapBudget.product(4, samplesPerPixel, l.samples()));
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
    @Override
    public String scratchSizedBy(int samplesPerPixel) {
        String pixel = "samples " + samplesPerPixel + " of the settings";
        if (stratifiedLights == 0) return pixel;
        long sum = 0;
        StringBuilder counts = new StringBuilder(), names = new StringBuilder();
        for (Light l : lightArray) {
            if (l.isDelta()) continue;
            sum += l.samples();
            counts.append(counts.length() == 0 ? "" : " + ").append(l.samples());
            names.append(names.length() == 0 ? "" : ", ").append(l.statement());
        }
        if (stratifiedLights > 4) return pixel + " x samples " + sum + " of " + stratifiedLights + " lights together";
        return pixel + " x samples " + counts + " of the " + names;
    }

    /** Colour seen along a camera ray, written to out[0..2]. */
    @Override
    public void traceCamera(Ray ray, TracerScratch s, double[] out) {
        s.cameraRays++;
        s.mediaCount = 0;
        s.path[0].travelled = 0;
        trace(ray, 0, 1, s, out);
    }

    @Override
    public int traceFirstHit(Ray ray, TracerScratch s, double[] out) { return firstHits.trace(ray, s, out); }

    /** Colour seen along {@code ray}, traced at recursion depth {@code depth}, written to out[0..2]. */
    private void trace(Ray ray, int depth, double weight, TracerScratch s, double[] out) {
        TracerScratch.PathVertex v = s.path[depth];
        Hit hit = v.hit;
        Material medium = s.innermost();
        double dlen = Math.sqrt(ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz);
        // Set before each query: the shadow rays of the depth above left it at SHADOW.
        if (TraversalScratch.COUNTING) s.ctx.rayKind = depth == 0 ? TraversalScratch.CAMERA : TraversalScratch.SECONDARY;
        boolean found = scene.intersect(ray, hit, s.ctx);
        if (lights.hasSurfaces()) {
            double[] seen = s.lightSeen;
            if (lights.nearestSurface(ray, found ? hit.t : Double.POSITIVE_INFINITY, seen) >= 0) { // a light is nearer than any surface
                out[0] = seen[0]; out[1] = seen[1]; out[2] = seen[2];
                if (medium != null) attenuate(medium, seen[3] * dlen, out);
                if (depth == 0) FirstHits.recordNothing(s);
                return;
            }
        }
        if (!found) {
            if (depth == 0) FirstHits.recordNothing(s);
            if (environment != null) {
                // Camera rays see the environment as its camera view says; reflections and refractions see the map.
                if (depth == 0) environment.lookupFromCamera(ray.dx / dlen, ray.dy / dlen, ray.dz / dlen, settings.background(), out);
                else environment.lookup(ray.dx / dlen, ray.dy / dlen, ray.dz / dlen, out);
            } else {
                Color bg = settings.background();
                out[0] = bg.r(); out[1] = bg.g(); out[2] = bg.b();
            }
            if (medium != null) attenuate(medium, Double.POSITIVE_INFINITY, out);
            return;
        }
        if (depth == 0 && hit.object instanceof lt.spindulys.scene.AdaptiveSubdivisionSurface) s.adaptiveCameraHits++;
        ShadingData sd = v.shading;
        hit.object.shade(ray, hit, sd);
        Material m = sd.material;
        v.weight = weight;
        v.time = ray.time;
        double dx = ray.dx / dlen, dy = ray.dy / dlen, dz = ray.dz / dlen;
        v.dx = dx; v.dy = dy; v.dz = dz;
        double travelled = v.travelled + hit.t * dlen;

        // Textured surface terms (colour, ks, kr, kt, emission) and the bumped shading normal.
        TextureShading.evaluate(m, sd, m.isTextured() ? firstHits.footprint(sd, travelled, dx, dy, dz) : 0, s, v);
        if (depth == 0) FirstHits.recordHit(s, v, sd, dx, dy, dz, travelled);

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
        // Not from a lifted origin: its shadow rays may test lights behind the plane, which the plane must block.
        boolean lifted = v.entering && v.shading.lifted;
        s.ctx.shadowReceiver = v.hit.object.flat() && !lifted ? v.hit.object : null;
        directIllumination(m, v, s, out);
        s.ctx.shadowReceiver = null;
    }

    /** Slots of the thread's occluder cache (TraceContext#occluders), less one: a mask. */
    private static final int OCCLUDER_MASK = lt.spindulys.trace.TraceContext.OCCLUDER_SLOTS - 1;

    /** Columns and rows of the grid whose cells are a progressively sampled light's occluder slots. */
    private static final int PROGRESSIVE_CELLS = 8;

    /** Distinguishes the light strata's shuffle from the per-sample jitter and the pixel sampler's streams. */
    private static final long STRATA_STREAM = 0x61726561L, JITTER_STREAM = 0x6a697474L;

    /**
     * Adds to out[0..2] the diffuse and Blinn-Phong specular light from every light at vertex v
     * (material m). A point light takes one sample. Every other light takes its samples per pixel
     * sample, each in the stratum of the pixel's shuffled strata that its pixel sample and index
     * within the light select, jittered within it (the lights that take strata are numbered in
     * order for their seeds); or, when the pixel's count is open, point (pixel sample x samples
     * + index) of the light's progressive sequence. Each sample's shadow ray uses its own slot of the occluder cache:
     * the point lights' one each, then each light's strata.
     */
    private void directIllumination(Material m, TracerScratch.PathVertex v, TracerScratch s, double[] out) {
        double kd = m.kd(), ks = v.ks, shininess = m.shininess();
        double px = v.px, py = v.py, pz = v.pz;
        double nfx = v.nfx, nfy = v.nfy, nfz = v.nfz, snx = v.snx, sny = v.sny, snz = v.snz;
        // Shading uses the true point; only the shadow rays start off the surface.
        double ox = px, oy = py, oz = pz;
        // Seen from outside, a smooth triangle's shadow rays start on the curved surface its
        // vertex normals describe (ShadingData#shadowOrigin).
        ShadingData sd = v.shading;
        boolean lifted = v.entering && sd.lifted;
        if (lifted) { ox = sd.shadowOrigin[0]; oy = sd.shadowOrigin[1]; oz = sd.shadowOrigin[2]; }
        ox += nfx * v.eps; oy += nfy * v.eps; oz += nfz * v.eps;
        LightSample ls = s.lightSample;
        int slots = 0, stratified = 0;
        for (Light light : lightArray) {
            int k = light.samples(), n = 1, cols = 1, rows = 1, firstSlot = slots;
            int[] strata = null;
            Rng rng = null;
            boolean sequence = !light.isDelta() && s.progressive;
            long key = 0;
            if (sequence) {
                // The pixel's count is open: the light's samples are one progressive sequence over
                // the pixel's, and the occluder slot the cell of a fixed grid each falls in.
                key = ProgressiveSequence.key(s.seed ^ STRATA_STREAM, s.pixelX, s.pixelY, stratified++);
                n = PROGRESSIVE_CELLS * PROGRESSIVE_CELLS;
            } else if (!light.isDelta()) {
                int li = stratified++;
                n = s.samplesPerPixel * k;
                strata = strata(li, n, s);
                cols = s.lightStrataCols[li];
                rows = n / cols;
                rng = s.lightRng.seed(s.seed ^ JITTER_STREAM * (li + 1), s.pixelX, s.pixelY, s.sample);
            }
            slots += n;
            for (int j = 0; j < k; j++) {
                double su = 0.5, sv = 0.5;
                int st = 0;
                if (sequence) {
                    double[] p = s.square;
                    ProgressiveSequence.get2D(s.sample * k + j, key, p);
                    su = p[0];
                    sv = p[1];
                    st = (int) (sv * PROGRESSIVE_CELLS) * PROGRESSIVE_CELLS + (int) (su * PROGRESSIVE_CELLS);
                } else if (rng != null) {
                    int at = s.sample * k + j; // below n for a sample index below the pixel's count
                    st = strata[at < n ? at : at % n];
                    int row = st / cols;
                    su = (st - row * cols + rng.nextDouble()) / cols;
                    sv = (row + rng.nextDouble()) / rows;
                }
                if (!light.sampleLi(px, py, pz, su, sv, ls)) continue;
                double ux = ls.wx, uy = ls.wy, uz = ls.wz;
                // A light behind the facet is shadowed, unless the shadow ray starts on the curved
                // surface (and the shading normal faces the light): then the ray decides, as the
                // curved surface would, and the terminator follows the shading, not the facets.
                if (ux * nfx + uy * nfy + uz * nfz <= 0 && !lifted) continue;
                double ndotl = ux * snx + uy * sny + uz * snz;
                if (ndotl <= 0) continue;
                boolean infinite = ls.distance == Double.POSITIVE_INFINITY;
                Ray shadow = infinite ? s.shadowRay.set(ox, oy, oz, ux, uy, uz, 0, Double.POSITIVE_INFINITY)
                        : s.shadowRay.set(ox, oy, oz, ls.x - ox, ls.y - oy, ls.z - oz, 0, ls.shadowTMax);
                shadow.time = v.time; // a moving object casts its shadow where it is at the shaded ray's time
                s.ctx.occluderSlot = (firstSlot + st) & OCCLUDER_MASK;
                if (!shadowTransmission(shadow, infinite ? 1 : ls.distance, s)) continue;
                double[] t = s.transmission;
                addLight(v, kd, ks, shininess, ux, uy, uz, ndotl, ls.weightedR * t[0], ls.weightedG * t[1], ls.weightedB * t[2], out);
            }
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
     * The order in which the pixel's samples take stratified light li's n strata (the first n
     * entries): a shuffle seeded from the pass seed, pixel and light, drawn once per pixel and
     * thread.
     */
    private int[] strata(int li, int n, TracerScratch s) {
        if (s.lightStrata.length < stratifiedLights) { // a scratch not made by newScratch
            s.lightStrata = new int[stratifiedLights][];
            s.lightStrataGeneration = new int[stratifiedLights];
            s.lightStrataCols = new int[stratifiedLights];
        }
        int[] p = s.lightStrata[li];
        // The generation changes with the pixel's sample count, so it fixes n for this light.
        if (p != null && p.length >= n && s.lightStrataGeneration[li] == s.pixelGeneration) return p;
        // Sized for the settings' samples per pixel; a pass of fewer reuses it.
        if (p == null || p.length < n) p = s.lightStrata[li] = new int[n];
        s.lightStrataCols[li] = strataCols(n);
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
     * Fraction of a light's colour that reaches the origin of {@code ray}, the scratch's shadow
     * ray (t = 1 at the light, which is {@code dist} away; or, with tMax infinite, a ray with a
     * unit direction and {@code dist} 1 towards the environment), written to s.transmission;
     * false if nothing arrives.
     */
    private boolean shadowTransmission(Ray ray, double dist, TracerScratch s) {
        s.shadowRays++;
        if (TraversalScratch.COUNTING) s.ctx.rayKind = TraversalScratch.SHADOW;
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

    static double ior(Material m) { return m == null ? 1 : m.ior(); }

    /** Multiplies rgb by e^(-beta d) of the medium; an infinite distance leaves only channels with beta 0. */
    static void attenuate(Material medium, double distance, double[] rgb) {
        if (!medium.attenuates()) return;
        Color beta = medium.beta();
        rgb[0] *= beta.r() == 0 ? 1 : Math.exp(-beta.r() * distance);
        rgb[1] *= beta.g() == 0 ? 1 : Math.exp(-beta.g() * distance);
        rgb[2] *= beta.b() == 0 ? 1 : Math.exp(-beta.b() * distance);
    }
}
