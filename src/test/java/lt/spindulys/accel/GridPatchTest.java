package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import lt.spindulys.accel.GridTestSurfaces.Reference;
import lt.spindulys.math.Ray;

/**
 * The grid patch against the brute-force watertight test of every triangle: the same nearest t and cell on
 * bumpy, jittered, thin and degenerate grids for every leaf size, each cell cut along its shorter diagonal (v0-v2
 * on a tie) as the uniform subdivision path cuts its quads, watertightness of a closed set of six grids that share
 * bit-identical edge vertices (rays from inside, many aimed exactly at shared edges and vertices), occlusion agreeing with intersection, every watertight crossing of a line
 * among the visited triangles, the hit's parameters, the byte count, and no allocation per query.
 */
class GridPatchTest {

    private static float[] f(double[] d) {
        float[] r = new float[d.length];
        for (int k = 0; k < d.length; k++) r[k] = (float) d[k];
        return r;
    }

    private static GridPatch grid(int nu, int nv, float[] xyz, int leaf) {
        return new GridPatch(nu, nv, xyz, null, null, 0, 0, 1, 1, leaf);
    }

    /**
     * Checks one ray: the grid's nearest hit has the reference's t bit for bit, and its triangle is the
     * reference's or one the reference also hits at that t (a tie on a shared edge); occlusion agrees; the ray
     * is left alone. Returns whether it hit.
     */
    private static boolean agree(GridPatch g, Reference ref, Ray ray, TraversalScratch ctx, String what) {
        PrimitiveHit a = new PrimitiveHit(), b = new PrimitiveHit();
        double tMax = ray.tMax;
        boolean hg = g.intersect(ray, a, ctx);
        assertEquals(tMax, ray.tMax, "the ray is left alone");
        boolean hr = ref.intersect(ray, b, ctx);
        if (hg != hr) fail(what + ": grid " + (hg ? "hit at " + a.t : "missed") + ", reference " + (hr ? "hit at " + b.t : "missed") + " " + ray);
        assertEquals(hg, g.occluded(ray, ctx), what + ": occlusion agrees with intersection");
        if (!hg) return false;
        assertTrue(Double.isFinite(a.t) && Double.isFinite(a.u) && Double.isFinite(a.v), what);
        assertEquals(b.t, a.t, what + ": nearest t");
        if (a.sub != b.prim) assertTrue(ref.hitsAt(a.sub, a.t, ray, ctx), what + ": the grid's triangle is hit at t too");
        if (a.sub == b.prim) {
            assertEquals(b.u, a.u, 1e-12, what);
            assertEquals(b.v, a.v, 1e-12, what);
        }
        ray.tMax = a.t; // just before the hit nothing blocks, just beyond it something does
        assertFalse(g.occluded(ray, ctx), what + ": nothing before the nearest hit");
        ray.tMax = tMax;
        return true;
    }

    /**
     * Random rays at a grid: down onto it from above, across it at grazing angles, at its vertices, and along the
     * axes.
     */
    private static void randomRays(GridPatch g, long seed, int count, String what) {
        Reference ref = new Reference(g);
        TraversalScratch ctx = new TraversalScratch();
        Random rnd = new Random(seed);
        double[] box = new double[6];
        g.bounds(box);
        Ray ray = new Ray();
        int hits = 0;
        for (int k = 0; k < count; k++) {
            double tx = box[0] + rnd.nextDouble() * (box[3] - box[0]), ty = box[1] + rnd.nextDouble() * (box[4] - box[1]);
            double tz = box[2] + rnd.nextDouble() * (box[5] - box[2]);
            if (k % 4 == 3) { // exactly at a vertex
                int i = rnd.nextInt(g.nu()), j = rnd.nextInt(g.nv());
                tx = g.x(i, j, 0); ty = g.x(i, j, 1); tz = g.x(i, j, 2);
            }
            double ox, oy, oz;
            if (k % 2 == 0) { ox = tx + rnd.nextGaussian() * 0.3; oy = ty + rnd.nextGaussian() * 0.3; oz = 2 + rnd.nextDouble(); }
            else { ox = tx + 3 * rnd.nextGaussian(); oy = ty + 3 * rnd.nextGaussian(); oz = tz + 0.2 * rnd.nextGaussian(); }
            ray.set(ox, oy, oz, tx - ox, ty - oy, tz - oz, 0, k % 5 == 0 ? 0.999 : Double.POSITIVE_INFINITY);
            if (k % 7 == 6) ray.set(tx, ty, 2, 0, 0, -1, 0, Double.POSITIVE_INFINITY); // along an axis: infinite inverses
            if (k % 11 == 10) ray.set(-1, ty, tz, 1, 0, 0, 0, Double.POSITIVE_INFINITY);
            if (agree(g, ref, ray, ctx, what + " ray " + k)) hits++;
        }
        assertTrue(hits > count / 4, what + ": " + hits + " of " + count + " rays hit");
    }

    @ParameterizedTest(name = "{0} x {1}, leaves of {2}")
    @CsvSource({"2, 2, 2", "2, 2, 17", "3, 2, 2", "2, 40, 3", "40, 2, 5", "33, 7, 3", "17, 17, 17", "18, 18, 17",
        "65, 65, 3", "65, 65, 5", "65, 65, 9", "65, 65, 17", "100, 37, 5", "129, 129, 5"})
    void bumpyGridsAgreeWithEveryTriangleTested(int nu, int nv, int leaf) {
        for (int jittered = 0; jittered < 2; jittered++) {
            double[] p = jittered == 0 ? GridTestSurfaces.bumpy(nu, nv) : GridTestSurfaces.jittered(nu, nv);
            GridPatch g = grid(nu, nv, f(p), leaf);
            assertEquals(2 * (nu - 1) * (nv - 1), g.triangleCount());
            randomRays(g, 31 * nu + nv + leaf + 7 * jittered, 1500, nu + "x" + nv + "/" + leaf + (jittered == 0 ? " smooth" : " jittered"));
        }
    }

    /** The squared distance of vertices a and b, in double from their floats, written apart from the grid's. */
    private static double dist2(GridPatch g, int a, int b) {
        double s = 0;
        for (int ax = 0; ax < 3; ax++) {
            double d = (double) g.x(a % g.nu(), a / g.nu(), ax) - g.x(b % g.nu(), b / g.nu(), ax);
            s += d * d;
        }
        return s;
    }

    /**
     * Checks every cell of {@code g}: it is cut along its shorter diagonal by the squared lengths of its floats,
     * (i, j)-(i + 1, j + 1) on a tie; both triangles are counter-clockwise in (i, j), together the cell's four
     * corners, with the diagonal as their shared edge; the cell indices and the corners' floats follow. Returns
     * how many cells are cut along v1-v3.
     */
    private static int checkCells(GridPatch g) {
        int nu = g.nu(), alongV1V3 = 0;
        for (int s = 0; s < g.triangleCount(); s++) {
            int i = g.cellI(s), j = g.cellJ(s);
            assertEquals(s >> 1, j * (nu - 1) + i);
            int v0 = j * nu + i, v1 = v0 + 1, v2 = v0 + nu + 1, v3 = v0 + nu;
            double d02 = dist2(g, v0, v2), d13 = dist2(g, v1, v3);
            boolean along02 = d02 <= d13;
            assertEquals(along02, g.cutAlongV0V2(i, j), "cell " + i + ", " + j + ": |v0v2|² " + d02 + ", |v1v3|² " + d13);
            if (!along02 && (s & 1) == 0) alongV1V3++;
            int a = g.triangleVertex(s, 0), b = g.triangleVertex(s, 1), c = g.triangleVertex(s, 2);
            int[] want = along02
                    ? ((s & 1) == 0 ? new int[] {v0, v1, v2} : new int[] {v0, v2, v3})
                    : ((s & 1) == 0 ? new int[] {v0, v1, v3} : new int[] {v2, v3, v1});
            assertEquals(java.util.Arrays.toString(want), java.util.Arrays.toString(new int[] {a, b, c}), "triangle " + s);
            // counter-clockwise in (i, j)
            long ai = a % nu, aj = a / nu, bi = b % nu, bj = b / nu, ci = c % nu, cj = c / nu;
            assertEquals(1, (bi - ai) * (cj - aj) - (ci - ai) * (bj - aj), "triangle " + s + " winds counter-clockwise");
            for (int k = 0; k < 3; k++) {
                int vk = g.triangleVertex(s, k);
                for (int ax = 0; ax < 3; ax++) assertEquals(g.x(vk % nu, vk / nu, ax), g.cornerCoordinate(s, k, ax));
            }
        }
        return alongV1V3;
    }

    /**
     * On random bumpy grids (smooth, jittered, noisy) every cell is cut along its shorter diagonal, and both
     * diagonals occur. Against the uniform path's rule on the double positions the grid was rounded from, the two
     * disagree only where the squared lengths lie within float rounding of each other.
     */
    @Test
    void cellsAreCutAlongTheirShorterDiagonal() {
        Random rnd = new Random(41);
        int cells = 0, v1v3 = 0, disagree = 0;
        for (int k = 0; k < 30; k++) {
            int nu = 2 + rnd.nextInt(40), nv = 2 + rnd.nextInt(40);
            double[] p = k % 3 == 0 ? GridTestSurfaces.bumpy(nu, nv) : GridTestSurfaces.jittered(nu, nv);
            if (k % 3 == 2) for (int q = 0; q < p.length; q++) p[q] += 0.3 * rnd.nextGaussian() / Math.max(nu, nv);
            GridPatch g = grid(nu, nv, f(p), 2 + rnd.nextInt(16));
            cells += (nu - 1) * (nv - 1);
            v1v3 += checkCells(g);
            for (int j = 0; j < nv - 1; j++) for (int i = 0; i < nu - 1; i++) {
                int v0 = j * nu + i, v2 = v0 + nu + 1;
                double d02 = dist2(p, v0, v2), d13 = dist2(p, v0 + 1, v0 + nu);
                if ((d02 <= d13) != g.cutAlongV0V2(i, j)) {
                    disagree++;
                    assertTrue(Math.abs(d02 - d13) <= 0x1p-20 * (d02 + d13), "cell " + i + ", " + j + ": " + d02 + " vs " + d13);
                }
            }
        }
        assertTrue(v1v3 > cells / 5 && v1v3 < 4 * cells / 5, v1v3 + " of " + cells + " cells cut along v1-v3");
        assertTrue(disagree < cells / 1000, disagree + " of " + cells + " cells cut otherwise than their doubles would be");
        GridPatch g = new GridPatch(6, 5, GridTestSurfaces.jittered(6, 5), null, null, 3);
        assertThrows(IndexOutOfBoundsException.class, () -> g.cutAlongV0V2(5, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> g.cutAlongV0V2(0, -1));
    }

    private static double dist2(double[] p, int a, int b) {
        double dx = p[3 * a] - p[3 * b], dy = p[3 * a + 1] - p[3 * b + 1], dz = p[3 * a + 2] - p[3 * b + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    /** A grid of one cell with corners v0..v3 (x, y, z each). */
    private static GridPatch cell(float... v) {
        float[] p = new float[12];
        System.arraycopy(v, 0, p, 0, 6); // v0, v1: row 0
        System.arraycopy(v, 9, p, 6, 3); // v3, v2: row 1
        System.arraycopy(v, 6, p, 9, 3);
        return grid(2, 2, p, 2);
    }

    /**
     * Diagonals of exactly equal length go v0-v2: a flat rectangle, a saddle (v0, v2 raised), a grid of saddles
     * (every cell a tie); one float step longer, v1-v3; a NaN corner v1-v3, as the uniform path's rule decides.
     * Rays agree with every triangle tested.
     */
    @Test
    void tiesGoAlongV0V2() {
        assertTrue(cell(0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0).cutAlongV0V2(0, 0), "flat rectangle");
        assertTrue(cell(0, 0, 1, 2, 0, 0, 2, 1, 1, 0, 1, 0).cutAlongV0V2(0, 0), "saddle");
        assertFalse(cell(0, 0, 1, 2, 0, 0, Math.nextUp(2f), 1, 1, 0, 1, 0).cutAlongV0V2(0, 0), "v0-v2 a float step longer");
        assertTrue(cell(0, 0, 1, Math.nextUp(2f), 0, 0, 2, 1, 1, 0, 1, 0).cutAlongV0V2(0, 0), "v1-v3 a float step longer");
        assertFalse(cell(0, 0, 1, 2, 0, 0, 2, 1, 1, 0, 1, Float.NaN).cutAlongV0V2(0, 0), "NaN");
        for (GridPatch g : new GridPatch[] {cell(0, 0, 1, 2, 0, 0, 2, 1, 1, 0, 1, 0), cell(0, 0, 1, 2, 0, 0, Math.nextUp(2f), 1, 1, 0, 1, 0)}) {
            checkCells(g);
            randomRays(g, 3, 300, "one cell");
        }
        // every cell a saddle of equal diagonals, and a flat grid of floats i / (n - 1): all v0-v2
        int nu = 23, nv = 17;
        float[] saddles = new float[3 * nu * nv];
        double[] flat = GridTestSurfaces.bumpy(nu, nv);
        for (int j = 0; j < nv; j++) for (int i = 0; i < nu; i++) {
            int q = 3 * (j * nu + i);
            saddles[q] = 0.25f * i;
            saddles[q + 1] = 0.5f * j;
            saddles[q + 2] = 0.125f * ((i + j) & 1);
            flat[q + 2] = 0;
        }
        for (GridPatch g : new GridPatch[] {grid(nu, nv, saddles, 3), grid(nu, nv, f(flat), 3)}) {
            assertEquals(0, checkCells(g));
            randomRays(g, 5, 1000, "ties");
        }
    }

    @Test
    void doublePositionsAreRoundedToTheNearestFloat() {
        double[] p = GridTestSurfaces.bumpy(9, 5);
        GridPatch g = new GridPatch(9, 5, p, null, null, 3);
        for (int j = 0; j < 5; j++) for (int i = 0; i < 9; i++) for (int a = 0; a < 3; a++) {
            assertEquals((float) p[3 * (j * 9 + i) + a], g.x(i, j, a));
        }
        randomRays(g, 7, 500, "from doubles");
    }

    /** A grid snapped to coarser edges: repeated vertices on its borders, a repeated row and a repeated column. */
    private static float[] degenerate(int n) {
        double[] p = GridTestSurfaces.bumpy(n, n);
        for (int i = 1; i < n; i += 2) System.arraycopy(p, 3 * (i - 1), p, 3 * i, 3); // bottom row snapped 2:1
        for (int j = 1; j < n; j++) { // right column snapped 3:1 toward lower rows
            int from = (j / 3) * 3;
            System.arraycopy(p, 3 * (from * n + n - 1), p, 3 * (j * n + n - 1), 3);
        }
        System.arraycopy(p, 3 * (4 * n), p, 3 * (5 * n), 3 * n); // row 5 repeats row 4: a zero-area strip
        for (int j = 0; j < n; j++) System.arraycopy(p, 3 * (j * n + 6), p, 3 * (j * n + 7), 3); // column 7 repeats 6
        return f(p);
    }

    @ParameterizedTest(name = "leaves of {0}")
    @CsvSource({"2", "3", "5", "9", "17"})
    void snappedGridsWithZeroAreaTrianglesAgreeAndNeverGiveNaN(int leaf) {
        int n = 25;
        randomRays(grid(n, n, degenerate(n), leaf), 5 + leaf, 2000, "snapped");
    }

    @Test
    void aGridOfOnePointIsNeverHit() {
        float[] p = new float[3 * 9 * 9];
        for (int k = 0; k < p.length; k += 3) { p[k] = 0.5f; p[k + 1] = 0.25f; p[k + 2] = 0; }
        GridPatch g = grid(9, 9, p, 3);
        TraversalScratch ctx = new TraversalScratch();
        PrimitiveHit h = new PrimitiveHit();
        Ray ray = new Ray().set(0.5, 0.25, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        assertFalse(g.intersect(ray, h, ctx));
        assertFalse(g.occluded(ray, ctx));
        ray.set(-1, 0.25, 0, 1, 0, 0, 0, Double.POSITIVE_INFINITY);
        assertFalse(g.intersect(ray, h, ctx), "along the plane through the point");
    }

    // ---- six grids, one closed surface ----

    /**
     * Six faces, their cells cut along either diagonal, both kinds meeting along the shared edges (a shared edge is
     * a grid edge on both sides, whichever diagonal its cells take).
     */
    private static GridPatch[] cubeSphere(int n, int leaf) {
        GridPatch[] faces = new GridPatch[6];
        for (int f = 0; f < 6; f++) faces[f] = grid(n, n, GridTestSurfaces.cubeSphereFace(f, n), leaf);
        return faces;
    }

    @Test
    void theCubeSphereFacesShareBitIdenticalEdges() {
        int n = 9;
        GridPatch[] faces = cubeSphere(n, 3);
        java.util.Map<String, Integer> seen = new java.util.HashMap<>();
        for (GridPatch g : faces) {
            for (int j = 0; j < n; j++) for (int i = 0; i < n; i++) {
                if (i > 0 && j > 0 && i < n - 1 && j < n - 1) continue;
                seen.merge(g.x(i, j, 0) + " " + g.x(i, j, 1) + " " + g.x(i, j, 2), 1, Integer::sum);
            }
        }
        // 12 edges of n - 2 inner points shared by two faces, 8 corners shared by three
        assertEquals(12 * (n - 2) + 8, seen.size());
        assertEquals(2 * 12 * (n - 2) + 3 * 8, seen.values().stream().mapToInt(Integer::intValue).sum());
    }

    @ParameterizedTest(name = "{0} x {0} per face, leaves of {1}")
    @CsvSource({"9, 3", "17, 5", "33, 9", "65, 17"})
    void raysFromInsideTheClosedCubeSphereNeverEscape(int n, int leaf) {
        GridPatch[] faces = cubeSphere(n, leaf);
        Reference[] refs = new Reference[6];
        for (int f = 0; f < 6; f++) refs[f] = new Reference(faces[f]);
        TraversalScratch ctx = new TraversalScratch();
        Random rnd = new Random(n * 7 + leaf);
        Ray ray = new Ray();
        PrimitiveHit h = new PrimitiveHit(), r = new PrimitiveHit();
        int rays = 6000;
        for (int k = 0; k < rays; k++) {
            // from the centre or a point within 0.5 of it (the surface is at least 0.85 away), at random directions,
            // at shared edge vertices, at shared edge midpoints
            double ox = 0, oy = 0, oz = 0;
            if (k % 2 == 1) {
                do { ox = rnd.nextDouble() - 0.5; oy = rnd.nextDouble() - 0.5; oz = rnd.nextDouble() - 0.5; } while (ox * ox + oy * oy + oz * oz > 0.25);
            }
            double dx, dy, dz;
            int kind = k % 3;
            if (kind == 0) {
                dx = rnd.nextGaussian(); dy = rnd.nextGaussian(); dz = rnd.nextGaussian();
            } else {
                GridPatch g = faces[rnd.nextInt(6)];
                int i, j, i2, j2;
                if (rnd.nextBoolean()) { i = rnd.nextBoolean() ? 0 : n - 1; j = rnd.nextInt(n); } // a boundary column
                else { j = rnd.nextBoolean() ? 0 : n - 1; i = rnd.nextInt(n); } // a boundary row
                double tx = g.x(i, j, 0), ty = g.x(i, j, 1), tz = g.x(i, j, 2);
                if (kind == 2) { // the midpoint of a boundary edge
                    if (i == 0 || i == n - 1) { i2 = i; j2 = j == n - 1 ? j - 1 : j + 1; } else { j2 = j; i2 = i == n - 1 ? i - 1 : i + 1; }
                    tx = 0.5 * (tx + g.x(i2, j2, 0)); ty = 0.5 * (ty + g.x(i2, j2, 1)); tz = 0.5 * (tz + g.x(i2, j2, 2));
                }
                dx = tx - ox; dy = ty - oy; dz = tz - oz;
            }
            ray.set(ox, oy, oz, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
            double best = Double.POSITIVE_INFINITY, bestRef = Double.POSITIVE_INFINITY;
            boolean blocked = false;
            for (int f = 0; f < 6; f++) {
                if (faces[f].intersect(ray, h, ctx) && h.t < best) best = h.t;
                if (refs[f].intersect(ray, r, ctx) && r.t < bestRef) bestRef = r.t;
                blocked |= faces[f].occluded(ray, ctx);
            }
            if (best == Double.POSITIVE_INFINITY) fail("ray " + k + " escaped through the closed surface: " + ray);
            assertTrue(blocked, "ray " + k + " is occluded");
            assertEquals(bestRef, best, "ray " + k + ": the nearest hit of all six");
        }
    }

    // ---- every crossing of a line ----

    /** Records the triangles visited, and how often each. */
    private static final class Visited implements GridTriangleVisitor {
        int[] count = new int[0];
        int calls;

        void reset(GridPatch g) {
            if (count.length != g.triangleCount()) count = new int[g.triangleCount()];
            java.util.Arrays.fill(count, 0);
            calls = 0;
        }

        @Override public void triangle(GridPatch grid, int sub, Ray ray, TraversalScratch ctx) {
            count[sub]++;
            calls++;
        }
    }

    /**
     * For random lines (rays over an infinite interval) through random grids of any leaf size,
     * smooth, noisy and snapped: every triangle the watertight test hits on the line is visited, and no triangle is
     * visited twice. Many lines run through vertices, along the axes and within the grid's plane.
     */
    @Test
    void everyWatertightCrossingOfALineIsAmongTheVisitedTriangles() {
        Random rnd = new Random(17);
        TraversalScratch ctx = new TraversalScratch();
        Visited visited = new Visited();
        Ray ray = new Ray();
        int crossings = 0, lines = 0, skipped = 0;
        for (int grid = 0; grid < 60; grid++) {
            int nu = 2 + rnd.nextInt(grid % 3 == 0 ? 70 : 20), nv = 2 + rnd.nextInt(grid % 3 == 0 ? 70 : 20);
            double[] p = GridTestSurfaces.bumpy(nu, nv);
            if (grid % 4 == 1) for (int k = 0; k < p.length; k++) p[k] += 0.3 * rnd.nextGaussian() / Math.max(nu, nv); // noisy, folded
            if (grid % 4 == 2 && nu > 3) { // snapped: a repeated column and a bottom row collapsed 2:1
                for (int j = 0; j < nv; j++) System.arraycopy(p, 3 * (j * nu + 1), p, 3 * (j * nu + 2), 3);
                for (int i = 1; i < nu; i += 2) System.arraycopy(p, 3 * (i - 1), p, 3 * i, 3);
            }
            int[] leaves = {2, 3, 5, 9, 17};
            GridPatch g = grid(nu, nv, f(p), leaves[rnd.nextInt(leaves.length)]);
            Reference ref = new Reference(g);
            double[] box = new double[6];
            g.bounds(box);
            for (int r = 0; r < 150; r++) {
                double tx = box[0] + rnd.nextDouble() * (box[3] - box[0]), ty = box[1] + rnd.nextDouble() * (box[4] - box[1]);
                double tz = box[2] + rnd.nextDouble() * (box[5] - box[2]);
                if (r % 3 == 1) { // through a vertex
                    int i = rnd.nextInt(nu), j = rnd.nextInt(nv);
                    tx = g.x(i, j, 0); ty = g.x(i, j, 1); tz = g.x(i, j, 2);
                }
                double dx = rnd.nextGaussian(), dy = rnd.nextGaussian(), dz = rnd.nextGaussian();
                if (r % 5 == 0) { dx = 0.05 * dx; dy = 0.05 * dy; } // steep
                if (r % 7 == 3) { dz = 0; } // within the grid's plane (nearly)
                if (r % 11 == 4) { dx = 0; dy = 0; dz = 1; } // along an axis: infinite inverses
                // the origin anywhere along the line, beyond the grid on either side
                double s = 4 * rnd.nextGaussian();
                ray.set(tx - s * dx, ty - s * dy, tz - s * dz, dx, dy, dz, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
                visited.reset(g);
                g.visitTriangles(ray, ctx, visited);
                assertEquals(Double.NEGATIVE_INFINITY, ray.tMin, "the ray is left alone");
                assertEquals(Double.POSITIVE_INFINITY, ray.tMax, "the ray is left alone");
                lines++;
                for (int t = 0; t < g.triangleCount(); t++) {
                    assertTrue(visited.count[t] <= 1, "triangle " + t + " visited " + visited.count[t] + " times");
                    if (WatertightTriangles.test(ref.tri, ref.pos, null, t, t + 1, ray, null, ctx)) {
                        crossings++;
                        if (visited.count[t] != 1) fail("grid " + grid + " (" + nu + " x " + nv + ", leaves " + g.leafSize()
                                + "): triangle " + t + " is crossed but not visited: " + ray);
                    }
                }
                if (visited.calls == g.triangleCount() && g.nodeCount() > 0) skipped++; // nothing culled
            }
        }
        assertTrue(crossings > lines, crossings + " crossings on " + lines + " lines");
        assertTrue(skipped < lines / 2, "the hierarchy culls: " + skipped + " of " + lines + " lines visited every triangle");
    }

    /** A visitor may run a traversal of its own on the same scratch (a nested grid): the outer one carries on. */
    @Test
    void aVisitorMayTraverseWithTheSameScratch() {
        GridPatch outer = grid(65, 65, f(GridTestSurfaces.jittered(65, 65)), 3);
        GridPatch inner = grid(129, 129, f(GridTestSurfaces.bumpy(129, 129)), 2);
        TraversalScratch ctx = new TraversalScratch();
        ctx.stackTop = 4;
        Visited alone = new Visited(), nested = new Visited();
        PrimitiveHit h = new PrimitiveHit();
        int[] innerHits = new int[1];
        GridTriangleVisitor both = (grid, sub, ray, c) -> {
            nested.triangle(grid, sub, ray, c);
            if (inner.intersect(ray, h, c)) innerHits[0]++;
        };
        Random rnd = new Random(23);
        Ray ray = new Ray();
        int visitedRays = 0;
        for (int r = 0; r < 200; r++) {
            double tx = rnd.nextDouble(), ty = rnd.nextDouble();
            ray.set(tx + 0.2 * rnd.nextGaussian(), ty + 0.2 * rnd.nextGaussian(), 1, 0.2 * rnd.nextGaussian(), 0.2 * rnd.nextGaussian(), -1,
                    Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
            alone.reset(outer);
            nested.reset(outer);
            outer.visitTriangles(ray, ctx, alone);
            outer.visitTriangles(ray, ctx, both);
            if (alone.calls > 0) visitedRays++;
            assertEquals(java.util.Arrays.toString(alone.count), java.util.Arrays.toString(nested.count), "ray " + r);
            assertEquals(4, ctx.stackTop);
        }
        assertTrue(visitedRays > 100 && innerHits[0] > 100, visitedRays + " rays visited triangles, " + innerHits[0] + " inner hits");
    }

    // ---- the hit's parameters, normals and the byte count ----

    @Test
    void parametersAreInterpolatedFromTheCellAndNormalsFromTheVertices() {
        int nu = 11, nv = 6;
        // x and y linear in the indices, so that (x, y) is the parameter point whatever z does; z bumpy, so that
        // cells of both diagonals are hit
        double[] p = GridTestSurfaces.bumpy(nu, nv);
        float[] normals = new float[3 * nu * nv];
        for (int k = 0; k < normals.length; k += 3) { normals[k] = (float) p[k]; normals[k + 2] = 1; }
        TraversalScratch ctx = new TraversalScratch();
        PrimitiveHit h = new PrimitiveHit();
        double[] uv = new double[2], n = new double[3];
        Random rnd = new Random(3);
        GridPatch g = new GridPatch(nu, nv, f(p), normals, null, 0.5, 0.25, 1, 0.75, 3);
        int[] hitsAlong = new int[2];
        for (int k = 0; k < 1000; k++) {
            double x = rnd.nextDouble(), y = rnd.nextDouble();
            Ray ray = new Ray().set(x, y, 1, 0.1 * rnd.nextGaussian(), 0.1 * rnd.nextGaussian(), -1, 0, Double.POSITIVE_INFINITY);
            if (!g.intersect(ray, h, ctx)) continue;
            hitsAlong[g.cutAlongV0V2(g.cellI(h.sub), g.cellJ(h.sub)) ? 0 : 1]++;
            double hx = ray.pointX(h.t), hy = ray.pointY(h.t);
            assertEquals(g.cellI(h.sub), Math.min(nu - 2, (int) (hx * (nu - 1))), 1, "cell column");
            g.parameters(h.sub, h.u, h.v, uv);
            assertEquals(0.5 + 0.5 * hx, uv[0], 1e-6);
            assertEquals(0.25 + 0.5 * hy, uv[1], 1e-6);
            g.normal(h.sub, h.u, h.v, n);
            assertEquals(hx, n[0], 1e-6);
            assertEquals(1, n[2], 1e-6);
        }
        assertTrue(hitsAlong[0] > 100 && hitsAlong[1] > 100, hitsAlong[0] + " hits in cells cut along v0-v2, " + hitsAlong[1] + " along v1-v3");
        // explicit parameters win over the linear ones
        float[] given = new float[2 * nu * nv];
        for (int v = 0; v < nu * nv; v++) { given[2 * v] = (float) (p[3 * v] * p[3 * v]); given[2 * v + 1] = (float) p[3 * v + 1]; }
        GridPatch e = new GridPatch(nu, nv, f(p), null, given, 0, 0, 1, 1, 3);
        Ray ray = new Ray().set(0.55, 0.45, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        assertTrue(e.intersect(ray, h, ctx));
        e.parameters(h.sub, h.u, h.v, uv);
        assertEquals(0.5 * (0.5 * 0.5 + 0.6 * 0.6), uv[0], 1e-6); // linear over the cell between x = 0.5 and 0.6
        assertEquals(0.45, uv[1], 1e-6);
        assertThrows(IllegalStateException.class, () -> e.normal(0, 0, 0, new double[3]));
    }

    @Test
    void bytesFollowTheDocumentedFormula() {
        GridPatch one = grid(5, 5, f(GridTestSurfaces.bumpy(5, 5)), 5);
        assertEquals(0, one.nodeCount());
        assertEquals(128 + 16 + 304 + 16 + 24, one.bytes(),
                "one leaf: positions (75 floats, 300 bytes rounded to 304), an empty node array and one long of diagonal bits");
        GridPatch g = grid(65, 65, f(GridTestSurfaces.bumpy(65, 65)), 5);
        assertTrue(g.nodeCount() > 0);
        assertEquals(128 + 16 + up8(12L * 65 * 65) + 16 + 288L * g.nodeCount() + 16 + 8 * 64, g.bytes(), "64 x 64 cells: 64 longs of bits");
        float[] n = new float[3 * 65 * 65], uv = new float[2 * 65 * 65];
        GridPatch full = new GridPatch(65, 65, f(GridTestSurfaces.bumpy(65, 65)), n, uv, 0, 0, 1, 1, 5);
        assertEquals(g.bytes() + 16 + up8(12L * 65 * 65) + 16 + 8L * 65 * 65, full.bytes());
    }

    private static long up8(long bytes) { return (bytes + 7) & ~7L; }

    @Test
    void theHierarchyHalvesDownToLeavesOfTheGivenSize() {
        // 64 x 64 cells, leaves of 4 x 4 cells: eight halvings, two at the root and three per level below, so 256
        // leaves under a tree of 1 + 4 + 32 nodes (the root cut into four 32 x 32 ranges, each of those into eight
        // 8 x 16, each of those into eight leaves)
        GridPatch g = grid(65, 65, f(GridTestSurfaces.bumpy(65, 65)), 5);
        assertEquals(37, g.nodeCount());
        assertEquals(3, g.depth());
        assertEquals(0, grid(17, 17, f(GridTestSurfaces.bumpy(17, 17)), 17).nodeCount());
        assertEquals(1, grid(18, 18, f(GridTestSurfaces.bumpy(18, 18)), 17).nodeCount());
    }

    @Test
    void rejectsBadSizes() {
        assertThrows(IllegalArgumentException.class, () -> grid(1, 5, new float[15], 3));
        assertThrows(IllegalArgumentException.class, () -> grid(5, 5, new float[74], 3));
        assertThrows(IllegalArgumentException.class, () -> grid(5, 5, new float[75], 1));
        assertThrows(IllegalArgumentException.class, () -> grid(5, 5, new float[75], 18));
        assertThrows(IllegalArgumentException.class, () -> new GridPatch(GridPatch.MAX_SIDE + 1, 2, new double[0], null, null, 3));
    }

    @Test
    void steadyStateQueriesAllocateNothing() {
        GridPatch g = grid(129, 129, f(GridTestSurfaces.jittered(129, 129)), GridPatch.DEFAULT_LEAF_SIZE);
        int[] visits = new int[1];
        GridTriangleVisitor counter = (grid, sub, ray, c) -> visits[0]++;
        TraversalScratch ctx = new TraversalScratch();
        ctx.stackTop = 8; // below a caller's entries, as inside a scene traversal
        Ray r = new Ray();
        PrimitiveHit h = new PrimitiveHit();
        Random rnd = new Random(5);
        double[] rays = new double[6 * 1024];
        for (int i = 0; i < rays.length; i += 6) {
            rays[i] = rnd.nextDouble(); rays[i + 1] = rnd.nextDouble(); rays[i + 2] = 1;
            rays[i + 3] = 0.3 * rnd.nextGaussian(); rays[i + 4] = 0.3 * rnd.nextGaussian(); rays[i + 5] = -1;
        }
        Runnable work = () -> {
            for (int i = 0; i < 20_000; i++) {
                int k = 6 * (i & 1023);
                r.set(rays[k], rays[k + 1], rays[k + 2], rays[k + 3], rays[k + 4], rays[k + 5], 0, Double.POSITIVE_INFINITY);
                g.intersect(r, h, ctx);
                g.occluded(r, ctx);
                if ((i & 3) == 0) {
                    r.tMin = Double.NEGATIVE_INFINITY;
                    g.visitTriangles(r, ctx, counter);
                }
            }
        };
        long least = lt.spindulys.SteadyAllocation.least(work, 3, 4096);
        assertTrue(least < 4096, "45,000 queries allocated " + least + " bytes");
        assertTrue(visits[0] > 0);
        assertEquals(8, ctx.stackTop, "the caller's stack entries are left as they were");
    }
}
