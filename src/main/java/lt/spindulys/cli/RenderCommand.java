package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.camera.PixelFilter;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.InputFile;
import lt.spindulys.scene.AdaptiveSettings;
import lt.spindulys.image.Aov;
import lt.spindulys.image.ExrCompression;
import lt.spindulys.image.ExrPrecision;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.io.AssetRoots;
import lt.spindulys.io.SceneException;
import lt.spindulys.io.SceneParser;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Ranges;
import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.frontend.HeapPeak;
import lt.spindulys.frontend.PeakResident;
import lt.spindulys.render.JitWarmup;
import lt.spindulys.render.RenderStats;
import lt.spindulys.render.RenderJob;
import lt.spindulys.render.RenderResult;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuildException;
import lt.spindulys.scene.SceneBuilder;

/** {@code render SCENE.dat [options]}: parse, override settings, render, write the image atomically. */
final class RenderCommand {
    /** The --assets-root lines of the usage, shared with render subdivide. */
    static final String ASSETS_USAGE = """
              --assets-root DIR  read only inside DIR (repeatable; SPINDULYS_ASSETS_ROOT, folders separated by
                                 the path separator, applies too): the scene file and every file it names,
                                 links resolved; a file outside is refused before it is opened
            """;

    static final String USAGE = """
            usage: render SCENE.dat [-o OUT] [--width W] [--height H] [--spp N] [--aperture R] [--focus D]
                                    [--threads N] [--seed S] [--accel A] [--aov LIST] [--shutter OPEN,CLOSE] [--timesteps N]
                                    [--integrator whitted|path] [--maxdepth N] [--clamp C] [--filter F[,W]] [--filter-width W]
                                    [--noise-threshold T] [--min-samples M]
                                    [--subdiv-target PX] [--subdiv-memory MIB] [--subdiv-cache MIB]
                                    [--frame N | --frames A-B[:STEP]] [--skip-existing]
                                    [--quality Q] [--exr-precision half|float] [--exr-compression none|zip|zips]
                                    [--denoise [--keep-noisy]] [--region X0,X1,Y0,Y1 | --tile I/N] [--progress openjd|plain]
                                    [--assets-root DIR]... [--stats] [--quiet] [--debug]
                   render assemble TILE.png... -o OUT [--frame N]                (see render assemble --help)
                   render subdivide MESH.obj|MESH.dat --level N|--scene SCENE.dat -o OUT.obj [...]   (see render subdivide --help)
                   render bench [--only NAME] [--runs N] [--accel A] [--list]      (see render bench --help)
                   render view [MESH.obj|MESH.dat|UNWRAP.tex ...] | render view SCENE.dat   (see render view --help)
                   render --help | --version

              -o, --output OUT   image to write: .png .jpg .jpeg .tga .pfm .exr (default: SCENE.png here)
              --width W          image width in pixels (overrides the scene); alone, the height
                                 follows the scene's aspect ratio (800x450 with --width 400: 400x225)
              --height H         image height in pixels (overrides the scene); alone, likewise the width
              --spp N            samples per pixel, stratified (overrides the scene)
              --aperture R       lens radius of the camera, 0 for a pinhole (overrides the scene)
              --focus D          distance to the focal plane along the view (overrides the scene)
              --threads N        render threads (default: all cores)
              --seed S           global random seed (overrides the scene)
              --accel A          acceleration structure: bvh, bvh-compact, bvh2, octree or bruteforce (overrides the scene)
              --integrator I     whitted (the thesis's ray tracing) or path (global illumination) (overrides the scene)
              --maxdepth N       most bounces of a ray or path, 0 to 64 (overrides the scene)
              --clamp C          path tracing: the largest value a channel of one indirect sample may bring,
                                 against fireflies; 0 for none (overrides the scene)
              --filter F[,W]     pixel filter: box (Whitted's default), gaussian, blackman-harris (the path
                                 tracer's default, as Blender's) or mitchell, optionally with its width W in
                                 pixels; without W the filter's own default width (1, 1.5, 1.5, 4)
                                 (overrides the scene)
              --filter-width W   the pixel filter's width in pixels, 0.1 to 16 (overrides the scene and --filter)
              --noise-threshold T  adaptive sampling: a pixel stops taking samples once its estimated relative
                                 error is below T (Cycles' default is 0.01); at most --spp samples;
                                 0 for none, every pixel takes them all (default) (overrides the scene)
              --min-samples M    adaptive sampling: samples every pixel takes before its error is first
                                 checked; 0 for max(4, 16 / T^0.3) (64 at 0.01) (overrides the scene)
              --aov LIST         render passes beside the image, comma-separated: depth, normal, object, albedo,
                                 noise (OUT.depth.pfm, OUT.normal.pfm, OUT.object.png, OUT.albedo.pfm,
                                 OUT.noise.pfm; overrides the scene); an .exr holds them as its channels Z,
                                 Normal.X/Y/Z, IndexOB.X, Albedo.R/G/B, Samples.X and Noise.X instead
              --shutter OPEN,CLOSE  shutter interval of the motion blur, e.g. 0,1 (overrides the scene)
              --timesteps N      1: one pass, every sample at its own time (default); N > 1: the thesis's
                                 method, N whole-frame passes at fixed times averaged (spp must be a multiple of N)
              --subdiv-target PX target edge length in pixels of every adaptive subdiv (overrides the scene's)
              --subdiv-memory MIB  heap for adaptive subdivision, eager and cached together (0: automatic;
                                 more than the heap can give is capped by it)
              --subdiv-cache MIB the lazy patches' cache, part of the subdivision memory (default 64; shrunk to it)
            """ + FrameOptions.USAGE + """
              --denoise          denoise the image, guided by the albedo, normal and depth the samples saw
                                 (whole frames only: not with --region or --tile)
              --keep-noisy       with --denoise (or the scene's denoise true), also write the image as
                                 rendered, as OUT.noisy.EXT
              --quality Q        JPEG quality from 0 to 1 (default 0.92)
              --exr-precision P  .exr colour and normals as half (default) or float; depth and object id
                                 are always float
              --exr-compression C  .exr compression: zip (default, 16 lines a block), zips (1 line) or none
            """ + FarmOptions.USAGE + ASSETS_USAGE + """
              --stats            print load, build and render times, rays by kind, Mrays/s, peak heap,
                                 per mesh its triangles and its tree's SAH cost, and per adaptive
                                 subdiv its levels, patches, cache hits and misses
              --quiet            no progress bar, and no closing 'wrote OUT (WxH, N spp) in T s' line
              --debug            stack traces on errors
            Exit status: 0 success, 2 bad usage or bad input, 1 failure while rendering or writing.""";

    private Path scene, output;
    /** The folders of --assets-root, in order. */
    private final List<Path> assetFolders = new ArrayList<>();
    /** What the scene may read: --assets-root and SPINDULYS_ASSETS_ROOT together. */
    private AssetRoots assetRoots = AssetRoots.ANY;
    private Integer width, height, spp, threads;
    private Long seed;
    private Double aperture, focus;
    private AcceleratorKind accel;
    private IntegratorKind integrator;
    private Integer maxDepth;
    private Double clamp;
    private PixelFilter filter;
    /** The filter width given: by --filter-width, or by --filter NAME,W; 0 for the filter's default. */
    private Double filterWidth;
    private boolean filterWidthOption;
    private Double noiseThreshold;
    private Integer minSamples;
    private Set<Aov> aovs;
    private double[] shutter;
    private Integer timeSteps;
    private Double subdivTarget, subdivMemory, subdivCache;
    private double quality = ImageOptions.DEFAULT.jpegQuality();
    private ExrPrecision exrPrecision = ImageOptions.DEFAULT.exrPrecision();
    private ExrCompression exrCompression = ImageOptions.DEFAULT.exrCompression();
    private boolean stats, quiet, denoise, keepNoisy;
    private final FarmOptions farm = new FarmOptions();
    private FarmProgress farmProgress;
    /** The job now running, whose step the farm progress reports (several frames: one job each). */
    private volatile RenderJob current;
    private final FrameOptions frames = new FrameOptions();
    private boolean outputDefaulted;
    /** What the command does before its first job: checking, then reading the scene (for the farm's progress). */
    private volatile RenderJob.Stage step = RenderJob.Stage.READY;
    /** When the read began: a still's time counts from it. */
    private long readStart;
    /** The scene file's reading time and the wait for the JIT warm-up, shown by the first render's statistics. */
    private double readSeconds, warmupSeconds;

    /** Parses arguments (after --debug was taken out), with the process's environment. */
    RenderCommand(String[] args) throws UsageException {
        this(args, System.getenv());
    }

    /** Parses arguments (after --debug was taken out); {@code env} gives SPINDULYS_ASSETS_ROOT. */
    RenderCommand(String[] args, Map<String, String> env) throws UsageException {
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "-o", "--output" -> output = Path.of(OptionValues.value(args, ++i, a));
                case "--width" -> width = OptionValues.intValue(args, ++i, a, 1, RenderSettings.MAX_SIDE);
                case "--height" -> height = OptionValues.intValue(args, ++i, a, 1, RenderSettings.MAX_SIDE);
                case "--spp" -> spp = OptionValues.intValue(args, ++i, a, 1, 65536);
                case "--aperture" -> aperture = OptionValues.lensValue(args, ++i, a, false);
                case "--focus" -> focus = OptionValues.lensValue(args, ++i, a, true);
                case "--threads" -> threads = OptionValues.intValue(args, ++i, a, 1, 1024);
                case "--seed" -> seed = OptionValues.longValue(args, ++i, a);
                case "--accel" -> {
                    String v = OptionValues.value(args, ++i, a);
                    if (!AcceleratorKind.keywords().contains(v)) {
                        throw new UsageException(a + " expects one of " + String.join(", ", AcceleratorKind.keywords()) + ", found '" + v + "'");
                    }
                    accel = AcceleratorKind.fromKeyword(v);
                }
                case "--integrator" -> {
                    String v = OptionValues.value(args, ++i, a);
                    if (!IntegratorKind.keywords().contains(v)) {
                        throw new UsageException(a + " expects one of " + String.join(", ", IntegratorKind.keywords()) + ", found '" + v + "'");
                    }
                    integrator = IntegratorKind.fromKeyword(v);
                }
                case "--maxdepth" -> maxDepth = OptionValues.intValue(args, ++i, a, 0, 64);
                case "--clamp" -> clamp = OptionValues.doubleValue(args, ++i, a, 0, Ranges.MAX_COLOUR);
                case "--filter" -> {
                    String v = OptionValues.value(args, ++i, a);
                    int comma = v.indexOf(',');
                    String name = comma < 0 ? v : v.substring(0, comma);
                    if (!PixelFilter.keywords().contains(name)) {
                        throw new UsageException(a + " expects one of " + String.join(", ", PixelFilter.keywords()) + ", found '" + name + "'");
                    }
                    filter = PixelFilter.fromKeyword(name);
                    // A filter named alone takes its own default width, not the scene's width for another filter.
                    if (!filterWidthOption) filterWidth = comma < 0 ? 0.0 : widthValue(v.substring(comma + 1), a);
                }
                case "--noise-threshold" -> noiseThreshold = OptionValues.doubleValue(args, ++i, a, 0, RenderSettings.MAX_NOISE_THRESHOLD);
                case "--min-samples" -> minSamples = OptionValues.intValue(args, ++i, a, 0, 65536);
                case "--filter-width" -> {
                    filterWidth = widthValue(OptionValues.value(args, ++i, a), a);
                    filterWidthOption = true;
                }
                case "--aov" -> {
                    String v = OptionValues.value(args, ++i, a);
                    try {
                        aovs = Aov.parseList(v);
                    } catch (IllegalArgumentException e) {
                        throw new UsageException(a + ": " + e.getMessage());
                    }
                }
                case "--shutter" -> shutter = OptionValues.shutterValue(args, ++i, a);
                case "--timesteps" -> timeSteps = OptionValues.intValue(args, ++i, a, 1, 65536);
                case "--quality" -> quality = OptionValues.doubleValue(args, ++i, a, 0, 1);
                case "--exr-precision" -> {
                    String v = OptionValues.value(args, ++i, a);
                    try {
                        exrPrecision = ExrPrecision.fromKeyword(v);
                    } catch (IllegalArgumentException e) {
                        throw new UsageException(a + ": " + e.getMessage());
                    }
                }
                case "--exr-compression" -> {
                    String v = OptionValues.value(args, ++i, a);
                    try {
                        exrCompression = ExrCompression.fromKeyword(v);
                    } catch (IllegalArgumentException e) {
                        throw new UsageException(a + ": " + e.getMessage());
                    }
                }
                case "--subdiv-target" -> subdivTarget = OptionValues.doubleValue(args, ++i, a, AdaptiveSettings.MIN_TARGET, AdaptiveSettings.MAX_TARGET);
                case "--subdiv-memory" -> subdivMemory = OptionValues.doubleValue(args, ++i, a, 0, AdaptiveSettings.MAX_BYTES >> 20);
                case "--subdiv-cache" -> {
                    subdivCache = OptionValues.doubleValue(args, ++i, a, 0, AdaptiveSettings.MAX_BYTES >> 20);
                    if (!(subdivCache * (1 << 20) >= 1)) throw new UsageException(a + " must be more than 0 (mebibytes of the lazy patches' cache), found " + args[i]);
                }
                case "--frame", "--frames", "--skip-existing" -> i = frames.option(args, i);
                case "--assets-root" -> assetFolders.add(pathValue(args, ++i, a));
                case "--denoise" -> denoise = true;
                case "--keep-noisy" -> keepNoisy = true;
                case "--stats" -> stats = true;
                case "--quiet", "-q" -> quiet = true;
                default -> {
                    int used = farm.parse(args, i);
                    if (used >= 0) {
                        i = used;
                        continue;
                    }
                    if (a.startsWith("-") && a.length() > 1) throw new UsageException("unknown option '" + a + "' (see render --help)");
                    if (scene != null) throw new UsageException("more than one scene file given: '" + scene + "' and '" + a + "'");
                    scene = Path.of(a);
                }
            }
        }
        if (scene == null) throw new UsageException("no scene file given (see render --help)");
        if (output == null) {
            outputDefaulted = true;
            String name = scene.getFileName().toString();
            int dot = name.lastIndexOf('.');
            output = Path.of((dot > 0 ? name.substring(0, dot) : name) + ".png");
        }
        try {
            ImageWriter.checkFormat(output);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        farm.checkOutput(output);
        farm.checkDenoise(denoise);
        assetRoots = assetRoots(assetFolders, env);
    }

    /** A path option's value; a name the platform cannot take is bad usage. */
    static Path pathValue(String[] args, int i, String option) throws UsageException {
        String v = OptionValues.value(args, i, option);
        try {
            return Path.of(v);
        } catch (java.nio.file.InvalidPathException e) {
            throw new UsageException(option + ": '" + MessageText.cut(v, 200) + "' is not a valid path: " + e.getReason());
        }
    }

    /**
     * What a scene may read: inside the --assets-root folders given, and inside the folders of
     * SPINDULYS_ASSETS_ROOT when it is set (a farm's, which an option cannot widen).
     */
    static AssetRoots assetRoots(List<Path> folders, Map<String, String> env) throws UsageException {
        AssetRoots roots;
        try {
            roots = AssetRoots.of(folders);
        } catch (IllegalArgumentException e) {
            throw new UsageException("--assets-root: " + e.getMessage());
        }
        try {
            return AssetRoots.parse(env.get(AssetRoots.ENVIRONMENT_VARIABLE)).and(roots);
        } catch (IllegalArgumentException e) {
            throw new UsageException(AssetRoots.ENVIRONMENT_VARIABLE + ": " + e.getMessage());
        }
    }

    /**
     * Runs the command; returns the exit status. Bad input surfaces as exceptions handled by {@link Main}.
     * The scene is read once; a still is then one render, an animated one (or frames asked for)
     * one render a frame, each built from the scene as read.
     */
    int run(PrintStream out, PrintStream err) throws IOException, InterruptedException, UsageException {
        try {
            farmProgress = farm.progress(() -> current != null ? current.stage() : step, out, err, output.toString(), System.nanoTime());
            if (farmProgress != null) farmProgress.start();
            return renderAll(out, err);
        } catch (UsageException e) {
            if (farmProgress != null) farmProgress.failed("render: " + e.getMessage());
            throw e;
        } catch (Exception | Error e) {
            // The manager is told the line Main prints on stderr for the same failure.
            if (farmProgress != null) farmProgress.failed(e instanceof NoSuchFileException ? e.getMessage() : FailureMessage.of(e));
            throw e;
        } finally {
            if (farmProgress != null) farmProgress.close();
        }
    }

    /** Reads the scene, then renders the still or the frames: one loop over (output, frame or null). */
    private int renderAll(PrintStream out, PrintStream err) throws IOException, InterruptedException, UsageException {
        SceneBuilder read = read();
        List<FrameOptions.Item> items;
        String allExist;
        if (read.animation() == null && !frames.given()) {
            items = List.of(new FrameOptions.Item(output, null));
            allExist = output + " exists (--skip-existing)";
        } else {
            if (shutter != null) throw new UsageException("--shutter does not combine with an animation's frames: each frame's shutter is set by its shutter angle");
            FrameRange range = frames.frames(read.animation(), scene);
            items = FrameOptions.Item.frames(range, frames.pattern(output, outputDefaulted, range));
            allExist = "every frame of " + range + " exists (--skip-existing)";
        }
        Set<Aov> passes = aovs != null ? aovs : read.settings().aovs();
        List<FrameOptions.Item> todo = frames.unfinished(items, passes, quiet ? null : err);
        // A retried task whose outputs all exist is done too: the manager is told so.
        if (todo.isEmpty() && farmProgress != null) farmProgress.wrote(allExist);
        if (todo.isEmpty()) return 0;
        // Every output, before the first is rendered.
        for (FrameOptions.Item item : todo) {
            try {
                RenderJob.checkNotInput(item.output(), passes, read.inputFiles());
            } catch (InputFile.OutputIsInputException e) {
                throw new UsageException(e.getMessage());
            }
        }
        SceneBuilder scene = withOverrides(read);
        for (int i = 0; i < todo.size(); i++) {
            FrameOptions.Item item = todo.get(i);
            if (farmProgress != null && item.frame() != null) farmProgress.item(item.output().toString(), i, todo.size());
            render(out, err, scene, item);
        }
        return 0;
    }

    /**
     * Reads the scene file, after the checks that need only its name and the output's, while the
     * JIT warms up (once per process: the renders after the first find the code compiled).
     */
    private SceneBuilder read() throws IOException, InterruptedException, UsageException {
        readStart = System.nanoTime();
        step = RenderJob.Stage.CHECK;
        // Refused before anything is opened: a pipe would block, a device never end.
        String problem = InputFiles.problem(scene);
        if (problem != null) throw new NoSuchFileException(scene, problem);
        if (isObjMesh(scene)) {
            String name = MessageText.quote(scene.getFileName().toString(), "\"");
            throw new SceneException(scene.toString(), 0, 0, "this is an OBJ mesh, not a scene: to render it, name it in a scene's mesh { file "
                    + name + " } or subdiv { file " + name + " } block, or refine it with render subdivide");
        }
        try {
            if (aovs != null) ImageWriter.checkOutputs(output, aovs);
            RenderJob.checkOutput(output, scene);
            ImageWriter.checkOutput(output);
        } catch (IOException | InputFile.OutputIsInputException e) {
            // A missing directory, a directory, no permission, or the scene file itself.
            throw new UsageException(e.getMessage());
        }
        try (JitWarmup warm = JitWarmup.start()) {
            step = RenderJob.Stage.LOAD;
            SceneBuilder b = SceneParser.parse(scene, assetRoots);
            long w0 = System.nanoTime();
            readSeconds = (w0 - readStart) / 1e9;
            warm.finishFor(b, accel != null ? accel : b.settings().accelerator());
            warmupSeconds = (System.nanoTime() - w0) / 1e9;
            step = RenderJob.Stage.SETTINGS;
            return b;
        }
    }

    /**
     * Renders one item to its output: a job of the scene (with the command line's settings and
     * lens), checked first, so that an output or a frame refused before any work is bad usage.
     */
    private void render(PrintStream out, PrintStream err, SceneBuilder scene, FrameOptions.Item item)
            throws IOException, InterruptedException, UsageException {
        // A still's time counts from the start of the read, a frame's from its own start.
        long t0 = item.frame() == null ? readStart : System.nanoTime();
        int n = threads != null ? threads : Runtime.getRuntime().availableProcessors();
        RenderJob job = RenderJob.of(scene).output(item.output()).jpegQuality(quality).exr(exrPrecision, exrCompression).threads(n);
        if (item.frame() != null) job.frame(item.frame());
        // Without --denoise the scene's own denoise setting decides.
        if (denoise) job.denoise(true);
        if (keepNoisy && !denoise && !scene.settings().denoise()) {
            throw new UsageException("--keep-noisy keeps the noisy image of a denoised one: give --denoise too, or settings { denoise true }");
        }
        job.keepNoisy(keepNoisy);
        farm.apply(job);
        // A farm's manager reads lines; the bar redraws one line in place, for a person at a terminal.
        TerminalProgress bar = farmProgress == null && !quiet && System.console() != null ? new TerminalProgress(err) : null;
        job.progress(farmProgress != null ? farmProgress : bar);
        current = job;
        RenderResult result;
        try {
            try {
                job.check();
            } catch (IOException | InputFile.OutputIsInputException e) {
                // The output refused before any work: a missing directory, a directory, no permission, an input.
                throw new UsageException(e.getMessage());
            }
            result = job.run();
        } catch (java.util.concurrent.CancellationException e) {
            throw new InterruptedException("interrupted");
        } catch (InsufficientMemoryException e) {
            throw atTheSource(scene, e);
        } catch (SceneBuildException e) {
            // A motion's own times may not fit a shutter given here (an open start or finish is the shutter's).
            if (shutter == null) throw e;
            String given = "--shutter " + shutter[0] + "," + shutter[1];
            // The object's statement comes first when there is one, as in every other input error.
            if (e.source() != null) throw new IllegalArgumentException(e.getMessage() + " (with " + given + ")", e);
            throw new UsageException(given + ": " + e.getMessage());
        } finally {
            if (bar != null) bar.finish();
        }
        String done = MessageText.escape(doneLine(item.output(), result, (System.nanoTime() - t0) / 1e9));
        if (farmProgress != null) farmProgress.wrote(done);
        // On stderr with the progress bar it replaces: stdout carries only what was asked for (--stats).
        if (!quiet) err.println(done);
        if (stats) {
            printStats(out, readSeconds + result.loadSeconds(), warmupSeconds, result.buildSeconds(), result.settings().accelerator(), result.stats(), n);
            if (result.noisy().isPresent()) out.println(String.format(Locale.ROOT, "denoise: %.2f s", result.denoiseSeconds()));
            for (String line : result.structureStatistics()) out.println(MessageText.escape(line));
            for (String line : result.subdivisionStatistics()) out.println(MessageText.escape(line));
        }
        readSeconds = warmupSeconds = 0; // read once, shown once
    }

    /**
     * The scene as read with the command line's settings and lens. The settings are checked
     * here, once, before any render, and refused naming the options that made them.
     */
    private SceneBuilder withOverrides(SceneBuilder read) throws UsageException {
        SceneBuilder b = read.copy().settings(settings(read.settings()));
        if (aperture != null || focus != null) {
            // A pinhole becomes a thin lens focused on its look-at point unless --focus says otherwise.
            try {
                b.camera((read.camera() != null ? read.camera() : SceneBuilder.DEFAULT_CAMERA).withLens(aperture, focus));
            } catch (IllegalArgumentException e) {
                // An orthographic camera has no lens to give.
                throw new UsageException((aperture != null ? "--aperture" : "--focus") + ": " + e.getMessage());
            }
        }
        return b;
    }

    /** The scene's settings with the command line's overrides, checked; refusals name the options. */
    private RenderSettings settings(RenderSettings s) throws UsageException {
        RenderSettings.Builder o = s.toBuilder();
        if (width != null || height != null) {
            // One side alone keeps the scene's aspect ratio: 800x450 with --width 400 becomes 400x225.
            int w = width != null ? width : scaledSide(height, s.height(), s.width());
            int h = height != null ? height : scaledSide(width, s.width(), s.height());
            o.size(w, h);
        }
        if (spp != null) o.samplesPerPixel(spp);
        if (seed != null) o.seed(seed);
        if (accel != null) o.accelerator(accel);
        if (integrator != null) o.integrator(integrator);
        if (maxDepth != null) o.maxDepth(maxDepth);
        if (clamp != null) o.clamp(clamp);
        if (filter != null) o.filter(filter);
        if (filterWidth != null) o.filterWidth(filterWidth);
        if (noiseThreshold != null) o.noiseThreshold(noiseThreshold);
        if (minSamples != null) o.minSamples(minSamples);
        if (aovs != null) o.aovs(aovs);
        if (shutter != null) o.shutter(shutter[0], shutter[1]);
        if (timeSteps != null) o.timeSteps(timeSteps);
        if (subdivTarget != null || subdivMemory != null || subdivCache != null) {
            AdaptiveSettings a = s.adaptive();
            try {
                if (subdivMemory != null) a = a.withMemory((long) (subdivMemory * (1 << 20)));
                if (subdivCache != null) a = a.withCache((long) (subdivCache * (1 << 20)));
            } catch (IllegalArgumentException e) {
                throw new UsageException("--subdiv-memory/--subdiv-cache: " + e.getMessage());
            }
            if (subdivTarget != null) a = a.withTarget(subdivTarget);
            o.adaptive(a);
        }
        s = o.build();
        farm.checkFrame(s);
        if (spp != null || timeSteps != null) {
            try {
                s.checkTimeSteps();
            } catch (IllegalArgumentException e) {
                throw new UsageException((spp != null ? "--spp " + spp : "samples " + s.samplesPerPixel()) + " is not a multiple of "
                        + (timeSteps != null ? "--timesteps " : "the scene's timesteps ") + s.timeSteps() + " (each time step renders spp / timesteps per pixel)");
            }
        }
        try {
            s.checkNoiseControl();
        } catch (IllegalArgumentException e) {
            // Refused only by what the command line changed: the scene's own settings were checked when read.
            String options = (spp != null ? " --spp " + spp : "") + (noiseThreshold != null ? " --noise-threshold " + noiseThreshold : "")
                    + (minSamples != null ? " --min-samples " + minSamples : "") + (timeSteps != null ? " --timesteps " + timeSteps : "")
                    + (aovs != null ? " --aov " + aovs.stream().map(Aov::keyword).collect(java.util.stream.Collectors.joining(",")) : "");
            throw new UsageException((options.isEmpty() ? "" : options.substring(1) + ": ") + e.getMessage());
        }
        return s;
    }

    /**
     * The line that ends a render: the files written (the image, then its passes), the frame and
     * the time from start to written files, e.g. {@code wrote out.png (800x450, 16 spp) in 3.2 s}.
     */
    static String doneLine(Path output, RenderResult result, double seconds) {
        RenderSettings s = result.settings();
        StringBuilder line = new StringBuilder("wrote ").append(output);
        for (Path p : Aov.filesBeside(output, s.aovs())) line.append(", ").append(p);
        if (result.noisy().isPresent() && result.writesNoisy()) line.append(", ").append(RenderResult.noisyFileBeside(output));
        String part = result.region().map(r -> "region " + r + " of ").orElse("");
        // Adaptive sampling: the samples a pixel took on average, of at most the samples per pixel.
        String spp = s.adaptiveSampling() ? String.format(Locale.ROOT, "%.1f of %d spp adaptive", result.stats().meanSamples(), s.samplesPerPixel())
                : s.samplesPerPixel() + " spp";
        return line.append(String.format(Locale.ROOT, " (%s%dx%d, %s) in %.1f s", part, s.width(), s.height(), spp, seconds)).toString();
    }

    /**
     * An OBJ mesh given where a scene is expected, known by its extension; else false. (A Workframe
     * mesh is a .dat like a scene: the scene parser knows it by its first token, a point count.)
     */
    static boolean isObjMesh(Path file) {
        Path fileName = file.getFileName();
        return fileName != null && fileName.toString().toLowerCase(Locale.ROOT).endsWith(".obj");
    }

    /** A pixel filter's width, 0.1 to {@link RenderSettings#MAX_FILTER_WIDTH} pixels. */
    private static double widthValue(String v, String option) throws UsageException {
        try {
            double d = Double.parseDouble(v);
            if (!(d >= 0.1 && d <= RenderSettings.MAX_FILTER_WIDTH)) {
                throw new UsageException(option + " width must be between 0.1 and " + OptionValues.bound(RenderSettings.MAX_FILTER_WIDTH) + " pixels, found " + v);
            }
            return d;
        } catch (NumberFormatException e) {
            throw new UsageException(option + " expects a width in pixels, found '" + v + "'");
        }
    }

    /**
     * The other side of a frame resized to {@code given} along a side that was {@code from}, in
     * the proportion {@code to : from}: rounded to the nearest pixel, at least 1 and at most
     * {@link RenderSettings#MAX_SIDE} (a very thin frame may lose its exact aspect there).
     */
    static int scaledSide(int given, int from, int to) {
        long side = Math.round((double) given * to / from);
        return (int) Math.max(1, Math.min(RenderSettings.MAX_SIDE, side));
    }

    /**
     * A refusal of the heap reported where what it sized was given: the frame at the options that
     * resized it, else at the scene's settings key; the render threads' sample buffers at
     * {@code --spp} when it set the samples, else at the scene's key. Anything else as it is.
     */
    private RuntimeException atTheSource(SceneBuilder scene, InsufficientMemoryException e) throws UsageException {
        String at;
        if (Renderer.FRAME_KEY.equals(e.key())) {
            if (width != null || height != null || aovs != null) {
                String options = (width != null ? " --width " + width : "") + (height != null ? " --height " + height : "")
                        + (aovs != null ? " --aov " + aovs.stream().map(Aov::keyword).collect(java.util.stream.Collectors.joining(",")) : "");
                throw new UsageException(options.substring(1) + ": " + e.getMessage());
            }
            at = scene.frameSource();
        } else if (Renderer.SAMPLES_KEY.equals(e.key())) {
            if (spp != null) throw new UsageException("--spp " + spp + ": " + e.getMessage());
            at = scene.samplesSource();
        } else {
            return e;
        }
        return at == null ? e : new IllegalArgumentException(at + ": " + e.getMessage(), e);
    }

    private static void printStats(PrintStream out, double load, double warmup, double build, AcceleratorKind accel, RenderStats r, int threads) {
        if (warmup >= 0.0005) out.printf(Locale.ROOT, "load:    %.3f s (then %.3f s for the JIT warm-up to finish)%n", load, warmup);
        else out.printf(Locale.ROOT, "load:    %.3f s%n", load);
        out.printf(Locale.ROOT, "build:   %.3f s (%s)%n", build, accel.description());
        out.printf(Locale.ROOT, "render:  %.3f s (%d threads)%n", r.seconds(), threads);
        out.printf(Locale.ROOT, "rays:    %d camera, %d shadow, %d reflection, %d refraction%n",
                r.cameraRays(), r.shadowRays(), r.reflectionRays(), r.refractionRays());
        out.printf(Locale.ROOT, "speed:   %s Mrays/s%n", threeFigures(r.mraysPerSecond()));
        if (r.meanSamples() > 0) out.printf(Locale.ROOT, "samples: %.2f per pixel taken%n", r.meanSamples());
        if (r.traversal() != null) {
            // Per ray of each kind; secondary rays are the reflected and refracted ones together.
            String[] kinds = {"camera", "shadow", "secondary"};
            long[] rays = {r.cameraRays(), r.shadowRays(), r.reflectionRays() + r.refractionRays()};
            for (int k = 0; k < kinds.length; k++) {
                double n = Math.max(1, rays[k]);
                out.printf(Locale.ROOT, "traversal %s: %d rays, %.3f nodes/ray, %.3f leaves/ray, %.3f triangle tests/ray%n", kinds[k], rays[k],
                        r.traversal().nodes(k) / n, r.traversal().leaves(k) / n, r.traversal().triangleTests(k) / n);
            }
        }
        out.printf(Locale.ROOT, "heap:    %.1f MiB peak%n", HeapPeak.bytes() / 1048576.0);
        // The whole process, JVM included, as the peers' figures are taken: read after the render, so it covers it.
        PeakResident.bytes().ifPresent(b -> out.printf(Locale.ROOT, "memory:  %.1f MiB peak resident%n", b / 1048576.0));
    }

    /**
     * At least three significant figures, one decimal at the least: 12.3, 0.0412, 1234.5. A slow
     * render (a lazily refined surface) must not print 0.0.
     */
    static String threeFigures(double v) {
        if (!(v > 0) || v >= 10) return String.format(Locale.ROOT, "%.1f", v);
        int decimals = Math.min(12, 2 - (int) Math.floor(Math.log10(v)));
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }

    /** The scene file is missing: bad input, reported like the parser's errors. */
    static final class NoSuchFileException extends IOException {
        NoSuchFileException(Path p) { super(p + ": scene file not found"); }

        /** The scene path is not a regular file: {@code problem} as {@link InputFiles#problem} says it. */
        NoSuchFileException(Path p, String problem) { super(p + ": scene file " + problem); }
    }
}
