package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import lt.spindulys.camera.LensPattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class PixelSamplerTest {
    @ParameterizedTest
    @ValueSource(ints = {1, 2, 4, 6, 7, 9, 16, 251})
    void everyFilmStratumGetsExactlyOneSample(int n) {
        PixelSampler s = new PixelSampler(n);
        s.startPixel(42, 10, 20);
        int[] grid = PixelSampler.grid(n);
        int cols = grid[0], rows = grid[1];
        boolean[] seen = new boolean[cols * rows];
        for (int i = 0; i < n; i++) {
            double fx = s.filmX(i) - 10, fy = s.filmY(i) - 20;
            assertTrue(fx >= 0 && fx < 1 && fy >= 0 && fy < 1, "sample inside its pixel");
            int cell = (int) (fy * rows) * cols + (int) (fx * cols);
            assertFalse(seen[cell], "two samples in one stratum");
            seen[cell] = true;
            assertTrue(s.time(i) >= 0 && s.time(i) < 1);
            assertTrue(s.lensU(i) * s.lensU(i) + s.lensV(i) * s.lensV(i) <= 1, "lens sample on the unit disk");
        }
        boolean[] timeStrata = new boolean[n];
        for (int i = 0; i < n; i++) timeStrata[(int) (s.time(i) * n)] = true;
        for (boolean b : timeStrata) assertTrue(b, "time samples are stratified");
    }

    /** Counts that factor into a grid at most twice as wide as tall keep it; others, a nearly square padded grid. */
    @Test
    void gridsAreNearlySquare() {
        assertArrayEquals(new int[] {3, 1}, PixelSampler.grid(3), "small counts as they always were");
        assertArrayEquals(new int[] {4, 4}, PixelSampler.grid(16));
        assertArrayEquals(new int[] {4, 2}, PixelSampler.grid(8));
        assertArrayEquals(new int[] {3, 3}, PixelSampler.grid(7), "7 is prime: 9 cells, 2 of them left empty");
        assertArrayEquals(new int[] {16, 16}, PixelSampler.grid(251));
        for (int n = 1; n < 3000; n++) {
            int[] g = PixelSampler.grid(n);
            assertTrue((long) g[0] * g[1] >= n && (long) g[0] * g[1] < n + 2L * g[0] + 1, "n " + n);
            assertTrue(n <= 4 || g[0] <= 2 * g[1], "n " + n + " is cut into strips");
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 4, 5})
    void samplesDependOnlyOnSeedAndPixel(int n) {
        PixelSampler a = new PixelSampler(n), b = new PixelSampler(n);
        a.startPixel(7, 3, 4);
        b.startPixel(7, 100, 100); // a different history must not matter
        b.startPixel(7, 3, 4);
        for (int i = 0; i < n; i++) {
            assertEquals(a.filmX(i), b.filmX(i));
            assertEquals(a.filmY(i), b.filmY(i));
            assertEquals(a.time(i), b.time(i));
            assertEquals(a.lensU(i), b.lensU(i));
        }
        b.startPixel(8, 3, 4);
        assertNotEquals(a.time(0), b.time(0), "the global seed changes the samples");
    }

    /**
     * The concentric map sends the square ring of grid cells at distance r from the centre onto
     * the circle of radius r, so of an 8 x 8 grid's strata exactly the inner 4 x 4 land inside
     * radius 1/2 and the inner 6 x 6 inside radius 3/4: the lens is covered by equal areas.
     */
    @Test
    void concentricLensSamplesAreStratifiedOnTheDisk() {
        PixelSampler s = new PixelSampler(64);
        s.startPixel(3, 5, 6);
        int inHalf = 0, inThreeQuarters = 0;
        for (int i = 0; i < 64; i++) {
            double r = Math.hypot(s.lensU(i), s.lensV(i));
            assertTrue(r <= 1);
            if (r < 0.5) inHalf++;
            if (r < 0.75) inThreeQuarters++;
        }
        assertEquals(16, inHalf);
        assertEquals(36, inThreeQuarters);
    }

    /** The thesis's pattern: sample k at angle 2 pi k / n, radius 1 for even k and 1/2 for odd k, each once. */
    @ParameterizedTest
    @ValueSource(ints = {2, 6, 8, 9})
    void ringLensSamplesAreTheThesisPattern(int n) {
        PixelSampler s = new PixelSampler(n, LensPattern.RING);
        s.startPixel(11, 2, 3);
        boolean[] seen = new boolean[n];
        for (int i = 0; i < n; i++) {
            int found = -1;
            for (int k = 0; k < n; k++) {
                double r = k % 2 == 0 ? 1 : 0.5, a = 2 * Math.PI * k / n;
                if (Math.abs(s.lensU(i) - r * Math.cos(a)) < 1e-12 && Math.abs(s.lensV(i) - r * Math.sin(a)) < 1e-12) found = k;
            }
            assertTrue(found >= 0, "sample " + i + " is not a ring point: " + s.lensU(i) + ", " + s.lensV(i));
            assertFalse(seen[found], "ring point " + found + " twice");
            seen[found] = true;
        }
    }

    @Test
    void oneRingSampleIsTheLensCentre() {
        PixelSampler s = new PixelSampler(1, LensPattern.RING);
        s.startPixel(1, 0, 0);
        assertEquals(0, s.lensU(0));
        assertEquals(0, s.lensV(0));
    }

    /** The lens pattern changes only the lens samples: film and time samples stay the same. */
    @ParameterizedTest
    @ValueSource(ints = {1, 4, 12})
    void lensPatternLeavesFilmAndTimeAlone(int n) {
        PixelSampler a = new PixelSampler(n, LensPattern.CONCENTRIC), b = new PixelSampler(n, LensPattern.RING);
        a.startPixel(5, 7, 8);
        b.startPixel(5, 7, 8);
        for (int i = 0; i < n; i++) {
            assertEquals(a.filmX(i), b.filmX(i));
            assertEquals(a.filmY(i), b.filmY(i));
            assertEquals(a.time(i), b.time(i));
        }
    }

    /** Without a lens (a pinhole) every lens sample is the centre; film and time samples are those of a lens. */
    @ParameterizedTest
    @ValueSource(ints = {1, 4, 12})
    void noLensGivesTheCentreAndTheSameFilmAndTime(int n) {
        PixelSampler lens = new PixelSampler(n, LensPattern.CONCENTRIC), none = new PixelSampler(n, null);
        lens.startPixel(5, 7, 8);
        none.startPixel(5, 7, 8);
        boolean off = false;
        for (int i = 0; i < n; i++) {
            assertEquals(0, none.lensU(i));
            assertEquals(0, none.lensV(i));
            off |= lens.lensU(i) != 0 || lens.lensV(i) != 0;
            assertEquals(lens.filmX(i), none.filmX(i));
            assertEquals(lens.filmY(i), none.filmY(i));
            assertEquals(lens.time(i), none.time(i));
        }
        assertTrue(off, "a lens pattern moves samples off the centre");
    }

    /** Without time samples the film (and any lens) samples are exactly those drawn with them; every time is 0. */
    @ParameterizedTest
    @ValueSource(ints = {1, 4, 6, 16})
    void leavingOutTheTimesKeepsFilmAndLensSamples(int n) {
        for (LensPattern lens : new LensPattern[] {null, LensPattern.CONCENTRIC, LensPattern.RING}) {
            PixelSampler with = new PixelSampler(n, lens, true), without = new PixelSampler(n, lens, false);
            with.startPixel(5, 17, 9);
            without.startPixel(5, 17, 9);
            for (int i = 0; i < n; i++) {
                assertEquals(with.filmX(i), without.filmX(i));
                assertEquals(with.filmY(i), without.filmY(i));
                assertEquals(with.lensU(i), without.lensU(i));
                assertEquals(with.lensV(i), without.lensV(i));
                assertEquals(0, without.time(i));
            }
        }
    }

    /**
     * Adaptive sampling draws a pixel's rounds from one progressive sequence: at every check the
     * film positions of all the samples taken so far are stratified as one set, in every
     * elementary interval of area 2^-m for the largest power 2^m dividing the count (one sample
     * each at 64, 128, 256; the lens and time samples likewise). Rounds drawn each as a
     * stratified set of its own would put two samples in some interval.
     */
    @Test
    void theRoundsTakenSoFarAreOneStratifiedSetAtEveryCheck() {
        SampleRounds rounds = SampleRounds.adaptive(512, 64);
        PixelSampler s = new PixelSampler(rounds.largest(), LensPattern.CONCENTRIC, true);
        double[] fx = new double[512], fy = new double[512], time = new double[512];
        int taken = 0, checked = 0;
        for (int k = 0; k < rounds.rounds(); k++) {
            s.startProgressive(42, 10, 20, taken, rounds.size(k));
            for (int i = 0; i < rounds.size(k); i++, taken++) {
                fx[taken] = s.filmX(i) - 10;
                fy[taken] = s.filmY(i) - 20;
                time[taken] = s.time(i);
                assertTrue(s.lensU(i) * s.lensU(i) + s.lensV(i) * s.lensV(i) <= 1, "lens sample on the unit disk");
            }
            if (!rounds.checkAfter(k) && k < rounds.rounds() - 1) continue;
            checked++;
            int m = Integer.numberOfTrailingZeros(taken), per = taken >> m;
            for (int a = 0; a <= m; a++) {
                int cols = 1 << a, rows = 1 << (m - a);
                int[] cells = new int[cols * rows];
                for (int i = 0; i < taken; i++) {
                    assertTrue(fx[i] >= 0 && fx[i] < 1 && fy[i] >= 0 && fy[i] < 1, "sample inside its pixel");
                    cells[(int) (fy[i] * rows) * cols + (int) (fx[i] * cols)]++;
                }
                for (int c : cells) assertEquals(per, c, "after " + taken + " samples, grid " + cols + "x" + rows);
            }
            int[] strata = new int[1 << m];
            for (int i = 0; i < taken; i++) strata[(int) (time[i] * strata.length)]++;
            for (int c : strata) assertEquals(per, c, "time strata after " + taken + " samples");
        }
        assertEquals(7, checked, "checked at 64, 96, 128, 192, 256, 384 and at the end, 512");
    }

    /** A pixel's progressive samples depend on the seed, the pixel and their index only, not on the round they come in. */
    @Test
    void progressiveSamplesDependOnlyOnTheirIndex() {
        PixelSampler whole = new PixelSampler(32, LensPattern.CONCENTRIC, true), parts = new PixelSampler(32, LensPattern.CONCENTRIC, true);
        whole.startProgressive(7, 3, 4, 0, 32);
        for (int first = 0; first < 32; first += 8) {
            parts.startProgressive(7, 3, 4, first, 8);
            for (int i = 0; i < 8; i++) {
                assertEquals(whole.filmX(first + i), parts.filmX(i));
                assertEquals(whole.filmY(first + i), parts.filmY(i));
                assertEquals(whole.lensU(first + i), parts.lensU(i));
                assertEquals(whole.time(first + i), parts.time(i));
            }
        }
        parts.startProgressive(7, 4, 4, 0, 8);
        assertNotEquals(whole.filmX(0) - 3, parts.filmX(0) - 4, "another pixel, other samples");
    }
}
