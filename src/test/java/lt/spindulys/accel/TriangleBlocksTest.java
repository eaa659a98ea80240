package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;

/**
 * The four-wide float watertight test of {@link TriangleBlocks}: the hit record of the double test,
 * agreement with {@link WatertightTriangles} away from edges, no ray escaping a closed mesh, the
 * vector and scalar kernels equal to the bit, and no allocation per ray.
 */
class TriangleBlocksTest {

    private static final double[] FLAT = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    private static final int[] ONE = {0, 1, 2};

    /** A triangle soup: {@code n} triangles with corners in the unit cube, some positions shared. */
    private static Mesh soup(Random rnd, int n) {
        int positions = 2 * n;
        double[] pos = new double[3 * positions];
        for (int k = 0; k < pos.length; k++) pos[k] = rnd.nextDouble();
        int[] tri = new int[3 * n];
        for (int k = 0; k < tri.length; k++) tri[k] = rnd.nextInt(positions);
        return new Mesh(tri, pos);
    }

    /**
     * The surface of the cube [-1, 1]^3, each face an n x n grid of quads split in two, positions
     * shared along face borders; with {@code sphere} every position is pushed out to radius 1.3.
     */
    static Mesh cube(int n, boolean sphere) {
        Map<List<Integer>, Integer> index = new HashMap<>();
        List<double[]> pos = new ArrayList<>();
        List<Integer> tri = new ArrayList<>();
        for (int axis = 0; axis < 3; axis++) {
            for (int side = -1; side <= 1; side += 2) {
                int[][] id = new int[n + 1][n + 1];
                for (int i = 0; i <= n; i++) {
                    for (int j = 0; j <= n; j++) {
                        int[] g = new int[3];
                        g[axis] = side * n;
                        g[(axis + 1) % 3] = 2 * i - n;
                        g[(axis + 2) % 3] = 2 * j - n;
                        List<Integer> key = List.of(g[0], g[1], g[2]);
                        Integer k = index.get(key);
                        if (k == null) {
                            double x = g[0] / (double) n, y = g[1] / (double) n, z = g[2] / (double) n;
                            double r = sphere ? 1.3 / Math.sqrt(x * x + y * y + z * z) : 1;
                            k = pos.size();
                            pos.add(new double[] {x * r, y * r, z * r});
                            index.put(key, k);
                        }
                        id[i][j] = k;
                    }
                }
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        // alternate diagonals, so vertices meet 4, 6 or 8 triangles
                        if (((i + j) & 1) == 0) {
                            tri.addAll(List.of(id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j], id[i + 1][j + 1], id[i][j + 1]));
                        } else {
                            tri.addAll(List.of(id[i][j], id[i + 1][j], id[i][j + 1], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]));
                        }
                    }
                }
            }
        }
        double[] p = new double[3 * pos.size()];
        for (int k = 0; k < pos.size(); k++) System.arraycopy(pos.get(k), 0, p, 3 * k, 3);
        return new Mesh(tri.stream().mapToInt(Integer::intValue).toArray(), p);
    }

    record Mesh(int[] tri, double[] pos) {
        int count() { return tri.length / 3; }
    }

    /** A shuffled order of the mesh's triangles cut into leaves of 1 to 8. */
    static int[][] leaves(Mesh m, Random rnd) {
        int n = m.count();
        int[] perm = new int[n];
        for (int k = 0; k < n; k++) perm[k] = k;
        for (int k = n - 1; k > 0; k--) { int j = rnd.nextInt(k + 1), t = perm[k]; perm[k] = perm[j]; perm[j] = t; }
        List<Integer> bounds = new ArrayList<>(List.of(0));
        while (bounds.get(bounds.size() - 1) < n) bounds.add(Math.min(n, bounds.get(bounds.size() - 1) + 1 + rnd.nextInt(8)));
        return new int[][] {perm, bounds.stream().mapToInt(Integer::intValue).toArray()};
    }

    @Test
    void recordsTheHitAsTheDoubleTestDoes() {
        TriangleBlocks b = new TriangleBlocks(ONE, FLAT, null, new int[] {0, 1});
        assertEquals(1, b.blockCount());
        for (boolean simd : simdModes()) {
            Ray ray = new Ray().set(0.25, 0.5, 2, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
            PrimitiveHit hit = new PrimitiveHit();
            TraversalScratch s = new TraversalScratch();
            assertTrue(b.test(0, 1, ray, hit, s, simd));
            assertEquals(2.0, hit.t);
            assertEquals(0, hit.prim);
            assertEquals(0.25, hit.u);
            assertEquals(0.5, hit.v);
            assertEquals(2.0, ray.tMax);
            assertFalse(b.test(0, 1, new Ray().set(0.25, 0.25, 2, 0, 0, -1, 0, 2), hit, s, simd), "t = tMax is outside");
            assertFalse(b.test(0, 1, new Ray().set(0.25, 0.25, 2, 0, 0, -1, 2, 9), hit, s, simd), "t = tMin is outside");
            assertFalse(b.test(0, 1, new Ray().set(0.25, 0.25, 2, 0, 0, -1, 2 - 1e-12, 2 + 1e-12), null, s, simd) == false,
                    "an interval narrower than a float ulp still decides as in double");
            assertFalse(b.test(0, 1, new Ray().set(0.25, 0.25, 2, 0, 0, -1, 2 + 1e-12, 9), null, s, simd));
            assertFalse(b.test(0, 1, new Ray().set(0.75, 0.75, 2, 0, 0, -1, 0, 9), hit, s, simd), "outside the hypotenuse");
            Ray back = new Ray().set(0.25, 0.25, -2, 0, 0, 1, 0, 9);
            s.blockingPrimitive = -1;
            assertTrue(b.test(0, 1, back, null, s, simd), "from behind too");
            assertEquals(9.0, back.tMax, "any-hit leaves the ray alone");
            assertEquals(0, s.blockingPrimitive);
        }
    }

    @Test
    void agreesWithTheDoubleTestAwayFromEdges() {
        Random rnd = new Random(7);
        int compared = 0, hits = 0, nearEdge = 0;
        TraversalScratch s = new TraversalScratch();
        PrimitiveHit hd = new PrimitiveHit(), hf = new PrimitiveHit();
        for (int mesh = 0; mesh < 20; mesh++) {
            Mesh m = soup(rnd, 64);
            int[][] lv = leaves(m, rnd);
            int[] perm = lv[0], bounds = lv[1];
            TriangleBlocks b = new TriangleBlocks(m.tri(), m.pos(), perm, bounds);
            for (int r = 0; r < 500; r++) {
                double[] ray = rayAtSoup(rnd, m);
                for (int l = 0; l + 1 < bounds.length; l++) {
                    Ray rd = new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY);
                    Ray rf = new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY);
                    boolean d = WatertightTriangles.test(m.tri(), m.pos(), perm, bounds[l], bounds[l + 1], rd, hd, s);
                    boolean f = b.intersect(b.blockStart(l), b.blockEnd(l), rf, hf, s);
                    boolean fa = b.occluded(b.blockStart(l), b.blockEnd(l),
                            new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY), s);
                    assertEquals(f, fa, "any-hit and closest-hit find the same");
                    compared++;
                    // float coordinates err by ~1e-7 of the scene's size (1), so t by that over |d|
                    double len = Math.sqrt(ray[3] * ray[3] + ray[4] * ray[4] + ray[5] * ray[5]);
                    if (d && f && Math.abs(hd.t - hf.t) <= 1e-5 * (hd.t + 1 / len)) {
                        hits++;
                        if (hd.prim == hf.prim) {
                            assertEquals(hd.u, hf.u, 1e-3, "slivers magnify the corners' rounding");
                            assertEquals(hd.v, hf.v, 1e-3);
                        }
                        continue;
                    }
                    if (!d && !f) continue;
                    // two different triangles at nearly the same t: a grazing one (t's error
                    // grows as the ray turns parallel to it) in front of the other in float
                    if (d && f && grazing(m, hf, ray, s, len)) { nearEdge++; continue; }
                    // a disagreement: the nearer hit found must lie within float rounding of an edge
                    PrimitiveHit near = !f || (d && hd.t < hf.t) ? hd : hf;
                    double edge = Math.min(Math.min(near.u, near.v), 1 - near.u - near.v);
                    assertTrue(edge < 1e-5, "double " + d + " t " + hd.t + ", float " + f + " t " + hf.t + ": " + edge + " from an edge");
                    nearEdge++;
                }
            }
        }
        assertTrue(hits > 10000, hits + " hits of " + compared);
        assertTrue(nearEdge < compared / 1000, nearEdge + " near-edge or grazing disagreements of " + compared);
        System.out.println("TriangleBlocksTest: " + compared + " leaf tests, " + hits + " hits agreeing, " + nearEdge + " near-edge or grazing disagreements");
    }

    /**
     * Whether the float test's triangle, alone in the double test, is hit near the float's t
     * (within 1e-3 over |d|: t's error grows as a ray turns parallel to the triangle), so that
     * only the order of two near-tied triangles differs.
     */
    private static boolean grazing(Mesh m, PrimitiveHit hf, double[] ray, TraversalScratch s, double len) {
        PrimitiveHit h = new PrimitiveHit();
        Ray r = new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, Double.POSITIVE_INFINITY);
        return WatertightTriangles.test(m.tri(), m.pos(), new int[] {hf.prim}, 0, 1, r, h, s) && Math.abs(h.t - hf.t) <= 1e-3 / len;
    }

    /** A ray at a random point of a random triangle of the soup, or a random direction. */
    private static double[] rayAtSoup(Random rnd, Mesh m) {
        double ox = 3 * rnd.nextDouble() - 1, oy = 3 * rnd.nextDouble() - 1, oz = 3 * rnd.nextDouble() - 1;
        if (rnd.nextInt(4) == 0) return new double[] {ox, oy, oz, rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        int i = rnd.nextInt(m.count());
        double u = rnd.nextDouble(), v = rnd.nextDouble();
        if (u + v > 1) { u = 1 - u; v = 1 - v; }
        double[] p = new double[3];
        for (int a = 0; a < 3; a++) {
            p[a] = (1 - u - v) * m.pos()[3 * m.tri()[3 * i] + a] + u * m.pos()[3 * m.tri()[3 * i + 1] + a] + v * m.pos()[3 * m.tri()[3 * i + 2] + a];
        }
        return new double[] {ox, oy, oz, p[0] - ox, p[1] - oy, p[2] - oz};
    }

    @Test
    void noRayEscapesAClosedMesh() {
        for (boolean sphere : new boolean[] {false, true}) {
            Random rnd = new Random(sphere ? 11 : 12);
            Mesh m = cube(6, sphere);
            int[][] lv = leaves(m, rnd);
            TriangleBlocks b = new TriangleBlocks(m.tri(), m.pos(), lv[0], lv[1]);
            float[] corner = new float[3 * m.count() * 3];
            for (int k = 0; k < m.tri().length; k++) for (int a = 0; a < 3; a++) corner[3 * k + a] = (float) m.pos()[3 * m.tri()[k] + a];
            TraversalScratch s = new TraversalScratch();
            PrimitiveHit hit = new PrimitiveHit();
            int rays = 0;
            for (int r = 0; r < 6000; r++) {
                // origins: the centre (on the cube's symmetry planes), or random, as floats so the
                // aimed rays point exactly at the stored corners and edges
                double ox = 0, oy = 0, oz = 0;
                if (r % 3 != 0) { ox = (float) (rnd.nextDouble() - 0.5); oy = (float) (rnd.nextDouble() - 0.5); oz = (float) (rnd.nextDouble() - 0.5); }
                int k = rnd.nextInt(m.count());
                int c = rnd.nextInt(3), c2 = (c + 1) % 3;
                double w = switch (r % 4) { case 0 -> 0; case 1 -> 0.5; case 2 -> rnd.nextDouble(); default -> -1; };
                double dx, dy, dz;
                if (w < 0) { dx = rnd.nextGaussian(); dy = rnd.nextGaussian(); dz = rnd.nextGaussian(); }
                else {
                    // at a corner (w = 0) or a point on an edge of triangle k
                    int p = 9 * k + 3 * c, q = 9 * k + 3 * c2;
                    dx = (1 - w) * corner[p] + w * corner[q] - ox;
                    dy = (1 - w) * corner[p + 1] + w * corner[q + 1] - oy;
                    dz = (1 - w) * corner[p + 2] + w * corner[q + 2] - oz;
                }
                for (boolean simd : simdModes()) {
                    Ray ray = new Ray().set(ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
                    boolean found = false;
                    for (int l = 0; l < b.leafCount(); l++) found |= b.test(b.blockStart(l), b.blockEnd(l), ray, hit, s, simd);
                    assertTrue(found, "ray " + r + " from (" + ox + ", " + oy + ", " + oz + ") along (" + dx + ", " + dy + ", " + dz + ") escaped");
                    Ray shadow = new Ray().set(ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
                    boolean blocked = false;
                    for (int l = 0; l < b.leafCount() && !blocked; l++) blocked = b.test(b.blockStart(l), b.blockEnd(l), shadow, null, s, simd);
                    assertTrue(blocked, "shadow ray " + r + " escaped");
                    rays++;
                }
            }
            assertTrue(rays >= 6000);
        }
    }

    @Test
    void vectorAndScalarKernelsAgreeToTheBit() {
        Assumptions.assumeTrue(WideBvh.AVAILABLE, "no vector module here");
        Random rnd = new Random(3);
        TraversalScratch s = new TraversalScratch();
        PrimitiveHit a = new PrimitiveHit(), c = new PrimitiveHit();
        int hits = 0;
        for (int mesh = 0; mesh < 12; mesh++) {
            Mesh m = mesh % 3 == 0 ? cube(4, mesh % 2 == 0) : soup(rnd, 64);
            int[][] lv = leaves(m, rnd);
            TriangleBlocks b = new TriangleBlocks(m.tri(), m.pos(), lv[0], lv[1]);
            for (int r = 0; r < 400; r++) {
                double[] ray = mesh % 3 == 0 ? new double[] {0, 0, 0, rnd.nextInt(3) - 1, rnd.nextInt(3) - 1, rnd.nextInt(3) - 1} : rayAtSoup(rnd, m);
                if (ray[3] == 0 && ray[4] == 0 && ray[5] == 0) ray[5] = 1;
                for (int l = 0; l < b.leafCount(); l++) {
                    Ray rs = new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, 1e9);
                    Ray rv = new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, 1e9);
                    boolean hs = b.test(b.blockStart(l), b.blockEnd(l), rs, a, s, false);
                    boolean hv = b.test(b.blockStart(l), b.blockEnd(l), rv, c, s, true);
                    assertEquals(hs, hv);
                    assertEquals(Double.doubleToRawLongBits(rs.tMax), Double.doubleToRawLongBits(rv.tMax));
                    if (hs) {
                        hits++;
                        assertEquals(a.prim, c.prim);
                        assertEquals(Double.doubleToRawLongBits(a.t), Double.doubleToRawLongBits(c.t));
                        assertEquals(Double.doubleToRawLongBits(a.u), Double.doubleToRawLongBits(c.u));
                        assertEquals(Double.doubleToRawLongBits(a.v), Double.doubleToRawLongBits(c.v));
                    }
                    s.blockingPrimitive = -2;
                    boolean os = b.test(b.blockStart(l), b.blockEnd(l), new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, 1e9), null, s, false);
                    int ps = s.blockingPrimitive;
                    boolean ov = b.test(b.blockStart(l), b.blockEnd(l), new Ray().set(ray[0], ray[1], ray[2], ray[3], ray[4], ray[5], 0, 1e9), null, s, true);
                    assertEquals(os, ov);
                    if (os) assertEquals(ps, s.blockingPrimitive);
                }
            }
        }
        assertTrue(hits > 1000, hits + " hits");
    }

    @Test
    void allocatesNothingPerRay() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        Random rnd = new Random(5);
        Mesh m = soup(rnd, 256);
        int[][] lv = leaves(m, rnd);
        TriangleBlocks b = new TriangleBlocks(m.tri(), m.pos(), lv[0], lv[1]);
        double[][] rays = new double[1000][];
        for (int k = 0; k < rays.length; k++) rays[k] = rayAtSoup(rnd, m);
        Ray ray = new Ray();
        PrimitiveHit hit = new PrimitiveHit();
        TraversalScratch s = new TraversalScratch();
        long tid = Thread.currentThread().getId();
        int sink = 0;
        for (int i = 0; i < 30; i++) sink += run(b, rays, ray, hit, s);  // warm up: the vector kernel is boxed until C2 compiles it
        long before = mx.getThreadAllocatedBytes(tid);
        for (int i = 0; i < 5; i++) sink += run(b, rays, ray, hit, s);
        long used = mx.getThreadAllocatedBytes(tid) - before;
        // 5000 rays through every leaf: even one small object per ray would be 80 KB
        assertTrue(used < 16 * 1024, "allocated " + used + " bytes (sink " + sink + ")");
    }

    private static int run(TriangleBlocks b, double[][] rays, Ray ray, PrimitiveHit hit, TraversalScratch s) {
        int n = 0;
        for (double[] r : rays) {
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5], 0, Double.POSITIVE_INFINITY);
            for (int l = 0; l < b.leafCount(); l++) if (b.intersect(b.blockStart(l), b.blockEnd(l), ray, hit, s)) n++;
            ray.set(r[0], r[1], r[2], r[3], r[4], r[5], 0, Double.POSITIVE_INFINITY);
            for (int l = 0; l < b.leafCount(); l++) if (b.occluded(b.blockStart(l), b.blockEnd(l), ray, s)) { n++; break; }
        }
        return n;
    }

    private static boolean[] simdModes() {
        return WideBvh.AVAILABLE ? new boolean[] {false, true} : new boolean[] {false};
    }
}
