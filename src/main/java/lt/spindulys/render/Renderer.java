package lt.spindulys.render;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.camera.Camera;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.denoise.FeatureFrame;
import lt.spindulys.image.Aov;
import lt.spindulys.image.AovFrame;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.math.Ray;
import lt.spindulys.sampling.FilterSampler;
import lt.spindulys.sampling.NoiseEstimate;
import lt.spindulys.sampling.PixelSampler;
import lt.spindulys.sampling.SampleRounds;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.shading.TracerScratch;
import lt.spindulys.shading.Integrator;

/**
 * Renders a frozen scene on several threads. The image is cut into square tiles handed out from
 * an atomic counter, in an order spread over the frame ({@link #tileAt}) so that progress tracks
 * work; each thread has its own sampler and scratch, and every sample is seeded from its pixel,
 * so the result is the same for any thread count (and any tile order). When the settings ask for render
 * passes ({@link RenderSettings#aovs()}), each pixel gets one more camera ray for them; otherwise
 * nothing is traced or stored for them.
 *
 * <p><b>Time.</b> With one time step (the default) every sample of a pixel draws its film, lens
 * and time coordinates together ({@link PixelSampler}), in a single pass; the time in [0, 1) is
 * mapped into the shutter interval. With {@code timesteps N > 1} the frame is rendered as the
 * thesis did: N whole-frame passes, pass k with every ray at open + (k + 0.5) / N (close - open)
 * and samples / N samples per pixel (seeded per pass and pixel), averaged in pass order, so that
 * too is identical for any thread count.
 *
 * <p><b>Pixel filter.</b> The film samples are drawn from the settings' pixel filter
 * ({@link lt.spindulys.camera.PixelFilter}), so a filter wider than a pixel needs no samples
 * from the neighbours: each sample adds to its own pixel only, in sample order, and tiles and
 * regions assemble bit for bit. A pixel is the mean of its samples, or, for a filter with negative
 * lobes, their weighted average.
 *
 * <p><b>Adaptive sampling.</b> With a noise threshold ({@link RenderSettings#noiseThreshold()}) a
 * pixel takes its samples in rounds ({@link SampleRounds}), blocks of its progressive sequences
 * ({@link lt.spindulys.sampling.ProgressiveSequence}), and stops after a round once the
 * {@link NoiseEstimate} of its own samples is below the threshold. Nothing but the pixel's samples
 * decides, so tiles and regions still assemble bit for bit (Cycles also wakes up the neighbours of
 * pixels that go on, which would make a pixel depend on others). Without a threshold there is one
 * round of all the samples: the samples, and the image, are those of a render without rounds.
 */
public final class Renderer {
    /** Tile side in pixels: small enough to balance two cores, large enough to keep counters cheap. */
    static final int TILE = 16;
    /** Per-thread counts summed after a pass: the four ray kinds, adaptive camera hits, the traversal counts ({@link TraversalCounts#SIZE}), then the pixel samples taken. */
    private static final int COUNTS = 6 + TraversalCounts.SIZE;
    /** Where the pixel samples taken are in the counts. */
    private static final int PIXEL_SAMPLES = COUNTS - 1;

    /**
     * The tile (row-major index) handed out {@code k}-th: {@code k * stride mod tiles}, with the
     * golden-ratio stride of {@link #spreadStride}. Tiles differ in cost (sky is cheap, the objects
     * below it are not), so top to bottom the share of pixels done would run ahead of the share
     * of work done, and a remaining time estimated from it would grow as the render went on. In
     * this order the tiles done at any moment are spread evenly
     * over the rows and the columns of the frame (successive ones fall into the largest gaps
     * left, the golden ratio's three-gap property), so pixels done track work done. Every sample
     * is seeded from its pixel, so the image is identical in any order.
     */
    static int tileAt(int k, int tiles, int stride) {
        return (int) ((long) k * stride % tiles);
    }

    /**
     * The stride of {@link #tileAt}: the integer nearest {@code tiles / phi} that is coprime to
     * {@code tiles}, so that every tile comes exactly once.
     */
    static int spreadStride(int tiles) {
        int s = Math.max(1, (int) Math.round(tiles / 1.618033988749895));
        while (gcd(s, tiles) != 1) s++; // ends: tiles - 1 (or 1) is coprime to tiles
        return s;
    }

    private static int gcd(int a, int b) {
        while (b != 0) { int r = a % b; a = b; b = r; }
        return a;
    }

    /**
     * Stack size of a render thread. A ray recurses through each level of CSG nesting and each
     * bounce; at {@link lt.spindulys.scene.Bool#MAX_NESTING} levels under as many mirror bounces
     * as maxdepth allows it needs a small fraction of this, interpreted or compiled (measured: see
     * docs/performance.md, bounded resources), so the margin is wide. Only the pages a thread
     * touches are committed.
     */
    static final long WORKER_STACK_BYTES = 16L << 20;

    private Renderer() {}

    /**
     * Renders {@code scene} on every core the JVM reports, without progress reports: the one call
     * from a built scene to an image. Use a {@link RenderJob} for progress, cancellation, fewer
     * threads, or the whole route from a scene file to written files.
     *
     * @param scene the frozen scene, with its settings and camera
     * @return the finished frame, its passes and statistics
     * @throws lt.spindulys.limits.InsufficientMemoryException (an IllegalArgumentException) if
     *         the heap cannot hold the frame and its passes, or the render threads' sample buffers
     * @throws InterruptedException if the calling thread is interrupted (the workers are stopped)
     */
    public static RenderResult render(Scene scene) throws InterruptedException {
        return render(scene, Runtime.getRuntime().availableProcessors(), null);
    }

    /**
     * Renders {@code scene} with {@code threads} threads (at least 1), reporting progress to
     * {@code progress} (null: no reports). The image is the same for any thread count.
     * Interrupting the calling thread stops the workers and throws InterruptedException.
     *
     * @param scene    the frozen scene, with its settings and camera
     * @param threads  render threads, at least 1
     * @param progress told of the pixels done as tiles finish, from render threads; null: nobody
     * @return the finished frame, its passes and statistics
     * @throws lt.spindulys.limits.InsufficientMemoryException (an IllegalArgumentException) if
     *         the heap cannot hold the frame and its passes ({@link FrameBuffer#checkHeap}; then its
     *         {@link lt.spindulys.limits.InsufficientMemoryException#key() key} is {@value #FRAME_KEY}), or the
     *         render threads' sample buffers, which grow with the settings' and the lights' samples
     *         (then its key is {@value #SAMPLES_KEY})
     * @throws InterruptedException if the calling thread is interrupted (the workers are stopped)
     */
    public static RenderResult render(Scene scene, int threads, ProgressListener progress) throws InterruptedException {
        return render(scene, threads, progress, null);
    }

    /**
     * {@link #render(Scene, int, ProgressListener)}, stopping early with a
     * {@link CancellationException} once {@code cancelled} is set (checked between tiles and within them; null:
     * never).
     */
    static RenderResult render(Scene scene, int threads, ProgressListener listener, AtomicBoolean cancelled) throws InterruptedException {
        return render(scene, threads, listener, cancelled, null);
    }

    /** {@link #render(Scene, int, ProgressListener, AtomicBoolean)}, telling {@code tileListener} (null: nobody) of each finished tile. */
    static RenderResult render(Scene scene, int threads, ProgressListener listener, AtomicBoolean cancelled, TileListener tileListener) throws InterruptedException {
        return render(scene, threads, listener, cancelled, tileListener, null);
    }

    /**
     * {@link #render(Scene, int, ProgressListener, AtomicBoolean, TileListener)} of {@code region}
     * of the frame only (null: the whole frame): the result's frame is the region's size and holds
     * exactly the pixels a whole render has there, since every sample is seeded from its pixel in
     * the whole frame. Tiles reported to {@code tileListener} are in the region's coordinates.
     * Render passes are not made for a part of the frame.
     */
    static RenderResult render(Scene scene, int threads, ProgressListener listener, AtomicBoolean cancelled, TileListener tileListener,
                               PixelRegion region) throws InterruptedException {
        return render(scene, threads, listener, cancelled, tileListener, region, false);
    }

    /**
     * {@link #render(Scene, int, ProgressListener, AtomicBoolean, TileListener, PixelRegion)},
     * gathering the denoiser's {@link FeatureFrame} beside the colour when {@code features} is
     * true (whole frames only: the render of a region refuses it). The albedo pass is gathered
     * so whether asked or not.
     */
    static RenderResult render(Scene scene, int threads, ProgressListener listener, AtomicBoolean cancelled, TileListener tileListener,
                               PixelRegion region, boolean gatherFeatures) throws InterruptedException {
        ProgressListener progress = listener != null ? listener : ProgressListener.NONE;
        if (threads < 1) throw new IllegalArgumentException("threads must be at least 1, found " + threads);
        RenderSettings st = scene.settings();
        int w = st.width(), h = st.height();
        PixelRegion r = checkFrame(st, region, gatherFeatures); // the frame is asked for by input: checked before it is allocated
        int rw = r.width(), rh = r.height();
        FrameBuffer fb = new FrameBuffer(rw, rh);
        AovFrame aovs = st.aovs().isEmpty() ? null : new AovFrame(w, h, st.aovs());
        FeatureFrame features = gatherFeatures || st.aovs().contains(Aov.ALBEDO) ? new FeatureFrame(w, h) : null;
        int tilesX = (rw + TILE - 1) / TILE, tilesY = (rh + TILE - 1) / TILE, tiles = tilesX * tilesY;
        Integrator integrator = Integrator.of(scene);
        int steps = st.timeSteps(); // a multiple of the samples: the scene checked it when built
        long[] sum = new long[COUNTS];
        long start = System.nanoTime();
        for (int k = 0; k < steps; k++) {
            // One time step: a fixed time and its share of the samples, or (steps == 1) all samples at their own times.
            Pass pass = steps == 1 ? new Pass(st.samplesPerPixel(), st.seed(), Double.NaN, false, 1)
                    : new Pass(st.samplesPerPixel() / steps, passSeed(st.seed(), k), st.shutterTime((k + 0.5) / steps), k > 0, k == steps - 1 ? steps : 1);
            long done = (long) k * rw * rh, total = (long) steps * rw * rh;
            ProgressListener p = (pixels, all) -> progress.progress(done + pixels, total);
            long[] c = renderPass(scene, threads, p, integrator, fb, k == 0 ? aovs : null, features, pass, r, tilesX, tiles, cancelled,
                    k == steps - 1 ? tileListener : null);
            for (int i = 0; i < COUNTS; i++) sum[i] += c[i];
        }
        double seconds = (System.nanoTime() - start) / 1e9;
        if (aovs != null && aovs.passes().contains(Aov.ALBEDO)) {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    aovs.setAlbedo(x, y, features.get(x, y, FeatureFrame.ALBEDO), features.get(x, y, FeatureFrame.ALBEDO + 1),
                            features.get(x, y, FeatureFrame.ALBEDO + 2));
                }
            }
        }
        List<String> adaptive = new ArrayList<>(scene.adaptiveStatistics());
        long triangles = scene.adaptiveTriangleCount();
        if (triangles > 0) {
            // Covered pixels: camera samples whose first hit is an adaptive surface, per sample of a pixel.
            double covered = (double) sum[4] / st.samplesPerPixel();
            adaptive.add(String.format(Locale.ROOT, "adaptive subdivision: %,d triangles, %s covered pixels, %s triangles per covered pixel",
                    triangles, String.format(Locale.ROOT, "%,.0f", covered), covered > 0 ? String.format(Locale.ROOT, "%.2f", triangles / covered) : "no"));
        }
        double meanSamples = (double) sum[PIXEL_SAMPLES] / ((long) rw * rh);
        return new RenderResult(st, fb, aovs, new RenderStats(sum[0], sum[1], sum[2], sum[3], seconds,
                TraversalScratch.COUNTING ? TraversalCounts.of(sum, 5) : null, meanSamples), adaptive, scene.structureStatistics())
                .inRegion(region).withFeatures(gatherFeatures ? features : null);
    }

    /**
     * The one check of the frame a render makes: the region (null: the whole frame) lies inside
     * the frame of these settings and asks for no render passes, and the heap can hold the
     * frame's buffers now. A {@link RenderJob} makes it before it builds the scene, so that a
     * frame that cannot be rendered costs no build; the renderer makes it again before it
     * allocates, since a scene built meanwhile (or by a caller of {@link #render(Scene)}) may
     * have taken the heap the frame needs.
     *
     * @return the pixels to render: the region, or the whole frame
     * @throws IllegalArgumentException if the region is outside the frame or comes with passes
     * @throws InsufficientMemoryException sized by "frame" ({@link InsufficientMemoryException#key()})
     *         if the heap cannot hold the frame and its passes
     */
    static PixelRegion checkFrame(RenderSettings st, PixelRegion region) {
        return checkFrame(st, region, false);
    }

    /**
     * {@link #checkFrame(RenderSettings, PixelRegion)} of a render that gathers the denoiser's
     * features when {@code features} is true: a region is then refused ({@link #DENOISE_OF_REGION}),
     * and the heap must hold the features and the denoiser's buffers too (the albedo pass alone
     * needs the features only).
     */
    static PixelRegion checkFrame(RenderSettings st, PixelRegion region, boolean features) {
        PixelRegion r = region != null ? region : PixelRegion.whole(st.width(), st.height());
        r.checkInside(st.width(), st.height());
        if (region != null && !st.aovs().isEmpty()) throw new IllegalArgumentException(PASSES_OF_REGION);
        if (region != null && features) throw new IllegalArgumentException(DENOISE_OF_REGION);
        boolean gathered = features || st.aovs().contains(Aov.ALBEDO);
        try {
            FrameBuffer.checkHeap(r.width(), r.height(), st.aovs());
            if (gathered) {
                // With --denoise, the denoiser's buffers too: they are taken after the render, and
                // a frame that cannot be denoised is better refused before hours of rendering.
                long denoiser = features ? lt.spindulys.denoise.Denoiser.bytes(r.width(), r.height()) : 0;
                HeapBudget.require(HeapBudget.sum(FrameBuffer.bytesToRender(r.width(), r.height(), st.aovs()),
                        FeatureFrame.bytes(r.width(), r.height()), denoiser),
                        "the " + r.width() + "x" + r.height() + " frame with its denoising features" + (features ? " and the denoiser's buffers" : ""));
            }
        } catch (InsufficientMemoryException e) {
            throw e.sizedBy(FRAME_KEY);
        }
        return r;
    }

    /**
     * Why denoising a region is refused: the denoiser reads a window of pixels around each, so
     * a region's border pixels would differ from the whole frame's and the tiles would not
     * assemble into the denoised frame.
     */
    public static final String DENOISE_OF_REGION = "--denoise needs the whole frame (a denoised pixel depends on its neighbours,"
            + " so denoised tiles would not assemble into the denoised frame): render the tiles without it";

    /** The {@link InsufficientMemoryException#key() key} of a frame the heap cannot hold. */
    public static final String FRAME_KEY = "frame";

    /** The key of the render threads' sample buffers the heap cannot hold. */
    public static final String SAMPLES_KEY = "samples";

    /** Why a region of a frame with render passes is refused: the passes' files have no placement to assemble them by. */
    static final String PASSES_OF_REGION = "render passes (aov) are made for whole frames only: render a region without them, or the whole frame with them";

    /**
     * One pass over the frame.
     *
     * @param samples    samples per pixel in this pass
     * @param seed       seed of its samples
     * @param time       the time of every ray, or NaN: each sample's own time in the shutter
     * @param accumulate add to the frame buffer (a later time step) instead of setting it
     * @param divide     after adding, divide the pixel by this (the last time step: the average); 1 for none
     */
    private record Pass(int samples, long seed, double time, boolean accumulate, int divide) {}

    /** The seed of time step k: the scene's for step 0, a well-mixed other one for the rest, so the steps' samples differ. */
    static long passSeed(long seed, int k) {
        return k == 0 ? seed : new lt.spindulys.sampling.Rng().seed(seed, k, 0x6d6f74, 0x696f6e).nextLong();
    }

    /** Renders one pass on {@code threads} threads; returns its ray counts (camera, shadow, reflection, refraction). */
    private static long[] renderPass(Scene scene, int threads, ProgressListener progress, Integrator integrator, FrameBuffer fb,
                                     AovFrame aovs, FeatureFrame features, Pass pass, PixelRegion region, int tilesX, int tiles, AtomicBoolean cancelled,
                                     TileListener tileListener)
            throws InterruptedException {
        RenderSettings st = scene.settings();
        long pixels = region.pixels();
        // Tiles spread over the frame keep the time estimate steady; but a scene that refines
        // patches while it is traced takes them row by row, so that neighbouring tiles reuse the
        // patches in its cache instead of evicting them (the image is the same in any order).
        int stride = scene.refinesWhileTracing() ? 1 : spreadStride(tiles);
        AtomicInteger nextTile = new AtomicInteger();
        AtomicLong donePixels = new AtomicLong();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        long[][] counters = new long[threads][];

        Thread[] workers = new Thread[Math.min(threads, tiles)];
        // Every thread's scratch is sized by the samples (its light strata, its sampler): checked
        // and reserved for all of them at once, on this thread, before any starts. Checked one
        // by one as each thread started, they would all see the same free heap and all allocate.
        FilterSampler filter = new FilterSampler(st.filter(), st.pixelFilterWidth()); // one table, shared by the threads
        // Adaptive sampling takes the samples in rounds, each drawn by a sampler of its size: one per size, per thread.
        SampleRounds rounds = st.adaptiveSampling() ? SampleRounds.adaptive(pass.samples, st.adaptiveMinSamples()) : SampleRounds.uniform(pass.samples);
        // Adaptive: one sampler, as large as the largest round, draws each round's block of the pixel's sequence.
        int largest = rounds.largest();
        long sampler = PixelSampler.bytes(largest, filter), scratch = integrator.scratchBytes(st.samplesPerPixel());
        HeapBudget.Reservation reservation;
        try {
            reservation = HeapBudget.reserve(HeapBudget.product(workers.length, HeapBudget.sum(scratch, sampler)),
                    "buffering the samples of " + workers.length + " render thread" + (workers.length == 1 ? "" : "s")
                            + " (" + integrator.scratchSizedBy(st.samplesPerPixel()) + ")");
        } catch (InsufficientMemoryException e) {
            throw e.sizedBy(SAMPLES_KEY);
        }
        // Whatever stops the render: a failure on any thread, a cancel, an interrupt. Checked
        // between tiles and within them, so a tile of billions of rays does not go on after it.
        BooleanSupplier stop = () -> failure.get() != null || cancelled != null && cancelled.get() || Thread.currentThread().isInterrupted();
        try {
            for (int k = 0; k < workers.length; k++) {
                int index = k;
                workers[k] = new Thread(null, () -> {
                    TracerScratch own = null;
                    long[] taken = new long[1]; // the pixel samples this thread took
                    // Everything a worker does is caught, OutOfMemoryError included: a thread that died
                    // unseen would leave its tiles black and the run reported as a success.
                    try {
                        own = integrator.newScratch(reservation);
                        // Time samples only where something moves (an object or the camera) and each sample has its own time.
                        LensPattern lens = scene.camera().usesLens() ? scene.camera().lensPattern() : null;
                        boolean times = (scene.hasMovingObjects() || scene.camera().moves()) && Double.isNaN(pass.time);
                        PixelSampler ps = new PixelSampler(largest, lens, times, filter);
                        reservation.release(sampler);
                        Ray ray = new Ray();
                        double[] colour = new double[4];
                        NoiseEstimate noise = new NoiseEstimate();
                        double[] fsum = features != null ? new double[FEATURE_SUMS] : null;
                        own.recordFeatures = features != null;
                        for (int next; !stop.getAsBoolean() && (next = nextTile.getAndIncrement()) < tiles; ) {
                            int t = tileAt(next, tiles, stride);
                            // In the frame buffer's coordinates (the region's), then traced at the frame's.
                            int x0 = (t % tilesX) * TILE, y0 = (t / tilesX) * TILE;
                            int x1 = Math.min(x0 + TILE, region.width()), y1 = Math.min(y0 + TILE, region.height());
                            if (!renderTile(scene.camera(), integrator, st, pass, rounds, ps, noise, own, ray, colour, fb, aovs, features, fsum, region.x0(), region.y0(),
                                    x0, y0, x1, y1, stop, taken)) return;
                            if (tileListener != null) tileListener.tileDone(fb, x0, y0, x1, y1);
                            progress.progress(donePixels.addAndGet((long) (x1 - x0) * (y1 - y0)), pixels);
                        }
                    } catch (Throwable e) {
                        failure.compareAndSet(null, e);
                    } finally {
                        if (own == null) {
                            counters[index] = new long[COUNTS];
                        } else {
                            own.flushStatistics();
                            long[] c = counters[index] = new long[COUNTS];
                            c[0] = own.cameraRays; c[1] = own.shadowRays; c[2] = own.reflectionRays; c[3] = own.refractionRays;
                            c[4] = own.adaptiveCameraHits;
                            TraversalCounts.copy(own.ctx, c, 5);
                            c[PIXEL_SAMPLES] = taken[0];
                        }
                    }
                }, "spindulys-render-" + k, WORKER_STACK_BYTES);
                workers[k].start();
            }
            for (Thread worker : workers) worker.join();
        } catch (InterruptedException e) {
            for (Thread worker : workers) if (worker != null) worker.interrupt();
            throw e;
        } finally {
            reservation.close(); // what threads that failed before making their scratch did not take
        }
        if (cancelled != null && cancelled.get()) throw new CancellationException("the render was cancelled");
        Throwable f = failure.get();
        if (f instanceof RuntimeException re) throw re;
        if (f instanceof Error err) throw err;
        if (f != null) throw new IllegalStateException(f);
        long[] sum = new long[COUNTS];
        for (long[] c : counters) if (c != null) for (int i = 0; i < COUNTS; i++) sum[i] += c[i];
        return sum;
    }

    /**
     * Renders one tile; returns false, leaving it unfinished, once {@code stop} says so (checked
     * before each pixel and every {@value #STOP_CHECK} samples, so a pixel of millions of shadow
     * rays is not finished for a run that has already failed). Each pixel takes its samples in
     * the rounds of {@code rounds} (one round of all of them unless the sampling is adaptive) and
     * stops after a checked round once its {@link NoiseEstimate} is below the threshold; the
     * samples it took are added to {@code taken[0]}.
     *
     * @param sampler the thread's sampler, of the largest round's size
     * @param noise   the thread's noise estimate
     */
    private static boolean renderTile(Camera camera, Integrator integrator, RenderSettings st, Pass pass, SampleRounds rounds,
                                      PixelSampler sampler, NoiseEstimate noise, TracerScratch scratch, Ray ray, double[] colour,
                                      FrameBuffer fb, AovFrame aovs, FeatureFrame features, double[] fsum, int ox, int oy, int fx0, int fy0, int fx1, int fy1,
                                      BooleanSupplier stop, long[] taken) {
        int w = st.width(), h = st.height(), fw = fb.width();
        double aspect = st.aspect(), threshold = st.noiseThreshold();
        boolean weighted = sampler.filter().hasNegativeWeights();
        boolean ownTimes = Double.isNaN(pass.time);
        boolean centreRay = aovs != null && aovs.needsCentreRay();
        int last = rounds.rounds() - 1;
        // The noise is estimated from the rounds' means when there are rounds, else (for the
        // noise pass only) from the single samples; without either nothing is spent on it.
        boolean byRound = last > 0, bySample = last == 0 && aovs != null && aovs.passes().contains(Aov.NOISE);
        double[] data = fb.data();
        // The frame buffer's pixel (fx, fy) is the frame's (ox + fx, oy + fy): the pixel the samples are seeded from and traced through.
        for (int fy = fy0; fy < fy1; fy++) {
            int y = oy + fy;
            for (int fx = fx0; fx < fx1; fx++) {
                int x = ox + fx;
                double r = 0, g = 0, b = 0, weights = 0, plainR = 0, plainG = 0, plainB = 0;
                int n = 0;
                noise.reset();
                if (features != null) Arrays.fill(fsum, 0);
                for (int k = 0; k <= last; k++) {
                    int size = rounds.size(k);
                    // The round's own sums, for its mean.
                    double kr = r, kg = g, kb = b, kw = weights, kpr = plainR, kpg = plainG, kpb = plainB;
                    // Rounds are blocks of the pixel's progressive sequence; one round is the stratified set of before rounds.
                    if (byRound) sampler.startProgressive(pass.seed, x, y, n, size);
                    else sampler.startPixel(pass.seed, x, y);
                    for (int i = 0; i < size; i++, n++) {
                        if ((n & (STOP_CHECK - 1)) == 0 && stop.getAsBoolean()) return false;
                        double time = ownTimes ? st.shutterTime(sampler.time(i)) : pass.time;
                        camera.generateRay(sampler.filmX(i) / w, sampler.filmY(i) / h, aspect,
                                sampler.lensU(i), sampler.lensV(i), time, ray);
                        if (byRound) scratch.setProgressiveSample(pass.seed, x, y, n);
                        else scratch.setSample(pass.seed, x, y, i, size);
                        integrator.traceCamera(ray, scratch, colour);
                        if (features != null) gather(scratch.features, colour, weighted ? sampler.weight(i) : 1, fsum);
                        if (weighted) {
                            double wt = sampler.weight(i);
                            r += wt * colour[0]; g += wt * colour[1]; b += wt * colour[2];
                            weights += wt;
                            plainR += colour[0]; plainG += colour[1]; plainB += colour[2];
                        } else {
                            r += colour[0]; g += colour[1]; b += colour[2];
                        }
                        if (bySample) noise.add(1, colour[0], colour[1], colour[2]);
                    }
                    if (byRound) {
                        // The round's mean, as the pixel's own value is made (below).
                        kr = r - kr; kg = g - kg; kb = b - kb; kw = weights - kw;
                        if (weighted && !(kw > 0)) { kr = plainR - kpr; kg = plainG - kpg; kb = plainB - kpb; }
                        double kn = weighted && kw > 0 ? kw : size;
                        noise.add(size, kr / kn, kg / kn, kb / kn);
                        if (rounds.checkAfter(k) && noise.error() < threshold) break;
                    }
                }
                taken[0] += n;
                // Weights of exactly 1 (a non-negative filter sampled exactly): the mean. With
                // negative lobes, pbrt's weighted average, which keeps a flat colour flat. When the
                // negative samples weigh as much as the rest (a few samples, by chance) it would
                // divide by zero or flip sign, so then the samples' plain mean is taken: the
                // average under |f|, still exact on a flat colour.
                if (weighted && !(weights > 0)) {
                    r = plainR; g = plainG; b = plainB;
                }
                double norm = weighted && weights > 0 ? weights : n;
                r /= norm; g /= norm; b /= norm;
                if (pass.accumulate) {
                    int o = 3 * (fy * fw + fx);
                    r += data[o]; g += data[o + 1]; b += data[o + 2];
                }
                if (pass.divide != 1) { r /= pass.divide; g /= pass.divide; b /= pass.divide; }
                fb.set(fx, fy, r, g, b);
                if (features != null) features.put(x, y, featureMeans(fsum, n, weighted), pass.accumulate, pass.divide);
                if (aovs != null) aovs.setNoise(x, y, n, noise.error());
                if (centreRay) {
                    // One more ray, through the exact pixel centre from the lens centre when the
                    // shutter opens, so the passes do not depend on the sample pattern.
                    camera.generateRay((x + 0.5) / w, (y + 0.5) / h, aspect, 0, 0, st.shutterOpen(), ray);
                    int id = integrator.traceFirstHit(ray, scratch, colour);
                    if (id < 0) aovs.setBackground(x, y);
                    else aovs.setHit(x, y, colour[0], colour[1], colour[2], colour[3], id);
                }
            }
        }
        return true;
    }

    /**
     * Slots of a thread's feature sums ({@link #gather}): the weighted sums of the seven
     * features, their plain sums, the plain sums of the colour's squares and of the colour, the
     * weights' sum, then the plain sums of the features' squares; the first
     * {@link FeatureFrame#VALUES} are reused for the means.
     */
    static final int FEATURE_SUMS = 7 + 7 + 3 + 3 + 1 + 7;

    /** Adds one sample's features (the integrator's record of its first hit) and colour to a pixel's sums. */
    private static void gather(double[] f, double[] colour, double weight, double[] sum) {
        for (int i = 0; i < 7; i++) {
            sum[i] += weight * f[i];
            sum[7 + i] += f[i];
        }
        for (int c = 0; c < 3; c++) {
            sum[14 + c] += colour[c] * colour[c];
            sum[17 + c] += colour[c];
        }
        for (int i = 0; i < 7; i++) sum[21 + i] += f[i] * f[i];
        sum[20] += weight;
    }

    /**
     * The pixel's feature means from its sums, weighted as its colour is (with the same fall-back
     * to the plain mean when negative weights cancel the rest), and the variance of its mean
     * colour from the plain sums (for one sample, its square: nothing is known of its noise),
     * and of the features' means, per group (albedo, normal: the mean of their channels').
     * Written over the front of {@code sum}.
     */
    private static double[] featureMeans(double[] sum, int n, boolean weighted) {
        double weights = sum[20];
        boolean byWeight = weighted && weights > 0;
        double norm = byWeight ? weights : n;
        double albedo = 0, normal = 0, depth = 0;
        for (int i = 0; i < 7; i++) {
            double s = sum[7 + i], sq = sum[21 + i];
            double variance = n > 1 ? Math.max(0, sq - s * s / n) / ((double) n * (n - 1)) : 0;
            if (i < 3) albedo += variance / 3; else if (i < 6) normal += variance / 3; else depth = variance;
        }
        for (int i = 0; i < 7; i++) sum[i] = (byWeight || !weighted ? sum[i] : sum[7 + i]) / norm;
        for (int c = 0; c < 3; c++) {
            double s = sum[17 + c], sq = sum[14 + c];
            double variance = n > 1 ? Math.max(0, sq - s * s / n) / ((double) n * (n - 1)) : sq;
            sum[FeatureFrame.VARIANCE + c] = variance; // over the plain sums, used above
        }
        sum[FeatureFrame.FEATURE_VARIANCE] = albedo;
        sum[FeatureFrame.FEATURE_VARIANCE + 1] = normal;
        sum[FeatureFrame.FEATURE_VARIANCE + 2] = depth;
        return sum;
    }

    /** Samples of a pixel between two looks at whether the render must stop: a power of two. */
    static final int STOP_CHECK = 64;
}
