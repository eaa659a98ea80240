package lt.spindulys.cli;

import java.io.PrintStream;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Supplier;

import lt.spindulys.limits.MessageText;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.RenderJob;

/**
 * Progress for a render farm's manager, one line at a time (never redrawn in place), printed by a
 * daemon thread at least every {@link #INTERVAL_SECONDS} seconds from start to end, whatever the
 * job is doing: a manager that watches a task's output for signs of life (OpenCue flags a frame
 * silent for long as hung) sees one even while a large scene loads or builds.
 *
 * <ul>
 *   <li>{@link Mode#OPENJD}: the Open Job Description directives, which Deadline Cloud and other
 *       OpenJD runtimes read from a task's output: {@code openjd_status: MESSAGE} when the job
 *       enters a step (loading, building, rendering, writing), {@code openjd_progress: P} (percent,
 *       one decimal) every interval while it renders, {@code openjd_progress: 100.0} and
 *       {@code openjd_status: wrote ...} once the files are written, and
 *       {@code openjd_fail: MESSAGE} with the one-line error when it fails.</li>
 *   <li>{@link Mode#PLAIN}: {@code render: STEP, P% done, M:SS elapsed, about M:SS to go}, the
 *       share and the estimate only while rendering.</li>
 * </ul>
 *
 * <p>A task that renders several frames reports them as one piece of work: {@link #item} starts
 * frame {@code index} of {@code count}, and the share done is that of all of them.
 */
final class FarmProgress implements ProgressListener, AutoCloseable {
    /** The most seconds between two lines. */
    public static final int INTERVAL_SECONDS = 2;

    /** The form of the lines. */
    public enum Mode {
        /** Open Job Description's {@code openjd_progress:} and {@code openjd_status:} lines. */
        OPENJD,
        /** Plain sentences for a person reading a task's log. */
        PLAIN;

        /**
         * The mode named by {@code --progress}: {@code openjd} or {@code plain}.
         *
         * @param word the option's value
         * @return the mode
         * @throws IllegalArgumentException for any other word
         */
        public static Mode of(String word) {
            return switch (word) {
                case "openjd" -> OPENJD;
                case "plain" -> PLAIN;
                default -> throw new IllegalArgumentException("expected openjd or plain, found '" + word + "'");
            };
        }
    }

    private final Mode mode;
    private final PrintStream out;
    private final Supplier<RenderJob.Stage> stage;
    private String what;
    private int index, count = 1;
    private final long start;
    private long done, total;
    private RenderJob.Stage lastStage;
    private long lastLine;
    private Thread ticker;
    private boolean closed;

    /**
     * A sink that reports on {@code out}.
     *
     * @param mode  the form of the lines
     * @param out   where to print them (the command line prints OpenJD lines on standard output, plain ones on standard error)
     * @param stage tells the step the job now running is in ({@link RenderJob#stage})
     * @param what  what is rendered, for status lines, e.g. the output file's name
     * @param startNanos the {@link System#nanoTime} the run started at
     */
    public FarmProgress(Mode mode, PrintStream out, Supplier<RenderJob.Stage> stage, String what, long startNanos) {
        this.mode = Objects.requireNonNull(mode);
        this.out = Objects.requireNonNull(out);
        this.stage = Objects.requireNonNull(stage);
        this.what = MessageText.escape(what);
        this.start = startNanos;
    }

    /** How often the thread looks at the job: a new step is reported this soon. */
    static final long POLL_MILLIS = 200;

    /** Starts the thread that prints a line on every new step and at least every {@link #INTERVAL_SECONDS} seconds, and prints the first. */
    public synchronized void start() {
        if (ticker != null) return;
        tick(System.nanoTime());
        ticker = new Thread(() -> {
            try {
                while (!Thread.currentThread().isInterrupted()) {
                    Thread.sleep(POLL_MILLIS);
                    tick(System.nanoTime());
                }
            } catch (InterruptedException e) {
                // stopped by close()
            }
        }, "spindulys-farm-progress");
        ticker.setDaemon(true);
        ticker.start();
    }

    @Override
    public synchronized void progress(long donePixels, long totalPixels) {
        done = Math.max(done, donePixels); // reports from several threads may arrive out of order
        total = totalPixels;
    }

    /**
     * Prints what the job is doing now, if it has entered a new step or no line was printed for
     * {@link #INTERVAL_SECONDS} seconds; else nothing.
     *
     * @param now a {@link System#nanoTime} reading
     */
    public synchronized void tick(long now) {
        if (closed) return; // the ticker may wait for the lock while the end is reported: nothing after it
        RenderJob.Stage s = stage.get();
        // Steps that read the same (ready and checking, settings and building) are one status.
        boolean changed = lastStage == null || !step(s).equals(step(lastStage)), due = changed || now - lastLine >= INTERVAL_SECONDS * 1_000_000_000L;
        if (!changed && !due) return;
        double elapsed = (now - start) / 1e9;
        boolean rendering = s == RenderJob.Stage.RENDER;
        double share = (index + (rendering && total > 0 ? (double) done / total : 0)) / count;
        if (mode == Mode.OPENJD) {
            // The status again on each interval outside rendering: a sign of life while a large scene loads.
            if (changed || !rendering) out.println("openjd_status: " + step(s));
            if (rendering) out.println(String.format(Locale.ROOT, "openjd_progress: %.1f", Math.floor(share * 1000) / 10));
        } else {
            StringBuilder line = new StringBuilder("render: ").append(step(s));
            if (count > 1) line.append(" (").append(index + 1).append(" of ").append(count).append(')');
            if (rendering) line.append(String.format(Locale.ROOT, ", %d%% done", (int) Math.floor(share * 100)));
            line.append(", ").append(TerminalProgress.clock(elapsed)).append(" elapsed");
            // The rate so far over all the items: the first one's load and build weigh on it less and less.
            double remaining = rendering ? TerminalProgress.remainingSeconds(Math.round(share * 1e9), 1_000_000_000L, elapsed) : Double.NaN;
            if (!Double.isNaN(remaining)) line.append(", about ").append(TerminalProgress.clock(remaining)).append(" to go");
            out.println(line);
        }
        lastStage = s;
        lastLine = now;
        out.flush();
    }

    /** What the job is doing in step {@code s}, as a status. */
    private String step(RenderJob.Stage s) {
        return switch (s) {
            case READY, CHECK -> "starting " + what;
            case LOAD -> "loading the scene for " + what;
            case SETTINGS, BUILD -> "building the scene for " + what;
            case RENDER -> "rendering " + what;
            case WRITE -> "writing " + what;
            case DONE -> "wrote " + what;
        };
    }

    /**
     * Starts item {@code index} of {@code count} (a frame of several), rendered to {@code what}; its
     * step is reported as soon as it is seen.
     *
     * @param what  what the item writes, for status lines
     * @param index which item, from 0
     * @param count how many items the task renders, at least {@code index + 1}
     */
    public synchronized void item(String what, int index, int count) {
        if (index < 0 || count <= index) throw new IllegalArgumentException("item " + index + " of " + count);
        this.what = MessageText.escape(what);
        this.index = index;
        this.count = count;
        done = 0;
        total = 0;
        lastStage = null;
    }

    /**
     * Reports an item written: with OpenJD, the share of the task now done
     * ({@code openjd_progress: 100.0} after the last item) and a status naming what was written.
     * After the last item the thread stops.
     *
     * @param message what was done, e.g. the closing "wrote ..." line
     */
    public synchronized void wrote(String message) {
        if (index + 1 == count) close();
        if (mode == Mode.OPENJD) {
            out.println(String.format(Locale.ROOT, "openjd_progress: %.1f", Math.floor((index + 1) * 1000.0 / count) / 10));
            out.println("openjd_status: " + MessageText.escape(message));
            out.flush();
        }
    }

    /**
     * Stops the thread and reports a failure: with OpenJD, {@code openjd_fail:} and the one-line
     * error (printed on standard error too, by the command line).
     *
     * @param message the one-line error
     */
    public synchronized void failed(String message) {
        close();
        if (mode == Mode.OPENJD) {
            out.println("openjd_fail: " + MessageText.escape(message));
            out.flush();
        }
    }

    /**
     * Reports a failure before any progress was started, as {@link #failed} does with OpenJD: a
     * task whose arguments are refused ({@code --tile 9/3}) still tells its manager why it ended.
     *
     * @param out     where the OpenJD lines go (standard output)
     * @param message the one-line error
     */
    public static void failedBeforeStart(PrintStream out, String message) {
        new FarmProgress(Mode.OPENJD, out, () -> RenderJob.Stage.READY, "", System.nanoTime()).failed(message);
    }

    /** Stops the thread; prints nothing. */
    @Override
    public void close() {
        Thread t;
        synchronized (this) {
            t = ticker;
            ticker = null;
            closed = true;
        }
        if (t != null) t.interrupt();
    }
}
