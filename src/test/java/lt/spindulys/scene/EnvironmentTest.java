package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Random;
import org.junit.jupiter.api.Test;

import lt.spindulys.texture.TextureImage;

/** The environment's own arctangent and its argument checks. */
class EnvironmentTest {
    @Test
    void atan2MatchesTheLibraryWithin1e7() {
        Random r = new Random(11);
        double worst = 0;
        for (int i = 0; i < 2_000_000; i++) {
            double y = r.nextGaussian() * Math.pow(10, r.nextInt(7) - 3), x = r.nextGaussian() * Math.pow(10, r.nextInt(7) - 3);
            worst = Math.max(worst, Math.abs(Environment.atan2(y, x) - Math.atan2(y, x)));
        }
        assertEquals(0, worst, 1e-7);
        double[][] special = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}, {0.41421356237309503, 1}, {1e-300, 1}, {1, 1e-300}};
        for (double[] s : special) assertEquals(Math.atan2(s[0], s[1]), Environment.atan2(s[0], s[1]), 1e-7, s[0] + ", " + s[1]);
        assertEquals(0, Environment.atan2(0, 0));
        // -0 behind: +pi or -pi, the same column of the map.
        assertEquals(Math.PI, Math.abs(Environment.atan2(-0.0, -1)), 1e-15);
    }

    @Test
    void refusesABadRotationOrIntensity() {
        TextureImage m = TextureImage.fromLinear(2, 1, new double[6]);
        assertEquals("environment intensity must be between 0 and 100, found -1.0",
                assertThrows(IllegalArgumentException.class, () -> new Environment(m, 0, -1)).getMessage());
        assertEquals("environment rotate must be a finite number of degrees, found NaN",
                assertThrows(IllegalArgumentException.class, () -> new Environment(m, Double.NaN, 1)).getMessage());
    }
}
