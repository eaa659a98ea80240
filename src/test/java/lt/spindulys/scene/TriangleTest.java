package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;

import static lt.spindulys.scene.ShapeTestSupport.*;
import static org.junit.jupiter.api.Assertions.*;

import java.util.Random;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import org.junit.jupiter.api.Test;

class TriangleTest {
    private static final Vec3 A = new Vec3(0, 0, 0), B = new Vec3(1, 0, 0), C = new Vec3(0, 1, 0);

    private final Triangle tri = frozen(new Triangle(A, B, C));

    @Test void boundsAndOpen() {
        assertEquals(new Bounds(0, 0, 0, 1, 1, 0), tri.localBounds());
        assertFalse(tri.isClosed());
        assertThrows(UnsupportedOperationException.class, () -> spans(tri, ray(0.2, 0.2, 1, 0, 0, -1)));
    }

    @Test void hitRecordsBarycentrics() {
        Ray r = ray(0.25, 0.5, 2, 0, 0, -4);
        Hit h = hit(tri, r);
        assertEquals(0.5, h.t, EPS);
        assertEquals(0.25, h.u, EPS);
        assertEquals(0.5, h.v, EPS);
        ShadingData sd = shade(tri, r, h);
        assertVec(new Vec3(0.25, 0.5, 0), sd.p, EPS);
        assertVec(Vec3.Z, sd.ng, 0);
        assertVec(Vec3.Z, sd.ns, 0);
        assertEquals(0.25, sd.u, EPS);
        assertEquals(0.5, sd.v, EPS);
        assertVec(B.minus(A), sd.dpdu, 0);
        assertVec(C.minus(A), sd.dpdv, 0);
        // From behind: still hit (no culling), normal still by winding.
        Ray back = ray(0.25, 0.5, -2, 0, 0, 1);
        assertEquals(2, hit(tri, back).t, EPS);
        assertVec(Vec3.Z, shade(tri, back, hit(tri, back)).ng, 0);
    }

    @Test void missesAndParallelRays() {
        assertNull(hit(tri, ray(0.6, 0.6, 1, 0, 0, -1)), "beyond the hypotenuse");
        assertNull(hit(tri, ray(-0.1, 0.5, 1, 0, 0, -1)));
        assertNull(hit(tri, ray(0.2, 0.2, 1, 0, 0, 1)), "pointing away");
        assertNull(hit(tri, ray(-1, 0.2, 0, 1, 0, 0)), "in the triangle's plane");
        assertNull(hit(tri, ray(-1, 0.2, 0, 1, -0.0, 0.0)));
        assertNull(hit(tri, ray(0.2, 0.2, 1, 0, 0, 0)), "zero direction");
    }

    @Test void edgesAndVerticesAreInclusive() {
        assertNotNull(hit(tri, ray(0.5, 0, 1, 0, 0, -1)));
        assertNotNull(hit(tri, ray(0.5, 0.5, 1, 0, 0, -1)));
        assertNotNull(hit(tri, ray(0, 0, 1, 0, 0, -1)));
    }

    @Test void respectsTMinAndTMax() {
        Ray r = ray(0.2, 0.2, 3, 0, 0, -1);
        r.tMax = 3;
        assertNull(hit(tri, r));
        r.tMax = 3.5;
        assertNotNull(hit(tri, r));
        r.tMin = 3;
        assertNull(hit(tri, r));
    }

    @Test void vertexUvsInterpolateAndGiveDerivatives() {
        Triangle t = frozen(new Triangle(A, B, C).uvs(0.5, 0.5, 2.5, 0.5, 0.5, 4.5));
        Ray r = ray(0.25, 0.5, 1, 0, 0, -1);
        ShadingData sd = shade(t, r, hit(t, r));
        assertEquals(0.5 + 0.25 * 2, sd.u, EPS);
        assertEquals(0.5 + 0.5 * 4, sd.v, EPS);
        assertVec(new Vec3(0.5, 0, 0), sd.dpdu, EPS);
        assertVec(new Vec3(0, 0.25, 0), sd.dpdv, EPS);
    }

    @Test void derivativesReproduceTheEdgesForArbitraryUvs() {
        Random rnd = new Random(11);
        for (int i = 0; i < 50; i++) {
            Vec3 a = rndVec(rnd), b = rndVec(rnd), c = rndVec(rnd);
            double[] uv = new double[6];
            for (int k = 0; k < 6; k++) uv[k] = rnd.nextDouble() * 4 - 2;
            Triangle t = frozen(new Triangle(a, b, c).uvs(uv[0], uv[1], uv[2], uv[3], uv[4], uv[5]));
            Vec3 p = a.times(0.2).plus(b.times(0.3)).plus(c.times(0.5));
            Vec3 n = b.minus(a).cross(c.minus(a)).normalized();
            Ray r = ray(p.plus(n), n.times(-1));
            Hit h = hit(t, r);
            assertNotNull(h);
            ShadingData sd = shade(t, r, h);
            assertSane(sd);
            // A linear map: an edge's uv change times the derivatives is the edge itself.
            Vec3 e1 = v(sd.dpdu).times(uv[2] - uv[0]).plus(v(sd.dpdv).times(uv[3] - uv[1]));
            Vec3 e2 = v(sd.dpdu).times(uv[4] - uv[0]).plus(v(sd.dpdv).times(uv[5] - uv[1]));
            assertVec(b.minus(a), e1, 1e-7);
            assertVec(c.minus(a), e2, 1e-7);
        }
    }

    @Test void collinearUvsFallBackToTheEdges() {
        Triangle t = frozen(new Triangle(A, B, C).uvs(0, 0, 1, 1, 2, 2));
        Ray r = ray(0.2, 0.2, 1, 0, 0, -1);
        ShadingData sd = shade(t, r, hit(t, r));
        assertSane(sd);
        assertVec(B.minus(A), sd.dpdu, 0);
        assertVec(C.minus(A), sd.dpdv, 0);
    }

    @Test void vertexNormalsInterpolate() {
        Vec3 na = new Vec3(0, 0, 1), nb = new Vec3(1, 0, 1), nc = new Vec3(0, 2, 2);
        Triangle t = frozen(new Triangle(A, B, C).normals(na, nb, nc));
        assertTrue(t.hasNormals());
        Ray r = ray(0.5, 0, 1, 0, 0, -1); // midway between a and b
        ShadingData sd = shade(t, r, hit(t, r));
        Vec3 expected = na.plus(nb.normalized()).normalized();
        assertVec(expected, sd.ns, 1e-12);
        assertVec(Vec3.Z, sd.ng, 0);
    }

    @Test void geometricNormalTurnsToTheVertexNormals() {
        Vec3 down = new Vec3(0, 0, -1);
        Triangle t = frozen(new Triangle(A, B, C).normals(down, down, down));
        Ray r = ray(0.2, 0.2, 1, 0, 0, -1);
        ShadingData sd = shade(t, r, hit(t, r));
        assertVec(down, sd.ns, 0);
        assertVec(down, sd.ng, 0);
    }

    @Test void cancellingVertexNormalsFallBackToGeometric() {
        Triangle t = frozen(new Triangle(A, B, C).normals(Vec3.Z, new Vec3(0, 0, -1), Vec3.Z));
        Ray r = ray(0.5, 0.25, 1, 0, 0, -1);
        Hit h = hit(t, r);
        h.u = 0.5; h.v = 0; // exactly between a and b: the normals cancel
        ShadingData sd = shade(t, r, h);
        assertSane(sd);
        assertVec(Vec3.Z, sd.ns, 0);
    }

    @Test void optionsAreValidated() {
        Triangle t = new Triangle(A, B, C);
        assertThrows(IllegalArgumentException.class, () -> t.normals(Vec3.Z, Vec3.ZERO, Vec3.Z));
        assertThrows(IllegalArgumentException.class, () -> t.normals(Vec3.Z, new Vec3(Double.NaN, 0, 1), Vec3.Z));
        assertThrows(IllegalArgumentException.class, () -> t.normals(Vec3.Z, null, Vec3.Z));
        assertThrows(IllegalArgumentException.class, () -> t.uvs(0, 0, 1, Double.POSITIVE_INFINITY, 0, 1));
        assertFalse(t.hasNormals());
        assertFalse(t.hasUvs());
        frozen(t);
        assertThrows(IllegalStateException.class, () -> t.uvs(0, 0, 1, 0, 0, 1));
        assertThrows(IllegalStateException.class, () -> t.normals(Vec3.Z, Vec3.Z, Vec3.Z));
        assertThrows(IllegalArgumentException.class, () -> new Triangle(A, B, new Vec3(2, 0, 0)));
    }

    private static Vec3 rndVec(Random rnd) {
        return new Vec3(rnd.nextDouble() * 4 - 2, rnd.nextDouble() * 4 - 2, rnd.nextDouble() * 4 - 2);
    }
}
