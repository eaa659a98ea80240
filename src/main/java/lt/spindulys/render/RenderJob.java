package lt.spindulys.render;

import java.io.IOException;
import java.nio.file.Path;
import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.Future;
import java.util.concurrent.FutureTask;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import java.util.function.UnaryOperator;

import lt.spindulys.camera.Camera;
import lt.spindulys.denoise.Denoiser;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.image.Aov;
import lt.spindulys.io.AssetRoots;
import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.InputFile;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;

/**
 * The whole route from a scene to an image, as the command line runs it: read the scene file (or
 * take a scene made in code), apply setting and camera overrides, check the frame against the
 * heap, build, render on every core, and write the image with its render passes atomically.
 * The command line, the viewer's output plugin and tests all run renders through this class.
 *
 * <pre>{@code
 * RenderResult r = RenderJob.of(Path.of("scene.dat"))
 *         .settings(s -> s.toBuilder().samplesPerPixel(16).build())
 *         .output(Path.of("out.png"))
 *         .progress((done, total) -> System.err.print("\r" + 100 * done / total + "%"))
 *         .run();
 * }</pre>
 *
 * <p>A job is configured, then run once, on the calling thread ({@link #run}) or on a thread of
 * its own ({@link #start}). {@link #cancel} stops it from any thread: the run then throws
 * {@link CancellationException} and writes nothing. A job given a {@link SceneBuilder} builds
 * from it without changing it (its settings and camera stay as they were); a job given a
 * built {@link Scene} takes no overrides.
 */
public final class RenderJob {
    /** The steps of a run, in order; {@link #stage()} tells which one a failure came from. */
    public enum Stage {
        /** Not started yet. */
        READY,
        /** Checking that the output can be written, before any work. */
        CHECK,
        /** Reading the scene file. */
        LOAD,
        /** Applying overrides and checking the frame against the heap. */
        SETTINGS,
        /** Building the scene: freezing objects, building acceleration structures. */
        BUILD,
        /** Tracing rays. */
        RENDER,
        /** Writing the image and its passes. */
        WRITE,
        /** Finished. */
        DONE
    }

    private final Path sceneFile;
    private final SceneBuilder builder;
    private final Scene scene;
    private UnaryOperator<RenderSettings> settingsOverride = UnaryOperator.identity();
    private UnaryOperator<Camera> cameraOverride;
    private Consumer<SceneBuilder> onLoaded;
    private Path output;
    private AssetRoots assetRoots = AssetRoots.ANY;
    private Integer frame;
    private ImageOptions imageOptions = ImageOptions.DEFAULT;
    private int threads = Runtime.getRuntime().availableProcessors();
    private ProgressListener progress;
    private TileListener tiles;
    /** Whether the frame is denoised, overriding the settings' {@code denoise} (null: theirs; {@link #denoise}). */
    private Boolean denoise;
    /** Whether the noisy frame is written beside the denoised one ({@link #keepNoisy}). */
    private boolean keepNoisy;
    /** The region to render for a frame's width and height; null: the whole frame. */
    private RegionOf regionOf;
    private final AtomicBoolean cancelled = new AtomicBoolean();
    private final AtomicBoolean started = new AtomicBoolean();
    /** Set by {@link #check}: the one run that may follow it. */
    private final AtomicBoolean runAfterCheck = new AtomicBoolean();
    private volatile Stage stage = Stage.READY;
    /** The checks made by {@link #check}, for the run to go on from; null before, and once built. */
    private Checked checked;

    private RenderJob(Path sceneFile, SceneBuilder builder, Scene scene) {
        this.sceneFile = sceneFile;
        this.builder = builder;
        this.scene = scene;
    }

    /**
     * A job that reads a scene file (the scene format of docs/scene-format.md) when run.
     *
     * @param file the scene file
     * @return a job to configure and run
     */
    public static RenderJob of(Path file) { return new RenderJob(Objects.requireNonNull(file, "file"), null, null); }

    /**
     * A job that builds the scene a builder describes when run; the builder is not changed.
     *
     * @param builder the scene description, made in code or read by {@link SceneParser}
     * @return a job to configure and run
     */
    public static RenderJob of(SceneBuilder builder) { return new RenderJob(null, Objects.requireNonNull(builder, "builder"), null); }

    /**
     * A job that renders an already built scene; it takes no setting or camera overrides.
     *
     * @param scene the frozen scene
     * @return a job to configure and run
     */
    public static RenderJob of(Scene scene) { return new RenderJob(null, null, Objects.requireNonNull(scene, "scene")); }

    /**
     * Changes the scene's settings before it is built, for example
     * {@code s -> s.toBuilder().size(400, 225).build()}; applied to the settings the scene file or
     * builder gives.
     *
     * @param override maps the scene's settings to the ones to render with
     * @return this job
     * @throws IllegalStateException if the job has started or was given a built scene
     */
    public RenderJob settings(UnaryOperator<RenderSettings> override) {
        configurable(true);
        settingsOverride = Objects.requireNonNull(override, "override");
        return this;
    }

    /**
     * Replaces the scene's camera before it is built.
     *
     * @param change gets the scene's camera (or the default one) and returns the one to render with
     * @return this job
     * @throws IllegalStateException if the job has started or was given a built scene
     */
    public RenderJob camera(UnaryOperator<Camera> change) {
        configurable(true);
        cameraOverride = Objects.requireNonNull(change, "change");
        return this;
    }

    /**
     * Renders one frame of the scene's animation: after the setting overrides, the settings get
     * that frame's shutter and seed ({@link lt.spindulys.scene.Animation#settingsFor}), so the
     * image depends on the frame number alone.
     *
     * @param n the frame number; the run fails if the scene has no animation or n is outside its range
     * @return this job
     * @throws IllegalStateException if the job has started or was given a built scene
     */
    public RenderJob frame(int n) {
        configurable(true);
        frame = n;
        return this;
    }

    /**
     * Called with the scene as read (or as given), before the overrides: to look at it, or to run
     * work that should overlap with nothing else. Must not keep the builder.
     *
     * @param action called once, on the thread that runs the job
     * @return this job
     * @throws IllegalStateException if the job has started or was given a built scene
     */
    public RenderJob onLoaded(Consumer<SceneBuilder> action) {
        configurable(true);
        onLoaded = Objects.requireNonNull(action, "action");
        return this;
    }

    /**
     * Writes the image to {@code out} when the render is done (format by extension, with the
     * passes the settings ask for beside it; see {@link RenderResult#write(Path)}). Checked before
     * any work, so an unwritable path fails at once. Without an output nothing is written.
     *
     * @param out the image file; its extension names the format
     * @return this job
     * @throws IllegalArgumentException if the extension names no supported format
     */
    public RenderJob output(Path out) {
        configurable(false);
        ImageWriter.checkFormat(Objects.requireNonNull(out, "out"));
        output = out;
        return this;
    }

    /**
     * Confines what the scene file may read to {@code roots} ({@link SceneParser#parse(Path, AssetRoots)}):
     * the scene file and every file it names must be inside one of the folders, links resolved,
     * or the run fails at the key that named the file, before it is opened. For a farm that
     * renders scenes it did not write.
     *
     * @param roots the folders; {@link AssetRoots#ANY} (the default) for anywhere
     * @return this job
     * @throws IllegalStateException if the job has started, or was not given a scene file
     */
    public RenderJob assetRoots(AssetRoots roots) {
        configurable(false);
        if (sceneFile == null && Objects.requireNonNull(roots, "roots").confines()) {
            throw new IllegalStateException("asset folders confine what a scene file reads: parse the builder with SceneParser.parse(file, roots) instead");
        }
        assetRoots = Objects.requireNonNull(roots, "roots");
        return this;
    }

    /**
     * Sets the JPEG quality of a .jpg output (default 0.92; other formats ignore it).
     *
     * @param quality in [0, 1], 1 best
     * @return this job
     */
    public RenderJob jpegQuality(double quality) {
        configurable(false);
        imageOptions = imageOptions.withJpegQuality(quality);
        return this;
    }

    /**
     * Sets how an .exr output stores its channels (default: halves, ZIP; other formats ignore it).
     *
     * @param precision half or float colour and normals
     * @param compression the compression of the line blocks
     * @return this job
     */
    public RenderJob exr(lt.spindulys.image.ExrPrecision precision, lt.spindulys.image.ExrCompression compression) {
        configurable(false);
        imageOptions = imageOptions.withExr(precision, compression);
        return this;
    }

    /**
     * Sets the number of render threads (default: every core the JVM reports). The image does not
     * depend on it.
     *
     * @param n at least 1
     * @return this job
     */
    public RenderJob threads(int n) {
        configurable(false);
        if (n < 1) throw new IllegalArgumentException("threads must be at least 1, found " + n);
        threads = n;
        return this;
    }

    /**
     * Sets where to report progress.
     *
     * @param listener called from render threads as tiles finish; null: nowhere
     * @return this job
     */
    public RenderJob progress(ProgressListener listener) {
        configurable(false);
        progress = listener;
        return this;
    }

    /**
     * Sets who is shown each finished tile, for a picture that fills in as the render goes.
     *
     * @param listener called from render threads as tiles finish; null: nobody
     * @return this job
     */
    public RenderJob tiles(TileListener listener) {
        configurable(false);
        tiles = listener;
        return this;
    }

    /**
     * Renders only {@code region} of the frame: the result's frame is the region's size, holds
     * exactly the pixels a whole render has there, and is written as a PNG tile that records its
     * place ({@link lt.spindulys.image.TileFile}), for {@code render assemble} to put back. Checked
     * against the frame's size once the settings are known; render passes are refused for a region.
     *
     * @param region the pixels to render; null: the whole frame
     * @return this job
     */
    public RenderJob region(PixelRegion region) {
        configurable(false);
        regionOf = region == null ? null : (w, h) -> region;
        return this;
    }

    /**
     * Renders only tile {@code number} of {@code count} of the frame: the band of whole rows
     * {@link PixelRegion#band} gives, as {@link #region(PixelRegion)} does. The tiles of one count
     * cover the frame exactly once, for any size (down to bands of one row).
     *
     * @param number which tile, from 1 to {@code count}
     * @param count  how many tiles, at least 1 and at most the frame's height (checked when the size is known)
     * @return this job
     * @throws IllegalArgumentException if {@code number} is not in [1, count]
     */
    public RenderJob tile(int number, int count) {
        configurable(false);
        PixelRegion.checkTile(number, count);
        regionOf = (w, h) -> PixelRegion.band(number, count, w, h);
        return this;
    }

    /**
     * Denoises the frame before it is written: the render gathers albedo, normal, depth and
     * the variance of each pixel beside the colour, and {@link lt.spindulys.denoise.Denoiser}
     * filters the colour with them (on as many threads as the render). For whole frames only:
     * a region or tile is refused ({@link Renderer#DENOISE_OF_REGION}). The result's
     * {@link RenderResult#noisy()} keeps the frame as rendered. Overrides the settings'
     * {@link RenderSettings#denoise()}, which decides when this is not called.
     *
     * @param on true to denoise, false not to
     * @return this job
     */
    public RenderJob denoise(boolean on) {
        configurable(false);
        denoise = on;
        return this;
    }

    /**
     * With {@link #denoise}, also writes the frame as rendered beside the denoised one, as
     * {@link RenderResult#noisyFileBeside} names it ({@code out.png} gives {@code out.noisy.png}),
     * in the same atomic group. Without denoising it has no effect.
     *
     * @param on true to write the noisy frame too
     * @return this job
     */
    public RenderJob keepNoisy(boolean on) {
        configurable(false);
        keepNoisy = on;
        return this;
    }

    /** Asks the job to stop: a running render stops between tiles, and the run throws {@link CancellationException}. */
    public void cancel() { cancelled.set(true); }

    /**
     * Tells whether {@link #cancel} was called.
     *
     * @return true once cancelled
     */
    public boolean isCancelled() { return cancelled.get(); }

    /**
     * The step the job is in, or the one it failed in after a failure.
     *
     * @return the current or last step
     */
    public Stage stage() { return stage; }

    /**
     * Runs the job on a new thread; the future's {@code cancel} cancels the job.
     *
     * @return the result to come; {@code get} throws an ExecutionException wrapping what {@link #run} would throw
     * @throws IllegalStateException if the job was already run or started
     */
    public Future<RenderResult> start() {
        if (!runAfterCheck.getAndSet(false)) begin();
        FutureTask<RenderResult> task = new FutureTask<>(this::runStarted) {
            @Override
            public boolean cancel(boolean mayInterruptIfRunning) {
                RenderJob.this.cancel();
                return super.cancel(mayInterruptIfRunning);
            }
        };
        Thread t = new Thread(task, "spindulys-render-job");
        t.start();
        return task;
    }

    /**
     * Runs the job on the calling thread and returns the result, after writing it if an output was
     * given. Interrupting the thread stops the render.
     *
     * @return the finished render
     * @throws IOException                 if the scene file cannot be read or the image cannot be written
     * @throws IllegalArgumentException    for bad input: a scene file error ({@link lt.spindulys.io.SceneException}),
     *                                     bad settings, a scene that cannot be built, or a frame the heap cannot hold
     * @throws CancellationException       if the job was cancelled
     * @throws InterruptedException        if the thread was interrupted
     * @throws IllegalStateException       if the job was already run or started
     */
    public RenderResult run() throws IOException, InterruptedException {
        if (!runAfterCheck.getAndSet(false)) begin();
        return runStarted();
    }

    private void begin() {
        if (!started.compareAndSet(false, true)) throw new IllegalStateException("a render job runs once");
    }

    /**
     * Makes every check a run begins with, without building or rendering: the output can be
     * written and is none of the scene's files, the scene file reads, the settings (after the
     * overrides, and the frame's) describe a frame the region fits and the heap can hold. The run
     * that follows ({@link #run}, {@link #start}) does not make them again. For a caller that
     * reports bad input apart from failures while rendering, as the command line does.
     *
     * @return the settings the job will render with
     * @throws IOException              if the output cannot be written, or the scene file cannot be read
     * @throws IllegalArgumentException for bad input, as {@link #run} says; a frame the heap cannot
     *                                  hold is an {@link lt.spindulys.limits.InsufficientMemoryException}
     *                                  sized by {@value Renderer#FRAME_KEY}
     * @throws CancellationException    if the job was cancelled
     * @throws IllegalStateException    if the job was checked, run or started already
     */
    public RenderSettings check() throws IOException {
        begin();
        checked = prepare();
        runAfterCheck.set(true);
        return checked.settings();
    }

    /** What the checks found: the scene (or its description), the settings, the region (null: the whole frame), the load time. */
    private record Checked(Scene built, SceneBuilder description, RenderSettings settings, Camera camera, PixelRegion region, double load) {}

    /** The checks of a run, up to the build ({@link #check}). */
    private Checked prepare() throws IOException {
        if (output != null) {
            enter(Stage.CHECK);
            if (regionOf != null) RenderResult.checkTileOutput(output);
            // The scene file is known before it is read; what it names, once it is.
            if (sceneFile != null) checkOutput(output, sceneFile);
            if (builder != null) InputFile.checkOutput(output, builder.inputFiles());
            ImageWriter.checkOutput(output);
        }
        if (scene != null) {
            enter(Stage.SETTINGS);
            RenderSettings s = scene.settings();
            PixelRegion region = regionOf == null ? null : regionOf.of(s.width(), s.height());
            Renderer.checkFrame(s, region, denoises(s));
            if (output != null) checkPassOutputs(s);
            return new Checked(scene, null, s, null, region, 0);
        }
        long t0 = System.nanoTime();
        enter(Stage.LOAD);
        SceneBuilder b = builder != null ? builder : SceneParser.parse(sceneFile, assetRoots);
        if (onLoaded != null) onLoaded.accept(b);
        double load = (System.nanoTime() - t0) / 1e9;
        enter(Stage.SETTINGS);
        RenderSettings s = Objects.requireNonNull(settingsOverride.apply(b.settings()), "the settings override returned null");
        if (frame != null) {
            if (b.animation() == null) throw new IllegalArgumentException("frame " + frame + " asked of a scene without an animation");
            s = b.animation().settingsFor(s, frame);
        }
        PixelRegion region = regionOf == null ? null : regionOf.of(s.width(), s.height());
        // The frame is asked for by input: checked before anything is built for it.
        Renderer.checkFrame(s, region, denoises(s));
        if (output != null) {
            checkPassOutputs(s);
            checkNotInput(output, s.aovs(), b.inputFiles());
            if (writesNoisy(s)) InputFile.checkOutput(RenderResult.noisyFileBeside(output), b.inputFiles());
        }
        Camera c = cameraOverride == null ? b.camera()
                : cameraOverride.apply(b.camera() != null ? b.camera() : SceneBuilder.DEFAULT_CAMERA);
        return new Checked(null, b, s, c, region, load);
    }

    /** The passes' files and the noisy image's can be written (the image itself was checked first). */
    private void checkPassOutputs(RenderSettings s) throws IOException {
        ImageWriter.checkPassOutputs(output, s.aovs());
        if (writesNoisy(s)) lt.spindulys.files.AtomicFile.checkWritable(RenderResult.noisyFileBeside(output));
    }

    /** Whether a frame of these settings is denoised: as this job says, else as they say. */
    private boolean denoises(RenderSettings s) { return denoise != null ? denoise : s.denoise(); }

    private boolean writesNoisy(RenderSettings s) { return denoises(s) && keepNoisy && output != null; }

    private RenderResult runStarted() throws IOException, InterruptedException {
        Checked c = checked != null ? checked : prepare();
        checked = null; // the description is not kept once built
        Scene built = c.built();
        double build = 0;
        if (built == null) {
            long t1 = System.nanoTime();
            enter(Stage.BUILD);
            // The time steps are the scene's to refuse (Scene checks them as every scene is built).
            built = buildWith(c.description(), c.settings(), c.camera());
            build = (System.nanoTime() - t1) / 1e9;
        }
        enter(Stage.RENDER);
        boolean denoising = denoises(c.settings());
        RenderResult result = Renderer.render(built, threads, progress, cancelled, tiles, c.region(), denoising).withTimes(c.load(), build).ofFrame(frame);
        if (denoising) {
            enter(Stage.RENDER);
            long t2 = System.nanoTime();
            FrameBuffer clean = new Denoiser().denoise(result.frame(), result.features().orElseThrow(), threads);
            result = result.denoised(clean, keepNoisy, (System.nanoTime() - t2) / 1e9);
        }
        if (output != null) {
            enter(Stage.WRITE);
            result.write(output, imageOptions);
        }
        stage = Stage.DONE;
        return result;
    }

    /**
     * Refuses, before a scene file is read, an output that is that file (by name or through a
     * link): the output would replace its own input. What the file names is checked once it is
     * read ({@link #checkNotInput}).
     *
     * @param output    the image to be written
     * @param sceneFile the scene file to be read
     * @throws InputFile.OutputIsInputException naming the file
     */
    public static void checkOutput(Path output, Path sceneFile) {
        InputFile.checkOutput(output, java.util.List.of(new InputFile(sceneFile, "scene file", null)));
    }

    /**
     * Refuses an image, or a render pass beside it, that is one of the files the scene was read
     * from: the output would replace its own input.
     *
     * @param output the image to be written
     * @param passes the passes to be written beside it ({@link Aov#filesBeside})
     * @param inputs the files read ({@link SceneBuilder#inputFiles()})
     * @throws InputFile.OutputIsInputException naming the file and the input
     */
    public static void checkNotInput(Path output, java.util.Set<Aov> passes, java.util.List<InputFile> inputs) {
        InputFile.checkOutput(output, inputs);
        for (java.nio.file.Path p : Aov.filesBeside(output, passes)) InputFile.checkOutput(p, inputs);
    }

    /** A region chosen by the frame's size. */
    @FunctionalInterface
    private interface RegionOf {
        PixelRegion of(int width, int height);
    }

    /** Builds {@code b} with these settings and camera, leaving the builder as it was. */
    private static Scene buildWith(SceneBuilder b, RenderSettings s, Camera c) {
        SceneBuilder own = b.copy().settings(s);
        if (c != null) own.camera(c);
        return own.build();
    }

    private void enter(Stage next) {
        if (cancelled.get()) throw new CancellationException("the render job was cancelled");
        stage = next;
    }

    private void configurable(boolean needsSceneDescription) {
        if (started.get()) throw new IllegalStateException("a render job cannot change once it has started");
        if (needsSceneDescription && scene != null) {
            throw new IllegalStateException("a job given a built scene takes no overrides: give it the SceneBuilder instead");
        }
    }
}
