package lt.spindulys.scene;

import java.util.Collections;
import java.util.EnumSet;
import java.util.Objects;
import java.util.Set;

import lt.spindulys.image.Aov;
import lt.spindulys.math.Color;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Ranges;
import lt.spindulys.camera.PixelFilter;

/**
 * Image and integrator settings of a scene, immutable. Make them with a {@link Builder}, which
 * starts from {@link #DEFAULT} and checks each value as it is given; {@link #toBuilder()} gives a
 * changed copy (the command line overrides a scene file's values this way):
 *
 * <pre>{@code
 * RenderSettings s = RenderSettings.builder().size(800, 600).samplesPerPixel(16).build();
 * RenderSettings hd = s.toBuilder().size(1920, 1080).build();
 * }</pre>
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
 * @param adaptive        heap budget, cache and target edge length of adaptive subdivision
 *                        (see {@link AdaptiveSettings}); none of them changes the image
 * @param integrator      how light is gathered: Whitted ray tracing or path tracing
 * @param clamp           path tracing only: the largest value any channel of one indirect
 *                        sample may bring to a pixel (light reaching the camera after at least one
 *                        bounce), against fireflies; 0 for no clamp
 * @param filter          the pixel reconstruction filter the film samples are drawn from, or null
 *                        for the integrator's default ({@link #defaultFilter}; {@link #filter()}
 *                        tells the filter used)
 * @param filterWidth     the filter's width W in pixels (see {@link PixelFilter}), or 0 for the
 *                        filter's own default ({@link #pixelFilterWidth()} tells the width used)
 * @param noiseThreshold  adaptive sampling: a pixel stops taking samples once its estimated
 *                        relative error falls below this ({@link lt.spindulys.sampling.SampleRounds});
 *                        0 (the default) for none, every pixel takes samplesPerPixel samples
 * @param minSamples      adaptive sampling: the samples every pixel takes before its error is
 *                        first checked, or 0 for Cycles' default ({@link #adaptiveMinSamples()})
 * @param denoise         denoise the frame before it is written ({@link lt.spindulys.denoise.Denoiser}),
 *                        as a {@link lt.spindulys.render.RenderJob} renders it; whole frames only
 */
public record RenderSettings(int width, int height, int samplesPerPixel, int maxDepth, double minContribution,
                             Color background, Color ambient, boolean srgb, long seed, AcceleratorKind accelerator,
                             Set<Aov> aovs, double shutterOpen, double shutterClose, int timeSteps, AdaptiveSettings adaptive,
                             IntegratorKind integrator, double clamp, PixelFilter filter, double filterWidth,
                             double noiseThreshold, int minSamples, boolean denoise) {
    /** Widest accepted pixel filter, in pixels: wider only blurs, and costs nothing but sharpness. */
    public static final double MAX_FILTER_WIDTH = 16;

    /** Largest accepted image side, so that a typo cannot ask for terabytes. */
    public static final int MAX_SIDE = 32768;

    /**
     * The settings of a scene that gives none, and where {@link #builder()} starts: 640x480, 1
     * sample per pixel, depth 8, minimum contribution 0.001, black background, white ambient,
     * linear encoding, seed 0, the default accelerator, no passes, shutter [0, 1] in one pass,
     * Whitted ray tracing, no clamp, the integrator's default pixel filter ({@link #defaultFilter}),
     * no adaptive sampling, no denoising.
     */
    public static final RenderSettings DEFAULT = new RenderSettings(640, 480, 1, 8, 0.001, Color.BLACK, Color.WHITE, false, 0,
            AcceleratorKind.DEFAULT, Set.of(), Placement.OPEN, Placement.CLOSE, 1, AdaptiveSettings.DEFAULT,
            IntegratorKind.DEFAULT, 0, null, 0, 0, 0, false);

    /**
     * Checks every value as the {@link Builder}'s methods do, with the same messages; the
     * builder reads better than this positional form.
     *
     * @param width           image width in pixels
     * @param height          image height in pixels
     * @param samplesPerPixel antialiasing samples per pixel
     * @param maxDepth        maximum number of reflection/refraction bounces
     * @param minContribution secondary rays whose weight falls below this are not traced
     * @param background      colour of rays that hit nothing
     * @param ambient         ambient light intensity Ia
     * @param srgb            encode 8-bit outputs as sRGB
     * @param seed            global seed of every random number
     * @param accelerator     the acceleration structure
     * @param aovs            render passes to write beside the image (copied)
     * @param shutterOpen     time the shutter opens
     * @param shutterClose    time the shutter closes
     * @param timeSteps       1: one pass; N &gt; 1: N passes each at one time
     * @param adaptive        memory, cache and target of adaptive subdivision
     * @param integrator      Whitted ray tracing or path tracing
     * @param clamp           the largest value of an indirect sample's channel (path tracing), 0 for none
     * @param filter          the pixel reconstruction filter, null for the integrator's default
     * @param filterWidth     its width in pixels, 0 for its default
     * @param noiseThreshold  adaptive sampling's noise threshold, 0 for none
     * @param minSamples      adaptive sampling's minimum samples, 0 for the default
     * @param denoise         denoise the frame before it is written
     * @throws IllegalArgumentException if a value is out of its range
     * @throws NullPointerException     if accelerator or aovs is null
     */
    public RenderSettings {
        side("width", width);
        side("height", height);
        samples(samplesPerPixel);
        depth(maxDepth);
        contribution(minContribution);
        Ranges.colour("background", background, Ranges.MAX_COLOUR);
        Ranges.colour("ambient", ambient, Ranges.MAX_COLOUR);
        Objects.requireNonNull(accelerator, "accelerator");
        aovs = passes(aovs);
        Placement.checkShutter(shutterOpen, shutterClose);
        steps(timeSteps);
        Objects.requireNonNull(adaptive, "adaptive");
        Objects.requireNonNull(integrator, "integrator");
        clamp(clamp);
        filterWidth(filterWidth);
        noiseThreshold(noiseThreshold);
        minSamples(minSamples);
    }

    /** Largest accepted noise threshold: a relative error of 100 % would stop every pixel at its minimum. */
    public static final double MAX_NOISE_THRESHOLD = 1;

    /**
     * Whether pixels stop taking samples once their noise is low enough.
     *
     * @return true when the noise threshold is above 0
     */
    public boolean adaptiveSampling() { return noiseThreshold > 0; }

    /**
     * The samples every pixel takes before its error is first checked: the one given, or
     * Cycles' default {@code max(4, ceil(16 / threshold^0.3))} (64 at 0.01, 32 at 0.1), at most
     * samplesPerPixel. Without adaptive sampling, samplesPerPixel.
     *
     * @return the minimum samples per pixel, 1 to samplesPerPixel
     */
    public int adaptiveMinSamples() {
        if (!adaptiveSampling()) return samplesPerPixel;
        int m = minSamples > 0 ? minSamples : Math.max(4, (int) Math.ceil(16 / Math.pow(noiseThreshold, 0.3)));
        return Math.min(m, samplesPerPixel);
    }

    /**
     * The pixel filter in use: the one chosen, or when none was, the integrator's default
     * ({@link #defaultFilter}), so that switching the integrator of a scene that names no filter
     * (from the command line, say) also switches its filter.
     *
     * @return the filter
     */
    @Override
    public PixelFilter filter() { return filter != null ? filter : defaultFilter(integrator); }

    /**
     * The pixel filter of settings that choose none. The path tracer's is Blackman-Harris of
     * width 1.5, Cycles' and Blender's default, so that its images compare with Cycles' filter
     * for filter; at the sample counts path tracing takes (16 and more) it places a slanted hard
     * edge as well as the box or better (measured along a 3 degree edge, rms distance of the 0.5
     * crossing from the true line: 0.075 px for both at 16 samples, 0.054 against 0.063 px
     * converged). The Whitted tracer's is the box, the thesis's plain average: at the few samples
     * its scenes take, a wider filter's samples spread over three pixels and the edge gets
     * noisier (0.19 against 0.15 px at 4 samples), and a one-sample pixel is its centre.
     *
     * @param integrator the integrator
     * @return {@link PixelFilter#BLACKMAN_HARRIS} for path tracing, {@link PixelFilter#BOX} for Whitted
     */
    public static PixelFilter defaultFilter(IntegratorKind integrator) {
        return integrator == IntegratorKind.PATH ? PixelFilter.BLACKMAN_HARRIS : PixelFilter.BOX;
    }

    /**
     * Whether a filter was chosen, rather than left to {@link #defaultFilter}.
     *
     * @return true if the settings name a filter
     */
    public boolean filterChosen() { return filter != null; }

    /**
     * The pixel filter's width in use: the one given, or the filter's default.
     *
     * @return W in pixels
     */
    public double pixelFilterWidth() { return filterWidth > 0 ? filterWidth : filter().defaultWidth(); }

    /**
     * A builder holding {@link #DEFAULT}'s values.
     *
     * @return a new builder
     */
    public static Builder builder() { return DEFAULT.toBuilder(); }

    /**
     * A builder holding these settings' values, to make a changed copy.
     *
     * @return a new builder; these settings do not change
     */
    public Builder toBuilder() { return new Builder(this); }

    /**
     * Settings made one value at a time, each checked when given (an
     * {@code IllegalArgumentException} at the call that gave it, worded as the scene file's
     * errors are); unset values stay as the builder started.
     */
    public static final class Builder {
        private int width, height, samplesPerPixel, maxDepth, timeSteps;
        private double minContribution, shutterOpen, shutterClose;
        private Color background, ambient;
        private boolean srgb;
        private long seed;
        private AcceleratorKind accelerator;
        private Set<Aov> aovs;
        private AdaptiveSettings adaptive;
        private IntegratorKind integrator;
        private double clamp;
        private PixelFilter filter;
        private double filterWidth;
        private double noiseThreshold;
        private int minSamples;
        private boolean denoise;

        private Builder(RenderSettings s) {
            width = s.width;
            height = s.height;
            samplesPerPixel = s.samplesPerPixel;
            maxDepth = s.maxDepth;
            minContribution = s.minContribution;
            background = s.background;
            ambient = s.ambient;
            srgb = s.srgb;
            seed = s.seed;
            accelerator = s.accelerator;
            aovs = s.aovs;
            shutterOpen = s.shutterOpen;
            shutterClose = s.shutterClose;
            timeSteps = s.timeSteps;
            adaptive = s.adaptive;
            integrator = s.integrator;
            clamp = s.clamp;
            filter = s.filter;
            filterWidth = s.filterWidth;
            noiseThreshold = s.noiseThreshold;
            minSamples = s.minSamples;
            denoise = s.denoise;
        }

        /**
         * The image size in pixels, each side from 1 to {@link #MAX_SIDE}.
         *
         * @param width  the image width
         * @param height the image height
         * @return this builder
         * @throws IllegalArgumentException if a side is out of range
         */
        public Builder size(int width, int height) {
            side("width", width);
            this.height = side("height", height);
            this.width = width;
            return this;
        }

        /**
         * The image width in pixels, from 1 to {@link #MAX_SIDE}; the height stays.
         *
         * @param width the image width
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder width(int width) {
            this.width = side("width", width);
            return this;
        }

        /**
         * The image height in pixels, from 1 to {@link #MAX_SIDE}; the width stays.
         *
         * @param height the image height
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder height(int height) {
            this.height = side("height", height);
            return this;
        }

        /**
         * Antialiasing samples per pixel, from 1 to 65536.
         *
         * @param n the samples per pixel
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder samplesPerPixel(int n) {
            samplesPerPixel = samples(n);
            return this;
        }

        /**
         * The most reflection/refraction bounces, from 0 to 64.
         *
         * @param depth the bounces
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder maxDepth(int depth) {
            maxDepth = depth(depth);
            return this;
        }

        /**
         * The weight in [0, 1) below which secondary rays are not traced.
         *
         * @param weight the smallest weight traced
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder minContribution(double weight) {
            minContribution = contribution(weight);
            return this;
        }

        /**
         * The colour of rays that hit nothing, components from 0 to {@link Ranges#MAX_COLOUR}.
         *
         * @param c the background colour
         * @return this builder
         * @throws IllegalArgumentException if null or out of range
         */
        public Builder background(Color c) {
            background = Ranges.colour("background", c, Ranges.MAX_COLOUR);
            return this;
        }

        /**
         * The ambient light intensity Ia, components from 0 to {@link Ranges#MAX_COLOUR}.
         *
         * @param c the ambient intensity
         * @return this builder
         * @throws IllegalArgumentException if null or out of range
         */
        public Builder ambient(Color c) {
            ambient = Ranges.colour("ambient", c, Ranges.MAX_COLOUR);
            return this;
        }

        /**
         * Whether 8-bit outputs are encoded as sRGB (true) or hold linear values (false).
         *
         * @param encode true for sRGB
         * @return this builder
         */
        public Builder srgb(boolean encode) {
            srgb = encode;
            return this;
        }

        /**
         * The global seed of every random number.
         *
         * @param seed the seed
         * @return this builder
         */
        public Builder seed(long seed) {
            this.seed = seed;
            return this;
        }

        /**
         * The acceleration structure over the scene's objects and each mesh's triangles.
         *
         * @param kind the structure
         * @return this builder
         * @throws NullPointerException if kind is null
         */
        public Builder accelerator(AcceleratorKind kind) {
            accelerator = Objects.requireNonNull(kind, "accelerator");
            return this;
        }

        /**
         * The render passes written beside the image (an empty set: none); the set is copied.
         *
         * @param passes the passes
         * @return this builder
         * @throws NullPointerException if passes is null
         */
        public Builder aovs(Set<Aov> passes) {
            aovs = passes(passes);
            return this;
        }

        /**
         * The shutter interval [open, close] that ray times lie in (open == close: no motion blur).
         *
         * @param open  the time the shutter opens
         * @param close the time the shutter closes
         * @return this builder
         * @throws IllegalArgumentException if a time is not finite or close is before open
         */
        public Builder shutter(double open, double close) {
            Placement.checkShutter(open, close);
            shutterOpen = open;
            shutterClose = close;
            return this;
        }

        /**
         * Render in {@code n} time steps, from 1 to 65536 (1: one pass, every sample at its own
         * time); the samples per pixel must be a multiple of it ({@link RenderSettings#checkTimeSteps()}).
         *
         * @param n the time steps
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder timeSteps(int n) {
            timeSteps = steps(n);
            return this;
        }

        /**
         * Memory, cache and target of adaptive subdivision.
         *
         * @param a the adaptive subdivision settings
         * @return this builder
         */
        public Builder adaptive(AdaptiveSettings a) {
            adaptive = Objects.requireNonNull(a, "adaptive");
            return this;
        }

        /**
         * How light is gathered: Whitted ray tracing or path tracing.
         *
         * @param kind the integrator
         * @return this builder
         * @throws NullPointerException if kind is null
         */
        public Builder integrator(IntegratorKind kind) {
            integrator = Objects.requireNonNull(kind, "integrator");
            return this;
        }

        /**
         * Path tracing's clamp: the largest value any channel of one indirect sample (light that
         * reached the camera after at least one bounce) may bring, from 0 (no clamp) to
         * {@link Ranges#MAX_COLOUR}. It removes fireflies at the price of some energy (bias).
         *
         * @param max the largest value, or 0 for none
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder clamp(double max) {
            clamp = RenderSettings.clamp(max);
            return this;
        }

        /**
         * The pixel reconstruction filter; its width stays as given before (0: the filter's default).
         *
         * @param f the filter
         * @return this builder
         * @throws NullPointerException if f is null
         */
        public Builder filter(PixelFilter f) {
            filter = Objects.requireNonNull(f, "filter");
            return this;
        }

        /**
         * The pixel filter's width W in pixels, from 0.1 to {@link #MAX_FILTER_WIDTH}, or 0 for
         * the filter's default (see {@link PixelFilter}).
         *
         * @param w the width
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder filterWidth(double w) {
            filterWidth = RenderSettings.filterWidth(w);
            return this;
        }

        /**
         * Adaptive sampling's noise threshold, from 0 (none: every pixel takes all its samples)
         * to {@link #MAX_NOISE_THRESHOLD}: the estimated relative error at which a pixel stops.
         *
         * @param t the threshold, or 0
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder noiseThreshold(double t) {
            noiseThreshold = RenderSettings.noiseThreshold(t);
            return this;
        }

        /**
         * Adaptive sampling's minimum samples per pixel, from 1 to 65536, or 0 for the default
         * ({@link RenderSettings#adaptiveMinSamples()}); at most the samples per pixel
         * ({@link RenderSettings#checkNoiseControl()}).
         *
         * @param m the minimum, or 0
         * @return this builder
         * @throws IllegalArgumentException if out of range
         */
        public Builder minSamples(int m) {
            minSamples = RenderSettings.minSamples(m);
            return this;
        }

        /**
         * Whether the frame is denoised before it is written (whole frames only; see
         * {@link lt.spindulys.render.RenderJob#denoise}, which overrides it).
         *
         * @param on true to denoise
         * @return this builder
         */
        public Builder denoise(boolean on) {
            denoise = on;
            return this;
        }

        /**
         * The settings with the values given so far.
         *
         * @return new settings; the builder can go on to make more
         */
        public RenderSettings build() {
            return new RenderSettings(width, height, samplesPerPixel, maxDepth, minContribution, background, ambient, srgb, seed,
                    accelerator, aovs, shutterOpen, shutterClose, timeSteps, adaptive, integrator, clamp, filter, filterWidth,
                    noiseThreshold, minSamples, denoise);
        }
    }

    // The checks, shared by the builder and the constructor so that both word a refusal alike.

    private static int side(String name, int v) {
        if (v < 1 || v > MAX_SIDE) throw new IllegalArgumentException(name + " must be between 1 and " + MAX_SIDE + ", found " + v);
        return v;
    }

    private static int samples(int n) {
        if (n < 1 || n > 65536) throw new IllegalArgumentException("samples per pixel must be between 1 and 65536, found " + n);
        return n;
    }

    private static int depth(int d) {
        if (d < 0 || d > 64) throw new IllegalArgumentException("maxdepth must be between 0 and 64, found " + d);
        return d;
    }

    private static double clamp(double c) {
        if (!(c >= 0 && c <= Ranges.MAX_COLOUR)) throw new IllegalArgumentException("clamp must be 0 (none) or a positive value up to " + (int) Ranges.MAX_COLOUR + ", found " + c);
        return c;
    }

    private static double filterWidth(double w) {
        if (!(w == 0 || w >= 0.1 && w <= MAX_FILTER_WIDTH)) {
            throw new IllegalArgumentException("filterwidth must be 0 (the filter's default) or from 0.1 to " + (int) MAX_FILTER_WIDTH + " pixels, found " + w);
        }
        return w;
    }

    private static double noiseThreshold(double t) {
        if (!(t >= 0 && t <= MAX_NOISE_THRESHOLD)) {
            throw new IllegalArgumentException("noisethreshold must be 0 (no adaptive sampling) or a relative error up to " + (int) MAX_NOISE_THRESHOLD + ", found " + t);
        }
        return t;
    }

    private static int minSamples(int m) {
        if (m < 0 || m > 65536) throw new IllegalArgumentException("minsamples must be 0 (the default) or between 1 and 65536, found " + m);
        return m;
    }

    private static double contribution(double c) {
        if (!(c >= 0 && c < 1)) throw new IllegalArgumentException("mincontribution must be in [0, 1), found " + c);
        return c;
    }

    private static int steps(int n) {
        if (n < 1 || n > 65536) throw new IllegalArgumentException("timesteps must be between 1 and 65536, found " + n);
        return n;
    }

    /** An unmodifiable copy in declaration order whatever the caller's set, unchanged by later changes to it. */
    private static Set<Aov> passes(Set<Aov> aovs) {
        Objects.requireNonNull(aovs, "aovs");
        return aovs.isEmpty() ? Set.of() : Collections.unmodifiableSet(EnumSet.copyOf(aovs));
    }

    /**
     * Refuses samples per pixel that the time steps do not divide (each step takes an equal share).
     *
     * @return these settings
     * @throws IllegalArgumentException "samples 6 is not a multiple of timesteps 4"
     */
    public RenderSettings checkTimeSteps() {
        if (samplesPerPixel % timeSteps != 0) {
            throw new IllegalArgumentException("samples " + samplesPerPixel + " is not a multiple of timesteps " + timeSteps
                    + " (each time step renders samples / timesteps per pixel)");
        }
        return this;
    }

    /**
     * Refuses what adaptive sampling cannot do with the other settings: a minimum above the
     * samples per pixel, and time steps (each step would stop on a part of the pixel's samples
     * only); the noise pass, which records the samples a pixel took, likewise needs one time step.
     *
     * @return these settings
     * @throws IllegalArgumentException "minsamples 64 is more than samples 16"
     */
    public RenderSettings checkNoiseControl() {
        if (adaptiveSampling() && minSamples > samplesPerPixel) {
            throw new IllegalArgumentException("minsamples " + minSamples + " is more than samples " + samplesPerPixel
                    + " (expected at most the samples per pixel)");
        }
        if (timeSteps > 1 && adaptiveSampling()) {
            throw new IllegalArgumentException("noisethreshold " + noiseThreshold + " needs timesteps 1, found " + timeSteps
                    + " (adaptive sampling stops a pixel on all its samples at once)");
        }
        if (timeSteps > 1 && aovs.contains(Aov.NOISE)) {
            throw new IllegalArgumentException("the noise pass needs timesteps 1, found " + timeSteps);
        }
        return this;
    }

    /**
     * The time of a sample mapped into the shutter interval.
     *
     * @param u the sample's time in [0, 1)
     * @return the time within [shutterOpen, shutterClose]
     */
    public double shutterTime(double u) { return shutterOpen + u * (shutterClose - shutterOpen); }

    /**
     * The image's aspect ratio.
     *
     * @return width over height
     */
    public double aspect() { return (double) width / height; }
}
