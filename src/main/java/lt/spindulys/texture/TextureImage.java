package lt.spindulys.texture;

import lt.spindulys.math.Ranges;

/**
 * An image of linear RGB texels with its mip chain. Texels are stored as flat {@code float}
 * arrays (three per texel, rows TOP-DOWN as in image files) to halve the memory of a large image;
 * sampling is done in doubles.
 *
 * <p>The mip chain is built once, on the first request (in practice when a trilinear
 * {@link ImageTexture} is constructed, i.e. during scene setup), and is then immutable. Each level
 * halves both sizes (rounding down, never below 1) with an exact box filter: a destination texel
 * averages the source area it covers, with fractional weights for the texels straddling its
 * border, so odd (non-power-of-two) sizes keep the image's mean and nothing is dropped.
 *
 * <p>Immutable after construction (apart from that one-time, synchronised chain build) and
 * thread-safe.
 */
public final class TextureImage {
    private final int width, height;
    private final float[] base;
    /** Levels 0..n-1 (level 0 is {@link #base}); null until first requested. */
    private volatile float[][] levels;

    private TextureImage(int width, int height, float[] base) {
        this.width = width;
        this.height = height;
        this.base = base;
    }

    /**
     * An image from linear RGB values, three per texel, rows top to bottom (row 0 is the top of
     * the image, i.e. {@code v = 1}); the array is copied.
     *
     * @throws IllegalArgumentException if a size is not positive, the array length is not
     *         {@code 3 * w * h}, or a value is not finite
     */
    public static TextureImage fromLinear(int w, int h, double[] rgb) {
        checkSize(w, h);
        if (rgb.length != 3L * w * h) {
            throw new IllegalArgumentException("expected " + 3L * w * h + " values for " + w + "x" + h + ", got " + rgb.length);
        }
        float[] f = new float[rgb.length];
        for (int i = 0; i < f.length; i++) {
            // The bound keeps pixels finite (see Ranges); images read from files hold 0..1.
            if (!(Math.abs(rgb[i]) <= Ranges.MAX_COLOUR)) {
                throw new IllegalArgumentException("texel value " + rgb[i] + " at index " + i + " (texel values must be between -"
                        + Ranges.show(Ranges.MAX_COLOUR) + " and " + Ranges.show(Ranges.MAX_COLOUR) + ")");
            }
            f[i] = (float) rgb[i];
        }
        return new TextureImage(w, h, f);
    }

    /** Takes ownership of {@code rgb} (three floats per texel, rows top-down); for the loaders. */
    static TextureImage wrap(int w, int h, float[] rgb) {
        checkSize(w, h);
        if (rgb.length != 3L * w * h) throw new IllegalArgumentException("texel array length " + rgb.length);
        return new TextureImage(w, h, rgb);
    }

    private static void checkSize(int w, int h) {
        if (w <= 0 || h <= 0) throw new IllegalArgumentException("texture size must be positive, got " + w + "x" + h);
        if ((long) w * h * 3 > Integer.MAX_VALUE - 8) throw new IllegalArgumentException("texture too large: " + w + "x" + h);
    }

    /** Width in texels of level 0. */
    public int width() {
        return width;
    }

    /** Height in texels of level 0. */
    public int height() {
        return height;
    }

    /** Number of mip levels (1 for a 1x1 image); builds the chain if needed. */
    public int levelCount() {
        return levels().length;
    }

    /** Width of mip level {@code level}. */
    public int width(int level) {
        return Math.max(1, width >> level);
    }

    /** Height of mip level {@code level}. */
    public int height(int level) {
        return Math.max(1, height >> level);
    }

    /**
     * The linear RGB value of texel ({@code x}, {@code row}) of mip level {@code level}, channel
     * {@code c}; {@code row} counts from the TOP. For tests and inspection.
     */
    public double texel(int level, int x, int row, int c) {
        return levels()[level][(row * width(level) + x) * 3 + c];
    }

    /** Level 0 texels (not a copy: package-private for the sampler). */
    float[] base() {
        return base;
    }

    /** All levels; builds the chain on first use. */
    float[][] levels() {
        float[][] l = levels;
        if (l == null) {
            synchronized (this) {
                l = levels;
                if (l == null) {
                    l = buildChain();
                    levels = l;
                }
            }
        }
        return l;
    }

    private float[][] buildChain() {
        int n = 1;
        for (int w = width, h = height; w > 1 || h > 1; w = Math.max(1, w >> 1), h = Math.max(1, h >> 1)) n++;
        float[][] l = new float[n][];
        l[0] = base;
        for (int k = 1; k < n; k++) {
            int sw = width(k - 1), sh = height(k - 1), dw = width(k), dh = height(k);
            // Separable: halve the rows first (sw -> dw), then the columns (sh -> dh).
            float[] tmp = new float[dw * sh * 3];
            for (int row = 0; row < sh; row++) downsample(l[k - 1], row * sw * 3, 3, sw, tmp, row * dw * 3, 3, dw);
            float[] dst = new float[dw * dh * 3];
            for (int x = 0; x < dw; x++) downsample(tmp, x * 3, dw * 3, sh, dst, x * 3, dw * 3, dh);
            l[k] = dst;
        }
        return l;
    }

    /**
     * Box-filters one line of {@code sn} RGB texels (starting at {@code so}, stride {@code ss})
     * into {@code dn} texels: destination texel i covers source interval [i*sn/dn, (i+1)*sn/dn).
     */
    private static void downsample(float[] src, int so, int ss, int sn, float[] dst, int d0, int ds, int dn) {
        if (sn == dn) {
            for (int i = 0; i < dn; i++) for (int c = 0; c < 3; c++) dst[d0 + i * ds + c] = src[so + i * ss + c];
            return;
        }
        double ratio = (double) sn / dn, inv = 1 / ratio;
        for (int i = 0; i < dn; i++) {
            double a = i * ratio, b = (i + 1) * ratio;
            double r = 0, g = 0, bl = 0;
            for (int s = (int) Math.floor(a); s < b && s < sn; s++) {
                double wgt = Math.min(b, s + 1) - Math.max(a, s);
                if (wgt <= 0) continue;
                int p = so + s * ss;
                r += wgt * src[p];
                g += wgt * src[p + 1];
                bl += wgt * src[p + 2];
            }
            int q = d0 + i * ds;
            dst[q] = (float) (r * inv);
            dst[q + 1] = (float) (g * inv);
            dst[q + 2] = (float) (bl * inv);
        }
    }

    @Override
    public String toString() {
        return "TextureImage[" + width + "x" + height + "]";
    }
}
