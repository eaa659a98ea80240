package lt.spindulys.bench;

import static lt.spindulys.bench.BenchTable.fmt;
import static lt.spindulys.bench.BenchTable.median;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import lt.spindulys.io.SceneParser;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.subdiv.PatchRefiner;

/**
 * The adaptive-subdivision rows of {@code render bench}: the thesis's Table 1 (the
 * projected, lazy and combined methods side by side at four image sizes on two scenes), the lazy
 * method against the eager one at the same tessellation, and the lazy cache's policy and size.
 *
 * <p>Every cell is a whole new JVM with a 2 GiB heap running the ordinary command line
 * ({@code render SCENE --stats}), so its peak heap is its own and not what an earlier cell left
 * behind, and "does not fit" is what a user with that heap would see. Two heap figures are read:
 * the heap pools' peak (what {@code --stats} prints: everything the collector let accumulate,
 * garbage included) and the largest heap left live after a collection (from the child's GC log:
 * the retained data, the fairer figure for comparing methods). A third, the process's peak
 * resident memory ({@code --stats}' memory line, Linux only), is what the peers' figures compare. The cages are generated here, in a
 * scratch folder, from fixed formulas, so the rows do not depend on any scene file.
 */
final class AdaptiveBench {
    /** The thesis's image sizes (Table 1) and full HD. */
    static final int[][] TABLE_SIZES = {{150, 100}, {300, 200}, {450, 300}, {1920, 1080}};
    /** Heap of the child JVMs: 2 GiB, in which the huge scene's eager tessellation does not fit. */
    static final int CHILD_HEAP_MIB = 2048;
    /**
     * Heap of the close scene's Table 1 cells: its eager tessellation at 1920x1080 (levels 7 and 8,
     * 9.3 M quads) needs about 2.6 GiB live and an eager budget (a quarter of the heap) of 1.9 GiB,
     * so with 2 GiB it too would become combined; with 8 GiB every method fits at every size.
     */
    static final int CLOSE_HEAP_MIB = 8192;
    /** Image size of the lazy-against-eager and cache rows. */
    static final int PAIR_WIDTH = 640, PAIR_HEIGHT = 360;
    /** Cache sizes of the cache row, MiB. */
    static final int[] CACHE_MIB = {8, 64, 512};

    /** A camera: where it is, where it looks, its vertical field of view. */
    record View(String name, String camera) {}

    /** The close scene's two views: the torus filling the frame, and a grazing look along its tube. */
    static final View CLOSE_FRONT = new View("front", "eye 0 1.3 3.3  lookat 0 -0.15 0  up 0 1 0  fov 45");
    static final View CLOSE_GRAZING = new View("grazing", "eye 1.75 0.45 1.35  lookat -0.6 0 -0.35  up 0 1 0  fov 55");
    /** The huge scene's view: a hilly plain from just above it, out to its far edge. */
    static final View HUGE_VIEW = new View("low", "eye 0 1.6 15.5  lookat 0 0 2  up 0 1 0  fov 55");

    /** One child run: what was asked. */
    record Spec(String scene, View view, String method, int width, int height, int cacheMiB, boolean lastTwo, int heapMiB) {
        Spec(String scene, View view, String method, int width, int height, int cacheMiB, boolean lastTwo) {
            this(scene, view, method, width, height, cacheMiB, lastTwo, CHILD_HEAP_MIB);
        }

        String label() {
            return String.format(Locale.ROOT, "%s/%s %s %dx%d%s%s -Xmx%dm", scene, view.name(), method, width, height,
                    cacheMiB > 0 ? " cache " + cacheMiB + " MiB" : "", lastTwo ? " last-two" : "", heapMiB);
        }
    }

    /** One child run: what came out. {@code failure} is null on success. */
    record Cell(Spec spec, String failure, double wall, double load, double build, double render, long rays,
                double peakHeapMiB, double liveHeapMiB, double peakRssMiB, String subdivLine, boolean becameCombined,
                long hits, long misses, long evictions, String cachePeak) {
        double hitRate() { return hits + misses == 0 ? Double.NaN : hits / (double) (hits + misses); }
    }

    private final Path dir;
    private final int runs;
    private final int timeoutSeconds;
    private final PrintStream out;
    /** The main class of the command line each cell runs. */
    private final String commandLine;

    AdaptiveBench(int runs, int timeoutSeconds, PrintStream out, String commandLine) throws IOException {
        this.commandLine = commandLine;
        this.runs = runs;
        this.timeoutSeconds = timeoutSeconds;
        this.out = out;
        this.dir = Files.createTempDirectory("spindulys-bench-adaptive");
        try (BufferedWriter w = Files.newBufferedWriter(dir.resolve("close.obj"), StandardCharsets.US_ASCII)) {
            writeTorusCage(w, CLOSE_RING, CLOSE_TUBE);
        }
        try (BufferedWriter w = Files.newBufferedWriter(dir.resolve("huge.obj"), StandardCharsets.US_ASCII)) {
            writeHillsCage(w, HUGE_CELLS, HUGE_HALF);
        }
    }

    /** Removes the scratch folder. */
    void close() throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) Files.deleteIfExists(p);
        }
    }

    // ---- the cages ----

    /** Quads around the close scene's ring and tube: 288 control faces. */
    static final int CLOSE_RING = 24, CLOSE_TUBE = 12;
    /** Cells per side of the huge scene's hills, and its half-width. */
    static final int HUGE_CELLS = 64;
    static final double HUGE_HALF = 16;

    /** A torus (R 1, r 0.4, axis +Y) of ring x tube quads, wound outward, positions only. */
    static void writeTorusCage(Appendable w, int ring, int tube) throws IOException {
        w.append("# close scene cage: torus R 1, r 0.4, ").append(Integer.toString(ring * tube)).append(" quads\n");
        for (int i = 0; i < ring; i++) {
            double u = 2 * Math.PI * i / ring;
            for (int j = 0; j < tube; j++) {
                double v = 2 * Math.PI * j / tube, rr = 1 + 0.4 * Math.cos(v);
                vertex(w, rr * Math.cos(u), 0.4 * Math.sin(v), -rr * Math.sin(u));
            }
        }
        for (int i = 0; i < ring; i++) {
            for (int j = 0; j < tube; j++) {
                int i1 = (i + 1) % ring, j1 = (j + 1) % tube;
                w.append("f ").append(Integer.toString(i * tube + j + 1)).append(' ').append(Integer.toString(i1 * tube + j + 1))
                        .append(' ').append(Integer.toString(i1 * tube + j1 + 1)).append(' ').append(Integer.toString(i * tube + j1 + 1)).append('\n');
            }
        }
    }

    /** A square of cells x cells quads over [-half, half]^2 in x and z, with smooth hills in y; normals up. */
    static void writeHillsCage(Appendable w, int cells, double half) throws IOException {
        w.append("# huge scene cage: hills, ").append(Integer.toString(cells * cells)).append(" quads\n");
        for (int i = 0; i <= cells; i++) {
            for (int j = 0; j <= cells; j++) {
                double x = -half + 2 * half * i / cells, z = -half + 2 * half * j / cells;
                double y = 0.7 * Math.sin(0.8 * x) * Math.cos(0.6 * z) + 0.3 * Math.sin(2.1 * x + 1.3 * z);
                vertex(w, x, y, z);
            }
        }
        for (int i = 0; i < cells; i++) {
            for (int j = 0; j < cells; j++) {
                int a = i * (cells + 1) + j + 1, b = (i + 1) * (cells + 1) + j + 1;
                w.append("f ").append(Integer.toString(a)).append(' ').append(Integer.toString(a + 1)).append(' ')
                        .append(Integer.toString(b + 1)).append(' ').append(Integer.toString(b)).append('\n');
            }
        }
    }

    private static void vertex(Appendable w, double x, double y, double z) throws IOException {
        w.append("v ").append(BenchMeshes.number(x)).append(' ').append(BenchMeshes.number(y)).append(' ').append(BenchMeshes.number(z)).append('\n');
    }

    /** The scene text of one cell (method, view, policy), its cage beside it in the scratch folder. */
    static String sceneText(String scene, View view, String method, boolean lastTwo) {
        boolean close = scene.equals("close");
        return "# generated by render bench (adaptive rows)\n"
                + "settings { width 1920  height 1080  samples 1  background 0.05 0.06 0.1  ambient 0.15 0.15 0.15"
                + (lastTwo ? "  subdivpolicy last-two" : "") + " }\n"
                + "camera { " + view.camera() + " }\n"
                + "light { position 4 8 6  color 1 1 1  intensity 1 }\n"
                + "material m { color " + (close ? "0.85 0.55 0.3" : "0.45 0.7 0.35") + "  kd 0.8  ks 0.25  shininess 40 }\n"
                + "subdiv { file \"" + scene + ".obj\"  method " + method + "  shading smooth  material m }\n";
    }

    // ---- one cell ----

    private static final Pattern LOAD = Pattern.compile("(?m)^load:\\s+([0-9.]+) s"), BUILD = Pattern.compile("(?m)^build:\\s+([0-9.]+) s"),
            RENDER = Pattern.compile("(?m)^render:\\s+([0-9.]+) s"), RAYS = Pattern.compile("(?m)^rays:\\s+(\\d+) camera, (\\d+) shadow"),
            HEAP = Pattern.compile("(?m)^heap:\\s+([0-9.]+) MiB peak"), RSS = Pattern.compile("(?m)^memory:\\s+([0-9.]+) MiB peak resident"),
            SUBDIV = Pattern.compile("(?m)^subdiv .*$"),
            PATCHES = Pattern.compile("patches (\\d+) built, (\\d+) hits, (\\d+) misses, (\\d+) evictions"),
            CACHE_PEAK = Pattern.compile("evictions[^;]*?, peak ([0-9.]+ [KMGT]?i?B|[0-9]+ bytes)"),
            GC = Pattern.compile("(\\d+)([KMG])->(\\d+)([KMG])\\(");

    /** Runs one cell in a new JVM and reads its figures. */
    Cell run(Spec s) throws IOException {
        Path scene = dir.resolve("cell.dat"), image = dir.resolve("cell.tga"), log = dir.resolve("cell.out"), gc = dir.resolve("gc.log");
        Files.writeString(scene, sceneText(s.scene(), s.view(), s.method(), s.lastTwo()), StandardCharsets.US_ASCII);
        Files.deleteIfExists(gc);
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        // This JVM's options (the launcher's vector module and collector), less its heap and logging.
        for (String a : java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            if (!a.startsWith("-Xmx") && !a.startsWith("-Xms") && !a.startsWith("-Xlog") && !a.startsWith("-XX:MaxRAM")) cmd.add(a);
        }
        cmd.addAll(List.of("-Xmx" + s.heapMiB() + "m", "-Xlog:gc:file=" + gc, "-cp", classPath(), commandLine,
                scene.toString(), "-o", image.toString(), "--width", Integer.toString(s.width()), "--height", Integer.toString(s.height()),
                "--threads", Integer.toString(BenchCommand.THREADS), "--stats", "--quiet"));
        if (s.cacheMiB() > 0) cmd.addAll(List.of("--subdiv-cache", Integer.toString(s.cacheMiB())));
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        boolean done;
        try {
            done = p.waitFor(timeoutSeconds, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        double wall = (System.nanoTime() - t0) / 1e9;
        if (!done) {
            p.destroyForcibly();
            try {
                p.waitFor(30, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        String text = Files.isRegularFile(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
        double live = liveAfterGcMiB(gc);
        if (!done) return failed(s, "stopped after " + timeoutSeconds + " s", wall, live);
        if (p.exitValue() != 0) {
            String first = text.lines().filter(l -> !l.startsWith("WARNING: Using incubator")).findFirst().orElse("exit " + p.exitValue());
            boolean memory = first.contains("of heap") || first.contains("OutOfMemory") || first.contains("out of memory");
            return failed(s, memory ? "out of memory (" + first.strip() + ")" : "failed: " + first.strip(), wall, live);
        }
        Matcher sub = SUBDIV.matcher(text);
        String subdiv = sub.find() ? sub.group() : "";
        Matcher pm = PATCHES.matcher(subdiv), cp = CACHE_PEAK.matcher(subdiv);
        boolean patches = pm.find();
        Matcher rays = RAYS.matcher(text);
        long nRays = rays.find() ? Long.parseLong(rays.group(1)) + Long.parseLong(rays.group(2)) : 0;
        return new Cell(s, null, wall, num(LOAD, text), num(BUILD, text), num(RENDER, text), nRays, num(HEAP, text), live, num(RSS, text), subdiv,
                subdiv.contains("as combined"), patches ? Long.parseLong(pm.group(2)) : 0, patches ? Long.parseLong(pm.group(3)) : 0,
                patches ? Long.parseLong(pm.group(4)) : 0, cp.find() ? cp.group(1) : "-");
    }

    private static Cell failed(Spec s, String why, double wall, double live) {
        return new Cell(s, why, wall, Double.NaN, Double.NaN, Double.NaN, 0, Double.NaN, live, Double.NaN, "", false, 0, 0, 0, "-");
    }

    private static double num(Pattern p, String text) {
        Matcher m = p.matcher(text);
        return m.find() ? Double.parseDouble(m.group(1)) : Double.NaN;
    }

    /** The largest heap occupancy after any collection in the child's GC log, MiB; NaN without collections. */
    static double liveAfterGcMiB(Path gcLog) throws IOException {
        if (!Files.isRegularFile(gcLog)) return Double.NaN;
        double max = Double.NaN;
        for (String line : Files.readAllLines(gcLog, StandardCharsets.UTF_8)) {
            Matcher m = GC.matcher(line);
            if (m.find()) {
                double after = Double.parseDouble(m.group(3)) * switch (m.group(4)) {
                    case "K" -> 1.0 / 1024;
                    case "G" -> 1024.0;
                    default -> 1.0;
                };
                max = Double.isNaN(max) ? after : Math.max(max, after);
            }
        }
        return max;
    }

    private static String classPath() throws IOException {
        try {
            return Path.of(AdaptiveBench.class.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (java.net.URISyntaxException e) {
            throw new IOException("cannot locate the program's classes: " + e.getMessage());
        }
    }

    // ---- what the view asks for, without rendering ----

    /** Face levels and eager patch bytes of a cell's scene, from a lazy build in this JVM (no patch is refined). */
    record Need(int[] levelHistogram, long faces, long quads, long patchBytes) {
        String levels() {
            StringBuilder b = new StringBuilder();
            for (int l = 0; l < levelHistogram.length; l++) if (levelHistogram[l] > 0) b.append(b.length() == 0 ? "" : " ").append(l).append(':').append(levelHistogram[l]);
            return b.toString();
        }
    }

    Need need(String scene, View view, int width, int height) throws IOException {
        Path file = dir.resolve("need.dat");
        // The thesis's power-of-two levels: what the table's level columns describe.
        Files.writeString(file, sceneText(scene, view, "lazy  levels edge", false), StandardCharsets.US_ASCII);
        SceneBuilder b = SceneParser.parse(file);
        b.settings(b.settings().toBuilder().width(width).height(height).build());
        Scene sc = b.build();
        int[] hist = new int[lt.spindulys.scene.SubdivisionSurface.MAX_LEVEL + 1];
        long faces = 0, quads = 0, bytes = 0;
        for (GObject o : sc.objects()) {
            if (!(o instanceof AdaptiveSubdivisionSurface s)) continue;
            PatchRefiner r = s.refiner();
            int[] edge = s.edgeLevels();
            for (int f = 0; f < r.faceCount(); f++) {
                if (r.isHole(f)) continue;
                int l = 0;
                for (int k = 0; k < r.faceSize(f); k++) l = Math.max(l, edge[r.faceEdge(f, k)]);
                hist[l]++;
                faces++;
                quads += l == 0 ? 1 : (long) r.faceSize(f) << (2 * (l - 1));
                bytes = HeapBudget.sum(bytes, r.patchBytes(f, l, s.isSmooth()));
            }
        }
        return new Need(hist, faces, quads, bytes);
    }

    // ---- the rows ----

    static final String[] METHODS = {"projected", "lazy", "combined"};

    /** Table 1: the three methods at the four sizes on one scene, each cell a new JVM. */
    void table1(String scene, View view, int heapMiB) throws IOException {
        out.printf(Locale.ROOT, "  %s scene (%s), view '%s', target 1 px, rates per edge (face levels, fine quads and eager patches: what the"
                + " thesis's power-of-two levels would need), 64 MiB cache, -Xmx%dm per cell%n", scene,
                scene.equals("close") ? CLOSE_RING * CLOSE_TUBE + "-quad torus cage" : HUGE_CELLS * HUGE_CELLS + "-quad hills cage",
                view.name(), heapMiB);
        BenchTable t = new BenchTable("size", "face levels", "fine quads", "eager patches", "method", "wall s", "build s", "render s",
                "peak heap MiB", "live heap MiB", "peak RSS MiB", "hit rate", "note");
        for (int[] size : TABLE_SIZES) {
            Need n = need(scene, view, size[0], size[1]);
            out.printf(Locale.ROOT, "    %s %dx%d: face levels %s, %,d fine quads, eager patches %s%n", scene, size[0], size[1], n.levels(), n.quads(),
                    HeapBudget.format(n.patchBytes()));
            for (String m : METHODS) {
                Cell c = run(new Spec(scene, view, m, size[0], size[1], 0, false, heapMiB));
                String note = c.failure() != null ? c.failure()
                        : m.equals("projected") && c.becameCombined() ? "does not fit (became combined)"
                        : m.equals("combined") ? pinned(c.subdivLine()) : "";
                t.add(m.equals("projected") ? size[0] + "x" + size[1] : "", m.equals("projected") ? n.levels() : "",
                        m.equals("projected") ? String.format(Locale.ROOT, "%,d", n.quads()) : "",
                        m.equals("projected") ? HeapBudget.format(n.patchBytes()) : "", m,
                        fmt(c.wall(), 2), fmt(c.build(), 2), fmt(c.render(), 2), fmt(c.peakHeapMiB(), 0), fmt(c.liveHeapMiB(), 0),
                        fmt(c.peakRssMiB(), 0), Double.isNaN(c.hitRate()) ? "-" : fmt(100 * c.hitRate(), 1) + " %", note);
                out.printf(Locale.ROOT, "    %s: %s%n", c.spec().label(), c.failure() != null ? c.failure()
                        : String.format(Locale.ROOT, "wall %.2f s, render %.2f s, peak heap %.0f MiB, live %.0f MiB, peak RSS %.0f MiB; %s", c.wall(),
                        c.render(), c.peakHeapMiB(), c.liveHeapMiB(), c.peakRssMiB(), c.subdivLine()));
            }
        }
        t.print(out);
    }

    private static String pinned(String subdiv) {
        Matcher m = Pattern.compile("(\\d+) patches eager \\(([^)]*)\\)").matcher(subdiv);
        return m.find() ? m.group(1) + " patches eager (" + m.group(2) + ")" : "";
    }

    /**
     * Lazy (64 MiB cache) against projected (eager) at the same tessellation, on both views of
     * the close scene. Speed: renders in this JVM after two warm-up renders of each (so both run
     * compiled code; a new JVM renders a short lazy frame largely in unoptimised code), {@code runs}
     * alternated pairs, the median of the pairs' ratios. Heap: one new JVM per method, with the close
     * scene's heap ({@link #CLOSE_HEAP_MIB}), in which the eager tessellation stays eager.
     */
    void lazyVsEager() throws IOException {
        BenchTable t = new BenchTable("view", "face levels", "eager render s", "lazy render s", "speed lazy/eager", "eager cold wall s",
                "lazy cold wall s", "eager peak/live MiB", "lazy peak/live MiB", "heap eager/lazy (peak, live)", "peak RSS MiB eager/lazy",
                "lazy hit rate");
        for (View v : List.of(CLOSE_FRONT, CLOSE_GRAZING)) {
            Need n = need("close", v, PAIR_WIDTH, PAIR_HEIGHT);
            Path eagerScene = dir.resolve("eager-" + v.name() + ".dat"), lazyScene = dir.resolve("lazy-" + v.name() + ".dat");
            Files.writeString(eagerScene, sceneText("close", v, "projected", false), StandardCharsets.US_ASCII);
            Files.writeString(lazyScene, sceneText("close", v, "lazy", false), StandardCharsets.US_ASCII);
            java.util.function.UnaryOperator<lt.spindulys.scene.RenderSettings> size = st -> st.toBuilder().width(PAIR_WIDTH).height(PAIR_HEIGHT).build();
            for (int i = 0; i < 2; i++) {
                BenchCommand.renderOnce(eagerScene, null, size);
                BenchCommand.renderOnce(lazyScene, null, size);
            }
            double[] speed = new double[runs], er = new double[runs], lr = new double[runs];
            String lazyStats = "";
            for (int i = 0; i < runs; i++) {
                // Alternate which goes first, so drift on a shared machine hits both alike.
                BenchCommand.Measured e, l;
                if (i % 2 == 0) {
                    e = BenchCommand.renderOnce(eagerScene, null, size);
                    l = BenchCommand.renderOnce(lazyScene, null, size);
                } else {
                    l = BenchCommand.renderOnce(lazyScene, null, size);
                    e = BenchCommand.renderOnce(eagerScene, null, size);
                }
                er[i] = e.stats().seconds();
                lr[i] = l.stats().seconds();
                speed[i] = er[i] / lr[i];
                lazyStats = String.join("; ", l.subdivision());
                out.printf(Locale.ROOT, "    %s pair %d: eager render %.3f s, lazy render %.3f s: lazy %.2fx eager's speed%n", v.name(), i + 1, er[i], lr[i], speed[i]);
            }
            out.println("    " + lazyStats);
            // The close scene's heap, so that the eager tessellation fits its budget (a quarter of the heap) and stays eager.
            Cell e = run(new Spec("close", v, "projected", PAIR_WIDTH, PAIR_HEIGHT, 64, false, CLOSE_HEAP_MIB));
            Cell l = run(new Spec("close", v, "lazy", PAIR_WIDTH, PAIR_HEIGHT, 64, false, CLOSE_HEAP_MIB));
            for (Cell c : List.of(e, l)) {
                out.printf(Locale.ROOT, "    %s: %s%n", c.spec().label(), c.failure() != null ? c.failure()
                        : String.format(Locale.ROOT, "wall %.2f s, render %.2f s, peak heap %.0f MiB, live %.0f MiB, peak RSS %.0f MiB; %s", c.wall(),
                        c.render(), c.peakHeapMiB(), c.liveHeapMiB(), c.peakRssMiB(), c.subdivLine()));
            }
            t.add(v.name(), n.levels(), fmt(median(er), 3), fmt(median(lr), 3), fmt(median(speed), 2) + "x", fmt(e.wall(), 2), fmt(l.wall(), 2),
                    fmt(e.peakHeapMiB(), 0) + " / " + fmt(e.liveHeapMiB(), 0), fmt(l.peakHeapMiB(), 0) + " / " + fmt(l.liveHeapMiB(), 0),
                    fmt(e.peakHeapMiB() / l.peakHeapMiB(), 1) + "x, " + fmt(e.liveHeapMiB() / l.liveHeapMiB(), 1) + "x",
                    fmt(e.peakRssMiB(), 0) + " / " + fmt(l.peakRssMiB(), 0),
                    Double.isNaN(l.hitRate()) ? "-" : fmt(100 * l.hitRate(), 2) + " %");
        }
        t.print(out);
        out.printf(Locale.ROOT, "  close scene at %dx%d, target 1 px (both methods choose the same levels from the same view). Render s: in this JVM%n", PAIR_WIDTH, PAIR_HEIGHT);
        out.printf(Locale.ROOT, "  after 2 warm-up renders of each, %d alternated pairs, speed = median of eager s / lazy s (target: at least 0.8x).%n", runs);
        out.printf(Locale.ROOT, "  Heap and cold wall: one new JVM each (-Xmx%dm); peak: heap pools' peak; live: largest heap after a collection;%n", CLOSE_HEAP_MIB);
        out.println("  peak RSS: the whole process's peak resident memory (Linux; '-' elsewhere)");
        out.println("  (target: eager's at least 5x lazy's).");
    }

    /** The thesis's last-two policy and the shared LRU cache at several sizes, front view of the close scene. */
    void cache() throws IOException {
        BenchTable t = new BenchTable("policy", "cache", "render s", "wall s", "peak heap MiB", "live heap MiB", "peak RSS MiB", "built", "hits", "misses", "evictions",
                "hit rate", "cache peak");
        List<Spec> specs = new ArrayList<>();
        specs.add(new Spec("close", CLOSE_FRONT, "lazy", PAIR_WIDTH, PAIR_HEIGHT, 64, true));
        for (int c : CACHE_MIB) specs.add(new Spec("close", CLOSE_FRONT, "lazy", PAIR_WIDTH, PAIR_HEIGHT, c, false));
        List<List<Cell>> cells = new ArrayList<>();
        for (int k = 0; k < specs.size(); k++) cells.add(new ArrayList<>());
        int reps = Math.max(1, Math.min(runs, 3));
        for (int i = 0; i < reps; i++) {
            for (int k = 0; k < specs.size(); k++) {
                int kk = i % 2 == 0 ? k : specs.size() - 1 - k;
                Cell c = run(specs.get(kk));
                cells.get(kk).add(c);
                out.printf(Locale.ROOT, "    %s: %s%n", c.spec().label(), c.failure() != null ? c.failure()
                        : String.format(Locale.ROOT, "render %.2f s, %s", c.render(), c.subdivLine()));
            }
        }
        for (int k = 0; k < specs.size(); k++) {
            List<Cell> cs = cells.get(k);
            Cell last = cs.get(cs.size() - 1);
            Spec s = specs.get(k);
            long built = last.misses();
            t.add(s.lastTwo() ? "last two" : "LRU", s.lastTwo() ? "2 per thread" : s.cacheMiB() + " MiB", fmt(medianOf(cs, Cell::render), 2),
                    fmt(medianOf(cs, Cell::wall), 2), fmt(medianOf(cs, Cell::peakHeapMiB), 0), fmt(medianOf(cs, Cell::liveHeapMiB), 0),
                    fmt(medianOf(cs, Cell::peakRssMiB), 0),
                    Long.toString(built), Long.toString(last.hits()), Long.toString(last.misses()), Long.toString(last.evictions()),
                    Double.isNaN(last.hitRate()) ? "-" : fmt(100 * last.hitRate(), 2) + " %", last.cachePeak());
        }
        t.print(out);
        out.printf(Locale.ROOT, "  close scene, front view, %dx%d, target 1 px, lazy method, new JVM per run (-Xmx2048m), median of %d; counts%n", PAIR_WIDTH, PAIR_HEIGHT, reps);
        out.println("  from the last run's --stats (hit rate = hits / (hits + misses)).");
    }

    private static double medianOf(List<Cell> cells, java.util.function.ToDoubleFunction<Cell> f) {
        return median(cells.stream().mapToDouble(f).toArray());
    }
}
