package lt.spindulys.texture;

/**
 * A texture sampled from a {@link TextureImage}.
 *
 * <p>Coordinates: texel column {@code i} (of {@code w}) has its centre at {@code u = (i + 0.5)/w};
 * {@code v = 0} is the BOTTOM edge of the image and {@code v = 1} its top (the OBJ {@code vt}
 * convention), so texel row {@code j} counted from the bottom has its centre at
 * {@code v = (j + 0.5)/h}.
 *
 * <p>Filters: {@link Filter#NEAREST} takes the texel containing (u, v); {@link Filter#BILINEAR}
 * mixes the four texels whose centres surround (u, v) with weights linear in the distance;
 * {@link Filter#TRILINEAR} picks the mip level
 * {@code L = log2(footprint * max(w, h))} (clamped to the chain; footprint 0 gives level 0),
 * samples levels {@code floor(L)} and {@code floor(L) + 1} bilinearly and blends them by the
 * fraction of {@code L}. The wrap mode is applied to each texel index, so filters blend across
 * the image border the way the mode says (across the seam for {@link Wrap#REPEAT}).
 *
 * <p>Immutable and thread-safe; {@link #evaluate} does not allocate.
 */
public final class ImageTexture implements Texture {
    private final TextureImage image;
    private final Filter filter;
    private final Wrap wrap;
    /**
     * Mip levels (only level 0 unless trilinear), fetched once so sampling never synchronises;
     * level 0's entry is null when the image stores it as bytes (then read through the image).
     */
    private final float[][] levels;
    private final int[] lw, lh;
    /** Level 0 when the image keeps it as codes (see {@link TextureImage}): codes, their values, codes per texel. */
    private final byte[] bytes0;
    private final char[] chars0;
    private final float[] table0;
    private final int channels0;
    private final double maxSide;

    /**
     * A texture over {@code img} with the given filter and wrap mode.
     *
     * @param img the image
     * @param f the reconstruction filter
     * @param w what happens outside [0, 1]
     */
    public ImageTexture(TextureImage img, Filter f, Wrap w) {
        if (img == null || f == null || w == null) throw new NullPointerException("image, filter and wrap are required");
        this.image = img;
        this.filter = f;
        this.wrap = w;
        this.levels = f == Filter.TRILINEAR ? img.levels() : new float[][] {img.base()};
        int n = levels.length;
        lw = new int[n];
        lh = new int[n];
        for (int k = 0; k < n; k++) {
            lw[k] = img.width(k);
            lh[k] = img.height(k);
        }
        maxSide = Math.max(img.width(), img.height());
        bytes0 = img.baseBytes();
        chars0 = img.baseChars();
        table0 = img.table();
        channels0 = img.channels();
    }

    /**
     * The image sampled.
     *
     * @return the image
     */
    public TextureImage image() {
        return image;
    }

    /**
     * The reconstruction filter.
     *
     * @return the filter
     */
    public Filter filter() {
        return filter;
    }

    /**
     * The wrap mode.
     *
     * @return the wrap mode
     */
    public Wrap wrap() {
        return wrap;
    }

    /**
     * The (fractional) mip level trilinear filtering uses for a footprint of {@code footprint} uv
     * units: {@code log2(footprint * max(w, h))} clamped to {@code [0, levelCount - 1]}.
     *
     * @param footprint the footprint, uv units
     * @return the level, 0 the sharpest
     */
    public double mipLevel(double footprint) {
        if (!(footprint > 0)) return 0;
        double l = Math.log(footprint * maxSide) / Math.log(2);
        double top = levels.length - 1;
        return l <= 0 ? 0 : l >= top ? top : l;
    }

    @Override
    public void evaluate(TexturePoint p, double[] rgb) {
        // A NaN or infinite coordinate (degenerate mapping) would poison every weight; sample the
        // origin instead.
        double u = Double.isFinite(p.u) ? wrap.fold(p.u) : 0, v = Double.isFinite(p.v) ? wrap.fold(p.v) : 0;
        switch (filter) {
            case NEAREST:
                nearest(u, v, rgb);
                break;
            case BILINEAR:
                bilinear(0, u, v, rgb, 1, false);
                break;
            case TRILINEAR: {
                double l = mipLevel(p.footprint);
                int l0 = (int) l;
                double t = l - l0;
                bilinear(l0, u, v, rgb, 1 - t, false);
                if (t > 0) bilinear(l0 + 1, u, v, rgb, t, true);
                break;
            }
            default:
                throw new AssertionError(filter);
        }
    }

    private void nearest(double u, double v, double[] rgb) {
        int w = lw[0], h = lh[0];
        int i = wrap.apply(floor(u * w), w);
        int j = wrap.apply(floor(v * h), h);
        int t = (h - 1 - j) * w + i;  // j counts from the bottom; storage is top-down
        float[] d = levels[0];
        for (int ch = 0; ch < 3; ch++) rgb[ch] = d != null ? d[3 * t + ch] : image.base(t, ch);
    }

    /** Writes (or, if {@code add}, adds) {@code scale} times the bilinear sample of level {@code k}. */
    private void bilinear(int k, double u, double v, double[] rgb, double scale, boolean add) {
        int w = lw[k], h = lh[k];
        double x = u * w - 0.5, y = v * h - 0.5;
        long x0 = floor(x), y0 = floor(y);
        // Fractions from the unclamped floor, so they stay in [0, 1) however far out (u, v) is.
        double fx = x - Math.floor(x), fy = y - Math.floor(y);
        int i0 = wrap.apply(x0, w), i1 = wrap.apply(x0 + 1, w);
        int r0 = h - 1 - wrap.apply(y0, h), r1 = h - 1 - wrap.apply(y0 + 1, h);
        int a = r0 * w + i0, b = r0 * w + i1, c = r1 * w + i0, e = r1 * w + i1;
        double w00 = (1 - fx) * (1 - fy) * scale, w10 = fx * (1 - fy) * scale;
        double w01 = (1 - fx) * fy * scale, w11 = fx * fy * scale;
        float[] d = levels[k];
        if (d != null) {
            a *= 3;
            b *= 3;
            c *= 3;
            e *= 3;
            for (int ch = 0; ch < 3; ch++) {
                double s = w00 * d[a + ch] + w10 * d[b + ch] + w01 * d[c + ch] + w11 * d[e + ch];
                rgb[ch] = add ? rgb[ch] + s : s;
            }
        } else if (bytes0 != null) {
            // Level 0 as bytes: the same floats through the table (one byte a texel for grey).
            int m = channels0, step = m == 3 ? 1 : 0;
            a *= m;
            b *= m;
            c *= m;
            e *= m;
            for (int ch = 0, o = 0; ch < 3; ch++, o += step) {
                double s = w00 * table0[bytes0[a + o] & 0xFF] + w10 * table0[bytes0[b + o] & 0xFF]
                        + w01 * table0[bytes0[c + o] & 0xFF] + w11 * table0[bytes0[e + o] & 0xFF];
                rgb[ch] = add ? rgb[ch] + s : s;
            }
        } else {
            double s = w00 * table0[chars0[a]] + w10 * table0[chars0[b]] + w01 * table0[chars0[c]] + w11 * table0[chars0[e]];
            for (int ch = 0; ch < 3; ch++) rgb[ch] = add ? rgb[ch] + s : s;
        }
    }

    /** Floor to long, saturating for huge or infinite coordinates (the wrap then folds them). */
    private static long floor(double x) {
        // Bounded well inside long range so that index + 1 cannot overflow.
        double f = Math.floor(x);
        return f < -0x1p62 ? -(1L << 62) : f > 0x1p62 ? 1L << 62 : (long) f;
    }

    @Override
    public String toString() {
        return "ImageTexture[" + image + ", " + filter + ", " + wrap + "]";
    }
}
