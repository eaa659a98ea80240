package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;
import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.scene.TriangleMesh;

/**
 * The eight-wide vector BVH: that the test JVM really runs it (so the parameterised agreement and
 * watertightness tests over {@link AcceleratorKind#BVH} exercise it), the inputs where its float
 * ray setup could lose a hit, its {@code visit}, and the collapse itself.
 */
class WideBvhTest {

    @Test
    void theTestJvmHasTheVectorModuleAndBvhBuildsTheWideTree() {
        // The build passes --add-modules jdk.incubator.vector to the tests, as ./render does.
        assertTrue(ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent(), "surefire argLine lost --add-modules");
        assumeTrue(WideBvh.AVAILABLE, "this machine has no 256-bit vectors");
        TriangleMesh m = new TriangleMesh(TestMeshes.icosphere(3, 1));
        assertInstanceOf(WideBvh.class, WideBvh.widen(new Bvh(m)));
    }

    /** A random soup in the unit cube, scaled by {@code scale} and moved by (x, y, z). */
    private static TriangleMesh soupMesh(long seed, int n, double scale, double x, double y, double z) {
        double[] c = BvhTest.soup(new Random(seed), n, 0.002, 0.1);
        for (int i = 0; i < c.length; i += 3) {
            c[i] = c[i] * scale + x;
            c[i + 1] = c[i + 1] * scale + y;
            c[i + 2] = c[i + 2] * scale + z;
        }
        return new TriangleMesh(TestMeshes.soup(c));
    }

    private static WideBvh wide(TriangleMesh m) {
        assumeTrue(WideBvh.AVAILABLE, "this machine has no 256-bit vectors");
        return new WideBvh(new Bvh(m));
    }

    @Test
    void agreesWithBruteForceFarFromTheOrigin() {
        // Small triangles around (1e5, -3e4, 7e5): the float ray origin is off by up to 1/32,
        // far more than the triangles' gaps, so only the slack added to it keeps their boxes hit.
        TriangleMesh m = soupMesh(301, 400, 1, 1e5, -3e4, 7e5);
        BvhTest.compare(m, wide(m), BvhTest.around(m), 100_000, 302);
    }

    @Test
    void theByteGridHoldsEveryPlaneOfItsRange() {
        // Ranges of 0 to 600 ulps just below powers of two (where the ulp doubles), both signs,
        // magnitudes 1e-12 to 1e12: the planes at lo, at hi and between round outward on the grid.
        Random r = new Random(351);
        for (int i = 0; i < 200_000; i++) {
            float lo = (float) Math.scalb(r.nextBoolean() ? 1.0 : -1.0, r.nextInt(80) - 40);
            for (int k = r.nextInt(300); k > 0; k--) lo = Math.nextDown(lo);
            float hi = lo;
            for (int k = r.nextInt(3) == 0 ? r.nextInt(4) : r.nextInt(600); k > 0; k--) hi = Math.nextUp(hi);
            float step = WideBvh.gridStep(lo, hi), base = WideBvh.gridBase(lo, step);
            float mid = lo + (hi - lo) * r.nextFloat();
            for (float v : new float[] {lo, hi, Math.max(lo, Math.min(hi, mid))}) {
                String what = "v " + v + " in [" + lo + ", " + hi + "]";
                assertTrue(WideBvh.decode(WideBvh.gridDown(v, base, step), base, step) <= v, what);
                assertTrue(WideBvh.decode(WideBvh.gridUp(v, base, step), base, step) >= v, what);
            }
        }
    }

    @Test
    void agreesWithBruteForceForNodesOnlyAFewUlpsWide() {
        // A cluster 0.01 wide at 1e5, where floats are 0.0078 apart: node boxes one or two ulps
        // wide on an axis, finer than any grid of 254 steps can be laid in float over them.
        TriangleMesh m = soupMesh(341, 300, 0.01, 1e5, 1e5, 1e5);
        BvhTest.compare(m, wide(m), BvhTest.around(m), 20_000, 342);
    }

    @Test
    void agreesWithBruteForceOnATinyMeshAndOnSlabPlanes() {
        // Coordinates of 1e-6 and faces exactly on box planes, hit by axis-parallel rays.
        TriangleMesh tiny = soupMesh(311, 300, 1e-6, 0, 0, 0);
        BvhTest.compare(tiny, wide(tiny), BvhTest.around(tiny), 50_000, 312);
        TriangleMesh grid = new TriangleMesh(TestMeshes.gridCube(6));
        WideBvh w = wide(grid);
        TraceContext ctx = new TraceContext();
        BruteForce brute = new BruteForce(grid);
        Ray ray = new Ray();
        int hits = 0;
        // Rays along each axis from points on the grid's planes (multiples of 1/3 of the side).
        for (int i = -9; i <= 9; i++) {
            for (int j = -9; j <= 9; j++) {
                double a = i / 3.0, b = j / 3.0;
                for (int axis = 0; axis < 3; axis++) {
                    for (int sign = -1; sign <= 1; sign += 2) {
                        double[] o = new double[3];
                        o[axis] = -3.0 * sign;
                        o[(axis + 1) % 3] = a;
                        o[(axis + 2) % 3] = b;
                        double[] d = {0, 0, 0};
                        d[axis] = sign;
                        ray.set(o[0], o[1], o[2], d[0], d[1], d[2], 0, Double.POSITIVE_INFINITY);
                        String what = "ray from " + java.util.Arrays.toString(o) + " along " + java.util.Arrays.toString(d);
                        if (BvhTest.agree(grid, brute, w, ray, ctx, () -> what)) hits++;
                    }
                }
            }
        }
        assertTrue(hits > 100, "axis rays should hit the grid cube: " + hits);
    }

    @Test
    void nodesWhoseBoxIsOnePointStillEnd() {
        assumeTrue(WideBvh.AVAILABLE, "this machine has no 256-bit vectors");
        // Primitives bounded by one point: every node's grid has zero steps on all three axes,
        // where even the empty lanes decode to that point and are entered (as empty leaves).
        PrimitiveSet points = new PrimitiveSet() {
            @Override public int size() { return 300; }
            @Override public void bounds(int i, double[] out) {
                java.util.Arrays.fill(out, 0, 6, 0.5);
            }
            @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) { return false; }
        };
        Bvh binary = new Bvh(points);
        assertTrue(WideBvh.canCollapse(binary), "a tree with inner nodes: " + binary.nodeCount());
        WideBvh w = new WideBvh(binary);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Random r = new Random(331);
        for (int i = 0; i < 1000; i++) {
            double dx = r.nextGaussian(), dy = r.nextGaussian(), dz = r.nextGaussian();
            ray.set(0.5 - dx, 0.5 - dy, 0.5 - dz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
            assertFalse(w.intersect(ray, new lt.spindulys.trace.Hit().reset(ray.tMax), ctx));
            assertFalse(w.occluded(ray, ctx));
            int[] seen = new int[points.size()];
            w.visit(ray, ctx, (prim, rr, cc) -> seen[prim]++);
            for (int k = 0; k < seen.length; k++) assertEquals(1, seen[k], "a line through the point passes primitive " + k + " once");
        }
    }

    @Test
    void visitOffersEveryPrimitiveTheLineCrosses() {
        TriangleMesh m = soupMesh(321, 500, 1, 0, 0, 0);
        WideBvh w = wide(m);
        TraceContext ctx = new TraceContext();
        Random r = new Random(322);
        Ray line = new Ray();
        lt.spindulys.trace.Hit h = new lt.spindulys.trace.Hit();
        int crossed = 0;
        for (int i = 0; i < 2000; i++) {
            line.set(r.nextDouble(), r.nextDouble(), r.nextDouble(), r.nextGaussian(), r.nextGaussian(), r.nextGaussian(),
                    Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
            boolean[] offered = new boolean[m.size()];
            w.visit(line, ctx, (prim, ray, c) -> offered[prim] = true);
            assertEquals(0, ctx.stackTop);
            for (int p = 0; p < m.size(); p++) {
                // Whatever the line crosses, on either side of its origin, must have been offered.
                Ray whole = new Ray().set(line.ox, line.oy, line.oz, line.dx, line.dy, line.dz, -1e9, 1e9);
                if (m.intersect(p, whole, h.reset(whole.tMax), ctx)) {
                    crossed++;
                    final int prim = p, n = i;
                    assertTrue(offered[p], () -> "line " + n + " crosses primitive " + prim + " but it was not offered");
                }
            }
        }
        assertTrue(crossed > 500, "lines should cross triangles: " + crossed);
    }

    @Test
    void collapseKeepsEveryLeafOnceInEightWideNodes() {
        TriangleMesh m = new TriangleMesh(TestMeshes.icosphere(4, 1));
        Bvh binary = new Bvh(m);
        WideBvh w = wide(m);
        int[] slots = w.leafSlotCounts(binary.primitiveCount());
        for (int k = 0; k < slots.length; k++) assertEquals(1, slots[k], "slot " + k);
        // Each wide node replaces at least one binary inner node; a tree of n leaves has n - 1.
        int binaryLeaves = (binary.nodeCount() + 1) / 2;
        assertTrue(w.nodeCount() <= binaryLeaves - 1, w.nodeCount() + " wide nodes");
        assertTrue(w.nodeCount() >= (binaryLeaves - 1) / 7, w.nodeCount() + " wide nodes");
    }

    @Test
    void theCollapseMakesTheNodesItMadeBefore() {
        // A checksum of the wide nodes the collapse made at the start of issue 18's second pass,
        // over a tree the build (on any thread count) makes the same: a change to the collapse
        // that changes the nodes must be deliberate.
        Bvh binary = new Bvh(BvhTest.randomSpheres(53, 300_000), Bvh.DEFAULT_LEAF_SIZE, 2);
        WideBvh one = new WideBvh(binary);
        java.util.zip.CRC32 c = new java.util.zip.CRC32();
        c.update(one.planes());
        for (float v : one.frames()) {
            int x = Float.floatToRawIntBits(v);
            c.update(x); c.update(x >> 8); c.update(x >> 16); c.update(x >> 24);
        }
        for (int x : one.links()) { c.update(x); c.update(x >> 8); c.update(x >> 16); c.update(x >> 24); }
        assertEquals(32_667, one.nodeCount());
        assertEquals(0x88d61cd0L, c.getValue());
    }
}
