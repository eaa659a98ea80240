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
        assertEquals(1234L, SampleRounds.seed(1234L, 0), "round 0 keeps the pass's seed: the samples of a render without rounds");
    }

    @Test
    void theDefaultMinimumIsFourRoundsOfSixteenThenRoundsOfHalfThePixelsSamples() {
        SampleRounds r = SampleRounds.adaptive(256, 64);
        assertEquals(List.of(64, 96, 144, 208), checks(r));
        assertEquals(256, total(r));
        assertEquals(16, r.size(0));
        assertEquals(48, r.size(r.rounds() - 1), "the last round takes the remainder");
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
    void roundSeedsDiffer() {
        assertNotEquals(SampleRounds.seed(7, 1), SampleRounds.seed(7, 2));
        assertNotEquals(SampleRounds.seed(7, 1), SampleRounds.seed(8, 1));
        assertNotEquals(7L, SampleRounds.seed(7, 1));
    }

    @Test
    void refusesAMinimumOutsideTheSamples() {
        assertThrows(IllegalArgumentException.class, () -> SampleRounds.adaptive(16, 17));
        assertThrows(IllegalArgumentException.class, () -> SampleRounds.adaptive(16, 0));
        assertThrows(IllegalArgumentException.class, () -> SampleRounds.uniform(0));
    }
}
