package lt.spindulys.shading;

import lt.spindulys.light.LightSample;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.TracedObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.material.Material;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.texture.TexturePoint;

/**
 * Per-thread scratch of the integrator: one {@link PathVertex} per recursion depth (the recursion
 * is depth-first, so a depth's vertex is free again when it returns), the stack of media the
 * current ray is inside, and ray counters. Never shared between threads.
 */
public final class TracerScratch {
    public final TraceContext ctx = new TraceContext();
    /** The vertex of each recursion depth, 0 for the camera ray's hit. */
    final PathVertex[] path;
    /** Output of {@link Optics#reflect} and {@link Optics#refract}, read at once. */
    final double[] dir = new double[3];
    final Ray shadowRay = new Ray();
    final Hit shadowHit = new Hit();
    final ShadingData shadowShading = new ShadingData();
    final double[] transmission = new double[3];
    // Texture evaluation (TextureShading): the point handed to textures, colour and scalar
    // scratch, and a shifted object point for bump differences.
    final TexturePoint texPoint = new TexturePoint();
    final double[] texRgb = new double[3];
    final double[] texScratch = new double[3];
    final double[] texObject = new double[3];

    // Media the ray is inside, innermost last: the material it entered by and the solid
    // (TracedObject.solid()) it entered, so leaving through another surface of the same CSG solid
    // leaves the same medium.
    Material[] media = new Material[8];
    TracedObject[] solids = new TracedObject[8];
    int mediaCount;

    // The pixel sample being traced, for light samples: global seed, pixel, sample index and
    // count. Set by setSample; a caller that never sets it traces as sample 0 of 1 of pixel (0, 0).
    long seed;
    int pixelX, pixelY, sample, samplesPerPixel = 1;
    /** The pixel's count is open (adaptive sampling): the first dimensions come from progressive sequences, at the sample's index. */
    boolean progressive;
    /** Bumped whenever the pixel or sample count changes, so per-pixel light strata are redrawn. */
    int pixelGeneration = 1;
    /** Per light that takes strata (the area lights, then the environment if it is a light): its strata in the order the pixel's samples take them, and the generation they were drawn for. */
    int[][] lightStrata = new int[0][];
    int[] lightStrataGeneration = new int[0];
    /** Per sampled light, as lightStrata: the columns of its strata's grid (rows = strata / cols). */
    int[] lightStrataCols = new int[0];
    final lt.spindulys.sampling.Rng lightRng = new lt.spindulys.sampling.Rng();
    /** What a ray sees of the area light it reaches first, and where: r, g, b, t (Lights#nearestSurface). */
    final double[] lightSeen = new double[4];
    /** The light sample being shaded (Light#sampleLi writes it). */
    final LightSample lightSample = new LightSample();

    // Path tracing (PathIntegrator): the path's random numbers, its throughput and sum, one
    // light's or surface's contribution, the BSDF of the current surface with its sample and
    // value, and the two tangents of its shading frame.
    final lt.spindulys.sampling.Rng pathRng = new lt.spindulys.sampling.Rng();
    final double[] throughput = new double[3];
    final double[] pathSum = new double[3];
    /** A path's indirect light, summed apart from pathSum when it is clamped as a whole. */
    final double[] indirectSum = new double[3];
    final double[] contribution = new double[3];
    final double[] bsdfValue = new double[3];
    final SurfaceBsdf bsdf = new SurfaceBsdf();
    /** The untextured material and index ratio the BSDF was last set to, or null (PathIntegrator). */
    Material configuredMaterial;
    double configuredEta;
    final BsdfSample bsdfSample = new BsdfSample();
    final double[] frame = new double[6];
    final lt.spindulys.sampling.PaddedStrata strata = new lt.spindulys.sampling.PaddedStrata();
    final double[] square = new double[2];

    /**
     * Says which pixel sample the next camera ray is, so that area-light samples are stratified
     * over the pixel's samples and seeded from (seed, pixel, sample, light) like every other random
     * number: the image does not depend on the thread count.
     *
     * @param seed            the pass's global seed
     * @param px              pixel column
     * @param py              pixel row
     * @param sample          sample index in the pixel, 0..samplesPerPixel-1
     * @param samplesPerPixel the pixel's sample count
     */
    public void setSample(long seed, int px, int py, int sample, int samplesPerPixel) {
        if (seed != this.seed || px != pixelX || py != pixelY || samplesPerPixel != this.samplesPerPixel) {
            this.seed = seed;
            pixelX = px;
            pixelY = py;
            this.samplesPerPixel = samplesPerPixel;
            pixelGeneration++;
        }
        this.sample = sample;
        progressive = false;
    }

    /**
     * Says which pixel sample the next camera ray is, of a pixel whose count is open (adaptive
     * sampling): its stratified dimensions (the path's first vertices, the area lights' samples)
     * are then points of progressive sequences ({@link lt.spindulys.sampling.ProgressiveSequence})
     * at the sample's index, so that the samples taken are stratified wherever the pixel stops.
     *
     * @param seed   the pass's global seed
     * @param px     pixel column
     * @param py     pixel row
     * @param sample sample index in the pixel, from 0
     */
    public void setProgressiveSample(long seed, int px, int py, int sample) {
        this.seed = seed;
        pixelX = px;
        pixelY = py;
        this.sample = sample;
        progressive = true;
    }

    /**
     * Whether the camera ray's first hit is recorded in {@link #features}, for a denoiser or the
     * albedo pass; off, the integrators skip it.
     */
    public boolean recordFeatures;
    /**
     * What the last camera ray saw first ({@link #recordFeatures}): albedo r, g, b, the unit
     * shading normal facing the ray x, y, z, and the inverse of the distance; all 0 when it
     * hit nothing (or reached a light's surface). See {@link FirstHits#recordHit}.
     */
    public final double[] features = new double[7];

    /** Rays traced, by kind (counted per thread and summed by the renderer). */
    public long cameraRays, shadowRays, reflectionRays, refractionRays;
    /** Camera samples whose first hit is an adaptive subdivision surface (its covered pixels, for --stats). */
    public long adaptiveCameraHits;

    public TracerScratch(int maxDepth) {
        path = new PathVertex[maxDepth + 2];
        for (int i = 0; i < path.length; i++) {
            path[i] = new PathVertex();
            path[i].shading.recentPatches = ctx.recentPatches;
        }
        shadowShading.recentPatches = ctx.recentPatches;
    }

    /** Adds this thread's batched counts of lazily refined patches to their caches' statistics; call when the thread is done. */
    public void flushStatistics() { ctx.recentPatches.flush(); }

    void pushMedium(Material m, TracedObject solid) {
        if (mediaCount == media.length) {
            media = java.util.Arrays.copyOf(media, media.length * 2);
            solids = java.util.Arrays.copyOf(solids, solids.length * 2);
        }
        solids[mediaCount] = solid;
        media[mediaCount++] = m;
    }

    Material innermost() { return mediaCount == 0 ? null : media[mediaCount - 1]; }

    /** The solid of the innermost medium, or null outside every medium. */
    TracedObject innermostSolid() { return mediaCount == 0 ? null : solids[mediaCount - 1]; }

    /** The medium enclosing the innermost one (what a ray leaving the innermost enters). */
    Material outer() { return mediaCount < 2 ? null : media[mediaCount - 2]; }

    /**
     * What the integrator keeps for one recursion depth: the ray traced there, its nearest hit
     * and shading record, the surface there after textures, the frame that lighting and the
     * secondary rays start from, and the colour seen along the ray. Named fields instead of
     * arguments: a depth's trace fills them once, and its lighting and secondary rays read them,
     * while deeper levels use their own vertices. Preallocated, so nothing is allocated per ray.
     */
    static final class PathVertex {
        /** The ray traced at this depth (at depth 0 the caller's camera ray is traced instead). */
        final Ray ray = new Ray();
        final Hit hit = new Hit();
        final ShadingData shading = new ShadingData();
        /** Colour seen along this depth's ray: what tracing it returns. */
        final double[] seen = new double[3];
        /** Path length from the camera to this depth's ray origin (texture footprints). */
        double travelled;
        /** The product of the reflected and transmitted shares that lead here (minimum contribution). */
        double weight;
        /** The ray's time in the shutter interval; shadow and secondary rays keep it. */
        double time;

        // The surface after the material's textures (TextureShading.evaluate).
        /** Colour, scaling ambient and diffuse light. */
        double colourR, colourG, colourB;
        /** Specular, reflected and transmitted fractions. */
        double ks, kr, kt;
        /**
         * A principled material's parameters, each in [0, 1] (the path integrator reads them, with
         * the colour as the base colour); a Whitted material's are set too, to its unused defaults.
         */
        double metallic, roughness, transmission;
        /** Light the surface emits: the material's emission plus an emission texture's colour. */
        double emissionR, emissionG, emissionB;

        // The frame at the hit, all in world space.
        /** The hit point (shading uses it as it is; new rays start eps off it). */
        double px, py, pz;
        /** Unit direction of the incoming ray. */
        double dx, dy, dz;
        /** Unit geometric normal turned to face the incoming ray. */
        double nfx, nfy, nfz;
        /** Unit shading normal (bumped), on the side of nf. */
        double snx, sny, snz;
        /** How far along nf new rays start, so that they do not hit the surface they leave. */
        double eps;
        /** Whether the ray arrives from the outside of its surface (against the outward normal). */
        boolean entering;
    }
}
