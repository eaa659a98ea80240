package lt.spindulys.sampling;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class PixelSamplerTest {
    @ParameterizedTest
    @ValueSource(ints = {1, 2, 4, 6, 7, 9, 16})
    void everyFilmStratumGetsExactlyOneSample(int n) {
        PixelSampler s = new PixelSampler(n);
        s.startPixel(42, 10, 20);
        int cols = 0, rows;
        for (int c = (int) Math.floor(Math.sqrt(n)); c >= 1; c--) if (n % c == 0) { cols = n / c; break; }
        rows = n / cols;
        boolean[] seen = new boolean[n];
        for (int i = 0; i < n; i++) {
            double fx = s.filmX(i) - 10, fy = s.filmY(i) - 20;
            assertTrue(fx >= 0 && fx < 1 && fy >= 0 && fy < 1, "sample inside its pixel");
            int cell = (int) (fy * rows) * cols + (int) (fx * cols);
            assertFalse(seen[cell], "two samples in one stratum");
            seen[cell] = true;
            assertTrue(s.time(i) >= 0 && s.time(i) < 1);
            assertTrue(s.lensU(i) >= 0 && s.lensU(i) < 1 && s.lensV(i) >= 0 && s.lensV(i) < 1);
        }
        boolean[] timeStrata = new boolean[n];
        for (int i = 0; i < n; i++) timeStrata[(int) (s.time(i) * n)] = true;
        for (boolean b : timeStrata) assertTrue(b, "time samples are stratified");
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
}
