package lt.spindulys.camera;

import java.util.ArrayList;
import java.util.List;

/**
 * The pixel reconstruction filter: how much a film sample at an offset from a pixel's centre
 * counts towards that pixel. Every filter here is separable, f(x, y) = f(x) f(y), and is applied
 * by importance sampling it (the sampling package's FilterSampler): the film offsets of a pixel's
 * samples are drawn from the filter, so each sample still belongs to its own pixel only.
 *
 * <p>The width W, in pixels, is read as Blender's Film &gt; Pixel Filter width for the filters
 * Cycles has (box, Gaussian, Blackman-Harris), so that a value copied from Blender gives the same
 * look; for Mitchell-Netravali, which Cycles lacks, it is the support, as pbrt's diameter.
 */
public enum PixelFilter {
    /** Every sample in a W x W square counts alike: the plain average of today's renders. */
    BOX("box", 1.0),
    /**
     * A Gaussian of standard deviation W / 4, cut off at 1.5 W from the centre (six deviations,
     * where it is negligible), as Cycles builds its Gaussian table: W = 1.5 gives sigma 0.375.
     */
    GAUSSIAN("gaussian", 1.5),
    /**
     * The four-term Blackman-Harris window over a support of 2 W: Cycles doubles the width it is
     * given, so W = 1.5 (Blender's default filter and width) spans 3 pixels and looks like a
     * Gaussian of about the same W while keeping more fine detail.
     */
    BLACKMAN_HARRIS("blackman-harris", 1.5),
    /**
     * Mitchell and Netravali's cubic with B = C = 1/3 over a support of W (radius W / 2, 2 by
     * default): sharper than the others, with small negative lobes that ring faintly at edges.
     */
    MITCHELL("mitchell", 4.0);


    /** Mitchell-Netravali's B and C. */
    private static final double B = 1.0 / 3, C = 1.0 / 3;

    private final String keyword;
    private final double defaultWidth;

    PixelFilter(String keyword, double defaultWidth) {
        this.keyword = keyword;
        this.defaultWidth = defaultWidth;
    }

    /**
     * The scene-language and command-line word.
     *
     * @return the keyword
     */
    public String keyword() { return keyword; }

    /**
     * The width used when none is given.
     *
     * @return W in pixels
     */
    public double defaultWidth() { return defaultWidth; }

    /**
     * How far from the pixel's centre the filter reaches, along each axis.
     *
     * @param width W in pixels
     * @return the radius in pixels
     */
    public double radius(double width) {
        return switch (this) {
            case BOX, MITCHELL -> width / 2;
            case GAUSSIAN -> 1.5 * width;
            case BLACKMAN_HARRIS -> width;
        };
    }

    /**
     * The one-dimensional filter, unnormalised, at offset x from the centre: 0 beyond the
     * {@link #radius}.
     *
     * @param x     offset in pixels
     * @param width W in pixels
     * @return f(x), negative only in Mitchell-Netravali's lobes
     */
    public double evaluate(double x, double width) {
        double r = radius(width), a = Math.abs(x);
        if (a > r) return 0;
        return switch (this) {
            case BOX -> 1;
            case GAUSSIAN -> {
                double sigma = width / 4;
                yield Math.exp(-x * x / (2 * sigma * sigma));
            }
            case BLACKMAN_HARRIS -> {
                double v = 2 * Math.PI * (x / (2 * r) + 0.5);
                yield 0.35875 - 0.48829 * Math.cos(v) + 0.14128 * Math.cos(2 * v) - 0.01168 * Math.cos(3 * v);
            }
            case MITCHELL -> mitchell(2 * a / r);
        };
    }

    /** Mitchell-Netravali's cubic at |x| in [0, 2]. */
    private static double mitchell(double x) {
        if (x < 1) return ((12 - 9 * B - 6 * C) * x * x * x + (-18 + 12 * B + 6 * C) * x * x + (6 - 2 * B)) / 6;
        if (x < 2) return ((-B - 6 * C) * x * x * x + (6 * B + 30 * C) * x * x + (-12 * B - 48 * C) * x + (8 * B + 24 * C)) / 6;
        return 0;
    }

    /**
     * The filter with this keyword.
     *
     * @param word the keyword
     * @return the filter
     * @throws IllegalArgumentException naming the keywords accepted
     */
    public static PixelFilter fromKeyword(String word) {
        for (PixelFilter f : values()) if (f.keyword.equals(word)) return f;
        throw new IllegalArgumentException("unknown filter '" + word + "' (expected one of " + String.join(", ", keywords()) + ")");
    }

    /**
     * Every keyword, in declaration order.
     *
     * @return the keywords
     */
    public static List<String> keywords() {
        List<String> out = new ArrayList<>();
        for (PixelFilter f : values()) out.add(f.keyword);
        return List.copyOf(out);
    }
}
