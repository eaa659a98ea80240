package lt.spindulys.shading;

import java.util.Arrays;
import java.util.SplittableRandom;

/**
 * Pearson's chi-square goodness-of-fit test of a direction sampler against its claimed density
 * over the sphere, binned in (theta, phi), after pbrt-v4's bsdfs_test and Mitsuba's chi2.py.
 * Expected counts come from integrating pdf * sin(theta) over each cell numerically;
 * the number of attempts (failed samples included) scales them, so a density whose integral is
 * below one must be matched by samplers failing that often.
 */
final class SphereChiSquare {
    private SphereChiSquare() {}

    /** Draws one direction into out[0..2], or returns false for no sample. */
    interface Sampler { boolean sample(SplittableRandom rng, double[] out); }

    /** The density claimed for the sampler's directions. */
    interface Density { double pdf(double x, double y, double z); }

    /**
     * Outcome.
     *
     * @param statistic the chi-square statistic
     * @param dof degrees of freedom (categories after pooling, minus one)
     * @param pValue probability of a statistic this large if the sampler follows the density
     * @param densityIntegral numerical integral of the density over the sphere
     * @param unexpectedSamples samples that fell where the density integrates to 0
     */
    record Result(double statistic, int dof, double pValue, double densityIntegral, int unexpectedSamples) {
        /**
         * Asserts that the sampler fits its density: the density integrates to at most 1, no
         * sample falls where it is 0, enough categories are left, and the p-value passes the
         * Sidak-corrected threshold of {@code tests} tests at family level {@code familyLevel}.
         */
        void assertFits(String what, double familyLevel, int tests) {
            String detail = what + ": " + this;
            org.junit.jupiter.api.Assertions.assertTrue(densityIntegral <= 1 + 1e-3, detail);
            org.junit.jupiter.api.Assertions.assertEquals(0, unexpectedSamples, detail);
            org.junit.jupiter.api.Assertions.assertTrue(dof > 10, detail);
            org.junit.jupiter.api.Assertions.assertTrue(pValue > sidakThreshold(familyLevel, tests), detail);
        }
    }

    /** A direction drawn uniformly over the sphere. */
    static double[] uniformDirection(java.util.SplittableRandom rng) {
        double z = 2 * rng.nextDouble() - 1, phi = 2 * Math.PI * rng.nextDouble(), s = Math.sqrt(Math.max(0, 1 - z * z));
        return new double[] {s * Math.cos(phi), s * Math.sin(phi), z};
    }

    /** Asserts that two values agree to {@code tolerance} relative to the larger. */
    static void assertRelative(double expected, double actual, double tolerance, String what) {
        org.junit.jupiter.api.Assertions.assertTrue(Math.abs(expected - actual) <= tolerance * Math.max(Math.abs(expected), Math.abs(actual)),
                what + ": expected " + expected + " but was " + actual);
    }

    static final int THETA_BINS = 40, PHI_BINS = 80;
    private static final int SUB_CELLS = 2; // per cell and dimension
    private static final double MIN_EXPECTED = 5;

    static Result run(Sampler sampler, Density density, int attempts, long seed) {
        int cells = THETA_BINS * PHI_BINS;
        long[] observed = new long[cells];
        SplittableRandom rng = new SplittableRandom(seed);
        double[] dir = new double[3];
        for (int i = 0; i < attempts; i++) {
            if (!sampler.sample(rng, dir)) continue;
            double theta = Math.acos(Math.max(-1, Math.min(1, dir[2])));
            double phi = Math.atan2(dir[1], dir[0]);
            if (phi < 0) phi += 2 * Math.PI;
            int t = Math.min((int) (theta / Math.PI * THETA_BINS), THETA_BINS - 1);
            int p = Math.min((int) (phi / (2 * Math.PI) * PHI_BINS), PHI_BINS - 1);
            observed[t * PHI_BINS + p]++;
        }
        double[] expected = new double[cells];
        double integral = 0;
        for (int t = 0; t < THETA_BINS; t++) {
            for (int p = 0; p < PHI_BINS; p++) {
                double cell = integrateCell(density, t * Math.PI / THETA_BINS, (t + 1) * Math.PI / THETA_BINS,
                        p * 2 * Math.PI / PHI_BINS, (p + 1) * 2 * Math.PI / PHI_BINS);
                integral += cell;
                expected[t * PHI_BINS + p] = cell * attempts;
            }
        }
        // Pool sparse cells (the chi-square approximation needs about five expected per category).
        Integer[] order = new Integer[cells];
        for (int i = 0; i < cells; i++) order[i] = i;
        Arrays.sort(order, (a, b) -> Double.compare(expected[a], expected[b]));
        int unexpected = 0;
        double pooledExpected = 0, pooledObserved = 0;
        double statistic = 0;
        int categories = 0;
        double smallestExpected = 0, smallestObserved = 0;
        boolean haveSmallest = false;
        for (int k = 0; k < cells; k++) {
            int i = order[k];
            double e = expected[i], o = observed[i];
            if (e == 0 && o > 0) unexpected += (int) o;
            if (e < MIN_EXPECTED) {
                pooledExpected += e;
                pooledObserved += o;
                continue;
            }
            if (!haveSmallest) { // kept aside in case the pool is too small to stand alone
                smallestExpected = e; smallestObserved = o; haveSmallest = true;
                continue;
            }
            statistic += (o - e) * (o - e) / e;
            categories++;
        }
        if (haveSmallest) {
            if (pooledExpected >= MIN_EXPECTED) {
                statistic += sq(pooledObserved - pooledExpected) / pooledExpected;
                categories++;
            } else {
                smallestExpected += pooledExpected;
                smallestObserved += pooledObserved;
            }
            statistic += sq(smallestObserved - smallestExpected) / smallestExpected;
            categories++;
        }
        int dof = categories - 1;
        double pValue = dof < 1 ? 0 : chiSquareSurvival(statistic, dof);
        return new Result(statistic, dof, pValue, integral, unexpected);
    }

    /** Significance for one of several tests such that all together keep the family-wise level (Sidak). */
    static double sidakThreshold(double familyLevel, int tests) {
        return 1 - Math.pow(1 - familyLevel, 1.0 / tests);
    }

    // Five-point Gauss-Legendre on [-1, 1]. Unlike Simpson it never evaluates on a cell's edge,
    // where a density that jumps at the horizon would leak into the cell on the far side.
    private static final double[] GAUSS_NODES = {
        -0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
    private static final double[] GAUSS_WEIGHTS = {
        0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};

    /** Integral of pdf * sin(theta) over one cell, by Gauss-Legendre on a grid of sub-cells (kinks inside a cell stay accurate enough). */
    private static double integrateCell(Density density, double theta0, double theta1, double phi0, double phi1) {
        int n = SUB_CELLS;
        double ht = (theta1 - theta0) / n, hp = (phi1 - phi0) / n;
        double sum = 0;
        for (int a = 0; a < n; a++) {
            double tc = theta0 + (a + 0.5) * ht;
            for (int i = 0; i < GAUSS_NODES.length; i++) {
                double theta = tc + 0.5 * ht * GAUSS_NODES[i];
                double st = Math.sin(theta), ct = Math.cos(theta);
                for (int b = 0; b < n; b++) {
                    double pc = phi0 + (b + 0.5) * hp;
                    for (int j = 0; j < GAUSS_NODES.length; j++) {
                        double phi = pc + 0.5 * hp * GAUSS_NODES[j];
                        sum += GAUSS_WEIGHTS[i] * GAUSS_WEIGHTS[j] * density.pdf(st * Math.cos(phi), st * Math.sin(phi), ct) * st;
                    }
                }
            }
        }
        return sum * ht * hp / 4;
    }

    private static double sq(double x) { return x * x; }

    /** {@return P(X &gt;= statistic) for X chi-square distributed with dof degrees of freedom} */
    static double chiSquareSurvival(double statistic, int dof) {
        return regularizedGammaQ(0.5 * dof, 0.5 * statistic);
    }

    /** Upper regularized incomplete gamma Q(a, x) = Gamma(a, x) / Gamma(a): series below a + 1, continued fraction above. */
    static double regularizedGammaQ(double a, double x) {
        if (x <= 0) return 1;
        double logPrefactor = -x + a * Math.log(x) - logGamma(a);
        if (x < a + 1) {
            double term = 1 / a, sum = term;
            for (int n = 1; n < 100_000; n++) {
                term *= x / (a + n);
                sum += term;
                if (term < sum * 1e-16) break;
            }
            return Math.max(0, 1 - sum * Math.exp(logPrefactor));
        }
        // Modified Lentz evaluation of the continued fraction for Gamma(a, x).
        final double tiny = 1e-300;
        double b = x + 1 - a, c = 1 / tiny, d = 1 / b, h = d;
        for (int i = 1; i < 100_000; i++) {
            double an = -i * (i - a);
            b += 2;
            d = an * d + b;
            if (Math.abs(d) < tiny) d = tiny;
            c = b + an / c;
            if (Math.abs(c) < tiny) c = tiny;
            d = 1 / d;
            double delta = d * c;
            h *= delta;
            if (Math.abs(delta - 1) < 1e-16) break;
        }
        return Math.exp(logPrefactor) * h;
    }

    private static final double[] LANCZOS = {
        0.99999999999980993, 676.5203681218851, -1259.1392167224028, 771.32342877765313,
        -176.61502916214059, 12.507343278686905, -0.13857109526572012, 9.9843695780195716e-6,
        1.5056327351493116e-7};

    /** ln Gamma(x) for x &gt;= 0.5 by the Lanczos approximation (g = 7). */
    static double logGamma(double x) {
        x -= 1;
        double sum = LANCZOS[0];
        for (int i = 1; i < LANCZOS.length; i++) sum += LANCZOS[i] / (x + i);
        double t = x + 7.5;
        return 0.5 * Math.log(2 * Math.PI) + (x + 0.5) * Math.log(t) - t + Math.log(sum);
    }
}
