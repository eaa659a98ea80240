package lt.spindulys.cli;

import java.io.PrintStream;

import lt.spindulys.render.ProgressListener;

/**
 * A one-line progress bar (percent, elapsed, remaining) redrawn in place on a terminal, at most
 * ten times a second, and cleared when the render ends.
 */
final class TerminalProgress implements ProgressListener {
    private static final int BAR = 30;
    private final PrintStream out;
    private final long start = System.nanoTime();
    private long lastDraw;
    private int lastLength;

    /**
     * A bar drawn on {@code out}, which should be a terminal (the command line's standard error).
     *
     * @param out where to draw
     */
    public TerminalProgress(PrintStream out) { this.out = out; }

    @Override
    public synchronized void progress(long done, long total) {
        long now = System.nanoTime();
        if (done < total && now - lastDraw < 100_000_000L) return;
        lastDraw = now;
        double f = total == 0 ? 1 : (double) done / total;
        double elapsed = (now - start) / 1e9;
        int filled = (int) Math.round(f * BAR);
        StringBuilder line = new StringBuilder("\r[");
        for (int i = 0; i < BAR; i++) line.append(i < filled ? '=' : ' ');
        line.append(String.format("] %3d%%  elapsed %s", (int) Math.floor(f * 100), clock(elapsed)));
        double remaining = remainingSeconds(done, total, elapsed);
        if (!Double.isNaN(remaining)) line.append("  remaining ").append(clock(remaining));
        int len = line.length();
        while (line.length() < lastLength) line.append(' ');
        lastLength = len;
        out.print(line);
        out.flush();
    }

    /** Share of the work done before a remaining time is shown: the first tiles are too few to go by. */
    static final double FIRST_ESTIMATE = 0.01;

    /**
     * The time still to go, from the average rate so far: {@code elapsed} per share done. The
     * Renderer hands out tiles spread over the frame ({@link Renderer#tileAt}), so the share
     * of pixels done is an even sample of the frame's work at every moment, and the rate over the
     * whole run is its least noisy measure (no smoothing window to tune, and the start-up's slow
     * first tiles, while the JIT compiles, weigh less and less). NaN before
     * {@value #FIRST_ESTIMATE} of the pixels are done, and once all are.
     */
    static double remainingSeconds(long done, long total, double elapsed) {
        if (total <= 0 || done >= total || done < FIRST_ESTIMATE * total) return Double.NaN;
        double f = (double) done / total;
        return elapsed * (1 - f) / f;
    }

    /** Erases the bar so that later output starts on a clean line. */
    public synchronized void finish() {
        if (lastLength == 0) return;
        out.print("\r" + " ".repeat(lastLength) + "\r");
        out.flush();
    }

    static String clock(double seconds) {
        long s = Math.round(seconds);
        return s >= 3600 ? String.format("%d:%02d:%02d", s / 3600, s / 60 % 60, s % 60) : String.format("%d:%02d", s / 60, s % 60);
    }
}
