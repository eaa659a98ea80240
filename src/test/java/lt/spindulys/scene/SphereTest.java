package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

class SphereTest {
    private final Vec3 c = new Vec3(1, 2, 3);
    private final Sphere s = frozen(new Sphere(c, 2));

    /** The documented parametrisation, written independently of the implementation. */
    private Vec3 param(double u, double v) {
        double phi = 2 * Math.PI * u, theta = Math.PI * v;
        return c.plus(new Vec3(Math.sin(theta) * Math.cos(phi), Math.cos(theta), Math.sin(theta) * Math.sin(phi)).times(2));
    }

    @Test void boundsAndClosed() {
        assertEquals(new Bounds(-1, 0, 1, 3, 4, 5), s.localBounds());
        assertTrue(s.isClosed());
    }

    @Test void hitFromOutsideWithNonUnitDirection() {
        Ray r = ray(1, 2, -10, 0, 0, 2);
        Hit h = hit(s, r);
        assertNotNull(h);
        assertEquals(5.5, h.t, EPS); // surface at z = 1, reached after 11 units at speed 2
        assertSame(s, h.object);
        assertSame(Material.DEFAULT, h.material);
        ShadingData sd = shade(s, r, h);
        assertVec(new Vec3(1, 2, 1), sd.p, EPS);
        assertVec(new Vec3(0, 0, -1), sd.ng, EPS);
        assertSane(sd);
    }

    @Test void misses() {
        assertNull(hit(s, ray(1, 4.001, -10, 0, 0, 1)));
        assertNull(hit(s, ray(1, 2, -10, 0, 0, -1)), "sphere behind the ray");
        assertNull(hit(s, ray(1, 2, -10, 0, 1, 0)), "ray perpendicular, passing by");
        assertEquals(0, spans(s, ray(1, 4.001, -10, 0, 0, 1)).size());
    }

    @Test void zeroDirectionNeverHits() {
        assertNull(hit(s, ray(1, 2, 3, 0, 0, 0)));
    }

    @Test void tangentRayIsDeterministicAndFinite() {
        Ray r = ray(3, 2, -10, 0, 0, 1); // touches the sphere at (3, 2, 3)
        Hit h1 = hit(s, r), h2 = hit(s, r);
        assertNotNull(h1);
        assertEquals(13, h1.t, 1e-6);
        assertEquals(h1.t, h2.t);
        ShadingData sd = shade(s, r, h1);
        assertSane(sd);
        assertVec(new Vec3(1, 0, 0), sd.ng, 1e-6);
        SpanBuffer sp = spans(s, r);
        assertEquals(1, sp.size());
        assertEquals(sp.entry(0), sp.exit(0), 1e-6);
        // Just outside: a clean miss, not a NaN.
        assertNull(hit(s, ray(3 + 1e-9, 2, -10, 0, 0, 1)));
    }

    @Test void tangentAtTheOriginGivesNoNaN() {
        // Origin on the surface, direction tangent there: the double root is 0 and q is 0.
        Ray r = ray(3, 2, 3, 0, 1, 0);
        r.tMin = -1;
        Hit h = hit(s, r);
        assertNotNull(h);
        assertEquals(0, h.t, 0);
        SpanBuffer sp = spans(s, r);
        assertEquals(1, sp.size());
        assertEquals(0, sp.entry(0), 0);
        assertEquals(0, sp.exit(0), 0);
    }

    @Test void distantOriginKeepsPrecision() {
        Sphere unit = frozen(new Sphere(Vec3.ZERO, 1));
        // 1e7 away and nearly tangent: the naive b^2 - 4ac loses everything here.
        double y = 0.9999;
        Ray r = ray(-1e7, y, 0, 1, 0, 0);
        Hit h = hit(unit, r);
        assertNotNull(h);
        double expected = 1e7 - Math.sqrt(1 - y * y);
        assertEquals(expected, h.t, 1e-8);
    }

    @Test void originInsideReturnsTheExit() {
        Ray r = ray(1, 2, 3, 0, 0.5, 0);
        Hit h = hit(s, r);
        assertNotNull(h);
        assertEquals(4, h.t, EPS);
        assertVec(new Vec3(0, 1, 0), shade(s, r, h).ng, EPS);
        SpanBuffer sp = spans(s, r);
        assertEquals(1, sp.size());
        assertEquals(-4, sp.entry(0), EPS);
        assertTrue(sp.entry(0) < r.tMin);
        assertEquals(4, sp.exit(0), EPS);
    }

    @Test void respectsTMinAndTMax() {
        Ray r = ray(1, 2, -10, 0, 0, 1); // roots 11 and 15
        r.tMax = 11;
        assertNull(hit(s, r), "tMax is exclusive");
        assertEquals(0, spans(s, r).size(), "span starting at tMax does not overlap (tMin, tMax)");
        r.tMax = 12;
        assertEquals(11, hit(s, r).t, EPS);
        r.tMax = Double.POSITIVE_INFINITY;
        r.tMin = 11.5;
        assertEquals(15, hit(s, r).t, EPS);
        SpanBuffer sp = spans(s, r);
        assertEquals(1, sp.size());
        assertEquals(11, sp.entry(0), EPS, "true entry, before tMin");
        r.tMin = 15;
        assertNull(hit(s, r));
        assertEquals(0, spans(s, r).size());
    }

    @Test void uvAtKnownPoints() {
        double[][] cases = { // direction from the centre, u, v
                {1, 0, 0, 0, 0.5}, {0, 0, 1, 0.25, 0.5}, {-1, 0, 0, 0.5, 0.5}, {0, 0, -1, 0.75, 0.5}};
        for (double[] k : cases) {
            Vec3 dir = new Vec3(k[0], k[1], k[2]);
            Ray r = ray(c.plus(dir.times(5)), dir.times(-1));
            ShadingData sd = shade(s, r, hit(s, r));
            assertEquals(k[3], sd.u, EPS, "u at " + dir);
            assertEquals(k[4], sd.v, EPS, "v at " + dir);
            assertVec(dir, sd.ng, EPS);
        }
        Ray top = ray(1.0, 10, 3, 0, -1, 0);
        assertEquals(0, shade(s, top, hit(s, top)).v, EPS);
        Ray bottom = ray(1.0, -10, 3, 0, 1, 0);
        assertEquals(1, shade(s, bottom, hit(s, bottom)).v, EPS);
    }

    @Test void derivativesMatchFiniteDifferences() {
        double[][] uvs = {{0.1, 0.3}, {0.6, 0.7}, {0.9, 0.45}, {0.35, 0.15}};
        double eps = 1e-6;
        for (double[] uv : uvs) {
            double u = uv[0], v = uv[1];
            Vec3 p = param(u, v);
            Vec3 n = p.minus(c).normalized();
            Ray r = ray(p.plus(n.times(3)), n.times(-1));
            Hit h = hit(s, r);
            assertEquals(3, h.t, EPS);
            ShadingData sd = shade(s, r, h);
            assertSane(sd);
            assertEquals(u, sd.u, 1e-9);
            assertEquals(v, sd.v, 1e-9);
            Vec3 fdU = param(u + eps, v).minus(param(u - eps, v)).times(1 / (2 * eps));
            Vec3 fdV = param(u, v + eps).minus(param(u, v - eps)).times(1 / (2 * eps));
            assertVec(fdU, sd.dpdu, 1e-5);
            assertVec(fdV, sd.dpdv, 1e-5);
            assertTrue(v(sd.dpdu).cross(v(sd.dpdv)).dot(v(sd.ng)) > 0, "dpdu x dpdv points out");
        }
    }

    @Test void rejectsInvalidConstruction() {
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Vec3.ZERO, 0));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(Vec3.ZERO, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new Sphere(new Vec3(Double.NaN, 0, 0), 1));
    }
}
