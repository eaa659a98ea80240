package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

/** Shapes placed by non-trivial transforms, checked against hand-derived world geometry. */
class TransformedShapeTest {
    private static final double C30 = Math.cos(Math.toRadians(30)), S30 = Math.sin(Math.toRadians(30));

    /** Rotation by 30 degrees about z, written out by hand. */
    private static Vec3 rotZ30(Vec3 p) {
        return new Vec3(p.x() * C30 - p.y() * S30, p.x() * S30 + p.y() * C30, p.z());
    }

    @Test void ellipsoidHitAndNormal() {
        GObject s = new Sphere(Vec3.ZERO, 1)
                .transform(Transform.scale(2, 1, 1).then(Transform.rotateZ(30)).then(Transform.translate(1, 2, 3)));
        frozen(s);
        Vec3 t = new Vec3(1, 2, 3);
        double[][] angles = {{0.4, 1.1}, {2.0, 4.0}, {1.2, 0.3}, {Math.PI / 2, 0}};
        for (double[] a : angles) {
            double th = a[0], ph = a[1];
            Vec3 local = new Vec3(Math.sin(th) * Math.cos(ph), Math.cos(th), Math.sin(th) * Math.sin(ph));
            Vec3 world = rotZ30(new Vec3(2 * local.x(), local.y(), local.z())).plus(t);
            // Normals scale by the inverse of the scale, then rotate.
            Vec3 normal = rotZ30(new Vec3(local.x() / 2, local.y(), local.z())).normalized();
            Ray r = ray(world.plus(normal.times(3)), normal.times(-0.5));
            Hit h = hit(s, r);
            assertNotNull(h);
            assertEquals(6, h.t, 1e-9);
            ShadingData sd = shade(s, r, h);
            assertVec(world, sd.p, 1e-9);
            assertVec(normal, sd.ng, 1e-9);
            assertSane(sd);
            assertTrue(v(sd.dpdu).cross(v(sd.dpdv)).dot(v(sd.ng)) > 0 || v(sd.dpdu).length() < 1e-9);
            SpanBuffer sp = spans(s, r);
            assertEquals(1, sp.size());
            assertEquals(6, sp.entry(0), 1e-9);
        }
        // Along the long axis: through the centre, 2 each side.
        Vec3 axis = rotZ30(Vec3.X);
        Ray r = ray(t.minus(axis.times(10)), axis);
        assertEquals(8, hit(s, r).t, 1e-9);
        assertEquals(12, spans(s, r).exit(0), 1e-9);
    }

    @Test void parentTransformAppliesAfterTheObjects() {
        GObject s = new Sphere(Vec3.ZERO, 1).transform(Transform.translate(1, 0, 0));
        TestBuild.freeze(s, Transform.scale(2, 2, 2), Material.DEFAULT, 0); // centre (2, 0, 0), radius 2
        Hit h = new Hit().reset(Double.POSITIVE_INFINITY);
        assertTrue(s.intersect(ray(2, 0, -10, 0, 0, 1), h, new TraceContext()));
        assertEquals(8, h.t, 1e-12);
        Bounds b = s.bounds();
        assertEquals(0, b.minX(), 1e-12);
        assertEquals(4, b.maxX(), 1e-12);
    }

    @Test void rotatedScaledBox() {
        // [0,1]^3 scaled to [0,2]x[0,3]x[0,4]; rotating 90 degrees about y maps (x, y, z) to (z, y, -x);
        // then z moves by 5: the world box is [0,4] x [0,3] x [3,5].
        GObject box = frozen(new Box(Vec3.ZERO, new Vec3(1, 1, 1))
                .transform(Transform.scale(2, 3, 4).then(Transform.rotateY(90)).then(Transform.translate(0, 0, 5))));
        Bounds b = box.bounds();
        assertVec(new Vec3(0, 0, 3), b.min(), 1e-12);
        assertVec(new Vec3(4, 3, 5), b.max(), 1e-12);
        Ray r = ray(2, 1.5, -1, 0, 0, 1);
        Hit h = hit(box, r);
        assertEquals(4, h.t, 1e-12);
        assertEquals(1, h.prim, "world -z is the local +x face");
        ShadingData sd = shade(box, r, h);
        assertVec(new Vec3(0, 0, -1), sd.ng, 1e-12);
        assertVec(new Vec3(0, 3, 0), sd.dpdu, 1e-12);
        assertVec(new Vec3(4, 0, 0), sd.dpdv, 1e-12);
        assertEquals(0.5, sd.u, 1e-12);
        assertEquals(0.5, sd.v, 1e-12);
        // Origin inside: exits through world +x, the local +z face.
        Ray in = ray(1, 1, 4, 1, 0, 0);
        h = hit(box, in);
        assertEquals(3, h.t, 1e-12);
        assertEquals(5, h.prim);
        assertVec(Vec3.X, shade(box, in, h).ng, 1e-12);
        SpanBuffer sp = spans(box, in);
        assertEquals(-1, sp.entry(0), 1e-12);
    }

    @Test void ellipticCylinder() {
        // Unit cylinder along y, stretched: x^2/4 + z^2 <= 1, 0 <= y <= 3.
        GObject cyl = frozen(new Cylinder(Vec3.ZERO, Vec3.Y, 1).transform(Transform.scale(2, 3, 1)));
        Ray r = ray(-5, 1.5, 0, 1, 0, 0);
        Hit h = hit(cyl, r);
        assertEquals(3, h.t, 1e-12);
        assertVec(new Vec3(-1, 0, 0), shade(cyl, r, h).ng, 1e-12);
        double a = 0.7;
        Vec3 p = new Vec3(2 * Math.cos(a), 1.5, Math.sin(a));
        Vec3 n = new Vec3(Math.cos(a) / 2, 0, Math.sin(a)).normalized();
        r = ray(p.plus(n.times(2)), n.times(-1));
        h = hit(cyl, r);
        assertEquals(2, h.t, 1e-9);
        ShadingData sd = shade(cyl, r, h);
        assertVec(n, sd.ng, 1e-9);
        assertEquals(0.5, sd.v, 1e-9);
        r = ray(0.5, 10, 0.1, 0, -1, 0);
        h = hit(cyl, r);
        assertEquals(7, h.t, 1e-12);
        assertEquals(Cylinder.TOP_CAP, h.prim);
        assertVec(Vec3.Y, shade(cyl, r, h).ng, 1e-12);
    }

    @Test void planeUnderNonUniformScale() {
        // Local x + y <= 0; world x/2 + y <= 0 after scaling x by 2.
        GObject plane = frozen(new Plane(new Vec3(1, 1, 0), 0).transform(Transform.scale(2, 1, 1)));
        Ray r = ray(4, 5, 0, 0, -1, 0); // crosses y = -2 at t = 7
        Hit h = hit(plane, r);
        assertEquals(7, h.t, 1e-12);
        assertVec(new Vec3(0.5, 1, 0).normalized(), shade(plane, r, h).ng, 1e-12);
        SpanBuffer sp = spans(plane, r);
        assertEquals(1, sp.size());
        assertEquals(7, sp.entry(0), 1e-12);
        assertEquals(Double.POSITIVE_INFINITY, sp.exit(0));
    }

    @Test void rotatedTriangle() {
        // rotateX(90) maps (x, y, z) to (x, -z, y): the xy triangle stands up in the xz plane.
        GObject tri = frozen(new Triangle(Vec3.ZERO, Vec3.X, Vec3.Y)
                .transform(Transform.rotateX(90).then(Transform.translate(0, 3, 0))));
        Ray r = ray(0.2, -1, 0.3, 0, 2, 0);
        Hit h = hit(tri, r);
        assertEquals(2, h.t, 1e-12);
        assertEquals(0.2, h.u, 1e-12);
        assertEquals(0.3, h.v, 1e-12);
        ShadingData sd = shade(tri, r, h);
        assertVec(new Vec3(0, -1, 0), sd.ng, 1e-12); // +z turned by rotateX(90)
        assertVec(new Vec3(0.2, 3, 0.3), sd.p, 1e-12);
    }
}
