package lt.spindulys.bench;

import static lt.spindulys.bench.BenchTable.fmt;
import static lt.spindulys.bench.BenchTable.median;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import lt.spindulys.image.FrameBuffer;

/**
 * The path tracer beside Embree's {@code pathtracer} and Cycles on one path-traced view, at equal
 * samples per pixel and path depth: alternated pairs of our render in this JVM and the peer's
 * render-only time, the speed being samples per second (the ratio of render times). Beside Cycles
 * also the noise at equal time: on a quarter-size view, Cycles at {@link #NOISE_CYCLES_SPP} and ours at
 * as many samples as fit in Cycles' render time, each image's mean squared error against a
 * converged Cycles image ({@link #REFERENCE_SPP} samples) of the same view.
 */
final class PathBench {
    private PathBench() {}

    /** Our side: one render in this JVM at a sample count and seed, with its stats and image. */
    interface Ours {
        BenchCommand.Measured render(int spp, long seed, int width, int height) throws IOException;
    }

    /** Least speed ratios: ours over Embree's and over Cycles' samples per second. */
    static final double EMBREE_MIN_SPEED = 0.8, CYCLES_MIN_SPEED = 3.0;
    /** Frames Embree renders after its skipped first one, for its render-only figure. */
    static final int EMBREE_FRAMES = 5;
    /** The noise comparison's view is the row's divided by this in each direction. */
    static final int NOISE_DIVISOR = 4;
    /** Cycles' samples per pixel in the noise comparison, and of its converged reference. */
    static final int NOISE_CYCLES_SPP = 256, REFERENCE_SPP = 1024;
    private static final long TIMEOUT_MINUTES = 20;

    /**
     * Runs the peers of {@code peers} that are on PATH (Embree and Cycles; POV-Ray has no path
     * tracer) on {@code view} at {@code spp} and {@code maxDepth}, {@code pairs} pairs each, and
     * prints the table, the noise comparison and the targets.
     */
    static void run(PrintStream out, String row, PeerView view, int spp, int maxDepth, Set<PeerBench.Peer> peers, int pairs, int threads,
            Ours ours) throws IOException {
        Path scratch = Files.createTempDirectory("spindulys-path-peers-");
        List<String> missed = new ArrayList<>();
        BenchTable table = new BenchTable("peer", "settings", "pairs", "peer render s", "ours", "peer Msamples/s", "ours", "speed ours/peer",
                "target", "image |dL|");
        long samples = (long) view.width() * view.height() * spp;
        String cycles = null; // Blender, once it has run: the noise comparison follows the table
        try {
            FrameBuffer ourImage = ours.render(spp, 0, view.width(), view.height()).image();
            int[] ourRgb = ourImage.toRgb8(true);
            for (PeerBench.Peer p : peers) {
                if (p == PeerBench.Peer.POVRAY) continue;
                Path exe = ExternalTimer.onPath(p.program);
                if (exe == null) {
                    out.printf("  %s: %s is not on PATH, skipped%n", p.label, p.program);
                    continue;
                }
                double[] mine = new double[pairs], theirs = new double[pairs];
                String settings;
                PeerImages.Difference diff;
                if (p == PeerBench.Peer.EMBREE) {
                    settings = "--spp " + spp + " --max-path-length " + (maxDepth + 1);
                    Path image = scratch.resolve("embree.ppm");
                    Result first = exec(scratch, PeerInputs.embree(exe.toString(), view, threads, spp, maxDepth + 1, List.of("-o", image.toString())));
                    if (!first.ok()) {
                        out.printf("  %s failed (exit %d), skipped: %s%n", p.label, first.exit, first.lastLine());
                        continue;
                    }
                    diff = PeerImages.compare(ourRgb, PeerImages.readPpm(image, view.width(), view.height(), true));
                    List<String> bench = PeerInputs.embree(exe.toString(), view, threads, spp, maxDepth + 1,
                            List.of("--benchmark", "1", Integer.toString(EMBREE_FRAMES), "--legacy"));
                    for (int i = 0; i < pairs; i++) {
                        mine[i] = ours.render(spp, i + 1, view.width(), view.height()).stats().seconds();
                        Result r = exec(scratch, bench);
                        theirs[i] = r.ok() ? PeerLogs.embreeFrameSeconds(r.log) : Double.NaN;
                    }
                } else {
                    settings = spp + " samples, max_bounces " + maxDepth;
                    Path script = PeerInputs.writeCyclesScript(scratch), image = scratch.resolve("cycles.tga");
                    List<String> cmd = PeerInputs.cyclesPath(exe.toString(), script, view, threads, image, spp, maxDepth, 0, null);
                    Result first = exec(scratch, cmd);
                    if (!first.ok()) {
                        out.printf("  %s failed (exit %d), skipped: %s%n", p.label, first.exit, first.lastLine());
                        continue;
                    }
                    diff = PeerImages.compare(ourRgb, PeerImages.readTga(image, view.width(), view.height()));
                    for (int i = 0; i < pairs; i++) {
                        mine[i] = ours.render(spp, i + 1, view.width(), view.height()).stats().seconds();
                        Result r = exec(scratch, PeerInputs.cyclesPath(exe.toString(), script, view, threads, image, spp, maxDepth, i + 1, null));
                        theirs[i] = r.ok() ? PeerLogs.cyclesSamplingSeconds(r.log, spp) : Double.NaN;
                    }
                }
                double speed = PeerBench.medianRatio(theirs, mine);
                double target = p == PeerBench.Peer.EMBREE ? EMBREE_MIN_SPEED : CYCLES_MIN_SPEED;
                boolean met = speed >= target;
                if (!met) missed.add(p.label + " samples/s");
                table.add(p.label, settings, Integer.toString(pairs), fmt(median(theirs), 3), fmt(median(mine), 3),
                        fmt(samples / median(theirs) / 1e6, 2), fmt(samples / median(mine) / 1e6, 2),
                        fmt(speed, 2) + "x (" + fmt(median(theirs) / median(mine), 2) + "x)", ">= " + fmt(target, 1) + "x " + (met ? "met" : "NOT met"),
                        fmt(diff.meanLuma(), 2));
                if (p == PeerBench.Peer.CYCLES) cycles = exe.toString();
            }
            out.printf("  %s beside the peers (%dx%d, %d spp, maxdepth %d; %d alternated pairs each; medians):%n", row, view.width(), view.height(),
                    spp, maxDepth, pairs);
            table.print(out);
            out.printf("  render s: tracing the frame only (ours: in this JVM after the row's warm-up; Embree: --benchmark 1 %d --legacy,%n", EMBREE_FRAMES);
            out.printf("  the mean of its timed frames; Cycles: status line Sample 0/%d to Sample %d/%d). Msamples/s: pixels x spp / render s.%n", spp, spp, spp);
            out.println("  speed: the median of the pairs' ratios, in brackets the ratio of the medians. image |dL|: mean absolute luma");
            out.println("  difference from ours in 8-bit sRGB steps (both noisy at this sample count). Embree's path length N is N hits,");
            out.println("  each with a light sample: our maxdepth N - 1. Embree traces every path to its length (it stops below a");
            out.println("  throughput of 0.01); we and Cycles end paths by Russian roulette, so the rays per sample differ.");
            if (cycles != null) noise(out, view, maxDepth, pairs, threads, ours, cycles, scratch, missed);
            out.printf("  %s: %s%n", row, missed.isEmpty() ? "every target met" : "not met: " + String.join(", ", missed));
        } finally {
            deleteTree(scratch);
        }
    }

    /**
     * Noise at equal time beside Cycles on the view at a quarter of its size: a converged Cycles
     * image, then per pair Cycles at {@link #NOISE_CYCLES_SPP} and ours at as many samples as our
     * speed at that size says fit in Cycles' render time; each image's mean squared error against
     * the converged one.
     */
    private static void noise(PrintStream out, PeerView full, int maxDepth, int pairs, int threads, Ours ours, String exe, Path scratch,
            List<String> missed) throws IOException {
        PeerView v = full.withSize(full.width() / NOISE_DIVISOR, full.height() / NOISE_DIVISOR);
        Path script = PeerInputs.writeCyclesScript(scratch), tga = scratch.resolve("noise.tga"), pfm = scratch.resolve("noise.pfm");
        Result ref = exec(scratch, PeerInputs.cyclesPath(exe, script, v, threads, tga, REFERENCE_SPP, maxDepth, 1000, pfm));
        if (!ref.ok()) {
            out.printf("  noise at equal time: the Cycles reference failed (exit %d): %s%n", ref.exit, ref.lastLine());
            return;
        }
        double[] reference = readPfm(pfm, v.width(), v.height());
        // Our speed at this size, from a render at Cycles' sample count.
        ours.render(NOISE_CYCLES_SPP, 0, v.width(), v.height());
        double ourSeconds = ours.render(NOISE_CYCLES_SPP, 0, v.width(), v.height()).stats().seconds();
        double[] cyclesTime = new double[pairs], ourTime = new double[pairs], cyclesMse = new double[pairs], ourMse = new double[pairs];
        int[] ourSpp = new int[pairs];
        for (int i = 0; i < pairs; i++) {
            Result c = exec(scratch, PeerInputs.cyclesPath(exe, script, v, threads, tga, NOISE_CYCLES_SPP, maxDepth, 2000 + i, pfm));
            cyclesTime[i] = c.ok() ? PeerLogs.cyclesSamplingSeconds(c.log, NOISE_CYCLES_SPP) : Double.NaN;
            cyclesMse[i] = c.ok() ? mse(readPfm(pfm, v.width(), v.height()), reference) : Double.NaN;
            int n = Math.max(1, (int) Math.round(NOISE_CYCLES_SPP * cyclesTime[i] / ourSeconds));
            BenchCommand.Measured m = ours.render(n, 3000 + i, v.width(), v.height());
            ourSpp[i] = n;
            ourTime[i] = m.stats().seconds();
            ourMse[i] = mse(m.image().data(), reference);
            ourSeconds = m.stats().seconds() * NOISE_CYCLES_SPP / n; // the next pair's estimate follows this one
        }
        double ratio = PeerBench.medianRatio(ourMse, cyclesMse);
        boolean met = ratio <= 1;
        if (!met) missed.add("Cycles noise at equal time");
        BenchTable t = new BenchTable("noise at equal time", "spp", "render s", "MSE vs converged Cycles");
        t.add("Blender Cycles", Integer.toString(NOISE_CYCLES_SPP), fmt(median(cyclesTime), 3), String.format(Locale.ROOT, "%.3e", median(cyclesMse)));
        double[] spp = new double[pairs];
        for (int i = 0; i < pairs; i++) spp[i] = ourSpp[i];
        t.add("ours", fmt(median(spp), 0), fmt(median(ourTime), 3), String.format(Locale.ROOT, "%.3e", median(ourMse)));
        out.printf("  noise at equal time (%dx%d, maxdepth %d; Cycles' converged image at %d spp; %d alternated pairs, medians):%n",
                v.width(), v.height(), maxDepth, REFERENCE_SPP, pairs);
        t.print(out);
        out.printf("  MSE: mean over pixels and channels of the squared linear difference. Our spp per pair: Cycles' render s over our%n");
        out.printf("  seconds per sample. MSE ours/Cycles %s (target: at most 1) %s%n", fmt(ratio, 2), met ? "met" : "NOT met");
    }

    private static double mse(double[] a, double[] b) {
        double s = 0;
        for (int i = 0; i < a.length; i++) s += (a[i] - b[i]) * (a[i] - b[i]);
        return s / a.length;
    }

    /** Reads the little-endian colour PFM the Cycles script writes, as linear RGB with the top row first. */
    static double[] readPfm(Path file, int w, int h) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        String header = "PF\n" + w + " " + h + "\n-1.0\n";
        if (!new String(bytes, 0, Math.min(bytes.length, header.length()), StandardCharsets.US_ASCII).equals(header)
                || bytes.length != header.length() + 12L * w * h) {
            throw new IOException(file + ": not the " + w + "x" + h + " little-endian PFM expected");
        }
        java.nio.ByteBuffer buf = java.nio.ByteBuffer.wrap(bytes, header.length(), 12 * w * h).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        double[] rgb = new double[3 * w * h];
        for (int row = h - 1; row >= 0; row--) for (int i = 0; i < 3 * w; i++) rgb[3 * w * row + i] = buf.getFloat();
        return rgb;
    }

    /** A finished peer process. */
    private record Result(int exit, String log) {
        boolean ok() { return exit == 0; }

        String lastLine() {
            String[] lines = log.strip().split("\\R");
            return lines.length == 0 ? "" : lines[lines.length - 1];
        }
    }

    private static Result exec(Path dir, List<String> cmd) throws IOException {
        Path log = dir.resolve("peer.log");
        Process p = new ProcessBuilder(cmd).directory(dir.toFile()).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        try {
            if (!p.waitFor(TIMEOUT_MINUTES, TimeUnit.MINUTES)) {
                p.destroyForcibly();
                return new Result(-1, "timed out after " + TIMEOUT_MINUTES + " minutes");
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException("interrupted", e);
        }
        return new Result(p.exitValue(), Files.readString(log, StandardCharsets.ISO_8859_1));
    }

    private static void deleteTree(Path dir) throws IOException {
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) Files.deleteIfExists(p);
        }
    }
}
