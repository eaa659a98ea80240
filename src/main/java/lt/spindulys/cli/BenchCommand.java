package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import lt.spindulys.io.ObjReader;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;

/**
 * {@code render bench}: the project's fixed benchmark suite. Speed and memory targets live
 * here, not in timed tests. Every row warms the JVM up before it is timed and reports the median
 * of several runs; where a peer program is installed (OpenSubdiv's far_perf), the same input is
 * run through it in the same session and the ratio is printed beside our figure. Inputs are read
 * from scenes/bench/ under the current folder (the repository root).
 */
final class BenchCommand {
    static final String USAGE = """
            usage: render bench [--only NAME] [--runs N] [--list]

              --only NAME   run only the row NAME (see --list)
              --runs N      timed runs per row after the warm-up (default 5); the median is reported
              --list        list the rows and exit
            Run from the repository root: inputs are read from scenes/bench/. See docs/performance.md.""";

    /** One benchmark row: a name, what it measures, and how. */
    private record Row(String name, String section, String description, Action action) {}

    @FunctionalInterface
    private interface Action { void run(BenchCommand bench, PrintStream out) throws IOException; }

    private static final List<Row> ROWS = List.of(
            new Row("refine-bishop", "Subdivision",
                    "catmark_bishop (968 quads, 224 creases) refined uniformly to level 6 (~4M quads) on one thread; beside far_perf -u",
                    (b, out) -> b.refinement(out, "catmark_bishop.obj", 6)));

    private String only;
    private int runs = 5;
    private boolean list;
    private final Path benchDir = Path.of("scenes", "bench");

    BenchCommand(String[] args) throws UsageException {
        for (int i = 0; i < args.length; i++) {
            switch (args[i]) {
                case "--only" -> {
                    if (++i >= args.length) throw new UsageException("option --only needs a value");
                    only = args[i];
                    if (ROWS.stream().noneMatch(r -> r.name().equals(only))) {
                        throw new UsageException("unknown bench row '" + only + "' (rows: " + String.join(", ", ROWS.stream().map(Row::name).toList()) + ")");
                    }
                }
                case "--runs" -> {
                    if (++i >= args.length) throw new UsageException("option --runs needs a value");
                    try {
                        runs = Integer.parseInt(args[i]);
                    } catch (NumberFormatException e) {
                        throw new UsageException("--runs expects a whole number, found '" + args[i] + "'");
                    }
                    if (runs < 1 || runs > 100) throw new UsageException("--runs must be between 1 and 100, found " + runs);
                }
                case "--list" -> list = true;
                default -> throw new UsageException("unknown bench option '" + args[i] + "' (see render bench --help)");
            }
        }
    }

    int run(PrintStream out) throws IOException {
        if (list) {
            for (Row r : ROWS) out.printf("%-16s %s%n", r.name(), r.description());
            return 0;
        }
        if (!Files.isDirectory(benchDir)) {
            throw new IOException("bench inputs not found: " + benchDir.toAbsolutePath() + " (run render bench from the repository root)");
        }
        Runtime rt = Runtime.getRuntime();
        out.printf(Locale.ROOT, "Spindulys %s benchmark: Java %s, %d cores, max heap %.1f GiB, %d timed runs per row (median)%n",
                Main.version(), System.getProperty("java.version"), rt.availableProcessors(), rt.maxMemory() / (double) (1L << 30), runs);
        String section = null;
        for (Row r : ROWS) {
            if (only != null && !only.equals(r.name())) continue;
            if (!r.section().equals(section)) {
                section = r.section();
                out.println();
                out.println(section);
            }
            r.action().run(this, out);
        }
        return 0;
    }

    // ---- subdivision ----

    private void refinement(PrintStream out, String file, int level) throws IOException {
        Path obj = benchDir.resolve(file);
        ControlMesh mesh = ObjReader.readSubdiv(obj).toControlMesh();
        // Warm-up: compile the refinement code paths before timing.
        for (int i = 0; i < 3; i++) CatmullClark.refine(mesh, level - 1);
        double[] seconds = new double[runs];
        RefinedMesh refined = null;
        for (int i = 0; i < runs; i++) {
            refined = null;
            System.gc();
            long t0 = System.nanoTime();
            refined = CatmullClark.refine(mesh, level);
            seconds[i] = (System.nanoTime() - t0) / 1e9;
        }
        double t = median(seconds);
        long quads = refined.faceCount();
        long t1 = System.nanoTime();
        refined.limitNormals();
        double normalSeconds = (System.nanoTime() - t1) / 1e9;
        double bytesPerQuad = refined.memoryBytes() / (double) quads;
        double far = ExternalTimer.farPerfRefineSeconds(obj, level, Math.min(runs, 3));

        BenchTable table = new BenchTable("row", "control faces", "level", "quads", "refine s", "Mquads/s", "limit normals s",
                "bytes/quad", "far_perf s", "speed vs far_perf");
        table.add("refine-" + file.replace("catmark_", "").replace(".obj", ""), Integer.toString(mesh.faceCount()), Integer.toString(level),
                String.format(Locale.ROOT, "%,d", quads), fmt(t, 3), fmt(quads / t / 1e6, 2), fmt(normalSeconds, 3), fmt(bytesPerQuad, 1),
                Double.isNaN(far) ? "not installed" : fmt(far, 3),
                Double.isNaN(far) ? "-" : fmt(far / t, 2) + "x");
        table.print(out);
        out.println("  refine s: positions and topology of every level up to the last (one thread); far_perf s: OpenSubdiv's");
        out.println("  TopologyRefiner::Refine alone (topology only, no positions), so the ratio is conservative for us;");
        out.println("  speed vs far_perf = far_perf s / refine s (above 1: Spindulys is faster).");
        out.println("  bytes/quad: the refined level's topology, positions and limit normals, divided by its quads.");
    }

    private static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }

    private static String fmt(double v, int decimals) {
        return String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
