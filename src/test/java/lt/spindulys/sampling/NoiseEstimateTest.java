package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;

import org.junit.jupiter.api.Test;

class NoiseEstimateTest {
    @Test
    void equalGroupsHaveNoErrorAndOneGroupNothingToCompare() {
        NoiseEstimate e = new NoiseEstimate();
        e.add(16, 0.5, 0.25, 2);
        assertEquals(0.0, e.error());
        e.add(16, 0.5, 0.25, 2);
        assertEquals(0.0, e.error(), 1e-12);
        assertEquals(32, e.samples());
        e.reset();
        assertEquals(0, e.samples());
    }

    @Test
    void twoGroupsGiveTheStandardErrorOfTheirMeanRelativeToTheLevel() {
        NoiseEstimate e = new NoiseEstimate();
        // Grey means 1 and 3 of 4 samples each: I = 2, sum s (m - I)^2 = 8, variance 8 / (1 * 8) = 1 per channel.
        e.add(4, 1, 1, 1);
        e.add(4, 3, 3, 3);
        assertEquals(3.0 / 6, e.error(), 1e-12, "three channels' standard errors of 1 over a level of 6");
        // Below a level of 1 the error is relative to its square root, as Cycles divides.
        e.reset();
        e.add(4, 0.01, 0, 0);
        e.add(4, 0.03, 0, 0);
        assertEquals(0.01 / (1e-4 + Math.sqrt(0.02)), e.error(), 1e-12);
    }

    @Test
    void theEstimateMatchesTheScatterOfMeansOfIndependentSamples() {
        // Means of 64 samples of a uniform variable, each the mean of 8 groups of 8: the estimate
        // of its standard error averages to the true one, sqrt(1/12 / 64).
        Random random = new Random(5);
        NoiseEstimate e = new NoiseEstimate();
        double sum = 0;
        int trials = 4000;
        for (int t = 0; t < trials; t++) {
            e.reset();
            for (int g = 0; g < 8; g++) {
                double m = 0;
                for (int i = 0; i < 8; i++) m += random.nextDouble();
                m /= 8;
                e.add(8, m + 1, 1, 1); // level about 3.5: relative to it
            }
            sum += e.error() * 3.5;
        }
        double expected = Math.sqrt(1 / 12.0 / 64);
        assertEquals(expected, sum / trials, 0.05 * expected);
    }
}
