package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

class OpticsTest {
    private static final double EPS = 1e-12;

    @Test
    void reflectionMirrorsAboutTheNormal() {
        double[] r = new double[3];
        double s = Math.sqrt(0.5);
        Optics.reflect(s, -s, 0, 0, 1, 0, r);
        assertArrayEquals(new double[] {s, s, 0}, r, EPS);
        // The normal's side does not matter for a mirror.
        Optics.reflect(s, -s, 0, 0, -1, 0, r);
        assertArrayEquals(new double[] {s, s, 0}, r, EPS);
    }

    @Test
    void refractionObeysSnellsLaw() {
        double[] t = new double[3];
        double theta = Math.toRadians(40);
        double dx = Math.sin(theta), dy = -Math.cos(theta);
        assertTrue(Optics.refract(dx, dy, 0, 0, 1, 0, 1.0, 1.5, t));
        double sinT = Math.sqrt(t[0] * t[0] + t[2] * t[2]);
        assertEquals(Math.sin(theta) / 1.5, sinT, EPS, "n1 sin(i) = n2 sin(t)");
        assertTrue(t[1] < 0, "transmitted ray continues through the surface");
        assertEquals(1, Math.sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]), EPS);
        assertEquals(0, t[2], EPS, "stays in the plane of incidence");
    }

    @Test
    void normalIncidencePassesStraightThrough() {
        double[] t = new double[3];
        assertTrue(Optics.refract(0, -1, 0, 0, 1, 0, 1.0, 1.33, t));
        assertArrayEquals(new double[] {0, -1, 0}, t, EPS);
    }

    @Test
    void totalInternalReflectionBeyondTheCriticalAngle() {
        double critical = Math.asin(1 / 1.5);
        double[] t = new double[3];
        double above = critical + 1e-6, below = critical - 1e-6;
        assertFalse(Optics.refract(Math.sin(above), -Math.cos(above), 0, 0, 1, 0, 1.5, 1.0, t));
        assertTrue(Optics.refract(Math.sin(below), -Math.cos(below), 0, 0, 1, 0, 1.5, 1.0, t));
        assertEquals(1, Math.abs(t[0]), 1e-5, "just below the critical angle the ray leaves grazing the surface");
    }

    @Test
    void schlickMatchesItsEndpointsAndIsSymmetric() {
        double r0 = Math.pow((1 - 1.5) / (1 + 1.5), 2);
        assertEquals(r0, Optics.schlick(1, 1, 1.5), EPS);
        assertEquals(1, Optics.schlick(0, 1, 1.5), EPS);
        // Leaving glass at the transmitted angle of an entering ray gives the same reflectance.
        double cosI = Math.cos(Math.toRadians(35));
        double sinT = Math.sin(Math.toRadians(35)) / 1.5, cosT = Math.sqrt(1 - sinT * sinT);
        assertEquals(Optics.schlick(cosI, 1, 1.5), Optics.schlick(cosT, 1.5, 1), EPS);
        assertEquals(1, Optics.schlick(0.1, 1.5, 1), EPS, "total internal reflection reflects everything");
    }
}
