package lt.spindulys.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import lt.spindulys.subdiv.SubdivOptions;

/**
 * Runs a peer program that the benchmark compares against, when it is installed. The project
 * never depends on one: a missing peer yields no figure, and the bench says so.
 */
final class ExternalTimer {
    private ExternalTimer() {}

    /** The executable's path if it is on PATH, else null. */
    static Path onPath(String name) {
        String path = System.getenv("PATH");
        if (path == null) return null;
        for (String dir : path.split(java.io.File.pathSeparator)) {
            Path p = Path.of(dir, name);
            if (Files.isExecutable(p)) return p;
        }
        return null;
    }

    /**
     * Median over {@code runs} runs of OpenSubdiv's own time for uniform topology refinement of
     * {@code obj} with {@code scheme} to {@code level} ({@code far_perf -u -l N -nopatches
     * -nostencils -double -catmark|-loop|-bilinear}: far_perf takes the scheme from its command
     * line, not from the file), in seconds, or NaN if far_perf is not installed or its output
     * cannot be read.
     */
    static double farPerfRefineSeconds(Path obj, SubdivOptions.Scheme scheme, int level, int runs) {
        Path exe = onPath("far_perf");
        if (exe == null) return Double.NaN;
        Pattern row = Pattern.compile("TopologyRefiner::Refine\\s+([0-9.]+)");
        double[] times = new double[runs];
        for (int r = 0; r < runs; r++) {
            String out = run(List.of(exe.toString(), "-u", "-l", Integer.toString(level), "-nopatches", "-nostencils", "-double",
                    "-" + scheme.keyword(), obj.toString()));
            if (out == null) return Double.NaN;
            // The last "level N" block is the refinement to the requested level.
            int at = out.lastIndexOf("level " + level + ":");
            if (at < 0) return Double.NaN;
            Matcher m = row.matcher(out.substring(at));
            if (!m.find()) return Double.NaN;
            times[r] = Double.parseDouble(m.group(1));
        }
        Arrays.sort(times);
        return times[runs / 2];
    }

    private static String run(List<String> command) {
        try {
            Process p = new ProcessBuilder(new ArrayList<>(command)).redirectErrorStream(true).start();
            byte[] out = p.getInputStream().readAllBytes();
            if (!p.waitFor(10, TimeUnit.MINUTES) || p.exitValue() != 0) return null;
            return new String(out, StandardCharsets.UTF_8);
        } catch (IOException e) {
            return null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return null;
        }
    }
}
