package lt.spindulys.math;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Keyframes.Interpolation;
import lt.spindulys.math.Keyframes.Pose;

class KeyframesTest {
    private static Pose at(double x, double y, double z) { return new Pose(new Vec3(x, y, z), Vec3.ZERO, new Vec3(1, 1, 1)); }

    private static Keyframes track(Interpolation i, double[] times, double... xs) {
        Pose[] p = new Pose[xs.length];
        for (int k = 0; k < xs.length; k++) p[k] = at(xs[k], 0, 0);
        return Keyframes.of(times, p, i);
    }

    @Test
    void linearIsExactAtKeysAndHalfway() {
        Keyframes k = track(Interpolation.LINEAR, new double[] {1, 3, 4}, 2, 6, -1);
        assertEquals(2, k.value(0, 1));
        assertEquals(6, k.value(0, 3));
        assertEquals(-1, k.value(0, 4));
        assertEquals(4, k.value(0, 2));
        assertEquals(2.5, k.value(0, 3.5));
        // Held before the first key and after the last.
        assertEquals(2, k.value(0, -10));
        assertEquals(-1, k.value(0, 99));
        assertEquals(new Vec3(4, 0, 0), k.at(2).point(Vec3.ZERO));
    }

    @Test
    void easeStopsAtEveryKeyAndPassesHalfwayAtTheMiddle() {
        Keyframes k = track(Interpolation.EASE, new double[] {0, 1, 2}, 0, 10, 0);
        assertEquals(0, k.value(0, 0));
        assertEquals(10, k.value(0, 1));
        assertEquals(5, k.value(0, 0.5), 1e-12);
        double h = 1e-6;
        // Zero rate on both sides of the middle key.
        assertEquals(0, (k.value(0, 1) - k.value(0, 1 - h)) / h, 1e-4);
        assertEquals(0, (k.value(0, 1 + h) - k.value(0, 1)) / h, 1e-4);
    }

    @Test
    void smoothPassesThroughKeysWithAContinuousRate() {
        double[] times = {0, 1, 3, 4};
        Keyframes k = track(Interpolation.SMOOTH, times, 0, 2, -1, 5);
        for (int i = 0; i < times.length; i++) assertEquals(new double[] {0, 2, -1, 5}[i], k.value(0, times[i]), 1e-12);
        double h = 1e-6;
        for (double t : new double[] {1, 3}) {
            double left = (k.value(0, t) - k.value(0, t - h)) / h, right = (k.value(0, t + h) - k.value(0, t)) / h;
            assertEquals(left, right, 1e-4, "rate at key " + t);
            assertTrue(Math.abs(left) > 0.1, "a smooth key is passed through, not stopped at");
        }
        // The interior tangent is the neighbours' difference over their time apart (Catmull-Rom).
        double rate = (k.value(0, 1 + h) - k.value(0, 1 - h)) / (2 * h);
        assertEquals((-1 - 0) / 3.0, rate, 1e-5);
    }

    @Test
    void smoothWithTwoKeysIsLinear() {
        Keyframes k = track(Interpolation.SMOOTH, new double[] {2, 6}, 1, 9);
        for (double t = 2; t <= 6; t += 0.25) assertEquals(1 + 2 * (t - 2), k.value(0, t), 1e-12);
    }

    @Test
    void smoothScaleStaysPositiveWhereTheSplineOvershoots() {
        Vec3 one = new Vec3(1, 1, 1);
        Pose[] p = {new Pose(Vec3.ZERO, Vec3.ZERO, one), new Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(0.01, 1, 1)),
                new Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(100, 1, 1)), new Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(0.01, 1, 1))};
        Keyframes k = Keyframes.of(new double[] {0, 1, 2, 3}, p, Interpolation.SMOOTH);
        for (double t = 0; t <= 3; t += 0.01) assertTrue(k.value(6, t) > 0, "scale at " + t);
        assertEquals(100, k.value(6, 2), 1e-9);
    }

    @Test
    void rotationsAreDegreesAboutXThenYThenZAndMayTurnSeveralTimes() {
        Pose a = new Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(1, 1, 1)), b = new Pose(Vec3.ZERO, new Vec3(0, 720, 0), new Vec3(1, 1, 1));
        Keyframes k = Keyframes.of(new double[] {0, 8}, new Pose[] {a, b}, Interpolation.LINEAR);
        // A quarter turn about y after one eighth of the time (720 / 8 = 90 degrees).
        Vec3 p = k.at(1).point(new Vec3(1, 0, 0));
        assertEquals(0, p.x(), 1e-12);
        assertEquals(-1, p.z(), 1e-12);
        assertEquals(360, k.value(4, 4), 1e-9);
        // x, then y, then z: the same as the transforms written in that order.
        Pose r = new Pose(new Vec3(1, 2, 3), new Vec3(30, 40, 50), new Vec3(2, 3, 4));
        Keyframes one = Keyframes.of(new double[] {0}, new Pose[] {r}, Interpolation.LINEAR);
        Transform expected = Transform.scale(2, 3, 4).then(Transform.rotateX(30)).then(Transform.rotateY(40)).then(Transform.rotateZ(50))
                .then(Transform.translate(1, 2, 3));
        assertClose(expected, one.at(0));
    }

    @Test
    void inverseAndRayMotionAgreeWithTheMatrix() {
        Pose a = new Pose(new Vec3(1, -2, 0.5), new Vec3(10, 20, 30), new Vec3(1, 2, 0.5));
        Pose b = new Pose(new Vec3(-3, 1, 2), new Vec3(-40, 200, 5), new Vec3(3, 1, 1));
        Transform basis = Transform.rotate(new Vec3(1, 1, 0), 33).then(Transform.translate(0.3, 0.2, -1));
        for (Interpolation i : Interpolation.values()) {
            Keyframes k = Keyframes.of(new double[] {0, 1, 2.5}, new Pose[] {a, b, a}, i, basis);
            double[] m = new double[12], inv = new double[12], prod = new double[12];
            for (double t = -0.5; t < 3; t += 0.37) {
                k.matrices(t, m, inv);
                Transform.compose(inv, m, prod);
                for (int e = 0; e < 12; e++) assertEquals(e % 5 == 0 ? 1 : 0, prod[e], 1e-12, "m inv at " + t);
                Ray r = new Ray(new Vec3(0.1, 0.2, 0.3), new Vec3(0, 0.6, 0.8));
                k.moveRay(t, r);
                Transform at = Transform.ofMatrix(m);
                Vec3 o = at.point(new Vec3(0.1, 0.2, 0.3)), d = at.vector(new Vec3(0, 0.6, 0.8)).normalized();
                assertEquals(o.x(), r.ox, 1e-12);
                assertEquals(o.y(), r.oy, 1e-12);
                assertEquals(o.z(), r.oz, 1e-12);
                assertEquals(d.x(), r.dx, 1e-12);
                assertEquals(d.y(), r.dy, 1e-12);
                assertEquals(d.z(), r.dz, 1e-12);
            }
        }
    }

    @Test
    void sweepHoldsTheBoxAtEveryTime() {
        Random rnd = new Random(21);
        Bounds box = new Bounds(-1, -0.5, -2, 1, 1.5, 0.5);
        for (Interpolation i : Interpolation.values()) {
            for (int trial = 0; trial < 20; trial++) {
                Pose[] p = new Pose[4];
                for (int k = 0; k < 4; k++) {
                    p[k] = new Pose(new Vec3(rnd.nextGaussian() * 3, rnd.nextGaussian(), rnd.nextGaussian()),
                            new Vec3(rnd.nextGaussian() * 90, rnd.nextGaussian() * 200, rnd.nextGaussian() * 45),
                            new Vec3(0.5 + rnd.nextDouble(), 0.5 + rnd.nextDouble(), 0.5 + rnd.nextDouble()));
                }
                Keyframes k = Keyframes.of(new double[] {0, 1, 1.5, 3}, p, i, Transform.translate(0.5, 0, 0));
                double open = -0.5 + 3 * rnd.nextDouble(), close = open + rnd.nextDouble();
                Bounds swept = k.sweep(box, open, close);
                for (int s = 0; s <= 2000; s++) {
                    Bounds at = box.transformed(k.at(open + (close - open) * s / 2000.0));
                    assertTrue(swept.minX() <= at.minX() && swept.minY() <= at.minY() && swept.minZ() <= at.minZ()
                            && swept.maxX() >= at.maxX() && swept.maxY() >= at.maxY() && swept.maxZ() >= at.maxZ(),
                            i + " trial " + trial + " time " + s);
                }
            }
        }
        // An instant: exactly the box moved there.
        Keyframes k = track(Interpolation.LINEAR, new double[] {0, 1}, 0, 4);
        assertEquals(box.transformed(Transform.translate(1, 0, 0)).toString(), k.sweep(box, 0.25, 0.25).toString());
    }

    @Test
    void turntableOrbitsOnceOverItsSpanAndLoops() {
        // The camera's eye of scenes/turntable.dat: frames 1-24 at 24 fps, once about y.
        double start = 1 / 24.0, finish = 25 / 24.0;
        Keyframes k = Keyframes.turntable(Vec3.Y, Vec3.ZERO, 1, start, finish);
        Vec3 eye = new Vec3(0, 3, -7);
        assertClose(eye, k.at(start).point(eye));
        assertClose(new Vec3(-7, 3, 0), k.at(start + (finish - start) / 4).point(eye)); // a quarter turn, counter-clockwise from +y
        assertClose(new Vec3(0, 3, 7), k.at(start + (finish - start) / 2).point(eye));
        assertClose(eye, k.at(finish).point(eye));
        // Turning at the same rate a little before the start (a first frame's shutter).
        assertClose(Transform.rotateY(-7.5).point(eye), k.at(start - (finish - start) / 48).point(eye));

        // A tilted axis through an off-origin centre: points keep their distance from the axis and their height along it.
        Vec3 axis = new Vec3(1, 2, -0.5), c = new Vec3(3, -1, 2), p = new Vec3(0, 1, 1);
        Keyframes t = Keyframes.turntable(axis, c, -2, 0, 10);
        Vec3 a = axis.normalized();
        for (double time = 0; time <= 10; time += 0.7) {
            Vec3 q = t.at(time).point(p);
            assertEquals(p.minus(c).dot(a), q.minus(c).dot(a), 1e-9);
            assertEquals(p.minus(c).cross(a).length(), q.minus(c).cross(a).length(), 1e-9);
            assertClose(c, t.at(time).point(c));
        }
        assertClose(p, t.at(5).point(p)); // -2 turns: whole turns at half the span too
        assertFalse(t.at(2.5).point(p).minus(p).length() < 1e-3);
    }

    @Test
    void stillWhereThePoseHolds() {
        Keyframes k = track(Interpolation.SMOOTH, new double[] {1, 2, 3, 4}, 0, 5, 5, 1);
        assertTrue(k.isStill(0, 0.9), "before the first key");
        assertTrue(k.isStill(4, 9), "after the last");
        assertTrue(k.isStill(2.5, 2.5), "an instant");
        assertFalse(k.isStill(1.5, 1.6));
        assertFalse(k.isStill(0.5, 1.01), "a shutter reaching into the first span");
        // A smooth span between equal poses still bends (its neighbours' tangents); a linear one does not.
        assertFalse(k.isStill(2.2, 2.8));
        assertTrue(track(Interpolation.LINEAR, new double[] {1, 2, 3, 4}, 0, 5, 5, 1).isStill(2.2, 2.8));
    }

    @Test
    void refusesKeysOutOfOrderRepeatedOrTooMany() {
        Pose[] two = {Pose.IDENTITY, Pose.IDENTITY};
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Keyframes.of(new double[] {2, 2}, two, Interpolation.LINEAR));
        assertTrue(e.getMessage().contains("key 2 at time 2.0 is not after key 1"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Keyframes.of(new double[] {3, 1}, two, Interpolation.LINEAR));
        assertThrows(IllegalArgumentException.class, () -> Keyframes.of(new double[0], new Pose[0], Interpolation.LINEAR));
        int n = Keyframes.MAX_KEYS + 1;
        double[] times = new double[n];
        Pose[] poses = new Pose[n];
        for (int i = 0; i < n; i++) { times[i] = i; poses[i] = Pose.IDENTITY; }
        assertThrows(IllegalArgumentException.class, () -> Keyframes.of(times, poses, Interpolation.LINEAR));
        assertThrows(IllegalArgumentException.class, () -> new Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(1, 0, 1)));
        assertThrows(IllegalArgumentException.class, () -> new Pose(new Vec3(Double.NaN, 0, 0), Vec3.ZERO, new Vec3(1, 1, 1)));
        assertThrows(IllegalArgumentException.class, () -> Keyframes.turntable(Vec3.ZERO, Vec3.ZERO, 1, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> Keyframes.turntable(Vec3.Y, Vec3.ZERO, 1, 1, 1));
    }

    private static void assertClose(Vec3 expected, Vec3 actual) {
        assertEquals(expected.x(), actual.x(), 1e-9, "x of " + actual);
        assertEquals(expected.y(), actual.y(), 1e-9, "y of " + actual);
        assertEquals(expected.z(), actual.z(), 1e-9, "z of " + actual);
    }

    private static void assertClose(Transform expected, Transform actual) {
        for (Vec3 p : new Vec3[] {Vec3.ZERO, Vec3.X, Vec3.Y, Vec3.Z, new Vec3(1, 2, 3)}) assertClose(expected.point(p), actual.point(p));
    }
}
