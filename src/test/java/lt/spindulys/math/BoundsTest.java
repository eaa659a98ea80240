package lt.spindulys.math;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

class BoundsTest {
    private final Bounds unit = new Bounds(0, 0, 0, 1, 1, 1);
    private final double[] range = new double[2];

    private static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray().set(ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
    }

    @Test void slabRangeAndMisses() {
        assertTrue(unit.hitRange(ray(-1, 0.5, 0.5, 2, 0, 0), range));
        assertEquals(0.5, range[0], 1e-15);
        assertEquals(1, range[1], 1e-15);
        assertFalse(unit.hitRange(ray(-1, 1.5, 0.5, 1, 0, 0), range));
        assertFalse(unit.hitRange(ray(-1, 0.5, 0.5, -1, 0, 0), range));
        assertTrue(unit.hitRange(ray(-1, -1, 0.5, 1, 1, 0), null), "null range is allowed");
    }

    @Test void rangeIsClippedToTheRay() {
        Ray r = ray(0.5, 0.5, 0.5, 0, 0, 1);
        assertTrue(unit.hitRange(r, range));
        assertEquals(0, range[0]);
        assertEquals(0.5, range[1], 1e-15);
        r.tMax = 0.25;
        assertTrue(unit.hitRange(r, range));
        assertEquals(0.25, range[1]);
        r.tMin = 0.6;
        r.tMax = 5;
        assertFalse(unit.hitRange(r, range));
    }

    @Test void parallelRaysInsideOutsideAndOnTheBoundary() {
        assertTrue(unit.hitRange(ray(-1, 0.5, 0.5, 1, 0, 0), range));
        assertFalse(unit.hitRange(ray(-1, 1.5, 0.5, 1, 0, 0), range));
        for (double zero : new double[] {0.0, -0.0}) {
            for (double y : new double[] {0, 1}) {
                assertTrue(unit.hitRange(ray(-1, y, 0.5, 1, zero, zero), range), "face plane y=" + y + ", zero=" + zero);
                assertEquals(1, range[0], 1e-15);
                assertEquals(2, range[1], 1e-15);
                assertFalse(Double.isNaN(range[0]) || Double.isNaN(range[1]));
            }
            assertTrue(unit.hitRange(ray(0.5, 0.5, 0.5, zero, zero, 1), range));
            assertEquals(0.5, range[1], 1e-15);
        }
    }

    @Test void infiniteExtents() {
        Ray r = ray(3, 4, 5, -1, 2, 0.5);
        r.tMin = 0.1;
        r.tMax = 9;
        assertTrue(Bounds.INFINITE.hitRange(r, range));
        assertEquals(0.1, range[0]);
        assertEquals(9, range[1]);
        // The half-space y <= 0: a ray from above heading down enters at y = 0.
        Bounds lower = new Bounds(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
                Double.POSITIVE_INFINITY, 0, Double.POSITIVE_INFINITY);
        assertTrue(lower.hitRange(ray(1, 3, 1, 0.5, -1, 0), range));
        assertEquals(3, range[0], 1e-15);
        assertEquals(Double.POSITIVE_INFINITY, range[1]);
        assertFalse(lower.hitRange(ray(1, 3, 1, 0.5, 1, 0), range));
        assertTrue(lower.hitRange(ray(1, -3, 1, 1, 0, -0.0), range), "parallel inside the half-space");
        assertEquals(Double.POSITIVE_INFINITY, range[1]);
    }

    @Test void emptyBoxesAreNeverHit() {
        assertTrue(Bounds.EMPTY.isEmpty());
        assertFalse(Bounds.EMPTY.hitRange(ray(0, 0, 0, 1, 1, 1), range));
        Bounds disjoint = unit.intersection(new Bounds(2, 0, 0, 3, 1, 1));
        assertTrue(disjoint.isEmpty());
        assertFalse(disjoint.hitRange(ray(-5, 0.5, 0.5, 1, 0, 0), range));
    }

    @Test void unionIntersectionContains() {
        Bounds b = Bounds.EMPTY.union(1, 2, 3).union(-1, 0, 5);
        assertEquals(new Bounds(-1, 0, 3, 1, 2, 5), b);
        assertEquals(unit, unit.union(Bounds.EMPTY));
        assertEquals(new Bounds(0.5, 0, 0, 1, 1, 1), unit.intersection(new Bounds(0.5, -1, -1, 2, 2, 2)));
        assertTrue(unit.contains(1, 0, 0.5));
        assertFalse(unit.contains(1.0001, 0, 0.5));
        assertTrue(Bounds.INFINITE.contains(1e300, -1e300, 0));
        assertFalse(Bounds.INFINITE.isFinite());
        assertEquals(Bounds.of(new Vec3(1, 0, 1), new Vec3(0, 1, 0)), unit);
    }

    @Test void transformedBounds() {
        Bounds r = unit.transformed(Transform.rotateZ(45));
        double h = Math.sqrt(0.5);
        assertEquals(-h, r.minX(), 1e-12);
        assertEquals(h, r.maxX(), 1e-12);
        assertEquals(0, r.minY(), 1e-12);
        assertEquals(2 * h, r.maxY(), 1e-12);
        assertEquals(new Bounds(1, 0, 0, 3, 3, 1), unit.transformed(Transform.scale(2, 3, 1).then(Transform.translate(1, 0, 0))));
        assertSame(Bounds.EMPTY, Bounds.EMPTY.transformed(Transform.translate(1, 1, 1)));
        assertEquals(Bounds.INFINITE, Bounds.INFINITE.transformed(Transform.rotateX(10)));
    }
}
