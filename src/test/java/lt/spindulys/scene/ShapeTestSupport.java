package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

/** Helpers shared by the shape tests: freezing, querying and comparing vectors. */
final class ShapeTestSupport {
    static final double EPS = 1e-9;

    private ShapeTestSupport() {}

    static <T extends GObject> T frozen(T o) {
        TestBuild.freeze(o, Transform.IDENTITY, Material.DEFAULT, 0);
        return o;
    }

    static Ray ray(double ox, double oy, double oz, double dx, double dy, double dz) {
        return new Ray().set(ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
    }

    static Ray ray(Vec3 o, Vec3 d) { return ray(o.x(), o.y(), o.z(), d.x(), d.y(), d.z()); }

    /** The nearest hit, or null on a miss. */
    static Hit hit(GObject o, Ray r) {
        Hit h = new Hit().reset(r.tMax);
        return o.intersect(r, h, new TraceContext()) ? h : null;
    }

    /** Shading data with uv and derivatives whatever the material. */
    static ShadingData shade(GObject o, Ray r, Hit h) {
        ShadingData sd = new ShadingData();
        o.shade(r, h, sd, true);
        return sd;
    }

    static SpanBuffer spans(GObject o, Ray r) {
        SpanBuffer b = new SpanBuffer();
        o.spans(r, b, new TraceContext());
        return b;
    }

    static Vec3 v(double[] a) { return new Vec3(a[0], a[1], a[2]); }

    static void assertVec(Vec3 expected, Vec3 actual, double tol) {
        assertTrue(actual.isFinite(), () -> "not finite: " + actual);
        assertEquals(0, expected.minus(actual).length(), tol, () -> "expected " + expected + " but was " + actual);
    }

    static void assertVec(Vec3 expected, double[] actual, double tol) { assertVec(expected, v(actual), tol); }

    static void assertUnit(double[] n) {
        assertEquals(1, v(n).length(), 1e-12, () -> "not unit: " + v(n));
    }

    /** Asserts every shading vector is finite and the normals are unit length. */
    static void assertSane(ShadingData sd) {
        assertUnit(sd.ng);
        assertUnit(sd.ns);
        assertTrue(v(sd.dpdu).isFinite() && v(sd.dpdv).isFinite(), "derivatives not finite");
        assertTrue(Double.isFinite(sd.u) && Double.isFinite(sd.v), "uv not finite");
    }
}
