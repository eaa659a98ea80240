package lt.spindulys.image;

import java.util.Locale;
import java.util.Objects;

/**
 * Compares two images in 8-bit units (0..255 per channel), as a viewer would see them, for
 * regression renders against golden images.
 *
 * <p>A pixel is "over" the threshold when any of its channels differs by MORE than the threshold,
 * so threshold 0 asks for identical 8-bit output.
 */
public final class ImageDiff {
    private ImageDiff() {}

    /** How much the diff image amplifies differences: a channel difference of 255 / GAIN shows as full white. */
    public static final double DIFF_GAIN = 8;

    /**
     * The outcome of a comparison.
     *
     * @param width         image width
     * @param height        image height
     * @param threshold     the per-channel tolerance used, in 0..255 units
     * @param maxDifference largest absolute channel difference anywhere, in 0..255 units
     * @param pixelsOver    number of pixels with a channel difference above the threshold
     * @param rmse          root-mean-square channel difference over all channels, in 0..255 units
     * @param firstOverX    x of the first pixel over the threshold in row-major order, or -1
     * @param firstOverY    y of that pixel, or -1
     * @param diffImage     per channel min(1, |difference| * {@link #DIFF_GAIN} / 255), linear
     */
    public record Result(int width, int height, int threshold, int maxDifference, int pixelsOver, double rmse,
                         int firstOverX, int firstOverY, FrameBuffer diffImage) {
        public int pixelCount() { return width * height; }

        /** Fraction of pixels over the threshold, in [0, 1]. */
        public double fractionOver() { return pixelsOver / (double) pixelCount(); }

        /** True if no pixel is over the threshold. */
        public boolean withinThreshold() { return pixelsOver == 0; }

        /** A one-line summary for assertion messages. */
        @Override public String toString() {
            String s = String.format(Locale.ROOT,
                    "%dx%d: max channel difference %d, %d of %d pixels (%.4f%%) over threshold %d, RMSE %.4f",
                    width, height, maxDifference, pixelsOver, pixelCount(), 100 * fractionOver(), threshold, rmse);
            return pixelsOver == 0 ? s : s + ", first at (" + firstOverX + ", " + firstOverY + ")";
        }
    }

    /** Compares after converting both to sRGB-encoded 8-bit values (the default output encoding). */
    public static Result compare(FrameBuffer expected, FrameBuffer actual, int threshold) {
        return compare(expected, actual, threshold, true);
    }

    /** Compares after converting both with {@link FrameBuffer#toRgb8(boolean) toRgb8(srgb)}. */
    public static Result compare(FrameBuffer expected, FrameBuffer actual, int threshold, boolean srgb) {
        checkSameSize(expected.width(), expected.height(), actual.width(), actual.height());
        return compare(expected.width(), expected.height(), expected.toRgb8(srgb), actual.toRgb8(srgb), threshold);
    }

    /** Compares two packed {@code 0xRRGGBB} images of the given size (the top byte is ignored). */
    public static Result compare(int width, int height, int[] expected, int[] actual, int threshold) {
        Objects.requireNonNull(expected, "expected");
        Objects.requireNonNull(actual, "actual");
        if (threshold < 0 || threshold > 255) {
            throw new IllegalArgumentException("threshold must be in [0, 255], got " + threshold);
        }
        FrameBuffer diff = new FrameBuffer(width, height);
        int n = width * height;
        if (expected.length != n || actual.length != n) {
            throw new IllegalArgumentException("expected " + n + " pixels for " + width + "x" + height + ", got "
                    + expected.length + " and " + actual.length);
        }
        double[] d = diff.data();
        int max = 0, over = 0, first = -1;
        long sumSquares = 0;   // at most 3 * n * 255^2, well within a long
        for (int p = 0; p < n; p++) {
            boolean pixelOver = false;
            for (int c = 0; c < 3; c++) {
                int shift = 16 - 8 * c;
                int delta = Math.abs(((expected[p] >>> shift) & 0xFF) - ((actual[p] >>> shift) & 0xFF));
                max = Math.max(max, delta);
                sumSquares += (long) delta * delta;
                pixelOver |= delta > threshold;
                d[3 * p + c] = Math.min(1.0, delta * DIFF_GAIN / 255.0);
            }
            if (pixelOver) {
                if (over == 0) first = p;
                over++;
            }
        }
        double rmse = Math.sqrt(sumSquares / (3.0 * n));
        return new Result(width, height, threshold, max, over, rmse,
                first < 0 ? -1 : first % width, first < 0 ? -1 : first / width, diff);
    }

    private static void checkSameSize(int w1, int h1, int w2, int h2) {
        if (w1 != w2 || h1 != h2) {
            throw new IllegalArgumentException("cannot compare a " + w1 + "x" + h1 + " image with a "
                    + w2 + "x" + h2 + " image");
        }
    }
}
