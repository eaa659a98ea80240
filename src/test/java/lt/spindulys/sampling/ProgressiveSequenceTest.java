package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

class ProgressiveSequenceTest {
    private static final long[] KEYS = {ProgressiveSequence.key(1, 0, 0, 0), ProgressiveSequence.key(1, 74, 110, 3),
            ProgressiveSequence.key(-5, 1000, 7, 12), 0L};

    /**
     * Whether points first .. first + count - 1 (count 2^k) hold exactly count / 2^m points in
     * every elementary interval of area 2^-m, for every grid 2^a x 2^(m - a).
     */
    static void assertStratified(long key, int first, int count, int m) {
        double[] p = new double[2];
        for (int a = 0; a <= m; a++) {
            int cols = 1 << a, rows = 1 << (m - a);
            int[] cells = new int[cols * rows];
            for (int i = first; i < first + count; i++) {
                ProgressiveSequence.get2D(i, key, p);
                assertTrue(p[0] >= 0 && p[0] < 1 && p[1] >= 0 && p[1] < 1);
                cells[(int) (p[1] * rows) * cols + (int) (p[0] * cols)]++;
            }
            for (int c = 0; c < cells.length; c++) {
                assertEquals(count >> m, cells[c], "key " + key + ", points " + first + " to " + (first + count - 1) + ", grid " + cols + "x" + rows + ", cell " + c);
            }
        }
    }

    @Test
    void everyPowerOfTwoPrefixIsANet() {
        for (long key : KEYS) for (int k = 0; k <= 10; k++) assertStratified(key, 0, 1 << k, k);
    }

    /** A round is an aligned block of 2^k points: stratified by itself too. */
    @Test
    void everyAlignedBlockIsANet() {
        for (long key : KEYS) {
            for (int k = 0; k <= 7; k++) for (int j = 1; j < 5; j++) assertStratified(key, j << k, 1 << k, k);
        }
    }

    /** 96 = 64 + 32 points: stratified in the intervals of area 1/32, three points each. */
    @Test
    void aPrefixThatIsAMultipleOfAPowerOfTwoIsStratifiedAtThatPower() {
        for (long key : KEYS) {
            assertStratified(key, 0, 96, 5);
            assertStratified(key, 0, 192, 6);
        }
    }

    @Test
    void everyOneDimensionalPrefixTakesEachStratumOnce() {
        for (long key : KEYS) {
            for (int k = 0; k <= 10; k++) {
                int n = 1 << k;
                boolean[] seen = new boolean[n];
                for (int i = 0; i < n; i++) {
                    int s = (int) (ProgressiveSequence.get1D(i, key) * n);
                    assertFalse(seen[s], "stratum " + s + " of " + n + " twice");
                    seen[s] = true;
                }
            }
        }
    }

    /**
     * Sequences of different keys (other dimensions, other pixels) are not correlated: the same
     * index's points of two keys are spread over the square, not along a curve.
     */
    @Test
    void keysGiveUncorrelatedSequences() {
        double[] p = new double[2], q = new double[2];
        for (int d = 1; d < 8; d++) {
            long a = ProgressiveSequence.key(3, 5, 9, 0), b = ProgressiveSequence.key(3, 5, 9, d);
            int n = 256;
            int[] cells = new int[16];
            double sxy = 0, syx = 0;
            for (int i = 0; i < n; i++) {
                ProgressiveSequence.get2D(i, a, p);
                ProgressiveSequence.get2D(i, b, q);
                sxy += (p[0] - 0.5) * (q[0] - 0.5);
                syx += (p[1] - 0.5) * (q[1] - 0.5);
                cells[(int) (p[0] * 4) * 4 + (int) (q[0] * 4)]++;
            }
            // Uncorrelated: |r| about 1/sqrt(n) = 0.06; a shared scramble of x would make the 4x4 cells of (x_a, x_b) half empty.
            assertTrue(Math.abs(sxy / n * 12) < 0.25 && Math.abs(syx / n * 12) < 0.25, "dimension " + d + ": " + sxy / n * 12 + ", " + syx / n * 12);
            for (int c : cells) assertTrue(c > 0, "dimension " + d + ": an empty cell of the pair");
        }
    }

    @Test
    void keysDependOnEveryInput() {
        long k = ProgressiveSequence.key(1, 2, 3, 4);
        assertNotEquals(k, ProgressiveSequence.key(0, 2, 3, 4));
        assertNotEquals(k, ProgressiveSequence.key(1, 3, 3, 4));
        assertNotEquals(k, ProgressiveSequence.key(1, 2, 4, 4));
        assertNotEquals(k, ProgressiveSequence.key(1, 2, 3, 5));
    }
}
