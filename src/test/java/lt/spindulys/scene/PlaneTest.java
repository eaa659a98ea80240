package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

class PlaneTest {
    /** y = 2 after normalisation; inside is y <= 2. */
    private final Plane floor = frozen(new Plane(new Vec3(0, 2, 0), 4));

    @Test void normalisedAndUnbounded() {
        assertVec(Vec3.Y, floor.normal(), 0);
        assertEquals(2, floor.offset(), 0);
        assertEquals(Bounds.INFINITE, floor.localBounds());
        assertEquals(Bounds.INFINITE, floor.bounds());
        assertTrue(floor.isClosed());
    }

    @Test void hitsFromAboveAndBelow() {
        Ray down = ray(1, 5, 1, 0, -2, 0);
        Hit h = hit(floor, down);
        assertEquals(1.5, h.t, EPS);
        ShadingData sd = shade(floor, down, h);
        assertVec(new Vec3(1, 2, 1), sd.p, EPS);
        assertVec(Vec3.Y, sd.ng, 0);
        assertSane(sd);
        Ray up = ray(1, -1, 1, 0, 1, 0);
        h = hit(floor, up);
        assertEquals(3, h.t, EPS);
        assertVec(Vec3.Y, shade(floor, up, h).ng, 0); // outward, whichever side the ray came from
    }

    @Test void obliquePlane() {
        Plane p = frozen(new Plane(new Vec3(1, 1, 0), 2)); // x + y = 2
        Ray r = ray(0, 0, 7, 1, 0, 0);
        Hit h = hit(p, r);
        assertEquals(2, h.t, EPS);
        assertVec(new Vec3(1, 1, 0).normalized(), shade(p, r, h).ng, EPS);
    }

    @Test void parallelAndReceding() {
        assertNull(hit(floor, ray(0, 5, 0, 1, 0, 0)));
        assertNull(hit(floor, ray(0, 2, 0, 1, 0, 0)), "ray lying in the plane does not hit it");
        assertNull(hit(floor, ray(0, 5, 0, 0, 1, 0)));
        assertNull(hit(floor, ray(0, 1, 0, -0.0, -0.0, 1)));
    }

    @Test void spansByDirection() {
        SpanBuffer sp = spans(floor, ray(0, 5, 0, 0, -1, 0)); // entering
        assertEquals(1, sp.size());
        assertEquals(3, sp.entry(0), EPS);
        assertEquals(Double.POSITIVE_INFINITY, sp.exit(0));

        sp = spans(floor, ray(0, 0, 0, 0, 1, 0)); // leaving: inside since forever
        assertEquals(1, sp.size());
        assertEquals(Double.NEGATIVE_INFINITY, sp.entry(0));
        assertEquals(2, sp.exit(0), EPS);

        assertEquals(0, spans(floor, ray(0, 5, 0, 0, 1, 0)).size(), "outside and leaving: span ended before tMin");
    }

    @Test void parallelSpansAreAllOrNothing() {
        SpanBuffer below = spans(floor, ray(0, 1, 0, 1, 0, 0));
        assertEquals(1, below.size());
        assertEquals(Double.NEGATIVE_INFINITY, below.entry(0));
        assertEquals(Double.POSITIVE_INFINITY, below.exit(0));
        assertEquals(1, spans(floor, ray(0, 2, 0, 0, 0, -1)).size(), "the boundary belongs to the solid");
        assertEquals(0, spans(floor, ray(0, 3, 0, 1, 0, 0)).size());
    }

    @Test void spansRespectTheRange() {
        Ray r = ray(0, 5, 0, 0, -1, 0); // enters at 3
        r.tMax = 3;
        assertEquals(0, spans(floor, r).size());
        assertNull(hit(floor, r));
        Ray out = ray(0, 0, 0, 0, 1, 0); // leaves at 2
        out.tMin = 2;
        assertEquals(0, spans(floor, out).size());
        out.tMin = 1;
        assertEquals(1, spans(floor, out).size());
        assertEquals(2, hit(floor, out).t, EPS);
    }

    @Test void floorUvIsWorldDistance() {
        Ray r = ray(3.5, 7, -1.25, 0, -1, 0);
        ShadingData sd = shade(floor, r, hit(floor, r));
        assertEquals(3.5, sd.u, EPS);
        assertEquals(1.25, sd.v, EPS);
        assertVec(Vec3.X, sd.dpdu, 0);
        assertVec(new Vec3(0, 0, -1), sd.dpdv, 0);
        // Moving 1 along dpdu changes u by exactly 1.
        Ray r2 = ray(4.5, 7, -1.25, 0, -1, 0);
        assertEquals(sd.u + 1, shade(floor, r2, hit(floor, r2)).u, EPS);
    }

    @Test void tangentsAreAnOutwardOrthonormalFrame() {
        Random rnd = new Random(7);
        for (int i = 0; i < 200; i++) {
            Vec3 n = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
            if (i == 0) n = Vec3.X;
            if (i == 1) n = new Vec3(0, 0, -3);
            Plane p = new Plane(n, rnd.nextDouble());
            Vec3 t1 = p.tangentU(), t2 = p.tangentV();
            assertEquals(1, t1.length(), 1e-12);
            assertEquals(1, t2.length(), 1e-12);
            assertEquals(0, t1.dot(t2), 1e-12);
            assertEquals(0, t1.dot(p.normal()), 1e-12);
            assertVec(p.normal(), t1.cross(t2), 1e-12);
        }
    }

    @Test void rejectsInvalidConstruction() {
        assertThrows(IllegalArgumentException.class, () -> new Plane(Vec3.ZERO, 1));
        assertThrows(IllegalArgumentException.class, () -> new Plane(Vec3.Y, Double.POSITIVE_INFINITY));
    }
}
