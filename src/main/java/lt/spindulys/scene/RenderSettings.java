package lt.spindulys.scene;

import java.util.Collections;
import java.util.EnumSet;
import java.util.Set;

import lt.spindulys.image.Aov;
import lt.spindulys.math.Color;

/**
 * Image and integrator settings of a scene, immutable; the {@code with*} methods validate and
 * return a changed copy (the command line overrides a scene file's values this way).
 *
 * @param width           image width in pixels
 * @param height          image height in pixels
 * @param samplesPerPixel antialiasing samples per pixel, stratified on a grid as square as possible
 * @param maxDepth        maximum number of reflection/refraction bounces
 * @param minContribution secondary rays whose weight falls below this are not traced
 * @param background      colour of rays that hit nothing
 * @param ambient         ambient light intensity Ia
 * @param srgb            encode the image as sRGB for 8-bit outputs (else linear values are written)
 * @param seed            global seed of every random number, mixed with pixel and sample
 * @param accelerator     the acceleration structure of the scene over its objects and of each mesh over its triangles
 * @param aovs            render passes to write beside the image (unmodifiable, possibly empty; see {@link Aov})
 * @param shutterOpen     time the shutter opens: ray times lie in [shutterOpen, shutterClose]
 * @param shutterClose    time the shutter closes (equal to shutterOpen: no motion blur)
 * @param timeSteps       1: every sample of a pixel has its own time in one pass; N &gt; 1: the
 *                        thesis's method, N passes each at one time with samplesPerPixel / N
 *                        samples, averaged (samplesPerPixel must then be a multiple of N, checked
 *                        when the scene is built, see {@link #checkTimeSteps()})
 */
public record RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, double minContribution,
                             Color background, Color ambient, boolean srgb, long seed, AcceleratorKind accelerator,
                             Set<Aov> aovs, double shutterOpen, double shutterClose, int timeSteps) {
    /** Largest accepted image side, so that a typo cannot ask for terabytes. */
    public static final int MAX_SIDE = 32768;

    public static final RenderSettings DEFAULT = new RenderSettings(640, 480, 1, 8, 0.001, Color.BLACK, Color.WHITE, false, 0);

    /** Settings with the default acceleration structure. */
    public RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, double minContribution,
                          Color background, Color ambient, boolean srgb, long seed) {
        this(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, AcceleratorKind.DEFAULT);
    }

    /** Settings with the default shutter [0, 1] in one pass. */
    public RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, double minContribution,
                          Color background, Color ambient, boolean srgb, long seed, AcceleratorKind accelerator, Set<Aov> aovs) {
        this(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, aovs,
                lt.spindulys.math.Placement.OPEN, lt.spindulys.math.Placement.CLOSE, 1);
    }

    /** Settings without render passes. */
    public RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, double minContribution,
                          Color background, Color ambient, boolean srgb, long seed, AcceleratorKind accelerator) {
        this(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, Set.of());
    }

    public RenderSettings {
        if (width < 1 || width > MAX_SIDE) throw new IllegalArgumentException("width must be between 1 and " + MAX_SIDE + ", found " + width);
        if (height < 1 || height > MAX_SIDE) throw new IllegalArgumentException("height must be between 1 and " + MAX_SIDE + ", found " + height);
        if (samplesPerPixel < 1 || samplesPerPixel > 65536) throw new IllegalArgumentException("samples per pixel must be between 1 and 65536, found " + samplesPerPixel);
        if (maxDepth < 0 || maxDepth > 64) throw new IllegalArgumentException("maxdepth must be between 0 and 64, found " + maxDepth);
        if (!(minContribution >= 0 && minContribution < 1)) throw new IllegalArgumentException("mincontribution must be in [0, 1), found " + minContribution);
        lt.spindulys.math.Ranges.colour("background", background, lt.spindulys.math.Ranges.MAX_COLOUR);
        lt.spindulys.math.Ranges.colour("ambient", ambient, lt.spindulys.math.Ranges.MAX_COLOUR);
        java.util.Objects.requireNonNull(accelerator, "accelerator");
        java.util.Objects.requireNonNull(aovs, "aovs");
        lt.spindulys.math.Placement.checkShutter(shutterOpen, shutterClose);
        if (timeSteps < 1 || timeSteps > 65536) throw new IllegalArgumentException("timesteps must be between 1 and 65536, found " + timeSteps);
        // An EnumSet copy: declaration order whatever the caller's set, and no later changes.
        aovs = aovs.isEmpty() ? Set.of() : Collections.unmodifiableSet(EnumSet.copyOf(aovs));
    }

    public RenderSettings withSize(int w, int h) { return new RenderSettings(w, h, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withSamplesPerPixel(int n) { return new RenderSettings(width, height, n, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withMaxDepth(int d) { return new RenderSettings(width, height, samplesPerPixel, d, minContribution, background, ambient, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withMinContribution(double c) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, c, background, ambient, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withBackground(Color c) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, c, ambient, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withAmbient(Color c) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, c, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withSrgb(boolean s) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, s, seed, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }
    public RenderSettings withSeed(long s) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, s, accelerator, aovs, shutterOpen, shutterClose, timeSteps); }

    public RenderSettings withAccelerator(AcceleratorKind a) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, a, aovs, shutterOpen, shutterClose, timeSteps); }

    /** The same settings with these render passes (an empty set: none). */
    public RenderSettings withAovs(Set<Aov> a) { return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, a, shutterOpen, shutterClose, timeSteps); }

    /** The same settings with the shutter open over [open, close]. */
    public RenderSettings withShutter(double open, double close) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, aovs, open, close, timeSteps);
    }

    /** The same settings rendered in {@code n} time steps (1: one pass, every sample at its own time). */
    public RenderSettings withTimeSteps(int n) {
        return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed, accelerator, aovs, shutterOpen, shutterClose, n);
    }

    /**
     * Refuses samples per pixel that the time steps do not divide (each step takes an equal share).
     *
     * @throws IllegalArgumentException "samples 6 is not a multiple of timesteps 4"
     */
    public RenderSettings checkTimeSteps() {
        if (samplesPerPixel % timeSteps != 0) {
            throw new IllegalArgumentException("samples " + samplesPerPixel + " is not a multiple of timesteps " + timeSteps
                    + " (each time step renders samples / timesteps per pixel)");
        }
        return this;
    }

    /** The time of a sample in [0, 1) mapped into the shutter interval. */
    public double shutterTime(double u) { return shutterOpen + u * (shutterClose - shutterOpen); }

    public double aspect() { return (double) width / height; }
}
