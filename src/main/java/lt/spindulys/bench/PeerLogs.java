package lt.spindulys.bench;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Reads the peers' own render-only times out of their output: the time to trace the frame,
 * without start-up, parsing or acceleration build. Each returns NaN when its line is missing.
 */
final class PeerLogs {
    private PeerLogs() {}

    private static final Pattern EMBREE_AVG = Pattern.compile("^BENCHMARK_RENDER_AVG\\s+([0-9.]+)\\s*$", Pattern.MULTILINE);
    private static final Pattern POV_TRACE = Pattern.compile("Trace Time:[^(\\n]*\\(\\s*([0-9.]+) seconds\\)");
    private static final Pattern CYCLES_TIME = Pattern.compile("\\| Time:((?:\\d+:)*\\d+(?:\\.\\d+)?) \\|");

    /**
     * Embree's {@code --benchmark 1 N --legacy}: the mean frame time of the N timed frames
     * (1 / {@code BENCHMARK_RENDER_AVG}, in frames per second); the first frame, which builds
     * the BVH, is skipped by Embree itself.
     */
    static double embreeFrameSeconds(String log) {
        Matcher m = EMBREE_AVG.matcher(log);
        if (!m.find()) return Double.NaN;
        double fps = Double.parseDouble(m.group(1));
        return fps > 0 ? 1 / fps : Double.NaN;
    }

    /** POV-Ray's statistics: {@code Trace Time: ... (X seconds)}, the rendering of the frame after parsing. */
    static double povTraceSeconds(String log) {
        Matcher m = POV_TRACE.matcher(log);
        return m.find() ? Double.parseDouble(m.group(1)) : Double.NaN;
    }

    /**
     * Cycles' status lines: the time from {@code Sample 0/1} (scene and BVH ready) to
     * {@code Sample 1/1} (the one sample of every pixel traced), read from their
     * {@code | Time:MM:SS.ss |} fields.
     */
    static double cyclesSamplingSeconds(String log) {
        return cyclesSamplingSeconds(log, 1);
    }

    /** As {@link #cyclesSamplingSeconds(String)} for {@code samples} per pixel: {@code Sample 0/N} to {@code Sample N/N}. */
    static double cyclesSamplingSeconds(String log, int samples) {
        String first = "| Sample 0/" + samples, last = "| Sample " + samples + "/" + samples;
        double start = Double.NaN;
        for (String line : log.split("[\\r\\n]+")) {
            if (Double.isNaN(start) && line.endsWith(first)) {
                start = statusTime(line);
            } else if (!Double.isNaN(start) && line.endsWith(last)) {
                double end = statusTime(line);
                return end - start;
            }
        }
        return Double.NaN;
    }

    /** The elapsed time of a Cycles status line ({@code [H:]M:S.ss}), in seconds, or NaN. */
    static double statusTime(String line) {
        Matcher m = CYCLES_TIME.matcher(line);
        if (!m.find()) return Double.NaN;
        double t = 0;
        for (String part : m.group(1).split(":")) t = t * 60 + Double.parseDouble(part);
        return t;
    }
}
