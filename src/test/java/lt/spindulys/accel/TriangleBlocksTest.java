package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.Random;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.TestMeshes;

/**
 * The float triangles in the wide tree's leaves: the eight-lane test never drops a triangle the
 * exact double test hits (rays through corners and along edges, far from the origin, tiny
 * triangles), it does drop the ones far from the ray, and a tree with them answers every query
 * bit for bit as the compact tree does, which the heap chooses when the copies do not fit.
 */
class TriangleBlocksTest {

    /** Triangles on bare arrays, as the tree sees a mesh. */
    private record Soup(int[] corners, double[] positions) implements TriangleSet {
        @Override public int size() { return corners.length / 3; }
        @Override public void bounds(int i, double[] out) { WatertightTriangles.bounds(corners, positions, i, out); }
        @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
            return WatertightTriangles.test(corners, positions, null, i, i + 1, ray, hit, ctx);
        }
        @Override public boolean intersectRange(int[] prims, int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
            return WatertightTriangles.test(corners, positions, prims, from, to, ray, hit, ctx);
        }
        @Override public boolean occludedRange(int[] prims, int from, int to, Ray ray, TraversalScratch ctx) {
            return WatertightTriangles.test(corners, positions, prims, from, to, ray, null, ctx);
        }
        @Override public void corners(int i, double[] out) {
            for (int c = 0; c < 3; c++) System.arraycopy(positions, 3 * corners[3 * i + c], out, 3 * c, 3);
        }
        @Override public double maxAbsCoordinate() {
            double m = 0;
            for (double p : positions) m = Math.max(m, Math.abs(p));
            return m;
        }
    }

    /** Eight triangles of size {@code size} around {@code (offset, offset, offset)}, some sharing corners. */
    private static Soup block(Random r, double size, double offset) {
        double[] p = new double[3 * 12];
        for (int i = 0; i < p.length; i++) p[i] = offset + size * (r.nextDouble() - 0.5);
        int[] t = new int[24];
        for (int i = 0; i < 24; i++) t[i] = i < 9 ? i : r.nextInt(12);
        for (int k = 0; k < 8; k++) {
            // three distinct corners (a repeated one would make a degenerate triangle: fine, but rarely useful)
            while (t[3 * k] == t[3 * k + 1] || t[3 * k + 1] == t[3 * k + 2] || t[3 * k] == t[3 * k + 2]) t[3 * k + r.nextInt(3)] = r.nextInt(12);
        }
        return new Soup(t, p);
    }

    private static double[] corner(Soup s, int tri, int c) {
        int v = 3 * s.corners[3 * tri + c];
        return new double[] {s.positions[v], s.positions[v + 1], s.positions[v + 2]};
    }

    @ParameterizedTest(name = "size {0} at {1}")
    @CsvSource({"1, 0, 0.5", "1000, 0, 0.5", "0.01, -300, 0.05", "0.001, 10000, 0", "1e-6, 1, 0", "1e-4, 1e6, 0"})
    void neverDropsATriangleTheExactTestHits(double size, double offset, double minDropped) {
        // minDropped: where float cannot resolve the triangles (a size near the ulps of the
        // offset), the test may keep every lane; elsewhere it must drop most of those missed.
        Random r = new Random(Double.hashCode(size) * 31 + Double.hashCode(offset));
        TraversalScratch ctx = new TraversalScratch();
        PrimitiveHit hit = new PrimitiveHit();
        int exactHits = 0, dropped = 0, lanes = 0;
        for (int round = 0; round < 400; round++) {
            Soup s = block(r, size, offset);
            TriangleBlocks blocks = new TriangleBlocks(s, null, 1);
            blocks.add(0, 8);
            for (int q = 0; q < 60; q++) {
                // aimed at a corner, a point of an edge (in double, so often exactly on it), or inside
                int tri = r.nextInt(8);
                double[] a = corner(s, tri, 0), b = corner(s, tri, 1), c = corner(s, tri, 2);
                double u = r.nextDouble(), v = r.nextDouble();
                if (q % 3 == 0) { u = q % 2; v = 0; }
                else if (q % 3 == 1) v = 0;
                else if (u + v > 1) { u = 1 - u; v = 1 - v; }
                double[] target = new double[3];
                for (int k = 0; k < 3; k++) target[k] = a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]);
                double dist = size * (0.5 + 20 * r.nextDouble());
                double dx = r.nextGaussian(), dy = r.nextGaussian(), dz = r.nextGaussian();
                double len = Math.sqrt(dx * dx + dy * dy + dz * dz);
                dx /= len; dy /= len; dz /= len;
                Ray ray = new Ray().set(target[0] - dist * dx, target[1] - dist * dy, target[2] - dist * dz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
                int bits = blocks.candidates(0, ray, ctx);
                for (int l = 0; l < 8; l++) {
                    lanes++;
                    boolean maybe = (bits >>> l & 1) != 0;
                    if (!maybe) dropped++;
                    ray.tMax = Double.POSITIVE_INFINITY;
                    if (WatertightTriangles.test(s.corners, s.positions, null, l, l + 1, ray, hit, ctx)) {
                        exactHits++;
                        int lane = l;
                        assertTrue(maybe, () -> "lane " + lane + " hit exactly but dropped: ray " + ray + " soup " + java.util.Arrays.toString(s.positions));
                    }
                }
            }
        }
        assertTrue(exactHits > 24_000, "the rays hit: " + exactHits);
        assertTrue(dropped >= minDropped * lanes, "the float test drops the triangles the ray passes far from: " + dropped + " of " + lanes);
    }

    /** A unit icosphere's triangles, as a set that keeps its numbering (the trees index it through their slot order). */
    private static Soup sphere() {
        lt.spindulys.mesh.MeshData d = TestMeshes.icosphere(4, 1);
        for (int size : d.faceSizes()) assertEquals(3, size, "an icosphere of triangles");
        return new Soup(d.vertexIndex().clone(), d.positions().clone());
    }

    private static void assertSameAnswers(Accelerator expected, Accelerator actual, Soup m, long seed) {
        Random r = new Random(seed);
        TraversalScratch c1 = new TraversalScratch(), c2 = new TraversalScratch();
        PrimitiveHit h1 = new PrimitiveHit(), h2 = new PrimitiveHit();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            // from inside and outside the unit sphere, towards random points and the mesh's corners
            double ox = 3 * (r.nextDouble() - 0.5), oy = 3 * (r.nextDouble() - 0.5), oz = 3 * (r.nextDouble() - 0.5);
            double tx, ty, tz;
            if (i % 2 == 0) {
                double[] p = m.positions();
                int v = 3 * r.nextInt(p.length / 3);
                tx = p[v]; ty = p[v + 1]; tz = p[v + 2];
            } else {
                tx = r.nextGaussian(); ty = r.nextGaussian(); tz = r.nextGaussian();
            }
            double dx = tx - ox, dy = ty - oy, dz = tz - oz, len = Math.sqrt(dx * dx + dy * dy + dz * dz);
            Ray a = new Ray().set(ox, oy, oz, dx / len, dy / len, dz / len, 1e-9, Double.POSITIVE_INFINITY);
            Ray b = new Ray().set(ox, oy, oz, dx / len, dy / len, dz / len, 1e-9, Double.POSITIVE_INFINITY);
            boolean ha = expected.intersect(a, h1, c1), hb = actual.intersect(b, h2, c2);
            assertEquals(ha, hb, "ray " + i);
            if (ha) {
                hits++;
                assertEquals(h1.t, h2.t, "t of ray " + i);
                // Rays through a shared corner or edge meet several triangles at the same t; the
                // trees test them in different orders, so either may be the one recorded.
                if (h1.prim == h2.prim) {
                    assertEquals(h1.u, h2.u, "u of ray " + i);
                    assertEquals(h1.v, h2.v, "v of ray " + i);
                } else {
                    Ray c = new Ray().set(ox, oy, oz, dx / len, dy / len, dz / len, 1e-9, Double.POSITIVE_INFINITY);
                    PrimitiveHit h3 = new PrimitiveHit();
                    assertTrue(WatertightTriangles.test(m.corners, m.positions, null, h1.prim, h1.prim + 1, c, h3, c1) && h3.t == h2.t,
                            "ray " + i + ": triangles " + h1.prim + " and " + h2.prim + " both at t " + h2.t);
                }
            }
            a.tMax = b.tMax = 0.5 + r.nextDouble();
            assertEquals(expected.occluded(a, c1), actual.occluded(b, c2), "shadow ray " + i);
        }
        assertTrue(hits > 10_000, "hits " + hits);
    }

    @Test
    void aTreeWithTheTrianglesInItsLeavesAnswersAsTheCompactTree() {
        assumeTrue(WideBvh.AVAILABLE, "no vector module in this JVM");
        Soup m = sphere();
        Accelerator compact = WideBvh.widen(new Bvh(m, Bvh.DEFAULT_LEAF_SIZE, false));
        WideBvh blocks = assertInstanceOf(WideBvh.class, WideBvh.build(m, false));
        assertTrue(blocks.hasLeafBlocks());
        assertFalse(assertInstanceOf(WideBvh.class, compact).hasLeafBlocks());
        assertSameAnswers(compact, blocks, m, 5);
    }

    @Test
    void aHeapWithoutRoomForTheCopiesGivesTheCompactLayoutWithTheSameAnswers() {
        assumeTrue(WideBvh.AVAILABLE, "no vector module in this JVM");
        Soup m = sphere();
        Accelerator full = WideBvh.build(m, false);
        WideBvh compact;
        try (HeapBudget.Scope ignored = HeapBudget.cap(0)) {
            compact = assertInstanceOf(WideBvh.class, WideBvh.build(m, false));
        }
        assertFalse(compact.hasLeafBlocks(), "no room: the leaves name their triangles");
        assertSameAnswers(full, compact, m, 6);
    }
}
