package lt.spindulys.sampling;

import java.util.Objects;

import lt.spindulys.camera.PixelFilter;

/**
 * Draws film offsets from a {@link PixelFilter} of a given width, one axis at a time (the filters
 * are separable), by inverting a tabulated distribution, as pbrt-v4's FilterSampler and Cycles'
 * filter table do. The table holds |f| averaged over {@value #BINS} equal bins across the
 * support; within a bin the offset is spread uniformly, so the distribution sampled is that
 * piecewise-constant |f|, which is the filter applied (it differs from f by far less than a
 * sample's noise). The box is sampled exactly, without a table.
 *
 * <p>A sample's weight is f / pdf: 1 for the non-negative filters, and for Mitchell-Netravali's
 * negative lobes sign(f) times the constant (∫|f| / ∫f) per axis, so that the weights' mean is
 * 1. Immutable; one instance serves every render thread.
 */
public final class FilterSampler {
    /** Bins across the support: fine enough that the tabulated filter's moments match f's to about 1e-6. */
    static final int BINS = 1024;
    /** Points averaged within a bin, so that a bin the sign changes in gets its net value. */
    private static final int POINTS_PER_BIN = 8;

    private final PixelFilter filter;
    private final double width, radius, binWidth;
    /** cdf[k]: the share of ∫|f| left of bin k; cdf[BINS] is exactly 1. Null for the box. */
    private final double[] cdf;
    /** Whether bin k has a negative net value. Null when no bin does. */
    private final boolean[] negative;
    /** ∫|f| / ∫f over one axis: 1 for a non-negative filter. */
    private final double axisWeight;

    /**
     * @param filter the filter
     * @param width  W in pixels, positive
     */
    public FilterSampler(PixelFilter filter, double width) {
        this.filter = Objects.requireNonNull(filter, "filter");
        if (!(width > 0) || Double.isInfinite(width)) throw new IllegalArgumentException("filter width must be positive, found " + width);
        this.width = width;
        radius = filter.radius(width);
        binWidth = 2 * radius / BINS;
        if (filter == PixelFilter.BOX) {
            cdf = null;
            negative = null;
            axisWeight = 1;
            return;
        }
        cdf = new double[BINS + 1];
        boolean[] neg = new boolean[BINS];
        boolean anyNegative = false;
        double absSum = 0, sum = 0;
        for (int k = 0; k < BINS; k++) {
            double v = 0;
            for (int j = 0; j < POINTS_PER_BIN; j++) v += filter.evaluate(-radius + (k + (j + 0.5) / POINTS_PER_BIN) * binWidth, width);
            v /= POINTS_PER_BIN;
            neg[k] = v < 0;
            anyNegative |= v < 0;
            absSum += Math.abs(v);
            sum += v;
            cdf[k + 1] = absSum;
        }
        for (int k = 1; k < BINS; k++) cdf[k] /= absSum;
        cdf[BINS] = 1;
        negative = anyNegative ? neg : null;
        axisWeight = anyNegative ? absSum / sum : 1;
    }

    public PixelFilter filter() { return filter; }

    public double width() { return width; }

    /** How far from the pixel centre an offset may lie, in pixels. */
    public double radius() { return radius; }

    /** Whether some samples weigh less than zero (Mitchell-Netravali's lobes); otherwise every weight is exactly 1. */
    public boolean hasNegativeWeights() { return negative != null; }

    /**
     * The bin that u falls in (for {@link #offset} and {@link #sign}); 0 for the box.
     *
     * @param u uniform in [0, 1)
     * @return the bin
     */
    public int bin(double u) {
        if (cdf == null) return 0;
        // The last bin whose start is at most u; empty bins (cdf[k] == cdf[k + 1]) are never chosen.
        int lo = 0, hi = BINS - 1;
        while (lo < hi) {
            int mid = (lo + hi + 1) >>> 1;
            if (cdf[mid] <= u) lo = mid; else hi = mid - 1;
        }
        return lo;
    }

    /**
     * The film offset from the pixel centre, in pixels, that u maps to.
     *
     * @param bin {@link #bin bin(u)}
     * @param u   uniform in [0, 1)
     * @return the offset, in [-radius, radius]
     */
    public double offset(int bin, double u) {
        if (cdf == null) return width * (u - 0.5);
        double mass = cdf[bin + 1] - cdf[bin];
        double t = mass > 0 ? (u - cdf[bin]) / mass : 0.5; // an empty bin only if u lies past the last non-empty one
        return -radius + (bin + t) * binWidth;
    }

    /**
     * The sign of the filter in this bin.
     *
     * @param bin a bin from {@link #bin}
     * @return 1, or -1 in a negative lobe
     */
    public int sign(int bin) {
        return negative != null && negative[bin] ? -1 : 1;
    }

    /**
     * The weight of a sample whose axes fell in these bins: f / pdf, scaled so that its mean is 1.
     *
     * @param binX the x axis's bin
     * @param binY the y axis's bin
     * @return ±(∫|f| / ∫f)² for a filter with negative lobes, else exactly 1
     */
    public double weight(int binX, int binY) {
        if (negative == null) return 1;
        return sign(binX) * sign(binY) * axisWeight * axisWeight;
    }

    /** ∫|f| / ∫f along one axis (of the tabulated filter): 1 unless the filter has negative lobes. */
    public double axisWeight() { return axisWeight; }
}
