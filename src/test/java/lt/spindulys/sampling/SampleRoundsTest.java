package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

class SampleRoundsTest {
    /** The sample counts after which the pixel's error is checked. */
    private static List<Integer> checks(SampleRounds r) {
        List<Integer> at = new ArrayList<>();
        int taken = 0;
        for (int k = 0; k < r.rounds(); k++) {
            taken += r.size(k);
            if (r.checkAfter(k)) at.add(taken);
        }
        return at;
    }

    private static int total(SampleRounds r) {
        int n = 0;
        for (int k = 0; k < r.rounds(); k++) n += r.size(k);
        return n;
    }

    @Test
    void withoutAThresholdOneRoundOfAllSamplesNeverChecked() {
        SampleRounds r = SampleRounds.uniform(37);
        assertEquals(1, r.rounds());
        assertEquals(37, r.size(0));
        assertEquals(List.of(), checks(r));
    }

    @Test
    void theDefaultMinimumIsFourRoundsOfSixteenThenAlignedPowersOfTwo() {
        SampleRounds r = SampleRounds.adaptive(256, 64);
        assertEquals(List.of(64, 96, 128, 192), checks(r));
        assertEquals(256, total(r));
        assertEquals(16, r.size(0));
        assertEquals(64, r.size(r.rounds() - 1));
        assertEquals(64, r.largest());
        assertEquals(List.of(64, 96, 128, 192, 256, 384, 512, 768), checks(SampleRounds.adaptive(1024, 64)));
    }

    /**
     * Every round is a power of two that starts at a multiple of itself (an aligned block of the
     * pixel's sequence, so a net by itself), but the last, which takes the remainder.
     */
    @Test
    void roundsAreAlignedPowerOfTwoBlocks() {
        for (int n = 1; n <= 600; n += 13) {
            for (int m = 1; m <= n; m += 5) {
                SampleRounds r = SampleRounds.adaptive(n, m);
                int taken = 0;
                for (int k = 0; k < r.rounds() - 1; k++) {
                    int size = r.size(k);
                    assertEquals(1, Integer.bitCount(size), n + "/" + m + " round " + k + " of " + size);
                    assertEquals(0, taken % size, n + "/" + m + " round " + k + " starts at " + taken);
                    taken += size;
                }
            }
        }
    }

    @Test
    void roundsAddUpToTheSamplesAndNoRoundIsASingleSample() {
        for (int n = 1; n <= 300; n++) {
            for (int m = 1; m <= n; m += 7) {
                SampleRounds r = SampleRounds.adaptive(n, m);
                assertEquals(n, total(r), n + " samples, minimum " + m);
                for (int k = 0; k < r.rounds(); k++) assertTrue(r.size(k) >= Math.min(n, SampleRounds.MIN_ROUND), n + "/" + m + " round " + k);
                List<Integer> c = checks(r);
                if (!c.isEmpty()) {
                    assertTrue(c.get(0) >= m, "the first check comes at the minimum or after: " + n + "/" + m);
                    assertTrue(r.size(0) < c.get(0), "at least two rounds to compare");
                }
                assertFalse(c.contains(n), "no check after the last round");
            }
        }
    }

    @Test
    void refusesAMinimumOutsideTheSamples() {
        assertThrows(IllegalArgumentException.class, () -> SampleRounds.adaptive(16, 17));
        assertThrows(IllegalArgumentException.class, () -> SampleRounds.adaptive(16, 0));
        assertThrows(IllegalArgumentException.class, () -> SampleRounds.uniform(0));
    }
}
