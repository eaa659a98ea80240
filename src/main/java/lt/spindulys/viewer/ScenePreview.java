package lt.spindulys.viewer;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CancellationException;
import java.util.concurrent.Executor;

import lt.spindulys.camera.Camera;
import lt.spindulys.files.FileNames;
import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.io.CameraBlock;
import lt.spindulys.io.SceneParser;
import lt.spindulys.render.RenderJob;
import lt.spindulys.render.RenderResult;
import lt.spindulys.scene.InputFile;
import lt.spindulys.scene.SceneBuilder;

/**
 * A live preview of a scene file, without a window: it reads the scene, renders it in passes
 * ({@link PreviewPlan}) on a worker thread of its own, reads and renders again when the scene file
 * or a file it reads changes ({@link InputWatcher}), and lets the view be turned around the
 * camera's look-at point, with the camera written back as a {@code camera} block. What it shows
 * goes to a {@link Listener} through {@code ui} (the event thread, in the window).
 *
 * <p>A change cancels the render under way ({@link RenderJob#cancel}, which stops it between
 * tiles) and starts again from the first pass; what to do next and what to keep is decided by a
 * {@link PreviewState} under this object's lock.
 */
public final class ScenePreview implements AutoCloseable {
    /** How long the files must be quiet before a burst of changes is read. */
    static final long QUIET_MILLIS = 150;
    /** The least time between two showings of a pass filling in. */
    static final long TILES_INTERVAL_NANOS = 250_000_000L;

    /** Told what to show; called through the preview's {@code ui} executor, in order. */
    public interface Listener {
        /**
         * A pass finished: show its picture (scaled to fit: coarse passes are smaller).
         *
         * @param picture the pass's picture, 8-bit as {@code render} writes it
         * @param status  what it is, such as "pass 2 of 5: 80x60, 1 sample"
         */
        void picture(BufferedImage picture, String status);

        /**
         * A pass is under way: show its picture as far as it has come (its finished tiles over the
         * picture before, enlarged); a pass that takes long is shown so, at most 4 times a second.
         *
         * @param partial the pass's picture so far
         * @param status  what it is, with how much of it is done
         */
        void partial(BufferedImage partial, String status);

        /**
         * The state changed: reading, rendering pass N, done; and the error, if any.
         *
         * @param status what the preview is doing
         * @param error  the one-line error of the last read or pass (file:line:column: ...), or null
         */
        void status(String status, String error);
    }

    private final Path file;
    private final Integer frame;
    private final Executor ui;
    private final Listener listener;
    private final int threads;
    private final PreviewState state = new PreviewState();
    private final Thread worker;
    private InputWatcher watcher;
    /** The job rendering now, to cancel; guarded by the lock (this). */
    private RenderJob running;
    private boolean closed;

    /**
     * A preview of a scene file; nothing happens until {@link #start}.
     *
     * @param file     the scene file
     * @param frame    the animation frame to show, or null for a still (or an animation's first frame)
     * @param ui       where the listener is called (SwingUtilities::invokeLater in a window)
     * @param listener what is shown
     * @param threads  render threads
     */
    public ScenePreview(Path file, Integer frame, Executor ui, Listener listener, int threads) {
        this.file = Objects.requireNonNull(file, "file");
        this.frame = frame;
        this.ui = Objects.requireNonNull(ui, "ui");
        this.listener = Objects.requireNonNull(listener, "listener");
        if (threads < 1) throw new IllegalArgumentException("threads must be at least 1, found " + threads);
        this.threads = threads;
        worker = new Thread(this::work, "spindulys-preview");
        worker.setDaemon(true);
    }

    /**
     * Starts watching the files and rendering.
     *
     * @throws IOException if the file system cannot watch files
     */
    public void start() throws IOException {
        watcher = new InputWatcher(this::filesChanged, QUIET_MILLIS);
        watcher.watch(List.of(file), true);
        worker.start();
    }

    /** The files changed (the watcher calls this; so may a test): read them again. */
    synchronized void filesChanged() {
        state.filesChanged();
        interrupt();
    }

    /**
     * The view was dragged: it turns around the camera's look-at point; only coarse passes run
     * until {@link #released}.
     *
     * @param dx pixels to the right
     * @param dy pixels down
     */
    public synchronized void dragged(double dx, double dy) {
        state.dragged(dx, dy);
        interrupt();
    }

    /** The drag ended: the passes go on to the full picture. */
    public synchronized void released() {
        state.released();
        notifyAll();
    }

    /**
     * The wheel turned: the camera moves towards its look-at point (negative) or away.
     *
     * @param notches wheel notches
     */
    public synchronized void dollied(double notches) {
        state.dollied(notches);
        interrupt();
    }

    /** Back to the scene file's camera. */
    public synchronized void reset() {
        state.reset();
        interrupt();
    }

    /** {@return the camera the view shows as a {@code camera} block, or null before the scene was read well} */
    public synchronized String cameraBlock() { return state.cameraBlock(); }

    /** {@return the camera the view shows, or null before the scene was read well} */
    public synchronized Camera camera() { return state.camera(); }

    /**
     * Writes the camera the view shows into the scene file in place of its {@code camera}
     * statement ({@link CameraBlock#save}); the file's change is then read as any other, and the
     * view stays where it is, as the file's camera is now the view's.
     *
     * @return the block written
     * @throws IOException if the file cannot be read or written
     * @throws IllegalStateException before the scene was read well
     * @throws lt.spindulys.io.SceneException if the file does not read as statements now
     */
    public String saveCamera() throws IOException {
        Camera c = camera();
        if (c == null) throw new IllegalStateException("there is no camera to save before the scene has been read");
        return CameraBlock.save(file, c);
    }

    /** The work changed: the job under way is cancelled and the worker looks again. */
    private void interrupt() {
        if (running != null) running.cancel();
        notifyAll();
    }

    /** {@return the scene file} */
    public Path file() { return file; }

    private void work() {
        try {
            while (true) {
                PreviewState.Work w = null;
                synchronized (this) {
                    while (!closed && (w = state.next()) == null) wait();
                    if (closed) return;
                }
                try {
                    if (w instanceof PreviewState.Read r) read(r);
                    else render((PreviewState.Render) w);
                } catch (RuntimeException e) {
                    // A bug, not bad input (which read and render report): shown, and the preview goes on.
                    synchronized (this) { state.renderFailed(w.generation(), FailureMessage.of(e)); }
                    show("failed");
                }
            }
        } catch (InterruptedException e) {
            // Closed.
        }
    }

    private void read(PreviewState.Read r) {
        show("reading " + file.getFileName());
        SceneBuilder scene;
        CameraBlock.Located camera;
        String text;
        try {
            text = new String(Files.readAllBytes(file), StandardCharsets.UTF_8);
            scene = SceneParser.parse(file);
            camera = CameraBlock.locate(text, file.toString());
        } catch (NoSuchFileException e) {
            failed(r, file + ": the scene file is missing");
            return;
        } catch (IOException | RuntimeException | OutOfMemoryError e) {
            failed(r, FailureMessage.of(e));
            return;
        }
        List<Path> inputs = new ArrayList<>();
        inputs.add(file);
        for (InputFile f : scene.inputFiles()) inputs.add(f.path());
        String rest = rest(text, camera, scene);
        boolean finished;
        String shown;
        synchronized (this) {
            if (!state.read(r.generation(), scene, camera, rest)) return;
            finished = state.finished();
            shown = state.pictureOf() == null ? "" : state.pictureOf().describe();
        }
        watcher.watch(inputs, false);
        if (finished) show("done: " + shown + " (the file's camera is the view, and nothing else changed)");
    }

    /**
     * What the picture depends on besides the camera: the scene file's text without its camera
     * statement, and the size and time of every other file the scene read (a file that cannot be
     * looked at makes it unknown, null).
     */
    private String rest(String text, CameraBlock.Located camera, SceneBuilder scene) {
        StringBuilder s = new StringBuilder(camera == null ? text : text.substring(0, camera.start()) + text.substring(camera.end()));
        for (InputFile f : scene.inputFiles()) {
            if (FileNames.isSameFile(f.path(), file)) continue;
            try {
                // Size and time, not content: a file rewritten to the same size within the file
                // system's time step would pass for unchanged, a risk taken to read nothing twice.
                s.append('\0').append(f.path()).append(' ').append(Files.size(f.path())).append(' ')
                        .append(Files.getLastModifiedTime(f.path()).to(java.util.concurrent.TimeUnit.NANOSECONDS));
            } catch (IOException e) {
                return null;
            }
        }
        return s.toString();
    }

    private void failed(PreviewState.Read r, String message) {
        synchronized (this) {
            if (!state.readFailed(r.generation(), message)) return;
        }
        // The file missing may be one not watched yet: any change in the watched folders may fix it.
        if (watcher != null) watcher.watch(watchedAfterFailure(), true);
        show(keeping("the scene does not read"));
    }

    private synchronized List<Path> watchedAfterFailure() {
        List<Path> inputs = new ArrayList<>();
        inputs.add(file);
        if (state.scene() != null) for (InputFile f : state.scene().inputFiles()) inputs.add(f.path());
        return inputs;
    }

    private void render(PreviewState.Render r) {
        String what = "pass " + (r.index() + 1) + " of " + r.count() + ": " + r.pass().describe();
        BufferedImage before;
        synchronized (this) { before = state.picture(); }
        RenderJob job = RenderJob.of(r.scene()).settings(r.pass()::apply).threads(threads)
                .tiles(new TileCanvas(r.pass().width(), r.pass().height(), r.scene().settings().srgb(), before,
                        (partial, fraction) -> partly(r.generation(), partial, "rendering " + what + ", " + Math.round(fraction * 100) + " %"),
                        TILES_INTERVAL_NANOS));
        if (r.camera() != null) job.camera(c -> r.camera());
        Integer n = frame != null ? frame : r.scene().animation() != null ? Integer.valueOf(r.scene().animation().first()) : null;
        if (n != null) job.frame(n);
        synchronized (this) {
            if (r.generation() != state.generation() || closed) return;
            running = job;
        }
        show("rendering " + what);
        try {
            RenderResult result = job.run();
            BufferedImage picture = result.image();
            boolean done;
            synchronized (this) {
                running = null;
                if (!state.rendered(r.generation(), r.index(), picture)) return;
                done = state.finished();
            }
            String status = what + (done ? " (done)" : "");
            ui.execute(() -> listener.picture(picture, status));
            show(done ? "done: " + what : "rendered " + what);
        } catch (CancellationException e) {
            synchronized (this) { running = null; }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (IOException | RuntimeException | OutOfMemoryError e) {
            synchronized (this) {
                running = null;
                if (!state.renderFailed(r.generation(), FailureMessage.of(e))) return;
            }
            show(keeping("the scene does not render"));
        }
    }

    /** The status after a failure: what failed, and whether a picture from before stays shown. */
    private synchronized String keeping(String failure) {
        return state.picture() != null ? failure + "; showing the last good picture" : failure;
    }

    /** Shows a pass as far as it has come, unless the pass is already out of date. */
    private void partly(long generation, BufferedImage partial, String status) {
        synchronized (this) {
            if (generation != state.generation()) return;
        }
        ui.execute(() -> listener.partial(partial, status));
    }

    /** Tells the listener what the preview does, with the current error. */
    private void show(String status) {
        String error;
        synchronized (this) { error = state.error(); }
        ui.execute(() -> listener.status(status, error));
    }

    /** Stops rendering and watching; the worker ends once the job under way notices. */
    @Override
    public void close() {
        synchronized (this) {
            closed = true;
            interrupt();
        }
        if (watcher != null) watcher.close();
        worker.interrupt();
    }
}
