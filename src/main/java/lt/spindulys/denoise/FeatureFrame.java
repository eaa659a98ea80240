package lt.spindulys.denoise;

import java.util.Objects;

import lt.spindulys.limits.HeapBudget;

/**
 * The auxiliary buffers a denoiser is guided by, one value set per pixel, each averaged over the
 * pixel's samples with the same weights as its colour (so edges, depth of field and motion blur
 * match the image): the albedo of the first surface a camera sample hit (r, g, b), its shading
 * normal facing the camera (x, y, z; not renormalised, so a pixel across an edge has a shorter
 * mean), the inverse of its distance (0 for samples that hit nothing), the variance of the
 * pixel's mean colour per channel (the samples' variance over their count), and the variance of
 * the means of the albedo, the normal (each the mean over its channels) and the inverse depth.
 * Row-major, y = 0 the top row. Render threads may write disjoint pixels concurrently; no locking.
 */
public final class FeatureFrame {
    /** Values kept per pixel: albedo 3, normal 3, inverse depth 1, colour variance 3, feature variance 3. */
    public static final int VALUES = 13;
    /** Offsets of each kind of value within a pixel's {@link #VALUES}. */
    public static final int ALBEDO = 0, NORMAL = 3, INVERSE_DEPTH = 6, VARIANCE = 7, FEATURE_VARIANCE = 10;

    private final int width, height;
    private final double[] data;

    /**
     * A frame with every value 0.
     *
     * @param width pixels across, at least 1
     * @param height pixels down, at least 1
     * @throws IllegalArgumentException if the size is below 1x1 or too large for one array
     */
    public FeatureFrame(int width, int height) {
        if (width < 1 || height < 1) throw new IllegalArgumentException("image size must be at least 1x1, got " + width + "x" + height);
        if ((long) VALUES * width * height > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("image size " + width + "x" + height + " is too large for its denoising features");
        }
        this.width = width;
        this.height = height;
        this.data = new double[VALUES * width * height];
    }

    /**
     * Heap a frame of this size holds.
     *
     * @param width pixels across
     * @param height pixels down
     * @return bytes, saturating
     */
    public static long bytes(int width, int height) {
        return HeapBudget.product(Math.max(0, width), Math.max(0, height), 8L * VALUES);
    }

    /** {@return the width in pixels} */
    public int width() { return width; }

    /** {@return the height in pixels} */
    public int height() { return height; }

    /**
     * Stores the {@link #VALUES} of pixel (x, y), or adds them to what is there; then divides
     * the means by {@code divide} and the variances by its square (the last of several passes
     * averaged with equal weights).
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param values albedo, normal, inverse depth, variance of the mean colour, variances of the mean features, in the order of the offsets above
     * @param accumulate add instead of replacing
     * @param divide at least 1
     */
    public void put(int x, int y, double[] values, boolean accumulate, int divide) {
        int o = VALUES * index(x, y);
        for (int i = 0; i < VALUES; i++) {
            double v = accumulate ? data[o + i] + values[i] : values[i];
            if (divide != 1) v /= i < VARIANCE ? divide : (double) divide * divide; // the variances: of a mean of divide passes
            data[o + i] = v;
        }
    }

    /**
     * One value of pixel (x, y).
     *
     * @param x column, 0 at the left
     * @param y row, 0 at the top
     * @param value an offset ({@link #ALBEDO} + channel, ...), below {@link #VALUES}
     * @return the value
     */
    public double get(int x, int y, int value) {
        Objects.checkIndex(value, VALUES);
        return data[VALUES * index(x, y) + value];
    }

    /** The values, {@link #VALUES} per pixel, row-major (the backing array, not a copy). */
    double[] data() { return data; }

    private int index(int x, int y) {
        Objects.checkIndex(x, width);
        Objects.checkIndex(y, height);
        return y * width + x;
    }
}
