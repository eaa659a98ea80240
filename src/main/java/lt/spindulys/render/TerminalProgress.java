package lt.spindulys.render;

import java.io.PrintStream;

/**
 * A one-line progress bar (percent, elapsed, remaining) redrawn in place on a terminal, at most
 * ten times a second, and cleared when the render ends.
 */
public final class TerminalProgress implements ProgressListener {
    private static final int BAR = 30;
    private final PrintStream out;
    private final long start = System.nanoTime();
    private long lastDraw;
    private int lastLength;

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
        if (f > 0 && f < 1) line.append("  remaining ").append(clock(elapsed * (1 - f) / f));
        int len = line.length();
        while (line.length() < lastLength) line.append(' ');
        lastLength = len;
        out.print(line);
        out.flush();
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
