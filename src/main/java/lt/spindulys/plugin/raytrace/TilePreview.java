package lt.spindulys.plugin.raytrace;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.render.TileListener;

/**
 * The full picture filling in tile by tile over the coarse preview scaled up, handed to the host
 * as a preview at most once per interval (and never after the render, whose final picture the
 * plugin hands over itself). Tiles are converted as they finish, on the render threads: each
 * pixel once, as the written image's 8 bits.
 */
final class TilePreview implements TileListener {
    private final int width, height;
    private final int[] argb;
    private final PluginProgress progress;
    private final long intervalNanos;
    private long last;

    /**
     * @param width         the picture's width
     * @param height        the picture's height
     * @param coarse        the coarse preview, {@code coarseWidth * coarseHeight} pixels 0xAARRGGBB
     * @param progress      where previews go
     * @param intervalNanos the least time between two previews
     */
    TilePreview(int width, int height, int[] coarse, int coarseWidth, int coarseHeight, PluginProgress progress, long intervalNanos) {
        this.width = width;
        this.height = height;
        this.progress = progress;
        this.intervalNanos = intervalNanos;
        argb = new int[width * height];
        for (int y = 0; y < height; y++) {
            int cy = (int) ((long) y * coarseHeight / height);
            for (int x = 0; x < width; x++) argb[y * width + x] = coarse[cy * coarseWidth + (int) ((long) x * coarseWidth / width)];
        }
        last = System.nanoTime();
    }

    @Override
    public synchronized void tileDone(FrameBuffer frame, int x0, int y0, int x1, int y1) {
        double[] d = frame.data();
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int i = 3 * (y * width + x);
                argb[y * width + x] = 0xFF000000 | FrameBuffer.to8(d[i], true) << 16 | FrameBuffer.to8(d[i + 1], true) << 8 | FrameBuffer.to8(d[i + 2], true);
            }
        }
        long now = System.nanoTime();
        if (now - last >= intervalNanos) {
            last = now;
            // Handed over under the lock, so the host gets previews in the order they were made.
            progress.preview(width, height, argb.clone(), false);
        }
    }
}
