package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertTrue;

/**
 * The mean of independent estimates of one value and its standard error, for tests of
 * Monte Carlo integrators: pixels of an image whose pixels all have the same expectation (each
 * pixel's samples are seeded apart from every other pixel's and a box filter keeps them in their
 * pixel, so pixels are independent), or the samples of one pixel. The standard error comes from
 * the estimates' own spread, so a tolerance is the noise the sample count predicts, not a guess.
 */
final class PixelStatistics {
    /** Standard errors a mean may lie from its expectation: a false alarm about once in 10^5 seeds, per check. */
    static final double MEAN_SIGMAS = 4.5;
    /** Standard deviations one estimate may lie from the expectation, for outlier checks over some thousand pixels. */
    static final double OUTLIER_SIGMAS = 6.5;
    /** Rounding slack for estimators whose every sample is exact (zero variance): a few ulps of sums of a thousand terms. */
    static final double ROUNDING = 1e-9;

    private long n;
    private double mean, m2;

    /** Adds one estimate (Welford's update: no cancellation for means far from zero). */
    void add(double v) {
        n++;
        double d = v - mean;
        mean += d / n;
        m2 += d * (v - mean);
    }

    long count() { return n; }

    double mean() { return mean; }

    /** The unbiased sample variance of one estimate. */
    double variance() { return n > 1 ? m2 / (n - 1) : 0; }

    double standardDeviation() { return Math.sqrt(variance()); }

    /** The standard error of the mean. */
    double standardError() { return Math.sqrt(variance() / n); }

    /** Asserts that the mean lies within {@link #MEAN_SIGMAS} standard errors of the expectation. */
    void assertMean(double expected, String what) {
        assertTrue(n > 1, what + ": no estimates");
        double tolerance = MEAN_SIGMAS * standardError() + ROUNDING * Math.max(1, Math.abs(expected));
        assertTrue(Math.abs(mean - expected) <= tolerance, String.format(
                "%s: mean %.6f of %d estimates, expected %.6f within %.2e (%.1f standard errors of %.2e)",
                what, mean, n, expected, tolerance, MEAN_SIGMAS, standardError()));
    }

    @Override
    public String toString() {
        return String.format("mean %.6f, sd %.4f, se %.2e over %d", mean, standardDeviation(), standardError(), n);
    }
}
