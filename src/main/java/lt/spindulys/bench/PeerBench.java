package lt.spindulys.bench;

import static lt.spindulys.bench.BenchTable.fmt;
import static lt.spindulys.bench.BenchTable.median;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import lt.spindulys.files.FileNames;
import lt.spindulys.io.ObjReader;

/**
 * The peer renderers run from the bench on a bench row's own view: Embree's
 * {@code pathtracer} tutorial, POV-Ray and Blender's Cycles, each when its program is on PATH.
 * For every peer, alternated pairs: our render in this (warm) JVM beside the peer's own
 * render-only figure, then our whole cold process beside the peer's whole process, so drift on
 * a shared machine hits both sides of a pair alike. Rays per second of both sides are our
 * counted rays divided by each side's render time (the peers trace the same camera and shadow
 * rays, but report them differently or not at all), so the speed ratio is the ratio of render
 * times. The images are compared with ours to make sure the views agree, and kept as PNGs in
 * {@code target/bench-peers/}.
 */
final class PeerBench {
    /** A peer renderer: its keyword for {@code --peers}, its name, and its program. */
    enum Peer {
        EMBREE("embree", "Embree pathtracer", "pathtracer"),
        POVRAY("povray", "POV-Ray", "povray"),
        CYCLES("cycles", "Blender Cycles", "blender");

        final String keyword, label, program;

        Peer(String keyword, String label, String program) {
            this.keyword = keyword;
            this.label = label;
            this.program = program;
        }

        /** The peers named in a comma-separated list of keywords, or none for "none". */
        static Set<Peer> parse(String list) throws BenchUsageException {
            Set<Peer> s = EnumSet.noneOf(Peer.class);
            if (list.equals("none")) return s;
            for (String k : list.split(",", -1)) {
                Peer p = Arrays.stream(values()).filter(x -> x.keyword.equals(k)).findFirst().orElse(null);
                if (p == null) throw new BenchUsageException("unknown peer '" + k + "' in --peers (expected embree, povray, cycles or none)");
                s.add(p);
            }
            return s;
        }
    }

    /**
     * A row's targets: for each peer, the least speed ratio (ours over the peer's rays per
     * second) and the most wall-time ratio (our whole process over the peer's), where one is set.
     */
    record Targets(Map<Peer, Double> minSpeed, Map<Peer, Double> maxWall) {
        /**
         * Tracing a dense mesh under point lights (hard shadows): at least {@code embreeSpeed} x Embree's speed, 3x Cycles',
         * 4x POV-Ray's; a whole cold process at most 1.3x Embree's wall and below the others'.
         */
        static Targets meshTracing(double embreeSpeed) {
            return new Targets(Map.of(Peer.EMBREE, embreeSpeed, Peer.CYCLES, 3.0, Peer.POVRAY, 4.0),
                    Map.of(Peer.EMBREE, 1.3, Peer.CYCLES, 1.0, Peer.POVRAY, 1.0));
        }

        /** Soft shadows from an area light: at least 2x the speed (render time) of POV-Ray's area_light, no wall-time target. */
        static Targets softShadows() {
            return new Targets(Map.of(Peer.POVRAY, 2.0), Map.of());
        }
    }

    /** Our side of a pair. */
    interface Ours {
        /** One render in this JVM: its seconds and rays. */
        BenchCommand.Measured render() throws IOException;

        /** One whole new process rendering the scene: wall seconds, NaN if it failed. */
        double cold() throws IOException;
    }

    /** Frames Embree renders after its skipped first one, for its render-only figure. */
    static final int EMBREE_FRAMES = 10;
    /** The longest a peer process may take. */
    private static final long TIMEOUT_MINUTES = 10;

    private final PrintStream out;
    private final String row;
    private final PeerView view;
    private final int pairs, threads;
    private final Targets targets;
    private final Ours ours;
    private final Path scratch;
    private final BenchTable table = new BenchTable("peer", "pairs", "peer render s", "ours", "peer Mrays/s", "ours", "speed ours/peer",
            "target", "peer wall s", "ours", "wall ours/peer", "target", "image |dL|", ">5% px");
    /** The targets not met, for the summary line. */
    private final List<String> missed = new ArrayList<>();
    /** Targets judged so far: none means no peer ran, and nothing is printed. */
    private int judged;
    /** Our counted rays of a frame, as printed. */
    private String raysLine = "?";

    private PeerBench(PrintStream out, String row, PeerView view, int pairs, int threads, Targets targets, Ours ours, Path scratch) {
        this.out = out;
        this.row = row;
        this.view = view;
        this.pairs = pairs;
        this.threads = threads;
        this.targets = targets;
        this.ours = ours;
        this.scratch = scratch;
    }

    /**
     * Runs {@code peers} (those on PATH; one line for each that is not) on {@code view} against
     * {@code ours}, {@code pairs} alternated pairs each, and prints a table and the targets.
     * A peer that is missing or fails is reported and skipped; the bench goes on.
     */
    static void run(PrintStream out, String row, PeerView view, Set<Peer> peers, int pairs, int threads, Targets targets, Ours ours)
            throws IOException {
        if (peers.isEmpty()) return;
        Path scratch = Files.createTempDirectory("spindulys-peers-");
        try {
            PeerBench b = new PeerBench(out, row, view, pairs, threads, targets, ours, scratch);
            int[] reference = ours.render().image().toRgb8(true);
            b.savePng(reference, "ours");
            for (Peer p : peers) {
                Path exe = ExternalTimer.onPath(p.program);
                if (exe == null) {
                    out.printf("  %s: %s is not on PATH, skipped%n", p.label, p.program);
                    continue;
                }
                b.peer(p, exe.toString(), reference);
            }
            b.print();
        } finally {
            deleteTree(scratch);
        }
    }

    /** One peer's pairs and its table row. */
    private void peer(Peer p, String exe, int[] reference) throws IOException {
        Path image = scratch.resolve(p.keyword + (p == Peer.CYCLES ? ".tga" : ".ppm"));
        List<String> whole = wholeCommand(p, exe, image);
        // One untimed run first: the meshes in the page cache, and the image to compare.
        Result first = exec(whole);
        if (!first.ok()) {
            out.printf("  %s failed (exit %d), skipped: %s%n", p.label, first.exit, first.lastLine());
            return;
        }
        int[] img = switch (p) {
            case EMBREE -> PeerImages.readPpm(image, view.width(), view.height(), true);
            case POVRAY -> PeerImages.readPpm(image, view.width(), view.height(), false);
            case CYCLES -> PeerImages.readTga(image, view.width(), view.height());
        };
        savePng(img, p.keyword);
        PeerImages.Difference diff = PeerImages.compare(reference, img);

        double[] ourRender = new double[pairs], peerRender = new double[pairs], ourWall = new double[pairs], peerWall = new double[pairs];
        long rays = 0;
        for (int i = 0; i < pairs; i++) {
            BenchCommand.Measured m = ours.render();
            rays = m.stats().totalRays();
            ourRender[i] = m.stats().seconds();
            double pr = Double.NaN;
            if (p == Peer.EMBREE) {
                Result r = exec(PeerInputs.embree(exe, view, threads, List.of("--benchmark", "1", Integer.toString(EMBREE_FRAMES), "--legacy")));
                pr = r.ok() ? PeerLogs.embreeFrameSeconds(r.log) : Double.NaN;
            }
            ourWall[i] = ours.cold();
            Result w = exec(whole);
            peerWall[i] = w.ok() ? w.seconds : Double.NaN;
            if (p == Peer.POVRAY) pr = w.ok() ? PeerLogs.povTraceSeconds(w.log) : Double.NaN;
            if (p == Peer.CYCLES) pr = w.ok() ? PeerLogs.cyclesSamplingSeconds(w.log) : Double.NaN;
            peerRender[i] = pr;
        }
        double speed = medianRatio(peerRender, ourRender), wall = medianRatio(ourWall, peerWall);
        double minSpeed = targets.minSpeed().get(p);
        Double maxWall = targets.maxWall().get(p);
        table.add(p.label, Integer.toString(pairs), fmt(median(peerRender), 3), fmt(median(ourRender), 3),
                fmt(rays / median(peerRender) / 1e6, 2), fmt(rays / median(ourRender) / 1e6, 2),
                fmt(speed, 2) + "x (" + fmt(median(peerRender) / median(ourRender), 2) + "x)",
                ">= " + fmt(minSpeed, 1) + "x " + verdict(speed >= minSpeed, p.label + " render-only"),
                fmt(median(peerWall), 3), fmt(median(ourWall), 3),
                fmt(wall, 2) + "x (" + fmt(median(ourWall) / median(peerWall), 2) + "x)",
                maxWall == null ? "none" : (maxWall == 1.0 ? "< 1x " : "<= " + fmt(maxWall, 1) + "x ")
                        + verdict(maxWall == 1.0 ? wall < 1 : wall <= maxWall, p.label + " whole process"),
                fmt(diff.meanLuma(), 2), fmt(100 * diff.shareOff(), 2) + "%");
        if (rays > 0) raysLine = String.format(Locale.ROOT, "%,d", rays);
    }

    /** "met" or "NOT met", noting a miss for the summary line; an unknown figure (NaN) is a miss. */
    private String verdict(boolean met, String what) {
        judged++;
        if (!met) missed.add(what);
        return met ? "met" : "NOT met";
    }

    private void print() {
        if (judged == 0) return;
        out.printf("  %s beside the peers (same view; %d alternated pairs each; medians):%n", row, pairs);
        table.print(out);
        out.printf("  render s: tracing the frame only (ours: in this JVM after the row's warm-up; Embree: --benchmark 1 %d --legacy,%n", EMBREE_FRAMES);
        out.println("  the mean of its timed frames; POV-Ray: its Trace Time; Cycles: status line Sample 0/1 to Sample 1/1).");
        out.printf("  Mrays/s: our counted rays (%s camera and shadow rays) / render s, for both sides. speed ours/peer and%n", raysLine);
        out.println("  wall ours/peer: medians of the pairs' ratios (judged against the targets), in brackets the ratios of the medians;");
        out.println("  far apart, the machine was too noisy to trust either. wall s: whole processes (ours: java -cp render.jar ... as the cold");
        out.println("  column), each after one untimed run. image |dL|: mean absolute luma difference from ours in 8-bit sRGB steps; >5% px:");
        out.println("  pixels off by more than 5 % (Embree and Cycles jitter their sample; edges differ). Images: target/bench-peers/.");
        out.printf("  %s: %s%n", row, missed.isEmpty() ? "every target met" : "not met: " + String.join(", ", missed));
    }

    private List<String> wholeCommand(Peer p, String exe, Path image) throws IOException {
        return switch (p) {
            case EMBREE -> PeerInputs.embree(exe, view, threads, List.of("-o", image.toString()));
            case POVRAY -> {
                List<String> includes = new ArrayList<>();
                for (Path m : view.meshes()) {
                    String inc = FileNames.stem(m.getFileName().toString(), "mesh") + ".inc";
                    PeerInputs.writeMesh2(scratch.resolve(inc), ObjReader.read(m));
                    includes.add(inc);
                }
                Path pov = scratch.resolve("view.pov");
                Files.writeString(pov, PeerInputs.povScene(view, includes), StandardCharsets.US_ASCII);
                yield PeerInputs.povray(exe, view, threads, pov.getFileName().toString(), image.getFileName().toString());
            }
            case CYCLES -> PeerInputs.cycles(exe, PeerInputs.writeCyclesScript(scratch), view, threads, image);
        };
    }

    /** A finished peer process. */
    private record Result(int exit, double seconds, String log) {
        boolean ok() { return exit == 0; }

        String lastLine() {
            String[] lines = log.strip().split("\\R");
            return lines.length == 0 ? "" : lines[lines.length - 1];
        }
    }

    /** Runs {@code cmd} in the scratch folder, output gathered; the wall time is from start to exit. */
    private Result exec(List<String> cmd) throws IOException {
        Path log = scratch.resolve("peer.log");
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(cmd).directory(scratch.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        try {
            if (!p.waitFor(TIMEOUT_MINUTES, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                return new Result(-1, Double.NaN, "timed out after " + TIMEOUT_MINUTES + " minutes");
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        double seconds = (System.nanoTime() - t0) / 1e9;
        return new Result(p.exitValue(), seconds, Files.readString(log, StandardCharsets.ISO_8859_1));
    }

    private void savePng(int[] rgb, String who) throws IOException {
        Path dir = Path.of("target", "bench-peers");
        Files.createDirectories(dir);
        BufferedImage img = new BufferedImage(view.width(), view.height(), BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, view.width(), view.height(), rgb, 0, view.width());
        ImageIO.write(img, "png", dir.resolve(row + "-" + who + ".png").toFile());
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) Files.deleteIfExists(p);
        }
    }

    /** The median of a[i] / b[i] over the pairs where both are known; NaN if none. */
    static double medianRatio(double[] a, double[] b) {
        double[] r = new double[a.length];
        int n = 0;
        for (int i = 0; i < a.length; i++) if (a[i] > 0 && b[i] > 0) r[n++] = a[i] / b[i];
        return median(Arrays.copyOf(r, n));
    }

    /** The median of the known (not NaN) values; NaN if none. */}
