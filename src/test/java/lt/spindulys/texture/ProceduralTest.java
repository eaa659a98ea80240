package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import lt.spindulys.math.Color;
import org.junit.jupiter.api.Test;

class ProceduralTest {
    static final Color A = new Color(0.1, 0.8, 0.3), B = new Color(0.9, 0.2, 0.5);

    /** Every procedural, surface and solid. */
    static List<Texture> all() {
        List<Texture> list = new ArrayList<>();
        for (boolean solid : new boolean[] {false, true}) {
            list.add(new Checker(A, B, 3, solid));
            list.add(new Noise(A, B, 2.5, 4, solid));
            list.add(new Marble(A, B, 1.5, 2, 5, solid));
            list.add(new Wood(A, B, 4, 0.7, 3, solid));
        }
        return list;
    }

    private static double[] eval(Texture t, TexturePoint p) {
        double[] rgb = new double[3];
        t.evaluate(p, rgb);
        return rgb;
    }

    @Test
    void perlinNoiseIsZeroAtLatticePoints() {
        for (int x = -4; x <= 4; x++) {
            for (int y = -4; y <= 4; y++) {
                for (int z = -4; z <= 4; z++) assertEquals(0.0, Perlin.noise(x, y, z), 0, x + "," + y + "," + z);
            }
        }
        assertEquals(0.0, Perlin.noise(1000, -37, 123456), 0);
        assertNotEquals(0.0, Perlin.noise(0.5, 0.25, 0.75));
    }

    @Test
    void perlinNoiseIsContinuousAndBounded() {
        SplittableRandom r = new SplittableRandom(7);
        double min = 0, max = 0, sum = 0;
        int n = 20000;
        for (int i = 0; i < n; i++) {
            double x = r.nextDouble(-20, 20), y = r.nextDouble(-20, 20), z = r.nextDouble(-20, 20);
            double v = Perlin.noise(x, y, z);
            min = Math.min(min, v);
            max = Math.max(max, v);
            sum += v;
            double h = 1e-6;
            // Bounded slope: no jump anywhere, in particular not across cell faces.
            assertTrue(Math.abs(Perlin.noise(x + h, y, z) - v) < 10 * h);
            assertTrue(Math.abs(Perlin.noise(x, y, z + h) - v) < 10 * h);
        }
        assertTrue(min >= -1.1 && max <= 1.1, min + " " + max);
        assertTrue(min < -0.4 && max > 0.4, "noise spans a real range: " + min + " " + max);
        assertTrue(Math.abs(sum / n) < 0.03, "mean near 0: " + sum / n);
        // Straddling a lattice face: both sides agree.
        for (double y = 0.05; y < 3; y += 0.37) {
            assertEquals(Perlin.noise(2 - 1e-10, y, 0.4), Perlin.noise(2 + 1e-10, y, 0.4), 1e-8);
        }
    }

    @Test
    void perlinNoiseIsDeterministic() {
        double a = Perlin.noise(3.7, -1.2, 0.45), t = Perlin.turbulence(3.7, -1.2, 0.45, 5);
        assertEquals(a, Perlin.noise(3.7, -1.2, 0.45), 0);
        assertEquals(t, Perlin.turbulence(3.7, -1.2, 0.45, 5), 0);
        assertTrue(t >= Math.abs(a), "turbulence includes |noise| as its first octave");
        assertEquals(a, Perlin.fbm(3.7, -1.2, 0.45, 1), 0);
    }

    @Test
    void proceduralsAreDeterministicAndInRange() {
        SplittableRandom r = new SplittableRandom(11);
        List<Texture> first = all(), second = all();
        for (int k = 0; k < first.size(); k++) {
            Texture t = first.get(k);
            boolean sawA = false, sawB = false;
            for (int i = 0; i < 3000; i++) {
                TexturePoint p = new TexturePoint().uv(r.nextDouble(-3, 3), r.nextDouble(-3, 3), 0)
                        .xyz(r.nextDouble(-3, 3), r.nextDouble(-3, 3), r.nextDouble(-3, 3));
                double[] c = eval(t, p);
                double[] again = eval(second.get(k), p);
                for (int ch = 0; ch < 3; ch++) {
                    double lo = Math.min(A.get(ch), B.get(ch)), hi = Math.max(A.get(ch), B.get(ch));
                    assertTrue(c[ch] >= lo - 1e-12 && c[ch] <= hi + 1e-12, t + ": " + c[ch]);
                    assertEquals(c[ch], again[ch], 0, t.toString());
                }
                // Closeness to either colour, measured on the red channel (0.1 vs 0.9).
                sawA |= c[0] < 0.3;
                sawB |= c[0] > 0.7;
            }
            assertTrue(sawA && sawB, t + " reaches both colours");
        }
    }

    @Test
    void surfaceVariantsReadUvAndSolidVariantsReadXyz() {
        SplittableRandom r = new SplittableRandom(3);
        for (Texture t : all()) {
            boolean solid = ((Procedural) t).solid();
            int changedByUv = 0, changedByXyz = 0;
            for (int i = 0; i < 200; i++) {
                double u = r.nextDouble(-2, 2), v = r.nextDouble(-2, 2);
                double x = r.nextDouble(-2, 2), y = r.nextDouble(-2, 2), z = r.nextDouble(-2, 2);
                double[] base = eval(t, new TexturePoint().uv(u, v, 0).xyz(x, y, z));
                double[] newUv = eval(t, new TexturePoint().uv(v + 0.31, u - 0.17, 0).xyz(x, y, z));
                double[] newXyz = eval(t, new TexturePoint().uv(u, v, 0).xyz(z + 0.29, x - 0.13, y + 0.41));
                if (base[0] != newUv[0]) changedByUv++;
                if (base[0] != newXyz[0]) changedByXyz++;
            }
            if (solid) {
                assertEquals(0, changedByUv, t.toString());
                assertTrue(changedByXyz > 50, t.toString());
            } else {
                assertEquals(0, changedByXyz, t.toString());
                assertTrue(changedByUv > 50, t.toString());
            }
        }
    }

    private static void assertColour(Color expected, Texture t, TexturePoint p) {
        double[] c = eval(t, p);
        for (int ch = 0; ch < 3; ch++) assertEquals(expected.get(ch), c[ch], 1e-12, t + " channel " + ch);
    }

    @Test
    void checkerSquaresAlternate() {
        Checker c2 = new Checker(A, B, 2, false);
        assertColour(A, c2, new TexturePoint().uv(0.25, 0.25, 0));
        assertColour(B, c2, new TexturePoint().uv(0.75, 0.25, 0));
        assertColour(A, c2, new TexturePoint().uv(0.75, 0.75, 0));
        assertColour(B, c2, new TexturePoint().uv(-0.25, 0.25, 0));
        assertColour(A, c2, new TexturePoint().uv(-0.25, -0.25, 0));
        Checker c3 = new Checker(A, B, 2, true);
        assertColour(A, c3, new TexturePoint().xyz(0.25, 0.25, 0.25));
        assertColour(B, c3, new TexturePoint().xyz(0.25, 0.25, 0.75));
        assertColour(A, c3, new TexturePoint().xyz(0.75, 0.25, 0.75));
        assertColour(B, c3, new TexturePoint().xyz(-0.25, -0.25, -0.25));
    }

    @Test
    void marbleAndWoodWithoutTurbulenceAreStripesAndRings() {
        Marble m = new Marble(A, B, 2, 0, 1, false);
        assertColour(B, m, new TexturePoint().uv(0.125, 0.9, 0));   // sin = 1
        assertColour(A, m, new TexturePoint().uv(0.375, -4, 0));    // sin = -1
        Marble ms = new Marble(A, B, 2, 0, 1, true);
        assertColour(B, ms, new TexturePoint().xyz(0.625, 3, -2));
        Wood w = new Wood(A, B, 4, 0, 1, true);
        assertColour(A, w, new TexturePoint().xyz(0, 0, 7));          // on the axis
        assertColour(B, w, new TexturePoint().xyz(0.125, 0, -3));     // half a ring out
        assertColour(A, w, new TexturePoint().xyz(0, -0.25, 1));      // one ring out
        assertColour(B, w, new TexturePoint().xyz(0.3 * 0.125 / 0.5, 0.4 * 0.125 / 0.5, 0)); // r = 0.125
        Wood w2 = new Wood(A, B, 4, 0, 1, false);
        assertColour(A, w2, new TexturePoint().uv(0.5, 0.5, 0));      // centre of the uv square
        assertColour(B, w2, new TexturePoint().uv(0.5, 0.625, 0));
        // Turbulence moves the pattern.
        Marble mt = new Marble(A, B, 2, 1, 4, false);
        int differ = 0;
        for (double u = 0.01; u < 2; u += 0.05) {
            TexturePoint p = new TexturePoint().uv(u, 0.37, 0);
            if (Math.abs(eval(m, p)[0] - eval(mt, p)[0]) > 1e-6) differ++;
        }
        assertTrue(differ > 20, "turbulence changed " + differ + " of 40 samples");
    }

    @Test
    void parametersAreValidated() {
        assertThrows(IllegalArgumentException.class, () -> new Checker(A, B, 0, false));
        assertThrows(IllegalArgumentException.class, () -> new Checker(A, B, Double.NaN, false));
        assertThrows(IllegalArgumentException.class, () -> new Noise(A, B, 1, 0, false));
        assertThrows(IllegalArgumentException.class, () -> new Noise(A, B, 1, 17, true));
        assertThrows(IllegalArgumentException.class, () -> new Marble(A, B, 1, -1, 2, false));
        assertThrows(IllegalArgumentException.class, () -> new Wood(A, B, 1, Double.POSITIVE_INFINITY, 2, false));
        assertThrows(IllegalArgumentException.class, () -> new Wood(new Color(Double.NaN, 0, 0), B, 1, 0, 2, false));
        assertThrows(NullPointerException.class, () -> new Marble(null, B, 1, 0, 2, false));
    }
}
