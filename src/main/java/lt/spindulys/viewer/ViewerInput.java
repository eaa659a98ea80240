package lt.spindulys.viewer;

import java.awt.event.KeyEvent;

/**
 * The viewer's keys and mouse, turned into the model's actions; no window needed, so the
 * bindings are tested headless. Keys: arrows orbit, + and - zoom, F fits, 1, 2, 3 pick
 * polyhedron, lattice, smoothed, C the cage over the surface, Page Up and Page Down change the
 * level. Mouse: left drag orbits, right or shift-left drag pans, the wheel zooms.
 */
public final class ViewerInput {
    /** Pixels of orbit per arrow key press. */
    static final int KEY_ORBIT = 20;
    /** Zoom per key press or wheel notch. */
    static final double ZOOM_STEP = 1.15;

    private final ViewerModel model;
    private int lastX, lastY;
    private boolean panning, dragging;

    /**
     * Input for a model.
     *
     * @param model what the input acts on
     */
    public ViewerInput(ViewerModel model) { this.model = model; }

    /**
     * A key was pressed.
     *
     * @param keyCode {@link KeyEvent#getKeyCode()}
     * @param keyChar {@link KeyEvent#getKeyChar()}
     * @return whether the key did something
     */
    public boolean key(int keyCode, char keyChar) {
        switch (keyCode) {
            case KeyEvent.VK_LEFT -> model.orbit(-KEY_ORBIT, 0);
            case KeyEvent.VK_RIGHT -> model.orbit(KEY_ORBIT, 0);
            case KeyEvent.VK_UP -> model.orbit(0, -KEY_ORBIT);
            case KeyEvent.VK_DOWN -> model.orbit(0, KEY_ORBIT);
            case KeyEvent.VK_PLUS, KeyEvent.VK_ADD, KeyEvent.VK_EQUALS -> model.zoom(ZOOM_STEP);
            case KeyEvent.VK_MINUS, KeyEvent.VK_SUBTRACT -> model.zoom(1 / ZOOM_STEP);
            case KeyEvent.VK_F -> model.fit();
            case KeyEvent.VK_1, KeyEvent.VK_NUMPAD1 -> model.mode(DisplayMode.POLYHEDRON);
            case KeyEvent.VK_2, KeyEvent.VK_NUMPAD2 -> model.mode(DisplayMode.LATTICE);
            case KeyEvent.VK_3, KeyEvent.VK_NUMPAD3 -> model.mode(DisplayMode.SMOOTHED);
            case KeyEvent.VK_C -> model.toggleCage();
            case KeyEvent.VK_PAGE_UP -> model.levelUp();
            case KeyEvent.VK_PAGE_DOWN -> model.levelDown();
            default -> {
                // '+' typed with shift on layouts without a plus key.
                if (keyChar == '+') model.zoom(ZOOM_STEP);
                else return false;
            }
        }
        return true;
    }

    /**
     * A mouse button went down.
     *
     * @param x where, in pixels
     * @param y where, in pixels
     * @param pan right button, or left with shift: the drag pans instead of orbiting
     */
    public void press(int x, int y, boolean pan) {
        lastX = x;
        lastY = y;
        panning = pan;
        dragging = true;
    }

    /**
     * The mouse moved with a button down.
     *
     * @param x where, in pixels
     * @param y where, in pixels
     */
    public void drag(int x, int y) {
        if (!dragging) return;
        int dx = x - lastX, dy = y - lastY;
        lastX = x;
        lastY = y;
        if (dx == 0 && dy == 0) return;
        if (panning) model.pan(dx, dy);
        else model.orbit(dx, dy);
    }

    /** The button went up. */
    public void release() { dragging = false; }

    /**
     * The wheel turned.
     *
     * @param notches {@link java.awt.event.MouseWheelEvent#getPreciseWheelRotation()}: positive towards the user, which zooms out
     */
    public void wheel(double notches) {
        if (notches == 0 || !Double.isFinite(notches)) return;
        model.zoom(Math.pow(ZOOM_STEP, -notches));
    }
}
