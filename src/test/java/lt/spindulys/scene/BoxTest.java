package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

class BoxTest {
    /** Corners given out of order on purpose: the box is [-1,1] x [-2,2] x [-3,3]. */
    private final Box box = frozen(new Box(new Vec3(1, -2, 3), new Vec3(-1, 2, -3)));

    @Test void boundsAndClosed() {
        assertEquals(new Bounds(-1, -2, -3, 1, 2, 3), box.localBounds());
        assertTrue(box.isClosed());
    }

    @Test void eachFaceFromOutside() {
        // origin, direction, expected t, face, outward normal
        Object[][] cases = {
                {new Vec3(-5, 0.5, 0.5), new Vec3(1, 0, 0), 4.0, 0, new Vec3(-1, 0, 0)},
                {new Vec3(5, 0.5, 0.5), new Vec3(-2, 0, 0), 2.0, 1, new Vec3(1, 0, 0)},
                {new Vec3(0.5, -7, 0.5), new Vec3(0, 1, 0), 5.0, 2, new Vec3(0, -1, 0)},
                {new Vec3(0.5, 7, 0.5), new Vec3(0, -1, 0), 5.0, 3, new Vec3(0, 1, 0)},
                {new Vec3(0.5, 0.5, -4), new Vec3(0, 0, 0.5), 2.0, 4, new Vec3(0, 0, -1)},
                {new Vec3(0.5, 0.5, 9), new Vec3(0, 0, -1), 6.0, 5, new Vec3(0, 0, 1)}};
        for (Object[] k : cases) {
            Ray r = ray((Vec3) k[0], (Vec3) k[1]);
            Hit h = hit(box, r);
            assertNotNull(h, "from " + k[0]);
            assertEquals((double) k[2], h.t, EPS);
            assertEquals((int) k[3], h.prim);
            ShadingData sd = shade(box, r, h);
            assertVec((Vec3) k[4], sd.ng, 0);
            assertSane(sd);
            assertTrue(v(sd.dpdu).cross(v(sd.dpdv)).dot(v(sd.ng)) > 0, "dpdu x dpdv points out on face " + k[3]);
        }
    }

    @Test void obliqueHitAndMisses() {
        Ray r = ray(-3, -3, 0, 1, 1, 0); // enters x at t=2 (y=-1 inside), enters y at t=1
        Hit h = hit(box, r);
        assertEquals(2, h.t, EPS);
        assertEquals(0, h.prim);
        assertNull(hit(box, ray(-5, 2.5, 0, 1, 0, 0)));
        assertNull(hit(box, ray(-5, 0, 0, -1, 0, 0)));
        assertNull(hit(box, ray(-3, -6.5, 0, 1, 1, 0)), "passes beside the corner: x slab [2, 4], y slab [4.5, 8.5]");
    }

    @Test void rayAlongAFaceOrEdgeIsFiniteAndDeterministic() {
        Vec3[] origins = {new Vec3(-5, 2, 0), new Vec3(-5, 2, 3), new Vec3(-5, -2, -3)};
        for (Vec3 o : origins) {
            for (double zero : new double[] {0.0, -0.0}) {
                Ray r = ray(o.x(), o.y(), o.z(), 1, zero, zero);
                Hit h1 = hit(box, r), h2 = hit(box, r);
                assertNotNull(h1, "grazing " + o + " counts as touching the closed box");
                assertEquals(4, h1.t, 0);
                assertEquals(0, h1.prim);
                assertEquals(h1.t, h2.t);
                assertSane(shade(box, r, h1));
                SpanBuffer sp = spans(box, r);
                assertEquals(1, sp.size());
                assertEquals(4, sp.entry(0), 0);
                assertEquals(6, sp.exit(0), 0);
            }
        }
        // A hair outside the face: a clean miss.
        assertNull(hit(box, ray(-5, Math.nextUp(2.0), 0, 1, 0, 0)));
    }

    @Test void throughACornerPicksTheLowestAxis() {
        Ray r = ray(-2, -3, -4, 1, 1, 1); // reaches (-1, -2, -3) at t = 1 on all three slabs
        Hit h = hit(box, r);
        assertEquals(1, h.t, EPS);
        assertEquals(0, h.prim);
        assertEquals(h.prim, hit(box, r).prim);
        assertSane(shade(box, r, h));
    }

    @Test void originInsideReturnsTheExit() {
        Ray r = ray(0, 0, 0, 0, 0, -1);
        Hit h = hit(box, r);
        assertEquals(3, h.t, EPS);
        assertEquals(4, h.prim);
        SpanBuffer sp = spans(box, r);
        assertEquals(1, sp.size());
        assertEquals(-3, sp.entry(0), EPS);
        assertEquals(3, sp.exit(0), EPS);
        Hit entry = new Hit();
        sp.toHit(0, entry);
        assertEquals(5, entry.prim, "entry through +z when travelling -z");
        sp.toHit(1, entry);
        assertEquals(4, entry.prim);
    }

    @Test void respectsTMinAndTMax() {
        Ray r = ray(-5, 0, 0, 1, 0, 0); // span [4, 6]
        r.tMax = 4;
        assertNull(hit(box, r));
        assertEquals(0, spans(box, r).size());
        r.tMax = 5;
        assertEquals(4, hit(box, r).t, EPS);
        r.tMax = Double.POSITIVE_INFINITY;
        r.tMin = 4;
        assertEquals(6, hit(box, r).t, EPS);
        assertEquals(1, hit(box, r).prim);
        r.tMin = 6;
        assertNull(hit(box, r));
        assertEquals(0, spans(box, r).size());
    }

    @Test void uvPerFace() {
        // +x face: u along y, v along z.
        Ray r = ray(5, 1, -1.5, -1, 0, 0);
        ShadingData sd = shade(box, r, hit(box, r));
        assertEquals(0.75, sd.u, EPS);
        assertEquals(0.25, sd.v, EPS);
        assertVec(new Vec3(0, 4, 0), sd.dpdu, 0);
        assertVec(new Vec3(0, 0, 6), sd.dpdv, 0);
        // -x face: u along z, v along y.
        r = ray(-5, 1, -1.5, 1, 0, 0);
        sd = shade(box, r, hit(box, r));
        assertEquals(0.25, sd.u, EPS);
        assertEquals(0.75, sd.v, EPS);
        assertVec(new Vec3(0, 0, 6), sd.dpdu, 0);
        assertVec(new Vec3(0, 4, 0), sd.dpdv, 0);
        // +y face: u along z, v along x; corner (z, x) = (-3, -1) is uv (0, 0).
        r = ray(-1, 5, -3, 0, -1, 0);
        sd = shade(box, r, hit(box, r));
        assertEquals(0, sd.u, EPS);
        assertEquals(0, sd.v, EPS);
    }

    @Test void shadingWithoutAFaceUsesTheNearestOne() {
        Ray r = ray(0.2, 0.1, -10, 0, 0, 1);
        Hit h = hit(box, r);
        h.prim = -1; // as from an endpoint that carries no face
        assertVec(new Vec3(0, 0, -1), shade(box, r, h).ng, 0);
    }

    @Test void rejectsFlatBox() {
        assertThrows(IllegalArgumentException.class, () -> new Box(new Vec3(0, 0, 0), new Vec3(1, 0, 1)));
    }
}
