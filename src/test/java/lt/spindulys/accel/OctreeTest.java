package lt.spindulys.accel;

import static lt.spindulys.accel.BvhTest.agree;
import static lt.spindulys.accel.BvhTest.concat;
import static lt.spindulys.accel.BvhTest.soup;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.Hit;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.scene.TriangleMesh;

/** What is particular to the octree: rays on its cell planes, bounded memory, reachability. */
class OctreeTest {

    /** A plane of the cell grid at {@code level}: computed like the octree computes it. */
    private static double plane(double min, double side, int index, int level) {
        return min + index * Math.scalb(side, -level);
    }

    /**
     * Rays that start exactly on cell planes, edges and corners, run inside a plane or along an
     * edge (zero direction components), or pass exactly through a cell corner.
     */
    private static void boundaryRays(TriangleMesh m, int rays, long seed) {
        Octree oct = new Octree(m);
        BruteForce brute = new BruteForce(m);
        Bounds root = oct.rootCell();
        double side = root.maxX() - root.minX();
        double[] min = {root.minX(), root.minY(), root.minZ()};
        Random r = new Random(seed);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        double[] o = new double[3], d = new double[3];
        int hits = 0;
        for (int i = 0; i < rays; i++) {
            int level = 1 + r.nextInt(5), cells = 1 << level;
            for (int k = 0; k < 3; k++) {
                o[k] = min[k] + (r.nextDouble() * 1.2 - 0.1) * side;
                d[k] = r.nextGaussian();
            }
            // Snap one, two or three coordinates onto planes; a snapped axis without motion keeps
            // the ray inside that plane.
            int snapped = 1 + r.nextInt(3);
            for (int k = 0; k < snapped; k++) {
                int axis = (i + k) % 3;
                o[axis] = plane(min[axis], side, r.nextInt(cells + 1), level);
                if (i % 3 != 0) d[axis] = 0;
            }
            if (i % 3 == 0) {
                // Through a grid vertex instead: aim at one.
                for (int k = 0; k < 3; k++) d[k] = plane(min[k], side, r.nextInt(cells + 1), level) - o[k];
            }
            if (d[0] == 0 && d[1] == 0 && d[2] == 0) d[i % 3] = 1;
            ray.set(o[0], o[1], o[2], d[0], d[1], d[2], 0, Double.POSITIVE_INFINITY);
            final int n = i;
            if (agree(m, brute, oct, ray, ctx, () -> "ray " + n + " " + ray)) hits++;
        }
        assertTrue(hits > rays / 50, "hits " + hits);
    }

    @Test
    void raysOnCellPlanesAgreeWithBruteForce() {
        boundaryRays(new TriangleMesh(TestMeshes.soup(soup(new Random(1), 400, 0.005, 0.1))), 30_000, 2);
    }

    @Test
    void raysOnCellPlanesThroughFacesOnCellPlanesAgreeWithBruteForce() {
        // The grid's faces lie on cell planes too: rays run inside faces and along shared edges.
        boundaryRays(new TriangleMesh(TestMeshes.gridCube(4)), 30_000, 3);
    }

    @Test
    void raysOnCellPlanesInAFlatSceneAgreeWithBruteForce() {
        double[] c = soup(new Random(4), 400, 0.01, 0.1);
        for (int i = 2; i < c.length; i += 3) c[i] = 0.25;
        boundaryRays(new TriangleMesh(TestMeshes.soup(c)), 30_000, 5);
    }

    /** The memory bounds, whatever the input. */
    private static Octree bounded(double[] coords) {
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(coords));
        Octree oct = new Octree(m);
        int n = m.triangleCount();
        assertEquals(n, oct.primitiveCount());
        assertTrue(oct.depth() <= Octree.DEFAULT_MAX_DEPTH, "depth " + oct.depth());
        assertTrue(oct.referenceCount() <= (long) Octree.REFS_PER_PRIMITIVE * n + 8L * Octree.DEFAULT_LEAF_SIZE, "references " + oct.referenceCount() + " for " + n);
        assertTrue(oct.nodeCount() <= 2 * oct.referenceCount() + 1, "nodes " + oct.nodeCount());
        BvhTest.compare(m, oct, BvhTest.around(m), 300, 6);
        return oct;
    }

    @Test
    void memoryStaysBoundedOnDegenerateInput() {
        Random r = new Random(7);
        // Many identical large triangles: no split separates them, so none is made.
        double[] big = {0, 0, 0, 1, 0.1, 0.3, 0.2, 1, 1};
        double[][] parts = new double[5000][];
        java.util.Arrays.fill(parts, big);
        assertEquals(5000, bounded(concat(parts)).referenceCount());
        // Many identical tiny triangles: a chain down to the depth limit, one leaf at its end.
        double[] tiny = {0.5, 0.5, 0.5, 0.5 + 1e-9, 0.5, 0.5, 0.5, 0.5 + 1e-9, 0.5};
        java.util.Arrays.fill(parts, tiny);
        bounded(concat(concat(parts), big));
        // Everything in one plane, and one huge triangle among many tiny ones.
        double[] flat = soup(r, 20_000, 1e-4, 1e-2);
        for (int i = 1; i < flat.length; i += 3) flat[i] = 0.5;
        bounded(flat);
        bounded(concat(soup(r, 20_000, 1e-6, 1e-4), soup(r, 1, 100, 100)));
        // Large triangles crossing each other through one point: each overlaps every cell.
        double[] fan = new double[9 * 3000];
        for (int i = 0; i < 3000; i++) {
            double a = Math.PI * i / 3000;
            double[] t = {Math.cos(a), Math.sin(a), -1, -Math.cos(a), -Math.sin(a), -1, 0, 0, 1};
            System.arraycopy(t, 0, fan, 9 * i, 9);
        }
        bounded(fan);
    }

    @Test
    void everyPrimitiveIsReachableAndEmptyOnesAreLeftOut() {
        Random r = new Random(8);
        double[] c = new double[4 * 3000];
        for (int i = 0; i < c.length; i++) c[i] = i % 4 == 3 ? (i % 40 == 3 ? -1 : 0.01) : r.nextDouble();
        BvhTest.Spheres s = new BvhTest.Spheres(c); // every tenth has a negative radius: empty bounds
        Octree oct = new Octree(s);
        assertEquals(2700, oct.primitiveCount());
        int[] seen = new int[s.size()];
        Ray line = new Ray();
        for (int i = 0; i < s.size(); i++) {
            if (c[4 * i + 3] < 0) continue;
            line.set(c[4 * i], c[4 * i + 1], c[4 * i + 2], 0, 1, 0, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
            final int want = i;
            boolean[] found = {false};
            oct.visit(line, new TraceContext(), (prim, ray, ctx) -> {
                seen[prim]++;
                if (prim == want) found[0] = true;
            });
            assertTrue(found[0], "primitive " + i + " is reachable");
        }
        for (int i = 0; i < s.size(); i++) if (c[4 * i + 3] < 0) assertEquals(0, seen[i], "empty primitive " + i);
        // Brute force would test the empty ones too (a negative radius still makes a sphere), so
        // agreement is checked on the others alone.
        for (int i = 3; i < c.length; i += 4) c[i] = Math.abs(c[i]) * 0.01;
        BvhTest.compare(s, new Octree(s), new Bounds(-0.2, -0.2, -0.2, 1.2, 1.2, 1.2), 10_000, 9);

        Octree empty = new Octree(new BvhTest.Spheres(new double[0]));
        assertEquals(0, empty.nodeCount());
        assertEquals(Bounds.EMPTY, empty.rootCell());
        assertFalse(empty.intersect(line, new Hit().reset(1), new TraceContext()));
        assertFalse(empty.occluded(line, new TraceContext()));
    }

    @Test
    void refusesBadLimits() {
        BvhTest.Spheres s = new BvhTest.Spheres(new double[] {0, 0, 0, 1});
        assertThrows(IllegalArgumentException.class, () -> new Octree(s, 0, 8));
        assertThrows(IllegalArgumentException.class, () -> new Octree(s, 8, -1));
        assertThrows(IllegalArgumentException.class, () -> new Octree(s, 8, Octree.DEPTH_LIMIT + 1));
        assertThrows(IllegalArgumentException.class, () -> new Octree(new BvhTest.Spheres(new double[] {0, 0, 0, Double.POSITIVE_INFINITY})));
    }
}
