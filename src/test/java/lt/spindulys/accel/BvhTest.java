package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.scene.GObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.scene.TriangleMesh;

class BvhTest {

    /** Random triangles: a centre in the unit cube, corners spread by a size drawn log-uniformly from [lo, hi]. */
    static double[] soup(Random r, int n, double lo, double hi) {
        double[] c = new double[9 * n];
        for (int i = 0; i < n; i++) {
            double size = lo * Math.pow(hi / lo, r.nextDouble());
            double x = r.nextDouble(), y = r.nextDouble(), z = r.nextDouble();
            for (int k = 0; k < 3; k++) {
                c[9 * i + 3 * k] = x + size * r.nextGaussian();
                c[9 * i + 3 * k + 1] = y + size * r.nextGaussian();
                c[9 * i + 3 * k + 2] = z + size * r.nextGaussian();
            }
        }
        return c;
    }

    static double[] concat(double[]... parts) {
        int n = 0;
        for (double[] p : parts) n += p.length;
        double[] out = new double[n];
        int o = 0;
        for (double[] p : parts) {
            System.arraycopy(p, 0, out, o, p.length);
            o += p.length;
        }
        return out;
    }

    /**
     * Shoots seeded random rays (general, axis-parallel, aimed at a primitive's vertex, with and
     * without finite tMin/tMax) and requires the structure to agree with brute force.
     */
    static void compare(PrimitiveSet set, Accelerator bvh, Bounds region, int rays, long seed) {
        BruteForce brute = new BruteForce(set);
        TraceContext ctx = new TraceContext();
        Random r = new Random(seed);
        Ray ray = new Ray();
        double[] box = new double[6];
        int hits = 0;
        for (int i = 0; i < rays; i++) {
            double ox = region.minX() + r.nextDouble() * (region.maxX() - region.minX());
            double oy = region.minY() + r.nextDouble() * (region.maxY() - region.minY());
            double oz = region.minZ() + r.nextDouble() * (region.maxZ() - region.minZ());
            double dx = r.nextGaussian(), dy = r.nextGaussian(), dz = r.nextGaussian();
            switch (i % 4) {
                case 1 -> { // axis-parallel: infinite inverse components
                    int keep = r.nextInt(3);
                    if (keep != 0) dx = 0;
                    if (keep != 1) dy = 0;
                    if (keep != 2) dz = 0;
                }
                case 2 -> { // aimed at a corner of a primitive's box
                    set.bounds(r.nextInt(set.size()), box);
                    int c = r.nextInt(8);
                    dx = box[(c & 1) == 0 ? 0 : 3] - ox;
                    dy = box[(c & 2) == 0 ? 1 : 4] - oy;
                    dz = box[(c & 4) == 0 ? 2 : 5] - oz;
                }
                default -> { }
            }
            double tMin = r.nextInt(3) == 0 ? r.nextDouble() * 0.5 : 0;
            double tMax = r.nextInt(3) == 0 ? tMin + r.nextDouble() * 2 : Double.POSITIVE_INFINITY;
            ray.set(ox, oy, oz, dx, dy, dz, tMin, tMax);
            final int n = i;
            if (agree(set, brute, bvh, ray, ctx, () -> "ray " + n + " " + ray)) hits++;
        }
        assertTrue(hits > rays / 50, "the rays should find something: " + hits);
    }

    /**
     * Requires {@code acc} to give brute force's answers for one ray: the same hit or miss, the
     * same nearest t (to 1e-12 relative), the same primitive unless the two tie, the same
     * occluded answer, and ray and stack left as they were. Returns whether the ray hit.
     */
    static boolean agree(PrimitiveSet set, BruteForce brute, Accelerator acc, Ray ray, TraceContext ctx, Supplier<String> what) {
        Hit hf = new Hit(), hb = new Hit();
        double tMax = ray.tMax;
        boolean f = brute.intersect(ray, hf.reset(tMax), ctx);
        boolean b = acc.intersect(ray, hb.reset(tMax), ctx);
        assertEquals(tMax, ray.tMax, "tMax restored");
        assertEquals(0, ctx.stackTop, "stack top restored");
        assertEquals(f, b, what);
        if (f) {
            assertEquals(hf.t, hb.t, 1e-12 * Math.abs(hf.t), what);
            if (hf.prim != hb.prim) {
                // A tie: the structure's primitive must itself be hit at (nearly) the same distance.
                Hit check = new Hit();
                assertTrue(set.intersect(hb.prim, ray, check.reset(tMax), ctx), what);
                assertEquals(hb.t, check.t, what);
            }
        }
        assertEquals(brute.occluded(ray, ctx), acc.occluded(ray, ctx), () -> "occluded, " + what.get());
        return f;
    }

    private static void compareMesh(double[] coords, int rays, long seed) {
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(coords));
        Bvh bvh = new Bvh(m);
        assertEquals(m.triangleCount(), bvh.primitiveCount());
        compare(m, bvh, around(m), rays, seed);
    }

    /** The mesh's bounds widened by a quarter of their largest side on every side: rays start inside and outside. */
    static Bounds around(TriangleMesh m) {
        Bounds b = m.localBounds();
        double ex = b.maxX() - b.minX(), ey = b.maxY() - b.minY(), ez = b.maxZ() - b.minZ();
        double pad = 0.25 * Math.max(ex, Math.max(ey, ez));
        return new Bounds(b.minX() - pad, b.minY() - pad, b.minZ() - pad, b.maxX() + pad, b.maxY() + pad, b.maxZ() + pad);
    }

    @Test
    void agreesWithBruteForceOnARandomSoup() {
        compareMesh(soup(new Random(1), 300, 0.005, 0.2), 100_000, 2);
    }

    @Test
    void agreesWithBruteForceWhenEverythingLiesInOnePlane() {
        double[] c = soup(new Random(3), 500, 0.01, 0.15);
        for (int i = 2; i < c.length; i += 3) c[i] = 0.5;
        compareMesh(c, 25_000, 4);
    }

    @Test
    void agreesWithBruteForceOnIdenticalTriangles() {
        double[] one = {0.2, 0.2, 0.3, 0.8, 0.3, 0.5, 0.4, 0.9, 0.7};
        double[][] parts = new double[301][];
        for (int i = 0; i < 300; i++) parts[i] = one;
        parts[300] = soup(new Random(5), 100, 0.01, 0.1);
        compareMesh(concat(parts), 25_000, 6);
    }

    @Test
    void agreesWithBruteForceOnTinyAndHugeTriangles() {
        Random r = new Random(7);
        double[] tiny = soup(r, 300, 1e-7, 1e-5);
        double[] huge = soup(r, 10, 10, 1000);
        double[] medium = soup(r, 100, 0.01, 0.1);
        compareMesh(concat(tiny, huge, medium), 25_000, 8);
    }

    @Test
    void agreesWithBruteForceOnAClosedGridMesh() {
        // Axis-aligned faces: flat node boxes, rays aimed at shared edges and corners.
        TriangleMesh m = new TriangleMesh(TestMeshes.gridCube(6));
        compare(m, new Bvh(m), new Bounds(-2, -2, -2, 2, 2, 2), 25_000, 9);
    }

    /** Spheres, to show the hierarchy works over any primitive set. */
    record Spheres(double[] c) implements PrimitiveSet {
        @Override public int size() { return c.length / 4; }

        @Override public void bounds(int i, double[] out) {
            for (int k = 0; k < 3; k++) {
                out[k] = c[4 * i + k] - c[4 * i + 3];
                out[k + 3] = c[4 * i + k] + c[4 * i + 3];
            }
        }

        @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
            double px = ray.ox - c[4 * i], py = ray.oy - c[4 * i + 1], pz = ray.oz - c[4 * i + 2];
            double a = ray.dx * ray.dx + ray.dy * ray.dy + ray.dz * ray.dz;
            double b = px * ray.dx + py * ray.dy + pz * ray.dz;
            double cc = px * px + py * py + pz * pz - c[4 * i + 3] * c[4 * i + 3];
            double disc = b * b - a * cc;
            if (disc < 0) return false;
            double s = Math.sqrt(disc);
            double t = (-b - s) / a;
            if (!(t > ray.tMin)) t = (-b + s) / a;
            if (!(t > ray.tMin && t < ray.tMax)) return false;
            hit.t = t;
            hit.prim = i;
            return true;
        }
    }

    @Test
    void agreesWithBruteForceOverOtherPrimitives() {
        Random r = new Random(10);
        double[] c = new double[4 * 500];
        for (int i = 0; i < c.length; i++) c[i] = i % 4 == 3 ? 0.002 + 0.03 * r.nextDouble() : r.nextDouble();
        Spheres s = new Spheres(c);
        compare(s, new Bvh(s), new Bounds(-0.2, -0.2, -0.2, 1.2, 1.2, 1.2), 25_000, 11);
    }

    @Test
    void depthStaysBoundedOnAdversarialInput() {
        // Exponentially spaced triangles: SAH would peel them off one by one, 2000 levels deep.
        int n = 2000;
        double[] c = new double[9 * n];
        for (int i = 0; i < n; i++) {
            double x = Math.pow(1.01, i);
            double[] t = {x, 0, 0, x * 1.001, 1, 0, x, 0, 1};
            System.arraycopy(t, 0, c, 9 * i, 9);
        }
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(c));
        Bvh bvh = new Bvh(m);
        assertTrue(bvh.depth() <= 48 + 11, "depth " + bvh.depth());
        compare(m, bvh, new Bounds(0, -1, -1, Math.pow(1.01, n), 2, 2), 5_000, 12);
    }

    @Test
    void everyPrimitiveIsReachableAndEmptyOnesAreLeftOut() {
        Random r = new Random(13);
        double[] c = new double[4 * 3000];
        for (int i = 0; i < c.length; i++) c[i] = i % 4 == 3 ? (i % 40 == 3 ? -1 : 0.01) : r.nextDouble();
        Spheres s = new Spheres(c); // every tenth has a negative radius: empty bounds
        Bvh bvh = new Bvh(s);
        assertEquals(2700, bvh.primitiveCount());
        int[] seen = new int[s.size()];
        Ray all = new Ray().set(0.5, 0.5, 0.5, 1, 0, 0, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
        // A line through the middle with infinite limits visits only the leaves it passes; the root
        // box of everything at once is checked by visiting along each primitive's own centre.
        for (int i = 0; i < s.size(); i++) {
            if (c[4 * i + 3] < 0) continue;
            all.set(c[4 * i], c[4 * i + 1], c[4 * i + 2], 1, 0, 0, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
            final int want = i;
            boolean[] found = {false};
            bvh.visit(all, new TraceContext(), (prim, ray, ctx) -> {
                seen[prim]++;
                if (prim == want) found[0] = true;
            });
            assertTrue(found[0], "primitive " + i + " is reachable");
        }
        for (int i = 0; i < s.size(); i++) if (c[4 * i + 3] < 0) assertEquals(0, seen[i], "empty primitive " + i);
        Bvh empty = new Bvh(new Spheres(new double[0]));
        assertEquals(0, empty.nodeCount());
        assertFalse(empty.intersect(all, new Hit().reset(1), new TraceContext()));
        assertFalse(empty.occluded(all, new TraceContext()));
    }

    @Test
    void nestedHierarchiesInASceneAgreeWithTestingEveryObject() {
        // A scene BVH over meshes that have BVHs of their own shares one per-thread stack.
        Random r = new Random(14);
        SceneBuilder b = new SceneBuilder();
        MeshData sphere = TestMeshes.icosphere(2, 1);
        for (int i = 0; i < 40; i++) {
            TriangleMesh m = new TriangleMesh(sphere);
            double s = 0.2 + r.nextDouble();
            m.transform(Transform.scale(s, s * (0.5 + r.nextDouble()), s).then(Transform.translate(r.nextDouble() * 10, r.nextDouble() * 10, r.nextDouble() * 10)));
            b.add(m);
        }
        Scene scene = b.build();
        List<GObject> objects = new ArrayList<>(scene.objects());
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit hs = new Hit(), hb = new Hit();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            ray.set(r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2, r.nextGaussian(), r.nextGaussian(), r.nextGaussian(), 0, Double.POSITIVE_INFINITY);
            boolean s = scene.intersect(ray, hs, ctx);
            hb.reset(ray.tMax);
            boolean any = false;
            for (GObject o : objects) {
                if (o.intersect(ray, hb, ctx)) {
                    any = true;
                    ray.tMax = hb.t;
                }
            }
            ray.tMax = Double.POSITIVE_INFINITY;
            assertEquals(any, s);
            if (any) {
                hits++;
                assertEquals(hb.t, hs.t, 1e-12 * hb.t);
                assertEquals(hb.object, hs.object);
                assertEquals(hb.prim, hs.prim);
            }
            assertEquals(any, scene.occluded(ray, ctx));
            assertEquals(0, ctx.stackTop);
        }
        assertTrue(hits > 1000, "hits " + hits);
    }

    @Test
    void buildsLargeSetsIteratively() {
        // 100,000 triangles through the iterative build (no recursion to overflow).
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(soup(new Random(15), 100_000, 1e-4, 1e-2)));
        Bvh bvh = new Bvh(m);
        assertEquals(100_000, bvh.primitiveCount());
        assertTrue(bvh.depth() < 64, "depth " + bvh.depth());
        assertEquals(new Bounds(m.localBounds().minX(), m.localBounds().minY(), m.localBounds().minZ(),
                m.localBounds().maxX(), m.localBounds().maxY(), m.localBounds().maxZ()), bvh.bounds());
        compare(m, bvh, new Bounds(-0.1, -0.1, -0.1, 1.1, 1.1, 1.1), 100, 16);
    }

    /** Seeded random spheres: centres in the unit cube, radii log-uniform in [0.0005, 0.02]. */
    static Spheres randomSpheres(long seed, int n) {
        Random r = new Random(seed);
        double[] c = new double[4 * n];
        for (int i = 0; i < n; i++) {
            c[4 * i] = r.nextDouble(); c[4 * i + 1] = r.nextDouble(); c[4 * i + 2] = r.nextDouble();
            c[4 * i + 3] = 0.0005 * Math.pow(40, r.nextDouble());
        }
        return new Spheres(c);
    }

    @Test
    void sahCostIsTheNodesAreasOverTheRoots() {
        // Two unit boxes one apart on x, one per leaf: root half-area 3 + 1 + 3 = 7, leaves 3 each.
        Bvh bvh = new Bvh(new Spheres(new double[] {0.5, 0.5, 0.5, 0.5, 2.5, 0.5, 0.5, 0.5}), 1);
        assertEquals(3, bvh.nodeCount());
        assertEquals(13.0 / 7, bvh.sahCost(), 1e-12);
        // Four in one leaf: the root alone, cost 4 primitive tests.
        assertEquals(4, new Bvh(new Spheres(new double[] {0, 0, 0, 1, 1, 0, 0, 1, 2, 0, 0, 1, 3, 0, 0, 1})).sahCost(), 1e-12);
        assertEquals(0, new Bvh(new Spheres(new double[0])).sahCost());
    }

    @Test
    void parallelAndSerialBuildsMakeTheSameTree() {
        // Large enough for several levels of fork/join tasks above the serial chunks.
        Spheres set = randomSpheres(31, 60_000);
        Bvh parallel = new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, true), serial = new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, false);
        assertTrue(java.util.Arrays.equals(parallel.nodes(), serial.nodes()));
        assertTrue(java.util.Arrays.equals(parallel.perm(), serial.perm()));
        assertEquals(parallel.sahCost(), serial.sahCost());
    }

    @Test
    void theTreeIsTheSameForAnyThreadCountAndTheOneTheEarlierBuildMade() {
        // Large enough for the root's binning to be split into blocks across the pool.
        Spheres set = randomSpheres(53, 300_000);
        Bvh one = new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, 1);
        for (int threads : new int[] {2, 3}) {
            Bvh many = new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, threads);
            assertTrue(java.util.Arrays.equals(one.nodes(), many.nodes()), threads + " threads");
            assertTrue(java.util.Arrays.equals(one.perm(), many.perm()), threads + " threads");
        }
        // Checksums of the node records and the permutation the build before issue 18's
        // parallel top levels made for this set: the faster build makes the very same tree.
        assertEquals(201_599, one.nodeCount());
        assertEquals(0xc428d3a8L, crc(one.nodes()));
        assertEquals(0xe862317bL, crc(one.perm()));
        // With empty primitives among them (left out, the rest closing up): the same on the pool too.
        double[] c = randomSpheres(59, 100_000).c().clone();
        for (int i = 0; i < 100_000; i += 7) c[4 * i + 3] = -1;
        Bvh gaps1 = new Bvh(new Spheres(c), Bvh.DEFAULT_LEAF_SIZE, 1), gaps2 = new Bvh(new Spheres(c), Bvh.DEFAULT_LEAF_SIZE, 2);
        assertEquals(100_000 - 14_286, gaps1.primitiveCount());
        assertTrue(java.util.Arrays.equals(gaps1.nodes(), gaps2.nodes()));
        assertTrue(java.util.Arrays.equals(gaps1.perm(), gaps2.perm()));
        assertEquals(gaps1.bounds(), gaps2.bounds());
    }

    @Test
    void aMeshIsRenumberedTheSameWithAnyThreadCount() {
        // Enough triangles and vertices for the renumbering's copies to be split across the pool.
        MeshData d = TestMeshes.icosphere(7, 1);
        TriangleMesh one = new TriangleMesh(d), two = new TriangleMesh(d);
        assertNull(new Bvh(one, Bvh.DEFAULT_LEAF_SIZE, 1).perm());
        assertNull(new Bvh(two, Bvh.DEFAULT_LEAF_SIZE, 2).perm());
        assertTrue(one.triangleCount() > 300_000);
        for (int t = 0; t < one.triangleCount(); t++) {
            for (int c = 0; c < 3; c++) assertEquals(one.triangleVertex(t, c), two.triangleVertex(t, c));
        }
        assertTrue(java.util.Arrays.equals(one.data().positions(), two.data().positions()));
        assertTrue(java.util.Arrays.equals(one.data().uvIndex(), two.data().uvIndex()));
    }

    @Test
    void nonFiniteBoundsAreReportedAsBeforeWhateverTheThreadCount() {
        // Large enough for the bounds to be read on the pool: the message must not come wrapped.
        double[] c = new double[4 * 20_000];
        for (int i = 0; i < 20_000; i++) { c[4 * i] = i; c[4 * i + 3] = 0.5; }
        c[4 * 15_000 + 1] = Double.NaN;
        c[4 * 17_000 + 2] = Double.POSITIVE_INFINITY;
        for (int threads : new int[] {1, 2}) {
            IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                    () -> new Bvh(new Spheres(c), Bvh.DEFAULT_LEAF_SIZE, threads));
            assertEquals("primitive 15000 has non-finite bounds [14999.5, NaN, -0.5, 15000.5, NaN, 0.5]", e.getMessage());
        }
    }

    /** CRC-32 of the ints' little-endian bytes. */
    static long crc(int[] a) {
        java.util.zip.CRC32 c = new java.util.zip.CRC32();
        for (int v : a) { c.update(v); c.update(v >> 8); c.update(v >> 16); c.update(v >> 24); }
        return c.getValue();
    }

    @Test
    void treeQualityIsKept() {
        // The SAH cost the build before issue 18's speed-up gave for this set (the same tree):
        // a faster build must not give a worse tree.
        Bvh bvh = new Bvh(randomSpheres(47, 50_000));
        assertTrue(bvh.sahCost() <= OLD_SAH_COST * (1 + 1e-12), () -> "SAH cost " + bvh.sahCost() + " > " + OLD_SAH_COST);
        assertTrue(bvh.sahCost() > 0.5 * OLD_SAH_COST, () -> "SAH cost " + bvh.sahCost() + " implausibly low");
    }

    private static final double OLD_SAH_COST = 147.92586296036683;
}
