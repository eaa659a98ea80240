package lt.spindulys.viewer;

import java.util.List;
import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;

/**
 * One run of an output plugin on its own thread, reporting to a {@link Listener} through the
 * user-interface executor (Swing's {@code invokeLater} in the viewer, a direct executor in tests).
 *
 * <p>The plugin may report progress and previews far faster than a screen can show them, so the
 * bridge keeps only the newest of each and posts at most one pending update of each kind: the user
 * interface never queues a backlog, and the final preview, being the newest, is always shown.
 * Everything the listener hears arrives in the order the plugin said it, the end ({@code finished}
 * or {@code failed}) last.
 */
public final class PluginRun {
    /** What a run tells the user interface; every call comes through the run's executor. */
    public interface Listener {
        /**
         * @param fraction how far, 0 to 1
         * @param stage    what is being done
         */
        void progress(double fraction, String stage);

        /**
         * @param width  the picture's width
         * @param height the picture's height
         * @param argb   its pixels, row after row from the top; owned by the listener
         * @param last   true for the final picture
         */
        void preview(int width, int height, int[] argb, boolean last);

        /** @param result what the plugin wrote */
        void finished(PluginResult result);

        /**
         * @param message   one line for the user ({@link FailureMessage#of})
         * @param cancelled true if the run ended because the user cancelled it
         */
        void failed(String message, boolean cancelled);
    }

    private record Progress(double fraction, String stage) {}

    private record Preview(int width, int height, int[] argb, boolean last) {}

    private final AtomicBoolean cancelled = new AtomicBoolean();
    private final AtomicReference<Progress> pendingProgress = new AtomicReference<>();
    private final AtomicReference<Preview> pendingPreview = new AtomicReference<>();
    private final CountDownLatch ended = new CountDownLatch(1);
    private final Executor ui;
    private final Listener listener;
    private final Thread thread;

    private PluginRun(OutputPlugin plugin, List<DisplayedSurface> surfaces, PluginView view, PluginForm.Accepted accepted,
                      Executor ui, Listener listener) {
        this.ui = Objects.requireNonNull(ui, "ui");
        this.listener = Objects.requireNonNull(listener, "listener");
        PluginRequest request = new PluginRequest(surfaces, view, accepted.values(), accepted.output(), new Bridge());
        // Not a daemon: closing the viewer's windows must not kill a run between its temporary file and the rename.
        this.thread = new Thread(() -> work(plugin, request), "plugin " + plugin.id());
    }

    /**
     * Starts {@code plugin} on a new thread.
     *
     * @param plugin   the plugin
     * @param surfaces what the host displays
     * @param view     the host's view
     * @param accepted the values and output the user accepted
     * @param ui       runs the listener's calls (the event thread's {@code invokeLater})
     * @param listener hears progress, previews and the end
     * @return the run, to cancel or wait for
     */
    public static PluginRun start(OutputPlugin plugin, List<DisplayedSurface> surfaces, PluginView view,
                                  PluginForm.Accepted accepted, Executor ui, Listener listener) {
        PluginRun run = new PluginRun(plugin, surfaces, view, accepted, ui, listener);
        run.thread.start();
        return run;
    }

    /** Asks the plugin to stop; it does so at its next check and writes nothing. */
    public void cancel() { cancelled.set(true); }

    /** @return whether {@link #cancel()} was called */
    public boolean isCancelled() { return cancelled.get(); }

    /** @return whether the plugin has returned or thrown (its end may still be on its way to the listener) */
    public boolean isDone() { return ended.getCount() == 0; }

    /**
     * Waits for the plugin to return or throw.
     *
     * @param timeout how long at most
     * @param unit    its unit
     * @return whether it ended in time
     * @throws InterruptedException if interrupted while waiting
     */
    public boolean await(long timeout, TimeUnit unit) throws InterruptedException {
        return ended.await(timeout, unit);
    }

    private void work(OutputPlugin plugin, PluginRequest request) {
        try {
            PluginResult result = plugin.run(request);
            Objects.requireNonNull(result, "plugin " + plugin.id() + " returned no result");
            ui.execute(() -> listener.finished(result));
        } catch (CancellationException e) {
            ui.execute(() -> listener.failed(FailureMessage.CANCELLED, true));
        } catch (Throwable e) {
            // Anything else ends the run, not the viewer: a third-party plugin's missing class or
            // assertion is reported like any failure rather than leaving the window waiting forever.
            String message = FailureMessage.of(e);
            boolean byUser = cancelled.get() && e instanceof InterruptedException;
            ui.execute(() -> listener.failed(byUser ? FailureMessage.CANCELLED : message, byUser));
        } finally {
            ended.countDown();
        }
    }

    /** The plugin's side: hands the newest values to the user interface without flooding it. */
    private final class Bridge implements PluginProgress {
        @Override
        public void progress(double fraction, String stage) {
            Progress p = new Progress(Math.max(0, Math.min(1, fraction)), stage == null ? "" : stage);
            if (pendingProgress.getAndSet(p) == null) {
                ui.execute(() -> {
                    Progress q = pendingProgress.getAndSet(null);
                    if (q != null) listener.progress(q.fraction, q.stage);
                });
            }
        }

        @Override
        public boolean isCancelled() { return cancelled.get(); }

        @Override
        public void preview(int width, int height, int[] argb, boolean last) {
            Objects.requireNonNull(argb, "argb");
            if (width < 1 || height < 1 || (long) width * height != argb.length) {
                throw new IllegalArgumentException("a preview of " + width + " x " + height + " pixels needs "
                        + (long) width * height + " values, found " + argb.length);
            }
            if (pendingPreview.getAndSet(new Preview(width, height, argb, last)) == null) {
                ui.execute(() -> {
                    Preview q = pendingPreview.getAndSet(null);
                    if (q != null) listener.preview(q.width, q.height, q.argb, q.last);
                });
            }
        }
    }
}
