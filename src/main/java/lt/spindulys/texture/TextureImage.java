package lt.spindulys.texture;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Ranges;

/**
 * An image of linear RGB texels with its mip chain, rows TOP-DOWN as in image files; sampling is
 * done in doubles.
 *
 * <p>Storage of level 0: images decoded from 8-bit files keep their BYTES (three per texel for
 * colour, one for greyscale), and a 256-entry table gives the linear value of each byte as a
 * float (sRGB-decoded for colour, {@code byte / 255} for greyscale), so a texel costs 3 or 1
 * bytes instead of 12 and samples to exactly the floats that were stored before. 16-bit
 * greyscale keeps its precision in one {@code char} per texel, with a 65,536-entry table.
 * Programmatic images ({@link #fromLinear}) keep three floats per texel.
 *
 * <p>The mip chain (levels 1 and up, three floats per texel, together a third of level 0's texel
 * count: 4 bytes per texel of level 0) is built once, on the first request (in practice when a
 * trilinear {@link ImageTexture} is constructed, i.e. during scene setup), and is then immutable.
 * Each level halves both sizes (rounding down, never below 1) with an exact box filter: a
 * destination texel averages the source area it covers, with fractional weights for the texels
 * straddling its border, so odd (non-power-of-two) sizes keep the image's mean and nothing is
 * dropped. It is built a row at a time, so building it needs nothing beyond the levels themselves.
 *
 * <p>Immutable after construction (apart from that one-time, synchronised chain build) and
 * thread-safe.
 */
public final class TextureImage {
    /** Bytes a texel of the mip chain (all levels but 0) costs per texel of level 0, rounded up. */
    static final int MIP_BYTES_PER_TEXEL = 4;

    private final int width, height;
    /** Level 0 as floats, three per texel, or null when it is stored as codes. */
    private final float[] base;
    /** Level 0 as 8-bit codes ({@link #channels} per texel), or null. */
    private final byte[] bytes;
    /** Level 0 as 16-bit codes (one per texel), or null. */
    private final char[] chars;
    /** The linear value of each code (for bytes or chars). */
    private final float[] table;
    /** Codes per texel: 3 (colour) or 1 (grey, the same value in r, g and b). */
    private final int channels;
    /** Levels 0..n-1 (level 0 is {@link #base}, null when stored as codes); null until first requested. */
    private volatile float[][] levels;

    private TextureImage(int width, int height, float[] base, byte[] bytes, char[] chars, float[] table, int channels) {
        this.width = width;
        this.height = height;
        this.base = base;
        this.bytes = bytes;
        this.chars = chars;
        this.table = table;
        this.channels = channels;
    }

    /**
     * An image from linear RGB values, three per texel, rows top to bottom (row 0 is the top of
     * the image, i.e. {@code v = 1}); the array is copied.
     *
     * @param w width in texels
     * @param h height in texels
     * @param rgb linear values, 3 * w * h
     * @return the image
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
            // The bound keeps pixels finite (see Ranges); 8-bit images hold 0..1, HDR and PFM ones are clamped to it.
            if (!(Math.abs(rgb[i]) <= Ranges.MAX_COLOUR)) {
                throw new IllegalArgumentException("texel value " + rgb[i] + " at index " + i + " (texel values must be between -"
                        + Ranges.show(Ranges.MAX_COLOUR) + " and " + Ranges.show(Ranges.MAX_COLOUR) + ")");
            }
            f[i] = (float) rgb[i];
        }
        return new TextureImage(w, h, f, null, null, null, 3);
    }

    /** Takes ownership of {@code rgb} (three floats per texel, rows top-down); for the loaders. */
    static TextureImage wrap(int w, int h, float[] rgb) {
        checkSize(w, h);
        if (rgb.length != 3L * w * h) throw new IllegalArgumentException("texel array length " + rgb.length);
        return new TextureImage(w, h, rgb, null, null, null, 3);
    }

    /**
     * Takes ownership of {@code codes} ({@code channels} per texel, 3 or 1, rows top-down), whose
     * linear values {@code table} gives (256 entries); for the loaders.
     */
    static TextureImage ofBytes(int w, int h, byte[] codes, int channels, float[] table) {
        checkSize(w, h);
        if (channels != 1 && channels != 3 || codes.length != (long) channels * w * h || table.length != 256) {
            throw new IllegalArgumentException("texel codes " + codes.length + " for " + w + "x" + h + "x" + channels);
        }
        return new TextureImage(w, h, null, codes, null, table, channels);
    }

    /** Takes ownership of {@code codes} (one 16-bit grey code per texel, rows top-down), valued by {@code table}. */
    static TextureImage ofChars(int w, int h, char[] codes, float[] table) {
        checkSize(w, h);
        if (codes.length != (long) w * h || table.length != 65536) throw new IllegalArgumentException("texel codes " + codes.length + " for " + w + "x" + h);
        return new TextureImage(w, h, null, null, codes, table, 1);
    }

    private static void checkSize(int w, int h) {
        if (w <= 0 || h <= 0) throw new IllegalArgumentException("texture size must be positive, got " + w + "x" + h);
        if ((long) w * h * 3 > Integer.MAX_VALUE - 8) throw new IllegalArgumentException("texture too large: " + w + "x" + h);
    }

    /**
     * Width in texels of level 0.
     *
     * @return the width
     */
    public int width() {
        return width;
    }

    /**
     * Height in texels of level 0.
     *
     * @return the height
     */
    public int height() {
        return height;
    }

    /**
     * Number of mip levels (1 for a 1x1 image); builds the chain if needed.
     *
     * @return the level count
     */
    public int levelCount() {
        return levels().length;
    }

    /**
     * Width of mip level {@code level}.
     *
     * @param level the level, 0 the full image
     * @return the width in texels
     */
    public int width(int level) {
        return Math.max(1, width >> level);
    }

    /**
     * Height of mip level {@code level}.
     *
     * @param level the level, 0 the full image
     * @return the height in texels
     */
    public int height(int level) {
        return Math.max(1, height >> level);
    }

    /**
     * The linear RGB value of texel ({@code x}, {@code row}) of mip level {@code level}, channel
     * {@code c}; {@code row} counts from the TOP. For tests and inspection.
     *
     * @param level the level
     * @param x the column
     * @param row the row, from the top
     * @param c the channel, 0 to 2
     * @return the value
     */
    public double texel(int level, int x, int row, int c) {
        return level == 0 ? base(row * width + x, c) : levels()[level][(row * width(level) + x) * 3 + c];
    }

    /** Channel {@code c} of texel {@code t} (row-major index) of level 0, whatever its storage. */
    float base(int t, int c) {
        if (bytes != null) return table[bytes[channels == 1 ? t : 3 * t + c] & 0xFF];
        if (chars != null) return table[chars[t]];
        return base[3 * t + c];
    }

    /** Level 0 as three floats per texel, or null when it is stored as codes (then see the accessors below). */
    float[] base() {
        return base;
    }

    /** Level 0's 8-bit codes, or null. */
    byte[] baseBytes() {
        return bytes;
    }

    /** Level 0's 16-bit codes, or null. */
    char[] baseChars() {
        return chars;
    }

    /** The linear value of each code of level 0 (null for floats). */
    float[] table() {
        return table;
    }

    /** Codes per texel of level 0: 3 or 1. */
    int channels() {
        return channels;
    }

    /** Bytes the mip chain of a {@code w x h} image takes (levels 1 and up), whether built or not. */
    static long mipBytes(int w, int h) {
        long n = 0;
        for (int k = 1; w > 1 || h > 1; k++) {
            w = Math.max(1, w >> 1);
            h = Math.max(1, h >> 1);
            n += (long) w * h;
        }
        return n * 3 * 4;
    }

    /** All levels (level 0's entry null unless it is stored as floats); builds the chain on first use. */
    float[][] levels() {
        float[][] l = levels;
        if (l == null) {
            synchronized (this) {
                l = levels;
                if (l == null) {
                    HeapBudget.require(mipBytes(width, height), "the mip chain of the " + width + "x" + height + " texture");
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
        float[] expanded = base == null ? new float[3 * width] : null;
        for (int k = 1; k < n; k++) {
            int sw = width(k - 1), sh = height(k - 1), dw = width(k), dh = height(k);
            // Separable: each source row is halved (sw -> dw), then the halved rows are summed down
            // the columns (sh -> dh) straight into the destination, a row at a time. The sums run in
            // the same order as halving all rows first would, so the values are the same.
            float[] dst = new float[dw * dh * 3];
            float[] row = new float[dw * 3];
            double[] acc = new double[dw * 3];
            double ratio = (double) sh / dh, inv = 1 / ratio;
            for (int i = 0; i < dh; i++) {
                double a = i * ratio, b = (i + 1) * ratio;
                java.util.Arrays.fill(acc, 0);
                for (int s = sh == dh ? i : (int) Math.floor(a); sh == dh ? s == i : s < b && s < sh; s++) {
                    double wgt = sh == dh ? 1 : Math.min(b, s + 1) - Math.max(a, s);
                    if (wgt <= 0) continue;
                    halveRow(l, k, s, sw, dw, expanded, row);
                    if (sh == dh) {
                        System.arraycopy(row, 0, dst, i * dw * 3, dw * 3);
                        continue;
                    }
                    for (int x = 0; x < dw * 3; x++) acc[x] += wgt * row[x];
                }
                if (sh != dh) for (int x = 0; x < dw * 3; x++) dst[i * dw * 3 + x] = (float) (acc[x] * inv);
            }
            l[k] = dst;
        }
        return l;
    }

    /** Row {@code s} of level {@code k - 1}, halved from {@code sw} to {@code dw} texels, into {@code out}. */
    private void halveRow(float[][] l, int k, int s, int sw, int dw, float[] expanded, float[] out) {
        if (k == 1 && base == null) {
            for (int x = 0, t = s * sw; x < sw; x++, t++) {
                for (int c = 0; c < 3; c++) expanded[3 * x + c] = base(t, c);
            }
            downsample(expanded, 0, 3, sw, out, 0, 3, dw);
        } else {
            downsample(l[k - 1], s * sw * 3, 3, sw, out, 0, 3, dw);
        }
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
