package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;

/**
 * Moving objects: intersected and shaded at the ray's time exactly as the same object placed
 * statically where it is at that time; bounds that hold over the whole motion (nested motions
 * too); and moving subdivision surfaces and CSG objects without holes.
 */
class MovingObjectTest {
    private static Vec3 rv(Random r, double s) { return new Vec3(s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1), s * (2 * r.nextDouble() - 1)); }

    private static Motion randomMotion(Random r) {
        double start = 0.5 * r.nextDouble(), finish = start + 0.1 + 0.5 * r.nextDouble();
        Vec3 scale = new Vec3(0.5 + r.nextDouble(), 0.5 + r.nextDouble(), 0.5 + r.nextDouble());
        return Motion.of(scale, rv(r, 1).plus(new Vec3(0.01, 0, 0)), 360 * (2 * r.nextDouble() - 1), rv(r, 2), rv(r, 1), start, finish);
    }

    private static ControlMesh cube() {
        MeshData c = TestMeshes.cube();
        return ControlMesh.builder(c.positions(), c.faceSizes(), c.vertexIndex()).build();
    }

    /** A moving object answers a ray at time t as a static copy placed by its transform at t. */
    @Test
    void movingShapesHitAndShadeAsTheirStaticCopyAtTheRaysTime() {
        Random r = new Random(11);
        for (int i = 0; i < 60; i++) {
            Motion m = randomMotion(r);
            Transform own = Transform.rotateY(30).then(Transform.translate(0.3, 0, 0));
            GObject[] moving = {new Sphere(Vec3.ZERO, 1), new Box(new Vec3(-1, -0.5, -0.7), new Vec3(1, 0.5, 0.7)),
                    new Cylinder(new Vec3(0, -1, 0), new Vec3(0, 1, 0), 0.6)};
            for (GObject o : moving) {
                TestBuild.freeze(o.transform(own).motion(m), Transform.IDENTITY, Material.DEFAULT, 0);
                assertTrue(o.isMoving());
                TraceContext ctx = new TraceContext();
                for (int k = 0; k < 40; k++) {
                    double t = r.nextDouble();
                    GObject still = copy(o).transform(o.objectToWorld(t));
                    TestBuild.freeze(still, Transform.IDENTITY, Material.DEFAULT, 0);
                    Vec3 from = rv(r, 1).times(6).plus(new Vec3(0, 0, -8)), to = rv(r, 1.5);
                    Ray a = new Ray(from, to.minus(from)), b = new Ray(from, to.minus(from));
                    a.time = t;
                    b.time = 0.123; // ignored by the static copy
                    Hit ha = new Hit().reset(a.tMax), hb = new Hit().reset(b.tMax);
                    boolean hitA = o.intersect(a, ha, ctx), hitB = still.intersect(b, hb, ctx);
                    assertEquals(hitB, hitA, o.name() + " at " + t);
                    assertEquals(hitB, o.occluded(a, ctx));
                    if (!hitA) continue;
                    assertEquals(hb.t, ha.t, 1e-9 * (1 + hb.t));
                    ShadingData sa = new ShadingData(), sb = new ShadingData();
                    o.shade(a, ha, sa);
                    still.shade(b, hb, sb);
                    for (int c = 0; c < 3; c++) {
                        assertEquals(sb.ng[c], sa.ng[c], 1e-8);
                        assertEquals(sb.pObject[c], sa.pObject[c], 1e-8);
                    }
                    assertEquals(sb.u, sa.u, 1e-8);
                }
            }
        }
    }

    private static GObject copy(GObject o) {
        if (o instanceof Sphere s) return new Sphere(s.center(), s.radius());
        if (o instanceof Box b) return new Box(b.min(), b.max());
        Cylinder c = (Cylinder) o;
        return new Cylinder(new Vec3(0, -1, 0), new Vec3(0, 1, 0), 0.6);
    }

    /** For random motions and times, the object's box carried to time t lies inside bounds(); nested moving CSG included. */
    @Test
    void boundsHoldTheObjectAtEveryTime() {
        Random r = new Random(12);
        for (int i = 0; i < 100; i++) {
            Sphere leaf = new Sphere(rv(r, 1), 0.5 + r.nextDouble());
            leaf.transform(Transform.scale(1, 1.5, 0.7)).motion(randomMotion(r));
            Box other = new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1));
            Bool u = new Bool(Bool.Op.UNION, List.of(leaf, other));
            u.transform(Transform.rotateZ(20)).motion(randomMotion(r));
            TestBuild.freeze(u, Placement.of(Transform.translate(1, 0, 0), -0.5, 1.5), Material.DEFAULT, 0, AcceleratorKind.BVH);
            for (int k = 0; k < 100; k++) {
                double t = 2.4 * r.nextDouble() - 0.7;
                Bounds leafAtT = leaf.localBounds().transformed(leaf.objectToWorld(t));
                assertInside(leafAtT, leaf.bounds(), "leaf at " + t);
                assertInside(leafAtT, u.bounds(), "leaf in the union at " + t);
                assertInside(other.localBounds().transformed(other.objectToWorld(t)), u.bounds(), "box in the union at " + t);
            }
        }
    }

    @Test
    void objectsWithoutMotionKeepTheirOneTransform() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        s.transform(Transform.translate(1, 2, 3));
        TestBuild.freeze(s, Transform.rotateX(10), Material.DEFAULT, 0);
        assertFalse(s.isMoving());
        assertSame(s.objectToWorld(0), s.objectToWorld(0.7));
        assertEquals(Transform.translate(1, 2, 3).then(Transform.rotateX(10)), s.objectToWorld(0.3));
    }

    /** Whether a point lies inside a closed object at time t: a span of a ray from it contains t = 0. */
    private static boolean inside(GObject o, Vec3 p, double time, Random rnd, TraceContext ctx) {
        Ray r = new Ray().set(p.x(), p.y(), p.z(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
        r.time = time;
        SpanBuffer b = new SpanBuffer();
        o.spans(r, b, ctx);
        for (int s = 0; s < b.size(); s++) if (b.entry(s) < 0 && b.exit(s) > 0) return true;
        return false;
    }

    /** Rays from points inside the object at random times always leave it through a surface. */
    private static void assertWatertight(GObject o, Random rnd, int wanted) {
        TraceContext ctx = new TraceContext();
        Hit hit = new Hit();
        Bounds b = o.bounds();
        int found = 0, tried = 0;
        while (found < wanted) {
            assertTrue(++tried < 200 * wanted, "too few points inside");
            double t = rnd.nextDouble();
            Vec3 p = new Vec3(b.minX() + (b.maxX() - b.minX()) * rnd.nextDouble(), b.minY() + (b.maxY() - b.minY()) * rnd.nextDouble(),
                    b.minZ() + (b.maxZ() - b.minZ()) * rnd.nextDouble());
            if (!inside(o, p, t, rnd, ctx)) continue;
            found++;
            Ray r = new Ray().set(p.x(), p.y(), p.z(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), 0, Double.POSITIVE_INFINITY);
            r.time = t;
            hit.reset(r.tMax);
            assertTrue(o.intersect(r, hit, ctx), () -> "escaped from " + r);
            assertTrue(o.occluded(r, ctx), () -> "not occluded: " + r);
            ShadingData sd = new ShadingData();
            hit.object.shade(r, hit, sd);
            // From inside, the first surface is an exit: its outward normal points along the ray.
            assertTrue(sd.ng[0] * r.dx + sd.ng[1] * r.dy + sd.ng[2] * r.dz > 0, () -> "entered instead of leaving: " + r);
        }
    }

    @Test
    void movingSubdivisionSurfaceHasNoHoles() {
        SubdivisionSurface s = new SubdivisionSurface(cube(), 3);
        s.transform(Transform.rotateX(20)).motion(Motion.of(new Vec3(1.5, 1, 0.8), new Vec3(1, 1, 0), 120, new Vec3(2, 0.5, 0), new Vec3(0.3, 0, 0), 0.1, 0.9));
        TestBuild.freeze(s, Transform.IDENTITY, Material.DEFAULT, 0);
        assertWatertight(s, new Random(21), 2000);
    }

    @Test
    void movingCsgObjectWithAMovingOperandHasNoHoles() {
        SubdivisionSurface a = new SubdivisionSurface(cube(), 2);
        Sphere bite = new Sphere(new Vec3(0.8, 0.8, 0.8), 0.8);
        bite.motion(Motion.translation(new Vec3(-0.6, 0, -0.6), 0, 1));
        Cylinder drill = new Cylinder(new Vec3(0, -2, 0), new Vec3(0, 2, 0), 0.3);
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(a, bite, drill));
        d.motion(Motion.of(new Vec3(1, 1, 1), Vec3.Z, 90, new Vec3(0, 1, 0), Vec3.ZERO, 0, 0.7));
        TestBuild.freeze(d, Transform.IDENTITY, Material.DEFAULT, 0);
        assertWatertight(d, new Random(22), 2000);
    }

    private static void assertInside(Bounds inner, Bounds outer, String what) {
        assertNotNull(outer);
        assertTrue(inner.minX() >= outer.minX() && inner.minY() >= outer.minY() && inner.minZ() >= outer.minZ()
                && inner.maxX() <= outer.maxX() && inner.maxY() <= outer.maxY() && inner.maxZ() <= outer.maxZ(),
                () -> inner + " not inside " + outer + ": " + what);
    }
}
