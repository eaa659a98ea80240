package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import lt.spindulys.camera.LensPattern;
import lt.spindulys.camera.PixelFilter;

/**
 * Film offsets drawn by {@link FilterSampler} follow the filter (|f| for Mitchell-Netravali), and
 * the weights make a sample's expected contribution f: their mean is 1, their sign f's.
 */
class FilterSamplerTest {
    /** ∫ x^k g(x) dx over [-r, r] by the midpoint rule, fine enough for 1e-7 on these smooth filters. */
    private static double moment(PixelFilter f, double width, int k, boolean absolute) {
        double r = f.radius(width);
        int steps = 400_000;
        double h = 2 * r / steps, sum = 0;
        for (int i = 0; i < steps; i++) {
            double x = -r + (i + 0.5) * h, v = f.evaluate(x, width);
            sum += Math.pow(x, k) * (absolute ? Math.abs(v) : v);
        }
        return sum * h;
    }

    @ParameterizedTest
    @EnumSource(PixelFilter.class)
    void offsetsHaveTheFiltersMeanAndVariance(PixelFilter filter) {
        for (double width : new double[] {filter.defaultWidth(), 2.5}) {
            FilterSampler s = new FilterSampler(filter, width);
            // u on a fine even grid: the offsets' moments are then the sampled distribution's own.
            int n = 1 << 20;
            double sum = 0, sumSq = 0;
            for (int i = 0; i < n; i++) {
                double u = (i + 0.5) / n, x = s.offset(s.bin(u), u);
                assertTrue(Math.abs(x) <= s.radius() + 1e-12, "offset within the radius");
                sum += x;
                sumSq += x * x;
            }
            double variance = moment(filter, width, 2, true) / moment(filter, width, 0, true);
            assertEquals(0, sum / n, 1e-6, filter + " " + width + ": mean");
            // The tabulated filter is spread evenly within each bin, which adds a bin's variance (about 2e-6).
            double bin = 2 * s.radius() / FilterSampler.BINS;
            assertEquals(variance, sumSq / n, 1e-5 * variance + bin * bin / 12 + 1e-7, filter + " " + width + ": variance");
        }
    }

    /** Known second moments: a box W^2 / 12, the Gaussian (W / 4)^2 (its cut at six sigma is negligible). */
    @Test
    void knownVariances() {
        assertEquals(1.0 / 12, moment(PixelFilter.BOX, 1, 2, true) / moment(PixelFilter.BOX, 1, 0, true), 1e-9);
        assertEquals(0.375 * 0.375, moment(PixelFilter.GAUSSIAN, 1.5, 2, true) / moment(PixelFilter.GAUSSIAN, 1.5, 0, true), 1e-7);
        assertEquals(3, PixelFilter.BLACKMAN_HARRIS.radius(1.5) * 2, 1e-12, "Cycles doubles the Blackman-Harris width");
        assertEquals(2, PixelFilter.MITCHELL.radius(4), 1e-12);
    }

    /** Random offsets binned against the filter's probabilities: a chi-square test at 32 bins. */
    @ParameterizedTest
    @EnumSource(PixelFilter.class)
    void offsetsFollowTheDistribution(PixelFilter filter) {
        double width = filter.defaultWidth();
        FilterSampler s = new FilterSampler(filter, width);
        double r = s.radius();
        int bins = 32, n = 200_000;
        int[] counts = new int[bins];
        Rng rng = new Rng().seed(7);
        for (int i = 0; i < n; i++) {
            double u = rng.nextDouble(), x = s.offset(s.bin(u), u);
            counts[Math.min(bins - 1, (int) ((x + r) / (2 * r) * bins))]++;
        }
        double total = moment(filter, width, 0, true), chi2 = 0;
        for (int b = 0; b < bins; b++) {
            double lo = -r + 2 * r * b / bins, hi = lo + 2 * r / bins, mass = 0;
            int steps = 2000;
            for (int j = 0; j < steps; j++) mass += Math.abs(filter.evaluate(lo + (j + 0.5) * (hi - lo) / steps, width));
            double expected = n * mass * (hi - lo) / steps / total;
            chi2 += (counts[b] - expected) * (counts[b] - expected) / expected;
        }
        assertTrue(chi2 < 61.1, filter + ": chi-square " + chi2 + " at 31 degrees of freedom (0.1% level 61.1)");
    }

    @Test
    void nonNegativeFiltersWeighExactlyOne() {
        for (PixelFilter f : new PixelFilter[] {PixelFilter.BOX, PixelFilter.GAUSSIAN, PixelFilter.BLACKMAN_HARRIS}) {
            FilterSampler s = new FilterSampler(f, f.defaultWidth());
            assertFalse(s.hasNegativeWeights());
            for (double u = 0; u < 1; u += 0.01) assertEquals(1.0, s.weight(s.bin(u), s.bin(1 - u - 1e-9)));
        }
    }

    /** Mitchell's lobes: samples there weigh -(∫|f|/∫f)^2 or, negative on both axes, +; the mean weight is 1. */
    @Test
    void mitchellsNegativeLobesWeighNegativelyAndTheWeightsAverageOne() {
        FilterSampler s = new FilterSampler(PixelFilter.MITCHELL, 4);
        assertTrue(s.hasNegativeWeights());
        double c = moment(PixelFilter.MITCHELL, 4, 0, true) / moment(PixelFilter.MITCHELL, 4, 0, false);
        assertTrue(c > 1);
        assertEquals(c, s.axisWeight(), 1e-5, "the tabulated filter's ratio, close to f's");
        int m = 4096;
        double sum = 0;
        int negative = 0;
        for (int i = 0; i < m; i++) {
            double u = (i + 0.5) / m;
            int bx = s.bin(u);
            double x = s.offset(bx, u);
            // The sign follows the filter where the offset lies (away from its zero crossings).
            double fx = PixelFilter.MITCHELL.evaluate(x, 4);
            if (Math.abs(fx) > 1e-3) assertEquals(Math.signum(fx), s.sign(bx), "sign at " + x);
            if (s.sign(bx) < 0) negative++;
            for (int j = 0; j < m; j++) sum += s.weight(bx, s.bin((j + 0.5) / m));
        }
        assertTrue(negative > 0, "some offsets fall in the lobes");
        assertEquals(1, sum / ((double) m * m), 1e-3, "the weights' mean over an even grid of (u, v)");
        double a = s.axisWeight();
        assertEquals(-a * a, s.weight(s.bin(0.001), s.bin(0.5)), 1e-12);
        assertEquals(a * a, s.weight(s.bin(0.001), s.bin(0.999)), 1e-12);
    }

    /** The box of width 1 keeps the pixel's jittered strata bit for bit; other filters move them by their offsets. */
    @Test
    void theUnitBoxKeepsTheStrataAndOtherFiltersSpreadThem() {
        PixelSampler box = new PixelSampler(16, LensPattern.CONCENTRIC, true);
        PixelSampler unit = new PixelSampler(16, LensPattern.CONCENTRIC, true, new FilterSampler(PixelFilter.BOX, 1));
        PixelSampler wide = new PixelSampler(16, LensPattern.CONCENTRIC, true, new FilterSampler(PixelFilter.BLACKMAN_HARRIS, 1.5));
        box.startPixel(3, 5, 6);
        unit.startPixel(3, 5, 6);
        wide.startPixel(3, 5, 6);
        boolean outside = false;
        for (int i = 0; i < 16; i++) {
            assertEquals(box.filmX(i), unit.filmX(i), 0.0);
            assertEquals(box.filmY(i), unit.filmY(i), 0.0);
            assertEquals(1.0, unit.weight(i));
            assertEquals(box.lensU(i), wide.lensU(i), 0.0, "the filter moves only the film samples");
            assertEquals(box.time(i), wide.time(i), 0.0);
            assertTrue(Math.abs(wide.filmX(i) - 5.5) <= 1.5 && Math.abs(wide.filmY(i) - 6.5) <= 1.5);
            outside |= wide.filmX(i) < 5 || wide.filmX(i) >= 6 || wide.filmY(i) < 6 || wide.filmY(i) >= 7;
        }
        assertTrue(outside, "a filter wider than the pixel reaches past it");
    }

    /** With one sample the box's is the centre, as always; another filter's is drawn from it. */
    @Test
    void oneSampleIsTheCentreOnlyForTheBox() {
        PixelSampler box = new PixelSampler(1, null, false);
        box.startPixel(1, 2, 3);
        assertEquals(2.5, box.filmX(0));
        assertEquals(3.5, box.filmY(0));
        PixelSampler gauss = new PixelSampler(1, null, false, new FilterSampler(PixelFilter.GAUSSIAN, 1.5));
        boolean moved = false;
        for (int px = 0; px < 8; px++) {
            gauss.startPixel(1, px, 3);
            moved |= gauss.filmX(0) != px + 0.5;
        }
        assertTrue(moved);
    }
}
