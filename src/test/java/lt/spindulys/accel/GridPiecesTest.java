package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import lt.spindulys.math.Ray;

/**
 * A face's grid cut into pieces: the pieces tile the grid, sharing their boundary rows and columns, each at most
 * the given size; built pieces hold bit-identical shared vertices and the whole grid's triangles (each cell cut
 * along the same diagonal), answer every ray as the whole grid does, give
 * face parameters, and lie inside the bound supplied before building.
 */
class GridPiecesTest {

    /** The bumpy height field of {@link GridTestSurfaces#bumpy} of a face of nu x nv vertices, as a source. */
    private static GridPieces.Source bumpySource(int faceNu, int faceNv) {
        return (i0, j0, nu, nv, xyz) -> {
            for (int b = 0; b < nv; b++) {
                for (int a = 0; a < nu; a++) {
                    double x = (double) (i0 + a) / (faceNu - 1), y = (double) (j0 + b) / (faceNv - 1);
                    int q = 3 * (b * nu + a);
                    xyz[q] = x;
                    xyz[q + 1] = y;
                    xyz[q + 2] = GridTestSurfaces.bump(x, y);
                }
            }
        };
    }

    /** {@link GridTestSurfaces#jittered} of a face of nu x nv vertices, as a source. */
    private static GridPieces.Source jitteredSource(int faceNu, int faceNv) {
        return (i0, j0, nu, nv, xyz) -> {
            for (int b = 0; b < nv; b++) {
                for (int a = 0; a < nu; a++) GridTestSurfaces.jitteredVertex(i0 + a, j0 + b, faceNu, faceNv, xyz, 3 * (b * nu + a));
            }
        };
    }

    @ParameterizedTest(name = "{0} x {1} in pieces of {2}")
    @CsvSource({"2, 2, 17", "17, 17, 17", "18, 17, 17", "65, 65, 17", "100, 37, 17", "4097, 3, 17", "9, 33, 2", "257, 257, 9"})
    void piecesTileTheGridSharingTheirBoundaries(int nu, int nv, int side) {
        GridPieces p = new GridPieces(nu, nv, side);
        assertEquals(p.columns() * p.rows(), p.count());
        assertEquals((nu - 1 + side - 2) / (side - 1), p.columns(), "as few columns as the size allows");
        for (int k = 0; k < p.count(); k++) {
            int c = k % p.columns(), r = k / p.columns();
            assertTrue(p.i1(k) - p.i0(k) + 1 <= side && p.j1(k) - p.j0(k) + 1 <= side, "piece " + k);
            assertTrue(p.i1(k) > p.i0(k) && p.j1(k) > p.j0(k), "piece " + k + " has a cell");
            assertEquals(c == 0 ? 0 : p.i1(k - 1), p.i0(k), "shares its left neighbour's last column");
            assertEquals(r == 0 ? 0 : p.j1(k - p.columns()), p.j0(k), "shares the row below's last row");
            if (c == p.columns() - 1) assertEquals(nu - 1, p.i1(k));
            if (r == p.rows() - 1) assertEquals(nv - 1, p.j1(k));
            int cells = p.i1(k) - p.i0(k), first = p.i1(0) - p.i0(0);
            assertTrue(Math.abs(cells - first) <= 1, "cells spread evenly");
        }
        for (int j = 0; j < nv - 1; j += Math.max(1, nv / 50)) {
            for (int i = 0; i < nu - 1; i += Math.max(1, nu / 50)) {
                int k = p.pieceOfCell(i, j);
                assertTrue(p.i0(k) <= i && i < p.i1(k) && p.j0(k) <= j && j < p.j1(k), "cell " + i + ", " + j + " in piece " + k);
            }
        }
    }

    /**
     * 65: pieces starting at even columns and rows; 51: some at odd ones. Each cell takes its diagonal from its own
     * four vertices, so a piece cuts it as the whole grid does wherever the piece starts, on smooth and jittered
     * faces alike.
     */
    @ParameterizedTest(name = "{0} x {0}, jittered {1}")
    @CsvSource({"65, false", "51, false", "65, true", "51, true"})
    void builtPiecesAnswerEveryRayAsTheWholeGrid(int n, boolean jittered) {
        GridPieces pieces = new GridPieces(n, n, 17);
        GridPieces.Source source = jittered ? jitteredSource(n, n) : bumpySource(n, n);
        GridPatch[] built = new GridPatch[pieces.count()];
        for (int k = 0; k < built.length; k++) built[k] = pieces.build(k, source, 5);
        assertEquals(16, built.length);
        GridPatch whole = new GridPatch(n, n, jittered ? GridTestSurfaces.jittered(n, n) : GridTestSurfaces.bumpy(n, n), null, null, 5);
        // the pieces hold exactly the whole grid's triangles, corner for corner
        boolean odd = false;
        int alongV1V3 = 0;
        for (int k = 0; k < built.length; k++) {
            GridPatch g = built[k];
            int i0 = pieces.i0(k), j0 = pieces.j0(k);
            odd |= ((i0 + j0) & 1) == 1;
            for (int s = 0; s < g.triangleCount(); s++) {
                if ((s & 1) == 0 && !g.cutAlongV0V2(g.cellI(s), g.cellJ(s))) alongV1V3++;
                int ws = 2 * ((j0 + g.cellJ(s)) * (n - 1) + i0 + g.cellI(s)) + (s & 1);
                for (int c = 0; c < 3; c++) {
                    int v = g.triangleVertex(s, c), w = whole.triangleVertex(ws, c);
                    assertEquals(w, (j0 + v / g.nu()) * n + i0 + v % g.nu(), "piece " + k + " triangle " + s + " corner " + c);
                }
            }
        }
        assertEquals(n == 51, odd, "some piece starts at an odd i0 + j0");
        int cells = (n - 1) * (n - 1);
        assertTrue(alongV1V3 > cells / 5 && alongV1V3 < 4 * cells / 5, alongV1V3 + " of " + cells + " cells cut along v1-v3");
        // neighbours hold the same floats on their shared column and row
        for (int k = 0; k < built.length; k++) {
            if (k % pieces.columns() > 0) {
                GridPatch a = built[k - 1], b = built[k];
                for (int j = 0; j < b.nv(); j++) for (int ax = 0; ax < 3; ax++) assertEquals(a.x(a.nu() - 1, j, ax), b.x(0, j, ax));
            }
        }
        TraversalScratch ctx = new TraversalScratch();
        PrimitiveHit h = new PrimitiveHit(), w = new PrimitiveHit();
        double[] uv = new double[2], wuv = new double[2];
        Random rnd = new Random(11);
        Ray ray = new Ray();
        int hits = 0;
        for (int r = 0; r < 4000; r++) {
            double tx = rnd.nextDouble(), ty = rnd.nextDouble(), tz = GridTestSurfaces.bump(tx, ty);
            if (r % 3 == 0) { // at a vertex on a piece boundary
                int c = rnd.nextInt(pieces.columns() + 1);
                int i = c == pieces.columns() ? n - 1 : pieces.i0(c), j = rnd.nextInt(n);
                tx = whole.x(i, j, 0); ty = whole.x(i, j, 1); tz = whole.x(i, j, 2);
            }
            double ox = tx + 0.5 * rnd.nextGaussian(), oy = ty + 0.5 * rnd.nextGaussian(), oz = 1 + rnd.nextDouble();
            ray.set(ox, oy, oz, tx - ox, ty - oy, tz - oz, 0, Double.POSITIVE_INFINITY);
            boolean hw = whole.intersect(ray, w, ctx);
            double best = Double.POSITIVE_INFINITY;
            int bestPiece = -1, bestSub = -1;
            for (int k = 0; k < built.length; k++) {
                if (built[k].intersect(ray, h, ctx) && h.t < best) {
                    best = h.t;
                    bestPiece = k;
                    bestSub = h.sub;
                    built[k].parameters(h.sub, h.u, h.v, uv);
                }
            }
            assertEquals(hw, bestPiece >= 0, "ray " + r);
            if (!hw) continue;
            hits++;
            assertEquals(w.t, best, "ray " + r);
            GridPatch g = built[bestPiece];
            int fi = pieces.i0(bestPiece) + g.cellI(bestSub), fj = pieces.j0(bestPiece) + g.cellJ(bestSub);
            whole.parameters(w.sub, w.u, w.v, wuv);
            if (fi == whole.cellI(w.sub) && fj == whole.cellJ(w.sub) && (bestSub & 1) == (w.sub & 1)) {
                assertEquals(wuv[0], uv[0], 1e-12, "face parameter u");
                assertEquals(wuv[1], uv[1], 1e-12, "face parameter v");
            } else { // a tie on a shared edge: the same point
                assertEquals(wuv[0], uv[0], 1e-6);
                assertEquals(wuv[1], uv[1], 1e-6);
            }
        }
        assertTrue(hits > 3000, hits + " hits");
    }

    @Test
    void aPieceLiesInsideTheBoundSuppliedBeforeItIsBuilt() {
        int nu = 100, nv = 37;
        GridPieces pieces = new GridPieces(nu, nv, 17);
        GridPieces.Source source = bumpySource(nu, nv);
        // the tightest bound in double: the evaluated vertices' own box (a real supplier bounds the control points);
        // the stored floats may round outside it, which the outward widening covers
        GridPieces.BoundSupplier tight = (i0, j0, i1, j1, out) -> {
            int a = i1 - i0 + 1, b = j1 - j0 + 1;
            double[] xyz = new double[3 * a * b];
            source.positions(i0, j0, a, b, xyz);
            for (int k = 0; k < 3; k++) { out[k] = Double.POSITIVE_INFINITY; out[k + 3] = Double.NEGATIVE_INFINITY; }
            for (int q = 0; q < xyz.length; q += 3) {
                for (int k = 0; k < 3; k++) { out[k] = Math.min(out[k], xyz[q + k]); out[k + 3] = Math.max(out[k + 3], xyz[q + k]); }
            }
        };
        GridPieces.BoundSupplier analytic = (i0, j0, i1, j1, out) -> {
            out[0] = (double) i0 / (nu - 1); out[1] = (double) j0 / (nv - 1); out[2] = -0.1;
            out[3] = (double) i1 / (nu - 1); out[4] = (double) j1 / (nv - 1); out[5] = 0.1;
        };
        double[] bound = new double[6], box = new double[6];
        for (GridPieces.BoundSupplier s : new GridPieces.BoundSupplier[] {tight, analytic}) {
            for (int k = 0; k < pieces.count(); k++) {
                pieces.bound(k, s, bound);
                GridPatch g = pieces.build(k, source, 3);
                g.bounds(box);
                for (int a = 0; a < 3; a++) {
                    assertTrue(bound[a] <= box[a] && box[a + 3] <= bound[a + 3], "piece " + k + " axis " + a);
                    assertEquals(bound[a], (float) bound[a], "the bound is in floats");
                }
            }
        }
    }

    @Test
    void rejectsBadSizes() {
        assertThrows(IllegalArgumentException.class, () -> new GridPieces(1, 5, 17));
        assertThrows(IllegalArgumentException.class, () -> new GridPieces(5, GridPatch.MAX_SIDE + 1, 17));
        assertThrows(IllegalArgumentException.class, () -> new GridPieces(5, 5, 1));
    }
}
