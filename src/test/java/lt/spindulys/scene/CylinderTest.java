package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

class CylinderTest {
    /** Upright: base at the origin, top at y = 2, radius 1. */
    private final Cylinder cyl = frozen(new Cylinder(Vec3.ZERO, new Vec3(0, 2, 0), 1));
    /** Oblique, off the origin. */
    private final Cylinder tilted = frozen(new Cylinder(new Vec3(1, 1, 1), new Vec3(2, 3, 4), 0.5));

    /** The documented side parametrisation, from the public frame. */
    private static Vec3 side(Cylinder c, double u, double v) {
        double phi = 2 * Math.PI * u;
        return c.base().plus(c.axisU().times(c.radius() * Math.cos(phi))).plus(c.axisV().times(c.radius() * Math.sin(phi)))
                .plus(c.axis().times(v * c.height()));
    }

    /** The documented cap parametrisations. */
    private static Vec3 cap(Cylinder c, boolean top, double u, double v) {
        Vec3 centre = top ? c.top() : c.base();
        double y = top ? 2 * v - 1 : 1 - 2 * v;
        return centre.plus(c.axisU().times(c.radius() * (2 * u - 1))).plus(c.axisV().times(c.radius() * y));
    }

    @Test void frameAndBounds() {
        assertTrue(cyl.isClosed());
        assertEquals(new Bounds(-1, 0, -1, 1, 2, 1), cyl.localBounds());
        assertEquals(Transform.IDENTITY, tilted.transform(), "the canonical frame is internal, not a placement");
        assertEquals(Math.sqrt(14), tilted.height(), 1e-12);
        assertEquals(0, tilted.axisU().dot(tilted.axis()), 1e-12);
        assertVec(tilted.axis(), tilted.axisU().cross(tilted.axisV()), 1e-12);
        // Exact: every rim point inside, and each side of the box touched by some rim point.
        Bounds b = tilted.localBounds();
        double[] best = {1e9, 1e9, 1e9, 1e9, 1e9, 1e9};
        for (int i = 0; i < 3600; i++) {
            for (boolean top : new boolean[] {false, true}) {
                double phi = 2 * Math.PI * i / 3600;
                Vec3 p = (top ? tilted.top() : tilted.base()).plus(tilted.axisU().times(0.5 * Math.cos(phi)))
                        .plus(tilted.axisV().times(0.5 * Math.sin(phi)));
                best[0] = Math.min(best[0], p.x() - b.minX()); best[1] = Math.min(best[1], b.maxX() - p.x());
                best[2] = Math.min(best[2], p.y() - b.minY()); best[3] = Math.min(best[3], b.maxY() - p.y());
                best[4] = Math.min(best[4], p.z() - b.minZ()); best[5] = Math.min(best[5], b.maxZ() - p.z());
            }
        }
        for (double d : best) {
            // d < 0 would be a rim point outside the bounds; a large d, loose bounds.
            assertTrue(d > -1e-12 && d < 1e-5, "bounds not exact: gap " + d);
        }
    }

    @Test void sideAndCapHits() {
        Ray r = ray(-5, 1, 0, 2, 0, 0);
        Hit h = hit(cyl, r);
        assertEquals(2, h.t, EPS);
        assertEquals(Cylinder.SIDE, h.prim);
        ShadingData sd = shade(cyl, r, h);
        assertVec(new Vec3(-1, 1, 0), sd.p, EPS);
        assertVec(new Vec3(-1, 0, 0), sd.ng, EPS);
        assertSane(sd);

        r = ray(0.3, 5, 0.2, 0, -1, 0);
        h = hit(cyl, r);
        assertEquals(3, h.t, EPS);
        assertEquals(Cylinder.TOP_CAP, h.prim);
        assertVec(Vec3.Y, shade(cyl, r, h).ng, 0);

        r = ray(-0.3, -4, 0.2, 0, 1, 0);
        h = hit(cyl, r);
        assertEquals(4, h.t, EPS);
        assertEquals(Cylinder.BASE_CAP, h.prim);
        assertVec(new Vec3(0, -1, 0), shade(cyl, r, h).ng, 0);
    }

    @Test void obliqueCylinderAnalyticHits() {
        // Side: come in along the inward normal at a known side point.
        Vec3 n = tilted.axisU().times(Math.cos(1.0)).plus(tilted.axisV().times(Math.sin(1.0)));
        Vec3 p = tilted.base().plus(tilted.axis().times(1.5)).plus(n.times(0.5));
        Ray r = ray(p.plus(n.times(3)), n.times(-1));
        Hit h = hit(tilted, r);
        assertEquals(3, h.t, EPS);
        assertEquals(Cylinder.SIDE, h.prim);
        assertVec(n, shade(tilted, r, h).ng, 1e-9);
        // Top cap: straight down the axis, off centre.
        Vec3 q = tilted.top().plus(tilted.axisV().times(0.2));
        r = ray(q.plus(tilted.axis().times(2)), tilted.axis().times(-0.5));
        h = hit(tilted, r);
        assertEquals(4, h.t, EPS);
        assertEquals(Cylinder.TOP_CAP, h.prim);
        assertVec(tilted.axis(), shade(tilted, r, h).ng, 1e-12);
        // ...and out through the base cap when starting inside.
        r = ray(q.minus(tilted.axis().times(1)), tilted.axis().times(-1));
        h = hit(tilted, r);
        assertEquals(tilted.height() - 1, h.t, EPS);
        assertEquals(Cylinder.BASE_CAP, h.prim);
    }

    @Test void misses() {
        assertNull(hit(cyl, ray(-5, 2.5, 0, 1, 0, 0)), "above the top");
        assertNull(hit(cyl, ray(-5, 1, 1.5, 1, 0, 0)), "beside");
        assertNull(hit(cyl, ray(1.5, -5, 0, 0, 1, 0)), "parallel to the axis, outside");
        assertNull(hit(cyl, ray(0, 3, -5, 0, 0, 1)), "perpendicular, above");
        assertNull(hit(cyl, ray(0, 5, 0, 0, 1, 0)), "receding along the axis");
        assertEquals(0, spans(cyl, ray(-5, 1, 1.5, 1, 0, 0)).size());
    }

    @Test void parallelToTheAxisInside() {
        Ray r = ray(0.5, -5, 0, 0, 1, 0);
        Hit h = hit(cyl, r);
        assertEquals(5, h.t, EPS);
        assertEquals(Cylinder.BASE_CAP, h.prim);
        SpanBuffer sp = spans(cyl, r);
        assertEquals(1, sp.size());
        assertEquals(5, sp.entry(0), EPS);
        assertEquals(7, sp.exit(0), EPS);
        Hit e = new Hit();
        sp.toHit(1, e);
        assertEquals(Cylinder.TOP_CAP, e.prim);
    }

    @Test void grazingRaysAreFiniteAndDeterministic() {
        Ray tangent = ray(-5, 1, 1, 1, 0, 0); // touches the side at (0, 1, 1)
        Hit h = hit(cyl, tangent);
        assertNotNull(h);
        assertEquals(5, h.t, 1e-6);
        assertEquals(h.t, hit(cyl, tangent).t);
        ShadingData sd = shade(cyl, tangent, h);
        assertSane(sd);
        assertVec(new Vec3(0, 0, 1), sd.ng, 1e-6);
        assertNull(hit(cyl, ray(-5, 1, 1 + 1e-9, 1, 0, 0)));

        for (double zero : new double[] {0.0, -0.0}) {
            Ray inCapPlane = ray(-5, 2, 0, 1, zero, zero); // along the top cap's plane
            h = hit(cyl, inCapPlane);
            assertNotNull(h);
            assertEquals(4, h.t, EPS);
            assertSane(shade(cyl, inCapPlane, h));
            Ray alongSide = ray(1, -5, 0, zero, 1, zero); // on the side surface, parallel to the axis
            h = hit(cyl, alongSide);
            assertNotNull(h);
            assertEquals(5, h.t, EPS);
            assertSane(shade(cyl, alongSide, h));
        }

        Ray rim = ray(-2, 3, 0, 1, -1, 0); // reaches the rim (-1, 2, 0) at t = 1
        h = hit(cyl, rim);
        assertEquals(1, h.t, EPS);
        assertEquals(h.prim, hit(cyl, rim).prim);
        assertSane(shade(cyl, rim, h));
    }

    @Test void originInsideReturnsTheExit() {
        Ray r = ray(0, 1, 0, 0, 0, 1);
        Hit h = hit(cyl, r);
        assertEquals(1, h.t, EPS);
        assertEquals(Cylinder.SIDE, h.prim);
        SpanBuffer sp = spans(cyl, r);
        assertEquals(1, sp.size());
        assertEquals(-1, sp.entry(0), EPS);
        assertEquals(1, sp.exit(0), EPS);
    }

    @Test void spanFromCapToSide() {
        Ray r = ray(0, 5, 0, 0.25, -1, 0); // top cap at t = 3 (x = 0.75), side at t = 4
        SpanBuffer sp = spans(cyl, r);
        assertEquals(1, sp.size());
        assertEquals(3, sp.entry(0), EPS);
        assertEquals(4, sp.exit(0), EPS);
        Hit e = new Hit();
        sp.toHit(0, e);
        assertEquals(Cylinder.TOP_CAP, e.prim);
        sp.toHit(1, e);
        assertEquals(Cylinder.SIDE, e.prim);
    }

    @Test void respectsTMinAndTMax() {
        Ray r = ray(-5, 1, 0, 1, 0, 0); // span [4, 6]
        r.tMax = 4;
        assertNull(hit(cyl, r));
        assertEquals(0, spans(cyl, r).size());
        r.tMax = 4.5;
        assertEquals(4, hit(cyl, r).t, EPS);
        r.tMax = Double.POSITIVE_INFINITY;
        r.tMin = 5;
        assertEquals(6, hit(cyl, r).t, EPS);
        assertEquals(1, spans(cyl, r).size());
        r.tMin = 6;
        assertNull(hit(cyl, r));
    }

    @Test void sideUvAndDerivativesMatchTheParametrisation() {
        double eps = 1e-6;
        for (Cylinder c : new Cylinder[] {cyl, tilted}) {
            for (double[] uv : new double[][] {{0.1, 0.2}, {0.55, 0.5}, {0.8, 0.9}}) {
                double u = uv[0], v = uv[1];
                Vec3 p = side(c, u, v);
                Vec3 n = p.minus(c.base()).minus(c.axis().times(v * c.height())).normalized();
                Ray r = ray(p.plus(n.times(2)), n.times(-1));
                Hit h = hit(c, r);
                assertEquals(2, h.t, EPS);
                ShadingData sd = shade(c, r, h);
                assertSane(sd);
                assertVec(n, sd.ng, 1e-9);
                assertEquals(u, sd.u, 1e-9);
                assertEquals(v, sd.v, 1e-9);
                assertVec(side(c, u + eps, v).minus(side(c, u - eps, v)).times(1 / (2 * eps)), sd.dpdu, 1e-5);
                assertVec(side(c, u, v + eps).minus(side(c, u, v - eps)).times(1 / (2 * eps)), sd.dpdv, 1e-5);
                assertTrue(v(sd.dpdu).cross(v(sd.dpdv)).dot(v(sd.ng)) > 0);
            }
        }
    }

    @Test void capUvAndDerivatives() {
        double eps = 1e-6;
        for (boolean top : new boolean[] {false, true}) {
            double u = 0.3, v = 0.6;
            Vec3 p = cap(tilted, top, u, v);
            Vec3 n = top ? tilted.axis() : tilted.axis().times(-1);
            Ray r = ray(p.plus(n.times(1)), n.times(-1));
            Hit h = hit(tilted, r);
            assertEquals(1, h.t, EPS);
            assertEquals(top ? Cylinder.TOP_CAP : Cylinder.BASE_CAP, h.prim);
            ShadingData sd = shade(tilted, r, h);
            assertEquals(u, sd.u, 1e-9);
            assertEquals(v, sd.v, 1e-9);
            assertVec(cap(tilted, top, u + eps, v).minus(cap(tilted, top, u - eps, v)).times(1 / (2 * eps)), sd.dpdu, 1e-6);
            assertVec(cap(tilted, top, u, v + eps).minus(cap(tilted, top, u, v - eps)).times(1 / (2 * eps)), sd.dpdv, 1e-6);
            assertTrue(v(sd.dpdu).cross(v(sd.dpdv)).dot(v(sd.ng)) > 0, "dpdu x dpdv points out of the cap");
        }
        // The cap centre is the middle of the unit square.
        Ray r = ray(0, 5, 0, 0, -1, 0);
        ShadingData sd = shade(cyl, r, hit(cyl, r));
        assertEquals(0.5, sd.u, EPS);
        assertEquals(0.5, sd.v, EPS);
    }

    @Test void rejectsInvalidConstruction() {
        assertThrows(IllegalArgumentException.class, () -> new Cylinder(Vec3.Y, Vec3.Y, 1));
        assertThrows(IllegalArgumentException.class, () -> new Cylinder(Vec3.ZERO, Vec3.Y, -1));
        assertThrows(IllegalArgumentException.class, () -> new Cylinder(Vec3.ZERO, new Vec3(Double.NaN, 0, 0), 1));
    }
}
