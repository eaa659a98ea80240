package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

class PaddedStrataTest {
    @Test
    void permutationsAreBijectionsForEveryCount() {
        for (int n = 1; n <= 300; n++) {
            for (int p : new int[] {0, 1, -1, 0x12345678, 0x9abcdef0}) {
                boolean[] seen = new boolean[n];
                for (int i = 0; i < n; i++) {
                    int j = PaddedStrata.permute(i, n, p);
                    assertTrue(j >= 0 && j < n, "in range");
                    assertFalse(seen[j], "n " + n + " p " + p + ": " + j + " twice");
                    seen[j] = true;
                }
            }
        }
    }

    /** Over a pixel's samples every stratum of a dimension, and of a pair, is taken exactly once. */
    @Test
    void aPixelsSamplesTakeEveryStratumOnce() {
        PaddedStrata strata = new PaddedStrata();
        Rng rng = new Rng();
        double[] uv = new double[2];
        for (int n : new int[] {1, 7, 16, 24, 64, 251}) {
            int[] grid = PixelSampler.grid(n);
            int cols = grid[0], rows = grid[1];
            boolean[] line = new boolean[n], square = new boolean[cols * rows];
            for (int i = 0; i < n; i++) {
                strata.start(42, 3, 5, i, n);
                double u = strata.get1D(0, rng.seed(i));
                int s = (int) (u * n);
                assertFalse(line[s], "stratum " + s + " of " + n + " twice");
                line[s] = true;
                strata.get2D(1, rng, uv);
                int cell = (int) (uv[1] * rows) * cols + (int) (uv[0] * cols);
                assertFalse(square[cell], "cell " + cell + " of " + n + " twice");
                square[cell] = true;
            }
        }
    }

    /** Dimensions and pixels are shuffled independently: their orders differ. */
    @Test
    void dimensionsAndPixelsHaveTheirOwnOrders() {
        PaddedStrata strata = new PaddedStrata();
        Rng rng = new Rng();
        int n = 64, sameDims = 0, samePixels = 0;
        for (int i = 0; i < n; i++) {
            strata.start(7, 0, 0, i, n);
            int a = (int) (strata.get1D(0, rng) * n), b = (int) (strata.get1D(2, rng) * n);
            strata.start(7, 1, 0, i, n);
            int c = (int) (strata.get1D(0, rng) * n);
            if (a == b) sameDims++;
            if (a == c) samePixels++;
        }
        assertTrue(sameDims < 8, "dimensions 0 and 2 agree on " + sameDims + " of 64 samples");
        assertTrue(samePixels < 8, "two pixels agree on " + samePixels + " of 64 samples");
    }

    /**
     * Progressive (adaptive sampling): every dimension and pair is its own sequence over the
     * pixel's sample index, so the first 2^k samples take each of 2^k strata of a dimension, and
     * each cell of a 2^a x 2^(k-a) grid of a pair, once; the jitter generator is not drawn from.
     */
    @Test
    void progressiveSamplesAreStratifiedAtEveryPowerOfTwo() {
        PaddedStrata strata = new PaddedStrata();
        Rng rng = new Rng().seed(5);
        long before = new Rng().seed(5).nextLong();
        double[] uv = new double[2];
        for (int k = 0; k <= 8; k++) {
            int n = 1 << k, cols = 1 << (k / 2), rows = n / cols;
            boolean[] line = new boolean[n], square = new boolean[n];
            for (int i = 0; i < n; i++) {
                strata.startProgressive(42, 3, 5, i);
                int s = (int) (strata.get1D(0, rng) * n);
                assertFalse(line[s], "stratum " + s + " of " + n + " twice");
                line[s] = true;
                strata.get2D(1, rng, uv);
                int cell = (int) (uv[1] * rows) * cols + (int) (uv[0] * cols);
                assertFalse(square[cell], "cell " + cell + " of " + n + " twice");
                square[cell] = true;
            }
        }
        assertEquals(before, rng.nextLong(), "no jitter drawn");
    }
}
