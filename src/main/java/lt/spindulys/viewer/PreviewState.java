package lt.spindulys.viewer;

import java.awt.image.BufferedImage;
import java.util.List;

import lt.spindulys.camera.Camera;
import lt.spindulys.io.CameraBlock;
import lt.spindulys.scene.SceneBuilder;

/**
 * What the scene preview knows and what it does next, without threads or windows: the scene as
 * last read well, the error of the last read or render (or none), the picture of the last pass
 * finished, the user's orbit of the camera, and the passes still to render ({@link PreviewPlan}).
 *
 * <p>Every change that makes the work under way useless (the files changed, the view moved) starts
 * a new generation: work is handed out with its generation ({@link #next}), and a result that
 * comes back from an older one is dropped, so a slow render cancelled too late never replaces a
 * newer picture. A read that fails keeps the scene read before it, so the last good picture stays
 * and the view can still be turned while the file is being fixed.
 *
 * <p>The orbit is kept over reads as long as the file's camera statement reads the same (spacing
 * and comments aside); when it changes (the user edited it, or the preview saved the view into
 * it) the view follows the file. After a save the file's camera is the view's, so the picture
 * does not move. Not thread safe: the preview's worker and the window call it under one lock.
 */
final class PreviewState {
    /** Work for the preview's worker. */
    sealed interface Work permits Read, Render {
        /** {@return the generation the work belongs to} */
        long generation();
    }

    /** Read the scene file (and what it names). */
    record Read(long generation) implements Work {}

    /**
     * Render one pass.
     *
     * @param scene  the scene as read
     * @param camera the camera to render with, or null for the scene's own
     * @param pass   the pass
     * @param index  its place in the plan, from 0
     * @param count  the passes in the plan
     */
    record Render(long generation, SceneBuilder scene, Camera camera, PreviewPlan.Pass pass, int index, int count) implements Work {}

    private long generation;
    private boolean stale = true;
    private SceneBuilder scene;
    /** The file's camera statement as last read well, or null when it has none. */
    private CameraBlock.Located cameraText;
    private CameraOrbit orbit = CameraOrbit.NONE;
    /** What the picture depends on besides the camera, as of the last good read (see {@link #read}); null if not known. */
    private String rest;
    private boolean dragging;
    private List<PreviewPlan.Pass> plan = List.of();
    private int nextPass;
    private String error;
    /** True if the error is the last read's, which only a good read clears (a pass's is cleared by the next pass that succeeds). */
    private boolean readError;
    private BufferedImage picture;
    private PreviewPlan.Pass pictureOf;

    /** The files changed: read them again, and drop the work under way. */
    void filesChanged() {
        stale = true;
        generation++;
    }

    /**
     * The next work to do, or null when there is none (everything rendered, or nothing readable yet).
     *
     * @return the work
     */
    Work next() {
        if (stale) return new Read(generation);
        if (scene == null || nextPass >= plan.size()) return null;
        // While dragging only the coarse passes keep up; the first one runs whatever it is.
        if (dragging && nextPass > 0 && !plan.get(nextPass).coarse()) return null;
        Camera c = orbit.isNone() ? null : orbit.apply(sceneCamera());
        return new Render(generation, scene, c, plan.get(nextPass), nextPass, plan.size());
    }

    /**
     * A read of generation {@code g} succeeded.
     *
     * @param g      the generation of the {@link Read}
     * @param read   the scene
     * @param camera the file's camera statement, or null when it has none
     * @param rest   what the picture depends on besides the camera (the file's text without its
     *               camera statement, and the other files' sizes and times), or null if not known:
     *               when it is as it was and the file's camera is the view, as after the view was
     *               saved into the file, the passes done stay done and the picture stays
     * @return false if the read was of an older generation and was dropped
     */
    boolean read(long g, SceneBuilder read, CameraBlock.Located camera, String rest) {
        if (g != generation) return false;
        String view = scene == null ? null : cameraBlock();
        boolean unchanged = rest != null && rest.equals(this.rest) && view != null
                && view.equals(CameraBlock.format(cameraOf(read), camera == null ? null : camera.keysText()));
        String before = cameraText == null ? null : cameraText.tokens();
        String now = camera == null ? null : camera.tokens();
        // The first read, or a camera statement that changed: the view follows the file.
        if (scene == null || !java.util.Objects.equals(before, now)) orbit = CameraOrbit.NONE;
        scene = read;
        cameraText = camera;
        this.rest = rest;
        stale = false;
        error = null;
        readError = false;
        if (!unchanged) {
            plan = PreviewPlan.of(read.settings());
            nextPass = 0;
        }
        return true;
    }

    /**
     * A read of generation {@code g} failed: the scene read before stays, and so does its picture.
     *
     * @param g       the generation of the {@link Read}
     * @param message the one-line error
     * @return false if the read was of an older generation and was dropped
     */
    boolean readFailed(long g, String message) {
        if (g != generation) return false;
        stale = false;
        error = message;
        readError = true;
        // Nothing new to show until the file is fixed or the view moves.
        nextPass = plan.size();
        return true;
    }

    /**
     * A pass finished.
     *
     * @param g       the generation of the {@link Render}
     * @param index   the pass's place in the plan
     * @param image   its picture
     * @return false if the pass was of an older generation and was dropped
     */
    boolean rendered(long g, int index, BufferedImage image) {
        if (g != generation) return false;
        picture = image;
        pictureOf = plan.get(index);
        if (!readError) error = null;
        nextPass = index + 1;
        return true;
    }

    /**
     * A pass failed (the scene does not build, the frame does not fit in the heap): no more passes
     * until something changes; the picture stays.
     *
     * @param g       the generation of the {@link Render}
     * @param message the one-line error
     * @return false if the pass was of an older generation and was dropped
     */
    boolean renderFailed(long g, String message) {
        if (g != generation) return false;
        error = message;
        readError = false;
        nextPass = plan.size();
        return true;
    }

    /**
     * The view was dragged: the orbit turns, and only coarse passes run until {@link #released}.
     *
     * @param dx pixels to the right
     * @param dy pixels down
     */
    void dragged(double dx, double dy) {
        if (scene == null) return;
        dragging = true;
        turn(orbit.dragged(dx, dy, sceneCamera()));
    }

    /** The drag ended: the passes go on to the full picture, from where the coarse ones stopped. */
    void released() {
        dragging = false;
    }

    /**
     * The wheel turned: the camera moves nearer or farther.
     *
     * @param notches wheel notches, negative towards the look-at point
     */
    void dollied(double notches) {
        if (scene == null) return;
        turn(orbit.dollied(notches));
    }

    /** Back to the file's camera. */
    void reset() {
        if (scene == null || orbit.isNone()) return;
        orbit = CameraOrbit.NONE;
        restart();
    }

    /** Moves the view, unless the camera it gives is one the camera refuses (an eye beyond the numbers a scene may hold): the view then stays. */
    private void turn(CameraOrbit next) {
        try {
            next.apply(sceneCamera());
        } catch (IllegalArgumentException e) {
            return;
        }
        orbit = next;
        restart();
    }

    private void restart() {
        generation++;
        nextPass = 0;
    }

    private Camera sceneCamera() { return cameraOf(scene); }

    private static Camera cameraOf(SceneBuilder b) { return b.camera() != null ? b.camera() : SceneBuilder.DEFAULT_CAMERA; }

    /** {@return the camera the view shows: the file's, moved by the orbit; null before the first good read} */
    Camera camera() { return scene == null ? null : orbit.apply(sceneCamera()); }

    /** {@return the view as a {@code camera} block ({@link CameraBlock#format}); null before the first good read} */
    String cameraBlock() {
        Camera c = camera();
        return c == null ? null : CameraBlock.format(c, cameraText == null ? null : cameraText.keysText());
    }

    /** {@return true if the view is the file's camera as it is} */
    boolean atFileCamera() { return orbit.isNone(); }

    /** {@return the current generation} */
    long generation() { return generation; }

    /** {@return the error of the last read or pass, or null when they went well} */
    String error() { return error; }

    /** {@return the picture of the last pass finished, kept through errors; null before the first} */
    BufferedImage picture() { return picture; }

    /** {@return the pass the picture is of, or null} */
    PreviewPlan.Pass pictureOf() { return pictureOf; }

    /** {@return true once a read went well} */
    boolean hasScene() { return scene != null; }

    /** {@return the scene as last read well, or null} */
    SceneBuilder scene() { return scene; }

    /** {@return true when every pass of the view is done} */
    boolean finished() { return scene != null && !stale && nextPass >= plan.size(); }
}
