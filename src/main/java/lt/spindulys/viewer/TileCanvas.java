package lt.spindulys.viewer;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.function.BiConsumer;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.render.TileListener;

/**
 * A pass of the scene preview filling in tile by tile over the picture before it (enlarged to the
 * pass's size, nearest pixel), handed on at most once per interval with how much of the pass is
 * done. Tiles are converted on the render threads as they finish, each pixel once, to the 8 bits
 * the finished pass's picture has. The canvas is made at the first tile, once the render has
 * checked its frame against the heap, and is itself checked before it is allocated.
 */
final class TileCanvas implements TileListener {
    private final int width, height;
    private final boolean srgb;
    private final BufferedImage before;
    private final BiConsumer<BufferedImage, Double> show;
    private final long intervalNanos;
    private int[] rgb;
    private long done, last;

    /**
     * @param width         the pass's width
     * @param height        its height
     * @param srgb          whether the scene's 8-bit pictures are sRGB-encoded
     * @param before        the picture shown before the pass, or null (the canvas starts black)
     * @param show          given a copy of the canvas and the fraction of its pixels done, at most once per interval
     * @param intervalNanos the least time between two showings
     */
    TileCanvas(int width, int height, boolean srgb, BufferedImage before, BiConsumer<BufferedImage, Double> show, long intervalNanos) {
        this.width = width;
        this.height = height;
        this.srgb = srgb;
        this.before = before;
        this.show = show;
        this.intervalNanos = intervalNanos;
        last = System.nanoTime();
    }

    @Override
    public synchronized void tileDone(FrameBuffer frame, int x0, int y0, int x1, int y1) {
        if (rgb == null) start();
        double[] d = frame.data();
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int i = 3 * (y * width + x);
                rgb[y * width + x] = FrameBuffer.to8(d[i], srgb) << 16 | FrameBuffer.to8(d[i + 1], srgb) << 8 | FrameBuffer.to8(d[i + 2], srgb);
            }
        }
        done += (long) (x1 - x0) * (y1 - y0);
        long now = System.nanoTime();
        if (now - last >= intervalNanos && done < (long) width * height) {
            last = now;
            show.accept(image(), (double) done / ((long) width * height));
        }
    }

    /** The canvas, from the picture before enlarged (or black). */
    private void start() {
        HeapBudget.require(4L * width * height, "the preview's picture of " + width + "x" + height);
        rgb = new int[width * height];
        if (before == null) return;
        int bw = before.getWidth(), bh = before.getHeight();
        // A pass's picture is TYPE_INT_RGB: read in place rather than copied.
        int[] b = before.getType() == BufferedImage.TYPE_INT_RGB ? ((DataBufferInt) before.getRaster().getDataBuffer()).getData()
                : before.getRGB(0, 0, bw, bh, null, 0, bw);
        for (int y = 0; y < height; y++) {
            int by = (int) ((long) y * bh / height);
            for (int x = 0; x < width; x++) rgb[y * width + x] = b[by * bw + (int) ((long) x * bw / width)] & 0xFFFFFF;
        }
    }

    /** A copy of the canvas as an image. */
    private BufferedImage image() {
        BufferedImage img = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        System.arraycopy(rgb, 0, ((DataBufferInt) img.getRaster().getDataBuffer()).getData(), 0, rgb.length);
        return img;
    }
}
