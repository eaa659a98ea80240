package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import java.util.function.Predicate;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

/**
 * Seeded random rays against every closed shape, plain and transformed: the nearest hit must be
 * the first span endpoint after tMin, spans must be sorted and must agree with an independent
 * inside test, and normals at entries and exits must face the right way.
 */
class SpanConsistencyTest {
    private static final Transform PLACE = Transform.scale(1.5, 0.5, 2).then(Transform.rotate(new Vec3(1, 2, 3), 40))
            .then(Transform.translate(0.3, -0.2, 0.5));

    @Test void sphere() {
        Vec3 c = new Vec3(0.2, -0.3, 0.1);
        check(() -> new Sphere(c, 1.3), p -> p.minus(c).length() <= 1.3);
    }

    @Test void box() {
        check(() -> new Box(new Vec3(-1, -0.5, -1.5), new Vec3(1.2, 1, 0.5)),
                p -> p.x() >= -1 && p.x() <= 1.2 && p.y() >= -0.5 && p.y() <= 1 && p.z() >= -1.5 && p.z() <= 0.5);
    }

    @Test void cylinder() {
        Vec3 b = new Vec3(-0.5, -1, 0.2), t = new Vec3(0.7, 1.5, -0.4);
        Vec3 w = t.minus(b).normalized();
        double h = t.minus(b).length();
        check(() -> new Cylinder(b, t, 0.8), p -> {
            Vec3 q = p.minus(b);
            double z = q.dot(w);
            return z >= 0 && z <= h && q.minus(w.times(z)).length() <= 0.8;
        });
    }

    @Test void axisAlignedCylinder() {
        check(() -> new Cylinder(new Vec3(0, 0, -1), new Vec3(0, 0, 1), 1),
                p -> p.z() >= -1 && p.z() <= 1 && p.x() * p.x() + p.y() * p.y() <= 1);
    }

    @Test void plane() {
        Vec3 n = new Vec3(1, -2, 0.5).normalized();
        check(() -> new Plane(new Vec3(1, -2, 0.5), 0.7), p -> p.dot(n) <= 0.7 / new Vec3(1, -2, 0.5).length());
    }

    private interface Factory { GObject make(); }

    private void check(Factory factory, Predicate<Vec3> insideLocal) {
        GObject plain = frozen(factory.make());
        GObject placed = frozen(factory.make().transform(PLACE));
        Transform toLocal = PLACE.inverse();
        run(plain, insideLocal, 1);
        run(placed, p -> insideLocal.test(toLocal.point(p)), 2);
    }

    private void run(GObject o, Predicate<Vec3> inside, long seed) {
        Random rnd = new Random(seed * 7919 + o.kind().hashCode());
        TraceContext ctx = new TraceContext();
        SpanBuffer sp = new SpanBuffer();
        Hit h = new Hit();
        int hits = 0;
        for (int i = 0; i < 3000; i++) {
            Ray r = randomRay(rnd);
            sp.clear();
            o.spans(r, sp, ctx);
            String msg = r.toString();

            // Sorted, non-empty spans overlapping (tMin, tMax); a convex solid has at most one.
            assertTrue(sp.size() <= 1, msg);
            for (int s = 0; s < sp.size(); s++) {
                assertTrue(sp.entry(s) <= sp.exit(s), msg);
                assertTrue(sp.exit(s) > r.tMin && sp.entry(s) < r.tMax, msg);
                if (s > 0) assertTrue(sp.entry(s) >= sp.exit(s - 1), msg);
            }

            // The nearest hit is the first endpoint after tMin, with the same surface.
            int first = -1;
            for (int e = 0; e < 2 * sp.size(); e++) {
                if (sp.t(e) > r.tMin) { first = e; break; }
            }
            boolean expectHit = first >= 0 && sp.t(first) < r.tMax;
            boolean got = o.intersect(r, h.reset(r.tMax), ctx);
            assertEquals(expectHit, got, msg);
            if (got) {
                hits++;
                assertEquals(sp.t(first), h.t, 0, msg);
                Hit fromSpan = new Hit();
                sp.toHit(first, fromSpan);
                assertEquals(fromSpan.prim, h.prim, msg);
                ShadingData sd = new ShadingData();
                o.shade(r, h, sd);
                assertSane(sd);
                // Outward normal: against the ray at an entry, along it at an exit.
                double dn = (sd.ng[0] * r.dx + sd.ng[1] * r.dy + sd.ng[2] * r.dz) / Math.sqrt(r.dx * r.dx + r.dy * r.dy + r.dz * r.dz);
                if (first % 2 == 0) assertTrue(dn <= 1e-9, msg + " entry normal " + dn);
                else assertTrue(dn >= -1e-9, msg + " exit normal " + dn);
            }

            // Spans agree with the inside test at sample points away from the endpoints.
            double lo = Math.max(r.tMin, -6), hi = Math.min(r.tMax, 12);
            for (int k = 0; k < 8 && lo < hi; k++) {
                double t = lo + (hi - lo) * rnd.nextDouble();
                boolean inSpan = false, nearEnd = false;
                for (int s = 0; s < sp.size(); s++) {
                    inSpan |= t >= sp.entry(s) && t <= sp.exit(s);
                    nearEnd |= Math.abs(t - sp.entry(s)) < 1e-7 || Math.abs(t - sp.exit(s)) < 1e-7;
                }
                if (nearEnd) continue;
                Vec3 p = new Vec3(r.pointX(t), r.pointY(t), r.pointZ(t));
                assertEquals(inside.test(p), inSpan, msg + " at t=" + t);
            }
        }
        assertTrue(hits > 300, "too few hits to mean anything: " + hits);
    }

    private static Ray randomRay(Random rnd) {
        Vec3 o = new Vec3(rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4, rnd.nextDouble() * 8 - 4);
        Vec3 d;
        if (rnd.nextInt(5) == 0) {
            // Axis-parallel, with zeros of either sign: exercises the parallel-slab paths.
            int axis = rnd.nextInt(3);
            double s = rnd.nextBoolean() ? 1 : -1;
            double z1 = rnd.nextBoolean() ? 0.0 : -0.0, z2 = rnd.nextBoolean() ? 0.0 : -0.0;
            d = axis == 0 ? new Vec3(s, z1, z2) : axis == 1 ? new Vec3(z1, s, z2) : new Vec3(z1, z2, s);
        } else if (rnd.nextBoolean()) {
            d = new Vec3(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian());
        } else {
            // Aimed at a point near the middle, so that hits are common.
            d = new Vec3(rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1, rnd.nextDouble() * 2 - 1).minus(o);
        }
        d = d.times(0.2 + 2.8 * rnd.nextDouble());
        Ray r = ray(o, d);
        int mode = rnd.nextInt(3);
        if (mode == 1) r.tMin = rnd.nextDouble() * 4 - 2;
        if (mode == 2) { r.tMin = rnd.nextDouble() * 2; r.tMax = r.tMin + rnd.nextDouble() * 4; }
        return r;
    }
}
