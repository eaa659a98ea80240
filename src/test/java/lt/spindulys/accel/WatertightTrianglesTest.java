package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;

/**
 * The watertight ray/triangle test on bare index arrays, as a primitive set other than a mesh
 * (subdivision patches) will call it: exact hit records, the interval and any-hit contracts, the
 * leaf-range form, and no ray slipping between triangles that share an edge or vertex.
 */
class WatertightTrianglesTest {

    /** One triangle in the z = 0 plane, counter-clockwise seen from +z. */
    private static final double[] FLAT = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    private static final int[] ONE = {0, 1, 2};

    /** A closed octahedron with outward (counter-clockwise) winding: every edge and vertex shared. */
    private static final double[] OCTA = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
    private static final int[] OCTA_TRI = {
        0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4,
        2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5,
    };

    @Test
    void recordsTheHitAsTriangleAndBarycentricsOfTheSecondAndThirdCorner() {
        Ray ray = new Ray().set(0.25, 0.5, 2, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        PrimitiveHit hit = new PrimitiveHit();
        assertTrue(WatertightTriangles.test(ONE, FLAT, null, 0, 1, ray, hit, new TraversalScratch()));
        assertEquals(2.0, hit.t);
        assertEquals(0, hit.prim);
        assertEquals(0.25, hit.u, "weight of corner 1, (1, 0, 0)");
        assertEquals(0.5, hit.v, "weight of corner 2, (0, 1, 0)");
        assertEquals(2.0, ray.tMax, "a hit shrinks the interval");
    }

    @Test
    void hitsOnlyInsideTheOpenInterval() {
        TraversalScratch s = new TraversalScratch();
        PrimitiveHit hit = new PrimitiveHit();
        assertFalse(WatertightTriangles.test(ONE, FLAT, null, 0, 1, new Ray().set(0.25, 0.25, 2, 0, 0, -1, 0, 2), hit, s));
        assertFalse(WatertightTriangles.test(ONE, FLAT, null, 0, 1, new Ray().set(0.25, 0.25, 2, 0, 0, -1, 2, 9), hit, s));
        assertFalse(WatertightTriangles.test(ONE, FLAT, null, 0, 1, new Ray().set(0.75, 0.75, 2, 0, 0, -1, 0, 9), hit, s), "outside the hypotenuse");
        assertTrue(WatertightTriangles.test(ONE, FLAT, null, 0, 1, new Ray().set(0.25, 0.25, -2, 0, 0, 1, 0, 9), hit, s), "from behind too");
    }

    @Test
    void anyHitLeavesTheRayAlone() {
        Ray ray = new Ray().set(0.25, 0.25, 2, 0, 0, -1, 0, 9);
        assertTrue(WatertightTriangles.test(ONE, FLAT, null, 0, 1, ray, null, new TraversalScratch()));
        assertEquals(9.0, ray.tMax);
    }

    @Test
    void aLeafRangeReadsItsTrianglesThroughThePrimitiveList() {
        // Three stacked copies of the flat triangle at z = 0, 1, 2; the leaf lists two of them.
        double[] pos = new double[27];
        int[] tri = new int[9];
        for (int k = 0; k < 3; k++) {
            for (int c = 0; c < 3; c++) {
                pos[9 * k + 3 * c] = FLAT[3 * c];
                pos[9 * k + 3 * c + 1] = FLAT[3 * c + 1];
                pos[9 * k + 3 * c + 2] = k;
                tri[3 * k + c] = 3 * k + c;
            }
        }
        int[] prims = {7, 0, 2, 7}; // the leaf is prims[1..3)
        Ray ray = new Ray().set(0.2, 0.2, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        PrimitiveHit hit = new PrimitiveHit();
        assertTrue(WatertightTriangles.test(tri, pos, prims, 1, 3, ray, hit, new TraversalScratch()));
        assertEquals(2, hit.prim, "the nearest of the listed triangles, not triangle 1 between them");
        assertEquals(3.0, hit.t);
    }

    @Test
    void raysThroughSharedEdgesAndVerticesNeverSlipThrough() {
        Random r = new Random(15);
        TraversalScratch s = new TraversalScratch();
        PrimitiveHit hit = new PrimitiveHit();
        Ray ray = new Ray();
        int misses = 0;
        for (int i = 0; i < 20_000; i++) {
            // An origin well inside (|x| + |y| + |z| < 1), aimed at a vertex or a point of an edge.
            double ox = 0.3 * (r.nextDouble() - 0.5), oy = 0.3 * (r.nextDouble() - 0.5), oz = 0.3 * (r.nextDouble() - 0.5);
            int t = r.nextInt(8), c = r.nextInt(3);
            int a = 3 * OCTA_TRI[3 * t + c], b = 3 * OCTA_TRI[3 * t + (c + 1) % 3];
            double f = i % 2 == 0 ? 0 : r.nextBoolean() ? 0.5 : r.nextDouble();
            ray.set(ox, oy, oz,
                    OCTA[a] + f * (OCTA[b] - OCTA[a]) - ox,
                    OCTA[a + 1] + f * (OCTA[b + 1] - OCTA[a + 1]) - oy,
                    OCTA[a + 2] + f * (OCTA[b + 2] - OCTA[a + 2]) - oz, 0, Double.POSITIVE_INFINITY);
            if (!WatertightTriangles.test(OCTA_TRI, OCTA, null, 0, 8, ray, hit, s)) misses++;
        }
        assertEquals(0, misses, "rays that passed between neighbouring triangles");
    }
}
