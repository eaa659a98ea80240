package lt.spindulys.image;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.Objects;
import java.util.Set;
import java.util.stream.Collectors;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;

/**
 * A width x height image of linear RGB values in one flat {@code double[]}: row-major, y = 0 is
 * the top row, three consecutive values (r, g, b) per pixel, so pixel (x, y) starts at index
 * {@code 3 * (y * width + x)}.
 *
 * <p>Values are unbounded (HDR, negative or NaN values are stored as given); clamping happens only
 * when converting to 8 bits. Render threads may write disjoint pixels concurrently; the buffer has
 * no locking of its own.
 */
public final class FrameBuffer {
    /** Largest pixel count whose three doubles still fit in one Java array. */
    private static final long MAX_PIXELS = (Integer.MAX_VALUE - 8) / 3;

    private final int width, height;
    private final double[] data;

    /**
     * A black image; both dimensions must be at least 1.
     *
     * @param width pixels across
     * @param height pixels down
     */
    public FrameBuffer(int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        }
        if ((long) width * height > MAX_PIXELS) {
            throw new IllegalArgumentException("image size " + width + "x" + height + " is too large (at most "
                    + MAX_PIXELS + " pixels)");
        }
        this.width = width;
        this.height = height;
        this.data = new double[3 * width * height];
    }

    /**
     * Heap a render of a {@code width x height} frame needs for its images, per pixel: the frame
     * (three doubles), the 8-bit copy and the encoder's image made when it is written, and for
     * each pass asked: depth (a double), normal (three doubles, and a frame's worth again when it
     * is written), object (an int, and the codes and the encoder's image when written), noise
     * (two doubles, and a frame's worth when it is written).
     *
     * @param width pixels across
     * @param height pixels down
     * @param aovs the passes rendered beside the image
     * @return the bytes needed
     */
    public static long bytesToRender(int width, int height, Set<Aov> aovs) {
        long perPixel = 3 * 8 + 4 + 8;
        if (aovs.contains(Aov.DEPTH)) perPixel += 8;
        if (aovs.contains(Aov.NORMAL)) perPixel += 3 * 8 + 3 * 8;
        if (aovs.contains(Aov.OBJECT)) perPixel += 4 + 4 + 8;
        if (aovs.contains(Aov.NOISE)) perPixel += 2 * 8 + 3 * 8;
        if (aovs.contains(Aov.ALBEDO)) perPixel += 3 * 8 + 3 * 8;
        return HeapBudget.product(Math.max(0, width), Math.max(0, height), perPixel);
    }

    /**
     * Refuses a frame whose {@link #bytesToRender} the heap cannot give now.
     *
     * @param width pixels across
     * @param height pixels down
     * @param aovs the passes rendered beside the image
     * @throws InsufficientMemoryException "the 32768x16384 frame needs 17 GiB of heap, but only ..."
     */
    public static void checkHeap(int width, int height, Set<Aov> aovs) {
        String passes = aovs.isEmpty() ? "" : " with its " + aovs.stream().map(Aov::keyword).collect(Collectors.joining(", ")) + " pass"
                + (aovs.size() > 1 ? "es" : "");
        HeapBudget.require(bytesToRender(width, height, aovs), "the " + width + "x" + height + " frame" + passes);
    }

    /** {@return the width in pixels} */
    public int width() { return width; }

    /** {@return the height in pixels} */
    public int height() { return height; }

    /**
     * Stores the linear colour of pixel (x, y).
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param r linear red
     * @param g linear green
     * @param b linear blue
     */
    public void set(int x, int y, double r, double g, double b) {
        int i = index(x, y);
        data[i] = r;
        data[i + 1] = g;
        data[i + 2] = b;
    }

    /**
     * One linear channel (0 = red, 1 = green, 2 = blue) of pixel (x, y).
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param channel 0, 1 or 2
     * @return the linear value
     */
    public double get(int x, int y, int channel) {
        Objects.checkIndex(channel, 3);
        return data[index(x, y) + channel];
    }

    /**
     * The backing array itself (not a copy): 3 values per pixel, row-major, top row first.
     *
     * @return the pixel values
     */
    public double[] data() { return data; }

    private int index(int x, int y) {
        // Checked separately: a flat-index check alone would let x = width wrap into the next row.
        Objects.checkIndex(x, width);
        Objects.checkIndex(y, height);
        return 3 * (y * width + x);
    }

    /**
     * The image as an 8-bit {@link BufferedImage#TYPE_INT_RGB} image, converted as {@link #toRgb8}
     * does (so it holds exactly the pixels a PNG of this buffer would), for display or for
     * further processing with Java's imaging classes. A new image each call.
     *
     * @param srgb whether to encode with the sRGB curve (else linear), as for a PNG
     * @return a new image of this buffer's size
     */
    public BufferedImage toBufferedImage(boolean srgb) {
        return rgbImage(width, height, toRgb8(srgb));
    }

    /** A {@code TYPE_INT_RGB} image of packed {@code 0xRRGGBB} pixels (row-major, top row first), as they are. */
    static BufferedImage rgbImage(int w, int h, int[] rgb) {
        BufferedImage img = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) img.getRaster().getDataBuffer()).getData();
        System.arraycopy(rgb, 0, pixels, 0, pixels.length);
        return img;
    }

    /**
     * Converts to packed 8-bit {@code 0xRRGGBB} values, row-major, top row first. Each channel is
     * clamped to [0, 1] (NaN counts as 0), encoded with the sRGB transfer function if {@code srgb}
     * (otherwise left linear), then scaled by 255 and rounded to nearest.
     *
     * @param srgb whether to encode with the sRGB curve (else linear)
     * @return one int per pixel
     */
    public int[] toRgb8(boolean srgb) {
        int n = width * height;
        int[] out = new int[n];
        for (int p = 0, i = 0; p < n; p++, i += 3) {
            out[p] = (to8(data[i], srgb) << 16) | (to8(data[i + 1], srgb) << 8) | to8(data[i + 2], srgb);
        }
        return out;
    }

    /**
     * The inverse of {@link #toRgb8}: builds a buffer from packed {@code 0xRRGGBB} values (the top
     * byte is ignored), decoding sRGB to linear if {@code srgb}. {@code fromRgb8(...).toRgb8(srgb)}
     * gives the same packed values back.
     *
     * @param width pixels across
     * @param height pixels down
     * @param packed one int per pixel, at least width * height
     * @param srgb whether the values are sRGB-encoded
     * @return the buffer
     */
    public static FrameBuffer fromRgb8(int width, int height, int[] packed, boolean srgb) {
        FrameBuffer fb = new FrameBuffer(width, height);
        if (packed.length != width * height) {
            throw new IllegalArgumentException("expected " + width * height + " packed pixels for "
                    + width + "x" + height + ", got " + packed.length);
        }
        double[] lut = new double[256];
        for (int k = 0; k < 256; k++) lut[k] = srgb ? srgbToLinear(k / 255.0) : k / 255.0;
        double[] d = fb.data;
        for (int p = 0, i = 0; p < packed.length; p++, i += 3) {
            int v = packed[p];
            d[i] = lut[(v >>> 16) & 0xFF];
            d[i + 1] = lut[(v >>> 8) & 0xFF];
            d[i + 2] = lut[v & 0xFF];
        }
        return fb;
    }

    /**
     * One channel as {@link #toRgb8} converts it: clamped to [0, 1] (NaN counts as 0), encoded
     * with the sRGB curve if {@code srgb}, scaled by 255 and rounded to nearest; for code that
     * converts part of a frame, such as a tile just rendered.
     *
     * @param v    a linear value
     * @param srgb whether to encode with the sRGB curve (else linear)
     * @return 0 to 255
     */
    public static int to8(double v, boolean srgb) {
        // The negated comparison also catches NaN.
        if (!(v > 0)) return 0;
        if (v >= 1) return 255;
        return (int) Math.round((srgb ? linearToSrgb(v) : v) * 255.0);
    }

    /**
     * The sRGB opto-electronic transfer function (IEC 61966-2-1) for a linear value in [0, 1].
     *
     * @param linear a linear value in [0, 1]
     * @return the encoded value, in [0, 1]
     */
    public static double linearToSrgb(double linear) {
        return linear <= 0.0031308 ? 12.92 * linear : 1.055 * Math.pow(linear, 1 / 2.4) - 0.055;
    }

    /**
     * The inverse of {@link #linearToSrgb}, for an encoded value in [0, 1].
     *
     * @param encoded an encoded value in [0, 1]
     * @return the linear value, in [0, 1]
     */
    public static double srgbToLinear(double encoded) {
        return encoded <= 0.04045 ? encoded / 12.92 : Math.pow((encoded + 0.055) / 1.055, 2.4);
    }
}
