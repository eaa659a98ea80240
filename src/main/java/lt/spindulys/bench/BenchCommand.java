package lt.spindulys.bench;

import static lt.spindulys.bench.BenchTable.fmt;
import static lt.spindulys.bench.BenchTable.median;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import lt.spindulys.frontend.HeapPeak;
import lt.spindulys.frontend.Version;
import lt.spindulys.io.ObjReader;
import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.io.SceneParser;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.RenderStats;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions.Scheme;

/**
 * {@code render bench}: the project's fixed benchmark suite. Speed and memory targets live
 * here, not in timed tests. Every row warms the JVM up before it is timed and reports the median
 * of several runs; where a peer program is installed (OpenSubdiv's far_perf; Embree's pathtracer,
 * POV-Ray and Blender's Cycles for the rows with peer targets, see {@link PeerBench}), the same
 * input is run through it in the same session and the ratio is printed beside our figure. Inputs are read
 * from scenes/bench/ under the current folder (the repository root).
 */
public final class BenchCommand {
    public static final String USAGE = """
            usage: render bench [--only NAME] [--runs N] [--accel A] [--peers LIST] [--cell-timeout S] [--list]

              --only NAME   run only the row NAME, or the rows of the group NAME (see --list), or those of a
                            comma-separated list of names; the groups 'adaptive' (adaptive subdivision, long: each
                            cell is a new JVM) and 'viewer' (the viewer's frame rate) run only when asked for
              --runs N      timed runs per row after the warm-up (default 5); the median is reported
                            (adaptive rows: alternated pairs of new JVMs; Table 1 cells run once each)
              --cell-timeout S  stop an adaptive-row cell after S seconds (default 600) and report it as stopped
              --accel A     acceleration structure of the peer-scene rows: bvh (the scenes' default),
                            bvh-compact, bvh2, octree or bruteforce; to compare structures on the same scene
              --peers LIST  peer renderers run beside the rows torus-250k, torus-1m, knot-1m, torus-1m-close and path-torus, those of LIST
                            (comma-separated: embree, povray, cycles; default all three) that are on PATH, in --runs
                            alternated pairs each; 'none' runs none
              --list        list the rows and exit
            Run from the repository root: inputs are read from scenes/bench/; the torus-* and knot-* rows first
            write their meshes into scenes/bench/meshes/ when missing. See docs/performance.md.""";

    /**
     * One benchmark row: a name, what it measures, and how; rows with a group run only when
     * {@code --only} names the row or its group (they take too long for every run of the bench).
     */
    private record Row(String name, String section, String description, Action action, String group) {
        Row(String name, String section, String description, Action action) { this(name, section, description, action, null); }
        boolean selected(List<String> only) { return only == null ? group == null : only.contains(name) || group != null && only.contains(group); }
    }

    @FunctionalInterface
    private interface Action { void run(BenchCommand bench, PrintStream out) throws IOException; }

    /** The section of the views where a dense mesh fills the frame. */
    private static final String FILLING = "Peer scene, mesh-filling views";

    /** The group of the adaptive-subdivision rows. */
    static final String ADAPTIVE = "adaptive";
    /** The group of the viewer's row. */
    static final String VIEWER = "viewer";

    private static final List<Row> ROWS = List.of(
            new Row("refine-bishop", "Subdivision",
                    "catmark_bishop (968 quads, 224 creases) refined uniformly to level 6 (~4M quads) on one thread; beside far_perf -u",
                    (b, out) -> b.refinement(out, "refine-bishop", "catmark_bishop.obj", Scheme.CATMARK, 6)),
            new Row("refine-loop-bishop", "Subdivision",
                    "loop_bishop (catmark_bishop split into 1,804 triangles, 224 creases) refined uniformly with Loop's rules to level 5 "
                            + "(~1.8M triangles) on one thread; beside far_perf -u -loop",
                    (b, out) -> b.refinement(out, "refine-loop-bishop", "loop_bishop.obj", Scheme.LOOP, 5)),
            torusRow("1k"), torusRow("16k"), torusRow("250k"), torusRow("1m"),
            new Row("knot-1m", FILLING,
                    String.format(Locale.ROOT, "scenes/bench/knot-1m.dat: a tube of %,d triangles around a trefoil knot filling the frame, on the ground quad, "
                            + "1280x720, 1 spp, %d threads; in-process and cold process; beside the peers", BenchMeshes.KNOT_1M.triangles(), BenchCommand.THREADS),
                    (b, out) -> b.peerScene(out, BenchMeshes.KNOT_1M, "knot-1m", PeerBench.Targets.meshTracing(0.8))),
            new Row("torus-1m-close", FILLING,
                    String.format(Locale.ROOT, "scenes/bench/torus-1m-close.dat: the 1m torus close up, filling the frame, "
                            + "1280x720, 1 spp, %d threads; in-process and cold process; beside the peers", BenchCommand.THREADS),
                    (b, out) -> b.peerScene(out, BenchMeshes.size("1m"), "torus-1m-close", PeerBench.Targets.meshTracing(0.8))),
            new Row("soft-shadow", "Soft shadows",
                    String.format(Locale.ROOT, "scenes/bench/soft-shadow.dat: the 1k torus on the ground quad under a 3x3 rectangle light, "
                            + "1280x720, 16 spp with 1 light sample each, %d threads; beside POV-Ray's 4x4 jittered area_light "
                            + "(1 primary ray and 16 shadow rays per pixel; target: at least 2x its speed)", BenchCommand.THREADS),
                    (b, out) -> b.peerScene(out, BenchMeshes.size("1k"), "soft-shadow", PeerBench.Targets.softShadows())),
            new Row("soft-shadow-light16", "Soft shadows",
                    String.format(Locale.ROOT, "scenes/bench/soft-shadow-light16.dat: soft-shadow at 1 spp with 16 light samples, %d threads: "
                            + "the same rays per pixel as POV-Ray's 4x4 area_light (1 camera ray, 16 shadow rays)", BenchCommand.THREADS),
                    (b, out) -> b.peerScene(out, BenchMeshes.size("1k"), "soft-shadow-light16", PeerBench.Targets.softShadows())),
            new Row("soft-shadow-16k", "Soft shadows",
                    String.format(Locale.ROOT, "scenes/bench/soft-shadow-16k.dat: soft-shadow-light16 with the 16k torus (32,768 triangles), %d threads: "
                            + "1 camera ray and 16 shadow rays per pixel on both sides, beside POV-Ray's 4x4 area_light", BenchCommand.THREADS),
                    (b, out) -> b.peerScene(out, BenchMeshes.size("16k"), "soft-shadow-16k", PeerBench.Targets.softShadows())),
            new Row("path-torus", "Path tracing",
                    String.format(Locale.ROOT, "scenes/bench/path-torus.dat: the 1k torus on the ground quad path traced, 640x360, 16 spp, "
                            + "maxdepth 4, %d threads; beside Embree's pathtracer (--max-path-length 5) and Cycles (max_bounces 4) at equal "
                            + "spp: samples per second (targets: at least 0.8x Embree's, 3x Cycles'); beside Cycles also the mean squared "
                            + "error at equal time against its converged image (target: no higher)", BenchCommand.THREADS),
                    (b, out) -> b.pathScene(out, "path-torus")),
            new Row("csg-subdiv", "CSG",
                    "scenes/bench/csg-subdiv.dat: difference of two level-4 subdivision surfaces, 1280x720, 1 spp, 2 threads; "
                            + "beside csg-subdiv-plain.dat, the same two surfaces without CSG (target: at least half its speed)",
                    (b, out) -> b.csgScene(out)),
            new Row("motion-blur", "Motion blur",
                    "scenes/bench/motion-blur.dat: the figure-48 objects, 640x360, 16 spp, 2 threads, in one pass (each sample its own time) "
                            + "beside the thesis's method, 4 and 16 whole-frame time steps: equal samples; times and error against a reference",
                    (b, out) -> b.motionBlur(out)),
            new Row("adaptive-close", "Adaptive subdivision: the thesis's Table 1",
                    "the close scene (a 288-quad torus cage filling the frame, levels 6-7 at 1920x1080): projected, lazy and combined "
                            + "at 150x100, 300x200, 450x300 and 1920x1080; each cell a new JVM (-Xmx8192m, so that eager fits at full HD): time, peak and live heap",
                    (b, out) -> b.adaptive(out, a -> a.table1("close", AdaptiveBench.CLOSE_FRONT, AdaptiveBench.CLOSE_HEAP_MIB)), ADAPTIVE),
            new Row("adaptive-huge", "Adaptive subdivision: the thesis's Table 1",
                    "the huge scene (a 4,096-quad hills cage to the horizon, whose eager 1-pixel tessellation does not fit in 2 GiB): "
                            + "the same cells as adaptive-close, each in a new JVM with -Xmx2048m",
                    (b, out) -> b.adaptive(out, a -> a.table1("huge", AdaptiveBench.HUGE_VIEW, AdaptiveBench.CHILD_HEAP_MIB)), ADAPTIVE),
            new Row("adaptive-lazy", "Adaptive subdivision: lazy against eager",
                    "close scene, two views, 640x360: lazy (64 MiB cache) against projected at the same tessellation, alternated "
                            + "pairs of new JVMs (targets: at least 0.8x the speed, a fifth of the heap)",
                    (b, out) -> b.adaptive(out, AdaptiveBench::lazyVsEager), ADAPTIVE),
            new Row("adaptive-cache", "Adaptive subdivision: cache policy and size",
                    "close scene, front view, 640x360, lazy: the thesis's last two patches per thread, and a shared LRU cache of "
                            + "8, 64 and 512 MiB; hit rates",
                    (b, out) -> b.adaptive(out, AdaptiveBench::cache), ADAPTIVE),
            peerVariant("1k", "lazy", "the 1k cage as a lazy adaptive subdiv, target 1 px (beside Cycles' adaptive subdivision, dicing rate 1 px)"),
            peerVariant("1k", "combined", "the 1k cage as a combined adaptive subdiv, target 1 px (beside Cycles' adaptive subdivision)"),
            peerVariant("1k", "projected", "the 1k cage as a projected (eager) adaptive subdiv, target 1 px (beside Cycles' adaptive subdivision)"),
            new Row("torus-1k-close", "Peer scene, subdivision",
                    String.format(Locale.ROOT, "scenes/bench/torus-1k-close.dat: the 1k cage as a combined adaptive subdiv, target 1 px, seen from "
                            + "inside its ring so that the surface fills the frame, 1920x1080, 1 spp, %d threads; in-process and cold process "
                            + "(beside Cycles' adaptive subdivision, dicing rate 1 px, on the same view)", BenchCommand.THREADS),
                    (b, out) -> b.peerScene(out, BenchMeshes.size("1k"), "torus-1k-close", null), ADAPTIVE),
            new Row("adaptive-warm", "Adaptive subdivision: lazy against eager",
                    String.format(Locale.ROOT, "scenes/bench/torus-1k-lazy.dat against torus-1k-projected.dat (the same 1-pixel tessellation of the 1k cage, "
                            + "1280x720, %d threads), alternated in this JVM after warm-up, each frame loaded and built anew (target: lazy at least "
                            + "0.8x the eager speed)", BenchCommand.THREADS),
                    (b, out) -> b.warmLazyVsEager(out), ADAPTIVE),
            peerVariant("1k", "level2", "the 1k cage as a uniform subdiv at level 2 (beside Embree's subdivision at edge level 4)"),
            peerVariant("1k", "level2-lazy", "the 1k cage as a lazy subdiv at fixed level 2 (beside Embree's subdivision at edge level 4)"),
            new Row("viewer", "Viewer",
                    "the viewer's rasterizer: offscreen 1280x720 frames of a 102,400-quad torus (a 400-quad cage at level 4) orbited, "
                            + BenchCommand.THREADS + " threads; median frames/s smoothed, polyhedron and smoothed with the cage (target: 30)",
                    (b, out) -> ViewerBench.run(out, b.runs, BenchCommand.THREADS), VIEWER));

    /** A peer-scene row whose torus is a subdivision surface: scenes/bench/torus-SIZE-VARIANT.dat. */
    private static Row peerVariant(String size, String variant, String what) {
        BenchMeshes.Size s = BenchMeshes.size(size);
        String name = "torus-" + size + "-" + variant;
        return new Row(name, "Peer scene, subdivision",
                String.format(Locale.ROOT, "scenes/bench/%s.dat: %s, 1280x720, 1 spp, %d threads; in-process and cold process", name, what, THREADS),
                (b, out) -> b.peerScene(out, s, name, null), ADAPTIVE);
    }

    private static Row torusRow(String size) {
        BenchMeshes.Size s = BenchMeshes.size(size);
        // The 1m and 250k tori are the sizes with targets beside the peers.
        PeerBench.Targets targets = size.equals("1m") || size.equals("250k") ? PeerBench.Targets.meshTracing(1.0) : null;
        return new Row("torus-" + size, "Peer scene",
                String.format(Locale.ROOT, "scenes/bench/torus-%s.dat: torus of %,d triangles on a ground quad, 1280x720, 1 spp, %d threads; in-process and cold process%s",
                        size, s.triangles(), THREADS, targets != null ? "; beside the peers" : ""),
                (b, out) -> b.peerScene(out, s, "torus-" + size, targets));
    }

    /** Render threads of the peer-scene rows: the peers' protocol uses two everywhere. */
    static final int THREADS = 2;
    /** In-process renders before the timed ones, so the JIT has compiled the hot paths. */
    private static final int WARMUPS = 2;

    /** The rows or groups --only names, or null for every row without a group. */
    private List<String> only;
    private int runs = 5;
    /** Structure the peer-scene rows use instead of their scenes' own; null keeps the scenes'. */
    private AcceleratorKind accel;
    private boolean list;
    /** The peer renderers the rows with peer targets run beside ours (when on PATH). */
    private java.util.Set<PeerBench.Peer> peers = java.util.EnumSet.allOf(PeerBench.Peer.class);
    /** Seconds an adaptive-row cell (a child JVM) may take before it is stopped. */
    private int cellTimeout = 600;
    private final Path benchDir = Path.of("scenes", "bench");
    /** The main class of the command line, which the cold-process rows and the adaptive cells start in new JVMs. */
    private final String commandLine;

    /**
     * The bench as {@code args} ask.
     *
     * @param args the options after {@code render bench}
     * @param commandLine the main class of {@code render}, started in new JVMs to time whole processes
     * @throws BenchUsageException when an option is unknown or its value is bad
     */
    public BenchCommand(String[] args, Class<?> commandLine) throws BenchUsageException {
        this.commandLine = commandLine.getName();
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--only" -> {
                    if (++i >= args.length) throw new BenchUsageException("option --only needs a value");
                    only = List.of(args[i].split(",", -1));
                    for (String o : only) {
                        if (ROWS.stream().noneMatch(r -> r.name().equals(o) || o.equals(r.group()))) {
                            throw new BenchUsageException("unknown bench row '" + o + "' (rows: " + String.join(", ", ROWS.stream().map(Row::name).toList())
                                    + "; groups: " + ADAPTIVE + ", " + VIEWER + ")");
                        }
                    }
                }
                case "--runs" -> {
                    if (++i >= args.length) throw new BenchUsageException("option --runs needs a value");
                    try {
                        runs = Integer.parseInt(args[i]);
                    } catch (NumberFormatException e) {
                        throw new BenchUsageException("--runs expects a whole number, found '" + args[i] + "'");
                    }
                    if (runs < 1 || runs > 100) throw new BenchUsageException("--runs must be between 1 and 100, found " + runs);
                }
                case "--accel" -> {
                    if (++i >= args.length) throw new BenchUsageException("option --accel needs a value");
                    try {
                        accel = AcceleratorKind.fromKeyword(args[i]);
                    } catch (IllegalArgumentException e) {
                        throw new BenchUsageException(e.getMessage());
                    }
                }
                case "--cell-timeout" -> {
                    if (++i >= args.length) throw new BenchUsageException("option --cell-timeout needs a value");
                    try {
                        cellTimeout = Integer.parseInt(args[i]);
                    } catch (NumberFormatException e) {
                        throw new BenchUsageException("--cell-timeout expects a whole number of seconds, found '" + args[i] + "'");
                    }
                    if (cellTimeout < 1 || cellTimeout > 86400) throw new BenchUsageException("--cell-timeout must be between 1 and 86400 seconds, found " + cellTimeout);
                }
                case "--peers" -> {
                    if (++i >= args.length) throw new BenchUsageException("option --peers needs a value");
                    peers = PeerBench.Peer.parse(args[i]);
                }
                case "--list" -> list = true;
                default -> throw new BenchUsageException("unknown bench option '" + args[i] + "' (see render bench --help)");
            }
        }
    }

    /** Runs the rows asked for (or lists them), printing to {@code out}; returns the exit status. */
    public int run(PrintStream out) throws IOException {
        if (list) {
            for (Row r : ROWS) out.printf("%-22s %s%s%n", r.name(), r.group() != null ? "[" + r.group() + "] " : "", r.description());
            return 0;
        }
        if (!Files.isDirectory(benchDir)) {
            throw new IOException("bench inputs not found: " + benchDir.toAbsolutePath() + " (run render bench from the repository root)");
        }
        Runtime rt = Runtime.getRuntime();
        out.printf(Locale.ROOT, "Spindulys %s benchmark: Java %s, %d cores, max heap %.1f GiB, %d timed runs per row (median)%n",
                Version.text(), System.getProperty("java.version"), rt.availableProcessors(), rt.maxMemory() / (double) (1L << 30), runs);
        out.printf(Locale.ROOT, "Structure of the peer-scene rows: %s%n", (accel != null ? accel : AcceleratorKind.DEFAULT).description());
        String section = null;
        for (Row r : ROWS) {
            if (!r.selected(only)) continue;
            if (!r.section().equals(section)) {
                section = r.section();
                out.println();
                out.println(section);
            }
            r.action().run(this, out);
        }
        if (peerTable != null) {
            out.println();
            peerTable.print(out);
            out.println("  load s: parse the scene and read the OBJs; build s: freeze the scene (each mesh's BVH, the mesh put in its");
            out.println("  leaf order, and the top-level BVH over the objects); render s: trace the frame; all medians");
            out.printf(Locale.ROOT, "  after %d warm-up renders in this JVM. Mrays/s: rays of all kinds / render s. peak heap: the heap pools'%n", WARMUPS);
            out.println("  peak use during one load+build+render. bytes/tri: the meshes' arrays and BVHs / their triangles.");
            out.println("  cold s: wall clock of a whole new process `java [this JVM's options] -jar render.jar SCENE -o x.tga");
            out.println("  --quiet --stats --threads 2`");
            out.println("  (median; one untimed run first so the files are in the page cache); cold peak RSS: that process's peak");
            out.println("  resident memory from its --stats (Linux; '-' elsewhere), the figure to set beside a peer's.");
        }
        return 0;
    }

    // ---- the peer scene ----

    private BenchTable peerTable;

    /** The adaptive rows, in a scratch folder that is removed afterwards. */
    private void adaptive(PrintStream out, AdaptiveAction action) throws IOException {
        AdaptiveBench a = new AdaptiveBench(runs, cellTimeout, out, commandLine);
        try {
            action.run(a);
        } finally {
            a.close();
        }
    }

    @FunctionalInterface
    private interface AdaptiveAction { void run(AdaptiveBench a) throws IOException; }

    /**
     * The scene scenes/bench/NAME.dat, whose mesh is {@code size} on the ground quad (the peer
     * view of the torus, a subdivision variant of its cage, or a mesh-filling view); with
     * {@code targets}, the peers run on the same view afterwards.
     */
    private void peerScene(PrintStream out, BenchMeshes.Shape size, String name, PeerBench.Targets targets) throws IOException {
        Path meshes = benchDir.resolve("meshes");
        long g0 = System.nanoTime();
        BenchMeshes.ensure(meshes, size);
        double gen = (System.nanoTime() - g0) / 1e9;
        if (gen > 0.05) out.printf(Locale.ROOT, "  generated %s in %.1f s%n", meshes.resolve(size.file()), gen);
        Path scene = benchDir.resolve(name + ".dat");
        if (!Files.isRegularFile(scene)) throw new IOException("bench scene not found: " + scene.toAbsolutePath());

        for (int i = 0; i < WARMUPS; i++) renderOnce(scene, accel);
        double[] load = new double[runs], build = new double[runs], render = new double[runs], mrays = new double[runs];
        double[] peak = new double[runs];
        Measured last = null;
        for (int i = 0; i < runs; i++) {
            last = renderOnce(scene, accel);
            load[i] = last.load;
            build[i] = last.build;
            render[i] = last.stats.seconds();
            mrays[i] = last.stats.mraysPerSecond();
            peak[i] = last.peakHeap;
        }
        Cold coldRuns = coldRuns(scene, runs, accel);
        double cold = coldRuns.wall();
        if (peerTable == null) {
            peerTable = new BenchTable("row", "triangles", "load s", "build s", "render s", "camera rays", "shadow rays",
                    "refl. rays", "refr. rays", "Mrays/s", "peak heap MiB", "bytes/tri", "cold s", "cold peak RSS MiB");
        }
        String label = name + (accel != null ? " " + accel.keyword() : "");
        peerTable.add(label, String.format(Locale.ROOT, "%,d", last.triangles), fmt(median(load), 3),
                fmt(median(build), 3), fmt(median(render), 3), String.format(Locale.ROOT, "%,d", last.stats.cameraRays()),
                String.format(Locale.ROOT, "%,d", last.stats.shadowRays()), String.format(Locale.ROOT, "%,d", last.stats.reflectionRays()),
                String.format(Locale.ROOT, "%,d", last.stats.refractionRays()), fmt(median(mrays), 2),
                fmt(median(peak) / 1048576.0, 0), fmt(last.meshBytes / (double) last.triangles, 1),
                Double.isNaN(cold) ? "failed" : fmt(cold, 3), fmt(coldRuns.peakRssMiB(), 0));
        out.printf(Locale.ROOT, "  %s: load %.3f s, build %.3f s, render %.3f s (%.2f Mrays/s), cold %.3f s, cold peak RSS %s MiB%n", label,
                median(load), median(build), median(render), median(mrays), cold, fmt(coldRuns.peakRssMiB(), 0));
        for (String line : last.subdivision) out.println("    " + line);
        if (targets != null && !peers.isEmpty()) {
            List<Path> files = List.of(meshes.resolve(size.file()).toAbsolutePath(), meshes.resolve(BenchMeshes.GROUND_FILE).toAbsolutePath());
            SceneBuilder parsed = SceneParser.parse(scene);
            // A soft-shadow view goes to POV-Ray alone: its area_light is the peer of our area light here.
            boolean soft = !parsed.areaLights().isEmpty();
            PeerView view = soft ? PeerView.ofArea(parsed, files) : PeerView.of(parsed, files);
            java.util.Set<PeerBench.Peer> which = peers;
            if (soft) {
                which = java.util.EnumSet.noneOf(PeerBench.Peer.class);
                if (peers.contains(PeerBench.Peer.POVRAY)) which.add(PeerBench.Peer.POVRAY);
            }
            PeerBench.run(out, label, view, which, runs, THREADS, targets, new PeerBench.Ours() {
                @Override public Measured render() throws IOException { return renderOnce(scene, accel); }
                @Override public double cold() throws IOException { return coldOnce(scene, accel).wall(); }
            });
            if (soft && which.contains(PeerBench.Peer.POVRAY) && ExternalTimer.onPath(PeerBench.Peer.POVRAY.program) != null) {
                int spp = parsed.settings().samplesPerPixel();
                out.printf("  %s: equal shadow rays (%d per pixel; POV-Ray: a %dx%d jittered area_light, adaptive 0); camera rays per%n",
                        label, view.area().grid() * view.area().grid(), view.area().grid(), view.area().grid());
                out.println(spp == 1 ? "  pixel equal too: one, at the pixel centre on both sides (no anti-aliasing)."
                        : "  pixel not equal: we trace " + spp + " at stratified spots, POV-Ray one at the pixel centre (no anti-aliasing).");
            }
        }
    }

    // ---- path tracing ----

    /**
     * The path-traced scene scenes/bench/NAME.dat (the 1k torus on the ground quad): our medians
     * in this JVM, then Embree and Cycles beside it ({@link PathBench}).
     */
    private void pathScene(PrintStream out, String name) throws IOException {
        Path meshes = benchDir.resolve("meshes");
        BenchMeshes.ensure(meshes, BenchMeshes.size("1k"));
        Path scene = benchDir.resolve(name + ".dat");
        if (!Files.isRegularFile(scene)) throw new IOException("bench scene not found: " + scene.toAbsolutePath());
        for (int i = 0; i < WARMUPS; i++) renderOnce(scene, accel);
        double[] render = new double[runs];
        Measured last = null;
        for (int i = 0; i < runs; i++) {
            last = renderOnce(scene, accel);
            render[i] = last.stats.seconds();
        }
        SceneBuilder parsed = SceneParser.parse(scene);
        RenderSettings s = parsed.settings();
        long samples = (long) s.width() * s.height() * s.samplesPerPixel();
        RenderStats st = last.stats;
        out.printf(Locale.ROOT, "  %s: render %.3f s, %.2f Msamples/s, %.2f Mrays/s (per sample: %.2f rays: %.2f camera, %.2f shadow, %.2f bounce)%n",
                name, median(render), samples / median(render) / 1e6, st.totalRays() / median(render) / 1e6, st.totalRays() / (double) samples,
                st.cameraRays() / (double) samples, st.shadowRays() / (double) samples, st.reflectionRays() / (double) samples);
        if (peers.isEmpty()) return;
        List<Path> files = List.of(meshes.resolve(BenchMeshes.size("1k").file()).toAbsolutePath(), meshes.resolve(BenchMeshes.GROUND_FILE).toAbsolutePath());
        PeerView view = PeerView.ofPath(parsed, files);
        PathBench.run(out, name, view, s.samplesPerPixel(), s.maxDepth(), peers, runs, THREADS,
                (spp, seed, w, h) -> renderOnce(scene, accel, r -> r.toBuilder().samplesPerPixel(spp).seed(seed).size(w, h).build()));
    }

    // ---- adaptive subdivision in a warm JVM ----

    /** Least speed of the lazy method against the eager one, re-rendering in a warm JVM. */
    static final double LAZY_MIN_SPEED = 0.8;

    /**
     * The lazy method (64 MiB cache) against the eager one at the same tessellation, both in this
     * JVM: torus-1k-lazy and torus-1k-projected timed alternately after warm-up (so drift on a
     * shared machine hits both alike), each frame loaded, built and rendered from its file, so the
     * lazy one refines its patches during every render and the eager one during every build. The
     * speed ratios of render alone (judged) and of build + render, with each one's peak heap.
     */
    private void warmLazyVsEager(PrintStream out) throws IOException {
        BenchMeshes.ensure(benchDir.resolve("meshes"), BenchMeshes.size("1k"));
        Path lazy = benchDir.resolve("torus-1k-lazy.dat"), eager = benchDir.resolve("torus-1k-projected.dat");
        for (Path p : List.of(lazy, eager)) {
            if (!Files.isRegularFile(p)) throw new IOException("bench scene not found: " + p.toAbsolutePath());
        }
        for (int i = 0; i < WARMUPS; i++) {
            renderOnce(lazy, accel);
            renderOnce(eager, accel);
        }
        double[] rl = new double[runs], re = new double[runs], tl = new double[runs], te = new double[runs], hl = new double[runs], he = new double[runs];
        Measured l = null, e = null;
        for (int i = 0; i < runs; i++) {
            // Pairs alternate which goes first, as the peer rows' pairs do.
            if (i % 2 == 0) {
                l = renderOnce(lazy, accel);
                e = renderOnce(eager, accel);
            } else {
                e = renderOnce(eager, accel);
                l = renderOnce(lazy, accel);
            }
            rl[i] = l.stats.seconds();
            re[i] = e.stats.seconds();
            tl[i] = l.build + l.stats.seconds();
            te[i] = e.build + e.stats.seconds();
            hl[i] = l.peakHeap / 1048576.0;
            he[i] = e.peakHeap / 1048576.0;
        }
        BenchTable t = new BenchTable("scene", "build s", "render s", "build + render s", "Mrays/s", "peak heap MiB");
        t.add("torus-1k-projected", fmt(median(te) - median(re), 3), fmt(median(re), 3), fmt(median(te), 3),
                fmt(e.stats.totalRays() / median(re) / 1e6, 2), fmt(median(he), 0));
        t.add("torus-1k-lazy", fmt(median(tl) - median(rl), 3), fmt(median(rl), 3), fmt(median(tl), 3),
                fmt(l.stats.totalRays() / median(rl) / 1e6, 2), fmt(median(hl), 0));
        t.print(out);
        for (String line : e.subdivision) out.println("    projected: " + line);
        for (String line : l.subdivision) out.println("    lazy: " + line);
        double render = PeerBench.medianRatio(re, rl), whole = PeerBench.medianRatio(te, tl);
        out.printf(Locale.ROOT, "  adaptive-warm: lazy at %.2fx the eager speed rendering (target: at least %.1fx) %s; %.2fx over build + render%n",
                render, LAZY_MIN_SPEED, render >= LAZY_MIN_SPEED ? "met" : "NOT met", whole);
        out.println("  medians of alternated frames in this JVM; speed = eager s / lazy s, the median of the pairs' ratios; build s: the");
        out.println("  medians' difference. The eager method refines while building, the lazy one while rendering (64 MiB cache).");
    }

    // ---- CSG ----

    /**
     * The CSG scene and its plain twin, timed alternately (so drift on a shared machine hits both
     * alike), with the throughput ratio (target: at least half the plain scene's).
     */
    private void csgScene(PrintStream out) throws IOException {
        Path csg = benchDir.resolve("csg-subdiv.dat"), plain = benchDir.resolve("csg-subdiv-plain.dat");
        for (Path p : List.of(csg, plain)) {
            if (!Files.isRegularFile(p)) throw new IOException("bench scene not found: " + p.toAbsolutePath());
        }
        for (int i = 0; i < WARMUPS; i++) {
            renderOnce(csg, accel);
            renderOnce(plain, accel);
        }
        double[] rc = new double[runs], rp = new double[runs], mc = new double[runs], mp = new double[runs];
        Measured c = null, q = null;
        for (int i = 0; i < runs; i++) {
            c = renderOnce(csg, accel);
            q = renderOnce(plain, accel);
            rc[i] = c.stats.seconds();
            mc[i] = c.stats.mraysPerSecond();
            rp[i] = q.stats.seconds();
            mp[i] = q.stats.mraysPerSecond();
        }
        BenchTable t = new BenchTable("scene", "render s", "camera rays", "shadow rays", "Mrays/s");
        t.add("csg-subdiv", fmt(median(rc), 3), String.format(Locale.ROOT, "%,d", c.stats.cameraRays()),
                String.format(Locale.ROOT, "%,d", c.stats.shadowRays()), fmt(median(mc), 2));
        t.add("csg-subdiv-plain", fmt(median(rp), 3), String.format(Locale.ROOT, "%,d", q.stats.cameraRays()),
                String.format(Locale.ROOT, "%,d", q.stats.shadowRays()), fmt(median(mp), 2));
        t.print(out);
        double ratio = median(mc) / median(mp);
        out.printf(Locale.ROOT, "  csg-subdiv: %.2fx the throughput of the same surfaces without CSG (target: at least 0.5x)%n", ratio);
    }

    // ---- motion blur ----

    /** Time steps of the motion-blur row: 1 is the single pass; the others the thesis's method, dividing the scene's 16 samples. */
    static final int[] TIME_STEPS = {1, 4, 16};

    /**
     * The motion-blur scene rendered in one pass and in whole-frame time steps at equal samples
     * per pixel, timed alternately, with the ratio of their render times and each image's
     * distance from a high-sample one-pass reference.
     */
    private void motionBlur(PrintStream out) throws IOException {
        Path scene = benchDir.resolve("motion-blur.dat");
        if (!Files.isRegularFile(scene)) throw new IOException("bench scene not found: " + scene.toAbsolutePath());
        int n = TIME_STEPS.length;
        for (int i = 0; i < WARMUPS; i++) for (int steps : TIME_STEPS) renderOnce(scene, accel, s -> s.toBuilder().timeSteps(steps).build());
        double[][] seconds = new double[n][runs], cpu = new double[n][runs];
        Measured[] last = new Measured[n];
        for (int i = 0; i < runs; i++) {
            for (int k = 0; k < n; k++) {
                int steps = TIME_STEPS[k];
                last[k] = renderOnce(scene, accel, s -> s.toBuilder().timeSteps(steps).build());
                seconds[k][i] = last[k].stats.seconds();
                cpu[k][i] = last[k].cpuSeconds;
            }
        }
        // What the samples buy: the distance of each image from a one-pass reference at REFERENCE_SPP.
        Measured ref = renderOnce(scene, accel, s -> s.toBuilder().timeSteps(1).samplesPerPixel(REFERENCE_SPP).build());
        BenchTable t = new BenchTable("method", "render s", "vs one pass", "CPU s", "vs one pass", "camera rays", "shadow rays", "refl. rays", "Mrays/s", "RMS error");
        for (int k = 0; k < n; k++) {
            RenderStats st = last[k].stats;
            t.add(TIME_STEPS[k] == 1 ? "one pass" : TIME_STEPS[k] + " time steps", fmt(median(seconds[k]), 3),
                    fmt(median(seconds[k]) / median(seconds[0]), 2) + "x", fmt(median(cpu[k]), 3), fmt(median(cpu[k]) / median(cpu[0]), 2) + "x",
                    String.format(Locale.ROOT, "%,d", st.cameraRays()),
                    String.format(Locale.ROOT, "%,d", st.shadowRays()), String.format(Locale.ROOT, "%,d", st.reflectionRays()),
                    fmt(st.totalRays() / median(seconds[k]) / 1e6, 2), fmt(rms(last[k].image, ref.image), 4));
        }
        t.print(out);
        out.printf(Locale.ROOT, "  motion-blur: equal samples per pixel (the scene's 16; a time step renders 16 / steps of them), medians of%n");
        out.printf(Locale.ROOT, "  alternated runs. CPU s: process CPU time during the render (steadier than wall time on a shared machine).%n");
        out.printf(Locale.ROOT, "  RMS error: linear RGB against a one-pass render at %d spp. The single pass is faster where a ratio exceeds 1.00x.%n",
                REFERENCE_SPP);
    }

    /** Samples per pixel of the motion-blur row's reference image. */
    static final int REFERENCE_SPP = 256;

    /**
     * CPU time of the whole process so far (render threads, and the JIT and collector), or 0
     * where the JVM does not report it. Unlike wall time it barely changes when other processes
     * share the cores.
     */
    private static long processCpuNanos() {
        return java.lang.management.ManagementFactory.getOperatingSystemMXBean() instanceof com.sun.management.OperatingSystemMXBean os
                ? os.getProcessCpuTime() : 0;
    }

    /** Root mean square difference of two images' linear values. */
    private static double rms(lt.spindulys.image.FrameBuffer x, lt.spindulys.image.FrameBuffer y) {
        double[] a = x.data(), b = y.data();
        double sum = 0;
        for (int i = 0; i < a.length; i++) sum += (a[i] - b[i]) * (a[i] - b[i]);
        return Math.sqrt(sum / a.length);
    }

    /** One timed load, build and render of a scene file, and what it used. */
    record Measured(double load, double build, RenderStats stats, long peakHeap, long triangles, long meshBytes,
                            lt.spindulys.image.FrameBuffer image, double cpuSeconds, List<String> subdivision) {}

    private static Measured renderOnce(Path file, AcceleratorKind accel) throws IOException {
        return renderOnce(file, accel, s -> s);
    }

    /** {@link #renderOnce(Path, AcceleratorKind)} with the scene's settings changed by {@code settings}. */
    static Measured renderOnce(Path file, AcceleratorKind accel, java.util.function.UnaryOperator<RenderSettings> settings) throws IOException {
        System.gc();
        HeapPeak.reset();
        long t0 = System.nanoTime();
        SceneBuilder builder = SceneParser.parse(file);
        if (accel != null) builder.settings(builder.settings().toBuilder().accelerator(accel).build());
        builder.settings(settings.apply(builder.settings()));
        long t1 = System.nanoTime();
        Scene scene = builder.build();
        long t2 = System.nanoTime();
        long cpu0 = processCpuNanos();
        lt.spindulys.render.RenderResult result;
        try {
            result = Renderer.render(scene, THREADS, ProgressListener.NONE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        long cpu1 = processCpuNanos();
        long peak = HeapPeak.bytes();
        long triangles = 0, bytes = 0;
        for (GObject o : scene.objects()) {
            if (o instanceof TriangleMesh m && !m.isInstance()) { // an instance shares its original's arrays
                triangles += m.triangleCount();
                bytes += m.memoryBytes();
            }
        }
        return new Measured((t1 - t0) / 1e9, (t2 - t1) / 1e9, result.stats(), peak, triangles, bytes, result.frame(), (cpu1 - cpu0) / 1e9,
                result.subdivisionStatistics());
    }

    /**
     * One whole new process or the median of several: wall seconds (NaN if one failed) and the
     * process's peak resident memory from its {@code --stats} (NaN where the platform gives none).
     */
    record Cold(double wall, double peakRssMiB) {}

    private static final java.util.regex.Pattern RSS_LINE = java.util.regex.Pattern.compile("(?m)^memory:\\s+([0-9.]+) MiB peak resident");

    /** Median of {@code runs} whole new processes after one more that is not counted (the file cache warm). */
    private Cold coldRuns(Path scene, int runs, AcceleratorKind accel) throws IOException {
        double[] t = new double[runs], rss = new double[runs];
        for (int i = -1; i < runs; i++) {
            Cold c = coldOnce(scene, accel);
            if (Double.isNaN(c.wall())) return c;
            if (i >= 0) {
                t[i] = c.wall();
                rss[i] = c.peakRssMiB();
            }
        }
        return new Cold(median(t), median(rss));
    }

    /**
     * One whole new process rendering {@code scene} with this program's own classes, with
     * {@code --stats} for its peak resident memory (a few lines of output, not a cost to see).
     */
    private Cold coldOnce(Path scene, AcceleratorKind accel) throws IOException {
        Cold failed = new Cold(Double.NaN, Double.NaN);
        String javaExe = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        String cp;
        try {
            cp = Path.of(BenchCommand.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (java.net.URISyntaxException e) {
            return failed;
        }
        Path image = Files.createTempFile("spindulys-bench", ".tga"), log = Files.createTempFile("spindulys-bench", ".out");
        try {
            List<String> cmd = new java.util.ArrayList<>(List.of(javaExe));
            // The new process gets this one's JVM options (those ./render passes: the vector
            // module, the collector), so it measures what a render from the launcher does.
            cmd.addAll(java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments());
            cmd.addAll(List.of("-cp", cp, commandLine, scene.toString(), "-o", image.toString(),
                    "--quiet", "--stats", "--threads", Integer.toString(THREADS)));
            if (accel != null) cmd.addAll(List.of("--accel", accel.keyword()));
            long t0 = System.nanoTime();
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
            try {
                if (!p.waitFor(10, java.util.concurrent.TimeUnit.MINUTES) || p.exitValue() != 0) {
                    p.destroyForcibly();
                    return failed;
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
                Thread.currentThread().interrupt();
                return failed;
            }
            double wall = (System.nanoTime() - t0) / 1e9;
            java.util.regex.Matcher m = RSS_LINE.matcher(Files.readString(log, java.nio.charset.StandardCharsets.UTF_8));
            return new Cold(wall, m.find() ? Double.parseDouble(m.group(1)) : Double.NaN);
        } finally {
            Files.deleteIfExists(image);
            Files.deleteIfExists(log);
        }
    }

    // ---- subdivision ----

    /**
     * A refinement row: {@code file} read as a control mesh, given {@code scheme} (whatever its tags
     * say), refined uniformly to {@code level} on one thread, beside far_perf on the same file with
     * the same scheme and level.
     */
    private void refinement(PrintStream out, String name, String file, Scheme scheme, int level) throws IOException {
        Path obj = benchDir.resolve(file);
        SubdivInput input = ObjReader.readSubdiv(obj);
        ControlMesh mesh = input.withOptions(input.options().withScheme(scheme)).toControlMesh();
        // Warm-up: compile the refinement code paths before timing.
        for (int i = 0; i < 3; i++) Subdivision.refine(mesh, level - 1);
        double[] seconds = new double[runs];
        RefinedMesh refined = null;
        for (int i = 0; i < runs; i++) {
            refined = null;
            System.gc();
            long t0 = System.nanoTime();
            refined = Subdivision.refine(mesh, level);
            seconds[i] = (System.nanoTime() - t0) / 1e9;
        }
        double t = median(seconds);
        long faces = refined.faceCount();
        long t1 = System.nanoTime();
        refined.limitNormals();
        double normalSeconds = (System.nanoTime() - t1) / 1e9;
        double bytesPerFace = refined.memoryBytes() / (double) faces;
        double far = ExternalTimer.farPerfRefineSeconds(obj, scheme, level, Math.min(runs, 3));

        // Loop splits triangles into triangles; Catmull-Clark and bilinear make quads.
        String face = scheme == Scheme.LOOP ? "triangle" : "quad";
        String faceShort = scheme == Scheme.LOOP ? "tris" : "quads";
        BenchTable table = new BenchTable("row", "control faces", "level", face + "s", "refine s", "M" + faceShort + "/s", "limit normals s",
                "bytes/" + face, "far_perf s", "speed vs far_perf");
        table.add(name, Integer.toString(mesh.faceCount()), Integer.toString(level),
                String.format(Locale.ROOT, "%,d", faces), fmt(t, 3), fmt(faces / t / 1e6, 2), fmt(normalSeconds, 3), fmt(bytesPerFace, 1),
                Double.isNaN(far) ? "not installed" : fmt(far, 3),
                Double.isNaN(far) ? "-" : fmt(far / t, 2) + "x");
        table.print(out);
        out.println("  refine s: positions and topology of every level up to the last (one thread); far_perf s: OpenSubdiv's");
        out.printf(Locale.ROOT, "  TopologyRefiner::Refine alone (far_perf -u -%s, topology only, no positions), so the ratio is conservative%n", scheme.keyword());
        out.println("  for us; speed vs far_perf = far_perf s / refine s (above 1: Spindulys is faster).");
        out.printf(Locale.ROOT, "  bytes/%s: the refined level's topology, positions and limit normals, divided by its %ss.%n", face, face);
    }
}
