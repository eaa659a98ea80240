package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class GridPatternTest {

    @Test
    void theGridTakesTheLargerOfEachOppositePair() {
        GridPattern g = new GridPattern(68, 19, 60, 17);
        assertEquals(68, g.columns());
        assertEquals(19, g.rows());
        assertEquals(69 * 20, g.vertexCount());
        assertEquals(2 * 68 * 19, g.triangleCount());
        assertTrue(!g.isSnapped(0) && !g.isSnapped(1) && g.isSnapped(2) && g.isSnapped(3));
        assertEquals(2, g.vertex(2, 0));
        assertEquals(69 + 2, g.vertex(2, 1));
        assertEquals(g.vertex(68, 0), g.edgeVertex(1, 0), "edge 1 starts at corner 1");
        assertEquals(g.vertex(68, 19), g.edgeVertex(2, 0), "edge 2 starts at corner 2");
        assertEquals(g.vertex(0, 19), g.edgeVertex(3, 0), "edge 3 starts at corner 3");
        assertEquals(g.vertex(0, 0), g.edgeVertex(3, 19), "edge 3 ends at corner 0");
        assertThrows(IllegalArgumentException.class, () -> new GridPattern(0, 1, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> new GridPattern(1, 1, 4097, 1));
        assertThrows(IllegalArgumentException.class, () -> g.vertex(69, 0));
        assertThrows(IllegalArgumentException.class, () -> g.edgeVertex(1, 20));
    }

    @Test
    void snappingReachesEveryCoarsePointInOrder() {
        for (int rg = 1; rg <= 40; rg++) {
            for (int r = 1; r <= rg; r++) {
                int prev = -1;
                for (int k = 0; k <= rg; k++) {
                    int c = GridPattern.snap(k, rg, r);
                    assertTrue(c == prev || c == prev + 1, "steps by 0 or 1: " + k + " of " + rg + " -> " + c + " of " + r);
                    assertTrue(Math.abs(c * (double) rg - k * (double) r) <= rg / 2.0, "the nearest point");
                    prev = c;
                }
                assertEquals(r, prev, "ends at the edge's end");
            }
        }
        assertEquals(4096, GridPattern.snap(4096, 4096, 4096));
        assertEquals(1, GridPattern.snap(4095, 4096, 1));
        assertEquals(0, GridPattern.snap(2047, 4096, 1));
        assertEquals(1, GridPattern.snap(2048, 4096, 1), "halves round forwards");
    }

    /** (c) Small rates, every combination; then random larger ones. */
    @Test
    void theTrianglesCoverTheSquareExactlyOnce() {
        SplittableRandom rnd = new SplittableRandom(5);
        int zero = 0;
        for (int a = 1; a <= 5; a++) for (int b = 1; b <= 5; b++) for (int c = 1; c <= 5; c++) for (int d = 1; d <= 5; d++) {
            zero += Triangulations.check(Triangulations.of(new GridPattern(a, b, c, d)), rnd, 4);
        }
        assertTrue(zero > 0, "snapping made zero-area triangles, and they were checked");
        for (int n = 0; n < 60; n++) {
            GridPattern g = new GridPattern(1 + rnd.nextInt(40), 1 + rnd.nextInt(40), 1 + rnd.nextInt(40), 1 + rnd.nextInt(40));
            Triangulations.check(Triangulations.of(g), rnd, 2);
        }
        // No transition edge: no zero-area triangle.
        assertEquals(0, new GridPattern(7, 3, 7, 3).zeroAreaTriangles());
        // A large pattern, counted along its borders only: one per collapsed grid segment (4093 on
        // edge 2, 4095 on edge 1); at the corner between the two, both collapsed segments fall in
        // one triangle, and the cell's other triangle has two vertices snapped onto the corner.
        GridPattern big = new GridPattern(4096, 1, 3, 4096);
        assertEquals(4096 - 3 + 4096 - 1, big.zeroAreaTriangles());
    }

    /** (b) Every vertex on a transition edge lies exactly on one of that edge's points. */
    @Test
    void snappedVerticesLieExactlyOnCoarsePoints() {
        SplittableRandom rnd = new SplittableRandom(9);
        for (int n = 0; n < 300; n++) {
            GridPattern g = new GridPattern(1 + rnd.nextInt(50), 1 + rnd.nextInt(50), 1 + rnd.nextInt(50), 1 + rnd.nextInt(50));
            for (int e = 0; e < 4; e++) {
                int r = g.edgeRate(e), rg = g.gridRate(e);
                boolean[] used = new boolean[r + 1];
                for (int k = 0; k <= rg; k++) {
                    int vtx = g.edgeVertex(e, k), i = vtx % (g.columns() + 1), j = vtx / (g.columns() + 1);
                    int c = g.edgePoint(e, k);
                    used[c] = true;
                    // The coordinate along the edge, and the one across it (fixed at 0 or 1).
                    double along = (e & 1) == 0 ? g.u(i, j) : g.v(i, j), across = (e & 1) == 0 ? g.v(i, j) : g.u(i, j);
                    int numerator = e < 2 ? c : r - c;
                    assertEquals(Double.doubleToRawLongBits((double) numerator / r), Double.doubleToRawLongBits(along), g + " edge " + e + " vertex " + k);
                    assertEquals(e == 0 || e == 3 ? 0.0 : 1.0, across);
                }
                for (int c = 0; c <= r; c++) assertTrue(used[c], g + ": edge " + e + " point " + c + " used");
            }
            // Inside, the plain grid.
            for (int j = 1; j < g.rows(); j++) {
                for (int i = 1; i < g.columns(); i++) {
                    assertEquals((double) i / g.columns(), g.u(i, j));
                    assertEquals((double) j / g.rows(), g.v(i, j));
                }
            }
        }
    }

    /**
     * The shared edge's points, from face A (edge {@code ea}, forwards along the control edge)
     * and face B (edge {@code eb}, forwards or backwards): as control-edge parameters c / R.
     */
    static List<Double> controlEdgeParameters(GridPattern g, int edge, boolean forwards) {
        List<Double> out = new ArrayList<>();
        int r = g.edgeRate(edge), w = g.columns() + 1;
        for (int k = 0; k <= g.gridRate(edge); k++) {
            int vtx = g.edgeVertex(edge, k), i = vtx % w, j = vtx / w;
            double along = (edge & 1) == 0 ? g.u(i, j) : g.v(i, j);
            // The face's coordinate is a quotient n / r: recover n exactly, then the edge's own c.
            long n = Math.round(along * r);
            assertEquals(Double.doubleToRawLongBits((double) n / r), Double.doubleToRawLongBits(along), "an exact quotient");
            long local = edge < 2 ? n : r - n;               // points counted along the face's edge
            long c = forwards ? local : r - local;           // ... and along the control edge
            double s = (double) c / r;
            if (out.isEmpty() || out.get(out.size() - 1) != s) out.add(s);
        }
        return out;
    }

    /** (a) Two quads sharing an edge, with different rates elsewhere, in every slot and both orientations. */
    @Test
    void aSharedEdgeHasTheSameParametersFromBothFaces() {
        SplittableRandom rnd = new SplittableRandom(13);
        int cases = 0;
        for (int shared : new int[] {1, 2, 3, 5, 8, 13, 64}) {
            for (int ea = 0; ea < 4; ea++) {
                for (int eb = 0; eb < 4; eb++) {
                    for (boolean opposite : new boolean[] {true, false}) {
                        int[] ra = new int[4], rb = new int[4];
                        for (int k = 0; k < 4; k++) { ra[k] = 1 + rnd.nextInt(80); rb[k] = 1 + rnd.nextInt(80); }
                        ra[ea] = shared;
                        rb[eb] = shared;
                        GridPattern a = new GridPattern(ra[0], ra[1], ra[2], ra[3]), b = new GridPattern(rb[0], rb[1], rb[2], rb[3]);
                        List<Double> pa = controlEdgeParameters(a, ea, true), pb = controlEdgeParameters(b, eb, !opposite);
                        // B, read along the control edge, is A; read along its own edge, A reversed when opposite.
                        assertEquals(shared + 1, pa.size(), a + ": every point of the shared edge once");
                        if (opposite) java.util.Collections.reverse(pb);
                        assertEquals(bits(pa), bits(pb), a + " / " + b + " edges " + ea + ", " + eb + (opposite ? ", opposite" : ", same way"));
                        for (int c = 0; c <= shared; c++) assertEquals(Double.doubleToRawLongBits((double) c / shared), Double.doubleToRawLongBits(pa.get(c)));
                        cases++;
                    }
                }
            }
        }
        assertEquals(7 * 32, cases);
    }

    static List<Long> bits(List<Double> xs) {
        List<Long> out = new ArrayList<>();
        for (double x : xs) out.add(Double.doubleToRawLongBits(x));
        return out;
    }

    /**
     * The diagonals alternate in a checkerboard, as uniform subdivision's child quads are fanned
     * from their corner 0: cell (i, j) is cut along v0-v2 when i + j is even, along v1-v3 when odd.
     */
    @Test
    void theDiagonalsAlternateInACheckerboard() {
        GridPattern g = new GridPattern(2, 2, 2, 2);
        int[] t = new int[3];
        g.triangle(0, t); // cell (0, 0): v0-v2
        assertArrayEquals(new int[] {0, 1, 4}, t);
        g.triangle(1, t);
        assertArrayEquals(new int[] {0, 4, 3}, t);
        g.triangle(2, t); // cell (1, 0): v1-v3
        assertArrayEquals(new int[] {1, 2, 4}, t);
        g.triangle(3, t);
        assertArrayEquals(new int[] {5, 4, 2}, t);
        g.triangle(4, t); // cell (0, 1): v1-v3
        assertArrayEquals(new int[] {3, 4, 6}, t);
        g.triangle(5, t);
        assertArrayEquals(new int[] {7, 6, 4}, t);
        g.triangle(7, t); // cell (1, 1): v0-v2
        assertArrayEquals(new int[] {4, 8, 7}, t);
        assertThrows(IllegalArgumentException.class, () -> g.triangle(8, t));
        // A child quad's children are fanned from the corners they share with it towards its centre, which at
        // every level is the grid vertex with both indices odd: every triangle holds its cell's corner that has.
        for (GridPattern p : new GridPattern[] {g, new GridPattern(8, 8, 8, 8), new GridPattern(5, 4, 5, 3)}) {
            int w = p.columns() + 1;
            for (int k = 0; k < p.triangleCount(); k++) {
                p.triangle(k, t);
                int c = k >> 1, i = c % p.columns(), j = c / p.columns();
                int centre = (j | 1) * w + (i | 1);
                assertTrue(t[0] == centre || t[1] == centre || t[2] == centre, p + ": triangle " + k + " holds vertex " + centre);
            }
        }
    }

    /**
     * The rendered grid cuts each cell along its shorter diagonal in 3D, not by this checkerboard, so the
     * zero-area count must not depend on the diagonal: for every rate set up to 12 per edge, every cell has as
     * many zero-area triangles (exactly, in the lattice) cut along v0-v2 as along v1-v3.
     */
    @Test
    void everyCellHasAsManyZeroAreaTrianglesForEitherDiagonal() {
        int[][][] cuts = {{{0, 1, 2}, {0, 2, 3}}, {{0, 1, 3}, {2, 3, 1}}};
        long[][] p = new long[4][2];
        for (int r0 = 1; r0 <= 12; r0++) for (int r1 = 1; r1 <= 12; r1++) for (int r2 = 1; r2 <= 12; r2++) for (int r3 = 1; r3 <= 12; r3++) {
            GridPattern g = new GridPattern(r0, r1, r2, r3);
            int total = 0;
            for (int j = 0; j < g.rows(); j++) for (int i = 0; i < g.columns(); i++) {
                int[] ij = {i, j, i + 1, j, i + 1, j + 1, i, j + 1};
                for (int k = 0; k < 4; k++) {
                    p[k][0] = g.uLattice(ij[2 * k], ij[2 * k + 1]);
                    p[k][1] = g.vLattice(ij[2 * k], ij[2 * k + 1]);
                }
                int[] zero = new int[2];
                for (int d = 0; d < 2; d++) for (int[] t : cuts[d]) {
                    long[] a = p[t[0]], b = p[t[1]], c = p[t[2]];
                    if ((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]) == 0) zero[d]++;
                }
                assertEquals(zero[0], zero[1], g + ": cell " + i + ", " + j);
                total += zero[0];
            }
            assertEquals(g.zeroAreaTriangles(), total, g.toString());
        }
    }
}
