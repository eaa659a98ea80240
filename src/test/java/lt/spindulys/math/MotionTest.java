package lt.spindulys.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** Motion: interpolation, its analytic inverse, linear motion, and bounds that hold at every time. */
class MotionTest {
    private static Vec3 rv(Random r, double s) { return new Vec3(s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1)); }

    /** A random motion of every kind: scale, rotation about a random axis and pivot, translation, random times. */
    static Motion random(Random r) {
        double start = r.nextDouble() - 0.25, finish = start + 0.05 + r.nextDouble();
        Vec3 scale = new Vec3(0.3 + 2 * r.nextDouble(), 0.3 + 2 * r.nextDouble(), 0.3 + 2 * r.nextDouble());
        if (r.nextInt(3) == 0) scale = new Vec3(1, 1, 1);
        double degrees = r.nextInt(4) == 0 ? 0 : 720 * (2 * r.nextDouble() - 1);
        return Motion.of(scale, rv(r, 1).plus(new Vec3(0, 0.01, 0)), degrees, rv(r, 3), rv(r, 2), start, finish);
    }

    private static void assertMatrix(Transform expected, Transform actual, double tol) {
        for (Vec3 p : new Vec3[] {Vec3.ZERO, Vec3.X, Vec3.Y, Vec3.Z, new Vec3(-2, 3, 0.5)}) {
            assertEquals(0, expected.point(p).minus(actual.point(p)).length(), tol, () -> expected + " vs " + actual);
        }
    }

    @Test
    void identityAtTheStartEndTransformAtTheFinishClampedOutside() {
        Vec3 pivot = new Vec3(1, 2, 3);
        Motion m = Motion.of(new Vec3(2, 1, 0.5), Vec3.Z, 90, new Vec3(0, 0, 4), pivot, 0.2, 0.6);
        Transform end = Transform.translate(pivot.times(-1)).then(Transform.scale(2, 1, 0.5)).then(Transform.rotateZ(90))
                .then(Transform.translate(pivot)).then(Transform.translate(0, 0, 4));
        assertMatrix(Transform.IDENTITY, m.at(0.2), 1e-12);
        assertMatrix(Transform.IDENTITY, m.at(-5), 1e-12);
        assertMatrix(end, m.at(0.6), 1e-12);
        assertMatrix(end, m.at(7), 1e-12);
        // Halfway: half the angle, half the scale change, half the translation.
        Transform half = Transform.translate(pivot.times(-1)).then(Transform.scale(1.5, 1, 0.75)).then(Transform.rotateZ(45))
                .then(Transform.translate(pivot)).then(Transform.translate(0, 0, 2));
        assertMatrix(half, m.at(0.4), 1e-12);
        assertEquals(0.25, m.fraction(0.3), 1e-15);
    }

    @Test
    void analyticInverseInvertsAtEveryTime() {
        Random r = new Random(1);
        double[] f = new double[12], inv = new double[12];
        for (int i = 0; i < 500; i++) {
            Motion m = random(r);
            double t = m.start() - 0.2 + (m.finish() - m.start() + 0.4) * r.nextDouble();
            m.matrices(t, f, inv);
            Transform fwd = Transform.ofMatrix(f), back = Transform.ofMatrix(inv);
            assertMatrix(Transform.IDENTITY, fwd.then(back), 1e-9);
            assertMatrix(fwd.inverse(), back, 1e-9);
        }
    }

    @Test
    void linearMotionTravelsSpeedTimesDuration() {
        Motion m = Motion.linear(new Vec3(0, 3, 4), 2, 0.25, 0.75);
        assertEquals(0, m.translation().minus(new Vec3(0, 0.6, 0.8)).length(), 1e-15, "unit direction x speed 2 x 0.5 time");
        // Open times come from the shutter, and with them the distance.
        Motion open = Motion.linear(Vec3.X, 3, Double.NaN, Double.NaN);
        Motion resolved = open.resolve(1, 3);
        assertEquals(1, resolved.start());
        assertEquals(3, resolved.finish());
        assertEquals(new Vec3(6, 0, 0), resolved.translation());
        assertSame(resolved, resolved.resolve(0, 1));
        Motion late = Motion.translation(Vec3.X, 0.5, Double.NaN).resolve(0, 2);
        assertEquals(2, late.finish());
    }

    @Test
    void refusesWhatCannotBeInterpolated() {
        assertThrows(IllegalArgumentException.class, () -> Motion.of(new Vec3(1, 0, 1), Vec3.Y, 0, Vec3.ZERO, Vec3.ZERO, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> Motion.of(new Vec3(1, 1, 1), Vec3.ZERO, 30, Vec3.ZERO, Vec3.ZERO, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> Motion.translation(Vec3.X, 0.5, 0.5));
        assertThrows(IllegalArgumentException.class, () -> Motion.linear(Vec3.ZERO, 1, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> Motion.translation(Vec3.X, 2, Double.NaN).resolve(0, 1));
        assertThrows(IllegalStateException.class, () -> Motion.translation(Vec3.X, Double.NaN, Double.NaN).at(0));
    }

    /** The property the acceleration structures rely on: at any time, the moved box lies inside the swept bounds. */
    @Test
    void sweptBoundsHoldTheBoxAtEveryTime() {
        Random r = new Random(2);
        for (int i = 0; i < 400; i++) {
            Motion m = random(r);
            Vec3 a = rv(r, 2), b = a.plus(new Vec3(0.1 + r.nextDouble(), 0.1 + r.nextDouble(), 0.1 + r.nextDouble()));
            Bounds box = Bounds.of(a, b), swept = m.sweep(box), dense = Bounds.EMPTY;
            for (int k = 0; k < 200; k++) {
                double t = m.start() - 0.1 + (m.finish() - m.start() + 0.2) * r.nextDouble();
                assertInside(box.transformed(m.at(t)), swept, m + " at " + t);
            }
            // Not merely safe but close: within 0.5% of its size of the box swept at 2,001 times.
            for (int k = 0; k <= 2000; k++) dense = dense.union(box.transformed(m.at(m.start() + k * (m.finish() - m.start()) / 2000)));
            double size = Math.max(swept.maxX() - swept.minX(), Math.max(swept.maxY() - swept.minY(), swept.maxZ() - swept.minZ()));
            double slack = Math.max(Math.max(dense.minX() - swept.minX(), swept.maxX() - dense.maxX()),
                    Math.max(Math.max(dense.minY() - swept.minY(), swept.maxY() - dense.maxY()), Math.max(dense.minZ() - swept.minZ(), swept.maxZ() - dense.maxZ())));
            assertTrue(slack < 0.005 * size, "swept bounds " + slack + " larger than needed, of " + size);
        }
    }

    /** Nested: a placement with two motions and static factors between them is bounded at every time too. */
    @Test
    void placementBoundsHoldNestedMotions() {
        Random r = new Random(3);
        for (int i = 0; i < 200; i++) {
            Placement p = Placement.of(Transform.rotate(rv(r, 1).plus(Vec3.X), 40 * r.nextDouble()), 0, 1).then(random(r))
                    .then(Transform.translate(rv(r, 2))).then(random(r)).then(Transform.scale(1, 2, 0.5));
            Bounds box = Bounds.of(rv(r, 1), rv(r, 1).plus(new Vec3(1.5, 1.5, 1.5))), all = p.bounds(box);
            for (int k = 0; k < 100; k++) {
                double t = 2 * r.nextDouble() - 0.5;
                assertInside(box.transformed(p.at(t)), all, "at " + t);
            }
        }
    }

    @Test
    void staticPlacementIsItsTransform() {
        Transform t = Transform.rotateX(30).then(Transform.translate(1, 2, 3));
        Placement p = Placement.of(t).then(Transform.scale(2, 2, 2));
        assertTrue(p.isStatic());
        assertEquals(t.then(Transform.scale(2, 2, 2)), p.staticTransform());
        Bounds b = Bounds.of(Vec3.ZERO, new Vec3(1, 1, 1));
        assertEquals(b.transformed(p.staticTransform()), p.bounds(b));
    }

    private static void assertInside(Bounds inner, Bounds outer, String what) {
        assertTrue(inner.minX() >= outer.minX() && inner.minY() >= outer.minY() && inner.minZ() >= outer.minZ()
                && inner.maxX() <= outer.maxX() && inner.maxY() <= outer.maxY() && inner.maxZ() <= outer.maxZ(),
                () -> inner + " not inside " + outer + ": " + what);
    }
}
