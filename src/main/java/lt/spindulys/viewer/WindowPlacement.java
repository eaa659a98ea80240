package lt.spindulys.viewer;

import java.awt.Dimension;
import java.awt.Rectangle;

/**
 * Where the render window goes and how a picture fits in it: plain geometry, kept out of the
 * Swing classes so it is tested without a display.
 */
public final class WindowPlacement {
    private WindowPlacement() {}

    /**
     * A window of (about) {@code size} beside {@code owner}: to its right, top edges aligned, when
     * it fits on the screen; else to its left; else as far right as the screen allows, overlapping
     * the owner. The window is shrunk to the screen if larger, and never leaves it.
     *
     * @param owner  the owner's bounds, in screen coordinates
     * @param size   the wanted size
     * @param screen the usable screen area (without task bars)
     * @return the window's bounds
     */
    public static Rectangle beside(Rectangle owner, Dimension size, Rectangle screen) {
        int w = Math.max(1, Math.min(size.width, screen.width));
        int h = Math.max(1, Math.min(size.height, screen.height));
        int right = owner.x + owner.width;
        int x;
        if (right + w <= screen.x + screen.width) {
            x = Math.max(screen.x, right);
        } else if (owner.x - w >= screen.x) {
            x = owner.x - w;
        } else {
            x = screen.x + screen.width - w;
        }
        int y = Math.max(screen.y, Math.min(owner.y, screen.y + screen.height - h));
        return new Rectangle(x, y, w, h);
    }

    /**
     * The largest rectangle with the picture's proportions inside an area, centred in it.
     *
     * @param width      the picture's width, at least 1
     * @param height     the picture's height, at least 1
     * @param areaWidth  the area's width
     * @param areaHeight the area's height
     * @return where to draw the picture (empty if the area is)
     */
    public static Rectangle fit(int width, int height, int areaWidth, int areaHeight) {
        if (areaWidth <= 0 || areaHeight <= 0) return new Rectangle(0, 0, 0, 0);
        double scale = Math.min((double) areaWidth / width, (double) areaHeight / height);
        int w = Math.max(1, (int) Math.round(width * scale));
        int h = Math.max(1, (int) Math.round(height * scale));
        w = Math.min(w, areaWidth);
        h = Math.min(h, areaHeight);
        return new Rectangle((areaWidth - w) / 2, (areaHeight - h) / 2, w, h);
    }
}
