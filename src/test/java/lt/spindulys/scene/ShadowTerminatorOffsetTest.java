package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.trace.ShadingData;

/**
 * Hanika's shadow-terminator offset ({@link TriangleShading#liftShadowOrigin}): a point on a
 * triangle whose vertex normals describe a sphere is lifted towards that sphere; concave and flat
 * normals leave it where it is.
 */
class ShadowTerminatorOffsetTest {
    private static double[] unit(double x, double y, double z) {
        double l = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / l, y / l, z / l};
    }

    /** Shades barycentrics (u, v) on the triangle a, b, c with corner normals na, nb, nc; returns sd. */
    private static ShadingData shade(double[] a, double[] b, double[] c, double[] na, double[] nb, double[] nc, double u, double v) {
        ShadingData sd = new ShadingData();
        double[][] corners = {a, b, c, na, nb, nc};
        for (int k = 0; k < 6; k++) System.arraycopy(corners[k], 0, sd.corners, 3 * k, 3);
        sd.lifted = false;
        TriangleShading.shadeCorners(true, false, u, v, sd);
        return sd;
    }

    private static double[] point(ShadingData sd, double u, double v) {
        double[] c = sd.corners, p = new double[3];
        for (int i = 0; i < 3; i++) p[i] = (1 - u - v) * c[i] + u * c[3 + i] + v * c[6 + i];
        return p;
    }

    private static double norm(double[] p) { return Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]); }

    // A coarse triangle of the unit sphere (an octant's corners are far apart: a large lift).
    private static final double[] A = unit(1, 0.1, 0.1), B = unit(0.1, 1, 0.1), C = unit(0.1, 0.1, 1);

    @Test
    void convexNormalsLiftThePointTowardsTheSphere() {
        double[][] bary = {{1 / 3.0, 1 / 3.0}, {0.1, 0.2}, {0.45, 0.5}, {0.7, 0.05}};
        for (double[] uv : bary) {
            ShadingData sd = shade(A, B, C, A, B, C, uv[0], uv[1]);
            assertTrue(sd.lifted, "lifted at " + uv[0] + ", " + uv[1]);
            double[] p = point(sd, uv[0], uv[1]);
            double[] q = {p[0] + sd.shadowOrigin[0], p[1] + sd.shadowOrigin[1], p[2] + sd.shadowOrigin[2]};
            double before = 1 - norm(p), after = Math.abs(1 - norm(q));
            assertTrue(before > 0.05, "the flat triangle lies well inside the sphere: " + before);
            // Blending the tangent planes undershoots the sphere a little, never overshoots far.
            assertTrue(after < 0.35 * before, "lifted from " + before + " to " + after + " off the sphere");
            // Outward, along the surface's normal side.
            assertTrue(q[0] * p[0] + q[1] * p[1] + q[2] * p[2] > p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        }
    }

    @Test
    void theLiftIsOnTheWindingsSideAndNormalLengthsDoNotMatter() {
        // Wound the other way, the outward side is the sphere's inside (the corner normals are
        // turned to it, as the shading normal is): seen from there the surface is concave.
        assertFalse(shade(A, C, B, A, C, B, 0.3, 0.3).lifted);
        // Normals of other lengths give the same point: they are normalised first.
        ShadingData sd = shade(A, B, C, A, B, C, 0.3, 0.3);
        double[] a2 = {2 * A[0], 2 * A[1], 2 * A[2]}, c3 = {3 * C[0], 3 * C[1], 3 * C[2]};
        ShadingData scaled = shade(A, B, C, a2, B, c3, 0.3, 0.3);
        assertTrue(scaled.lifted);
        for (int i = 0; i < 3; i++) assertEquals(sd.shadowOrigin[i], scaled.shadowOrigin[i], 1e-12);
    }

    @Test
    void concaveNormalsLeaveThePoint() {
        // The inside of the sphere seen from its centre: wound towards the centre, normals pointing there.
        double[] na = {-A[0], -A[1], -A[2]}, nb = {-B[0], -B[1], -B[2]}, nc = {-C[0], -C[1], -C[2]};
        for (double[] uv : new double[][] {{1 / 3.0, 1 / 3.0}, {0.1, 0.2}, {0.45, 0.5}}) {
            ShadingData sd = shade(A, C, B, na, nc, nb, uv[0], uv[1]);
            assertFalse(sd.lifted, "concave at " + uv[0] + ", " + uv[1]);
        }
    }

    @Test
    void flatNormalsLeaveThePoint() {
        double[] a = {0.3, -1, 2}, b = {4, 0.5, 1.5}, c = {-1, 3, 0.25};
        double[] e1 = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2 = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double[] n = unit(e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]);
        for (double[] uv : new double[][] {{1 / 3.0, 1 / 3.0}, {0.1, 0.2}, {0.45, 0.5}}) {
            ShadingData sd = shade(a, b, c, n, n, n, uv[0], uv[1]);
            // Rounding may leave a lift of the order of the coordinates' last bits, no more.
            if (sd.lifted) assertTrue(norm(sd.shadowOrigin) < 1e-14, "offset " + norm(sd.shadowOrigin));
        }
    }

    @Test
    void aCreaseCornersNormalNeverTakesThePointBelowTheTriangle() {
        // A face of a creased cube (z = 0, normal +z) whose corner on the crease carries the side
        // face's normal, tipped a little into the solid, as a subdivision surface's crease vertex may.
        double[] a = {1, 0, 0}, b = {0, 1, 0}, c = {0, 0, 0}, up = {0, 0, 1};
        double[] side = unit(1, 0, -0.06);
        for (double[] uv : new double[][] {{1 / 3.0, 1 / 3.0}, {0.1, 0.2}, {0.45, 0.5}, {0.05, 0.05}}) {
            ShadingData sd = shade(a, b, c, side, up, up, uv[0], uv[1]);
            if (sd.lifted) assertTrue(sd.shadowOrigin[2] >= 0, "below the face by " + sd.shadowOrigin[2]);
        }
        // Tipped out of the solid instead, the corner lifts the point: above the face.
        ShadingData sd = shade(a, b, c, unit(1, 0, 0.5), up, up, 0.2, 0.3);
        assertTrue(sd.lifted && sd.shadowOrigin[2] > 0);
    }
}
