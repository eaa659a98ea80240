package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Placement;

class FacePatternTest {
    static final int W = 300, H = 200;
    static final PinholeCamera PINHOLE = EdgeLevelsTest.PINHOLE;

    @Test
    void aQuadIsOneGridAndOtherPolygonsHaveSubFaces() {
        FacePattern q = FacePattern.polygon(68, 19, 60, 17);
        assertTrue(!q.hasSubFaces());
        assertEquals(1, q.subFaceCount());
        assertEquals(68, q.subFace(0).columns());
        assertEquals(19, q.subFace(0).rows());
        assertEquals(2 * 68 * 19, q.triangleCount());
        assertEquals(2, q.baseEdge(0, 2));
        assertThrows(IllegalStateException.class, () -> q.spokeRate(0));

        FacePattern p = FacePattern.polygon(4, 6, 2, 8, 10);
        assertTrue(p.hasSubFaces());
        assertEquals(5, p.subFaceCount());
        // Spoke k: half the larger of base edges k - 1 and k + 1.
        assertEquals(5, p.spokeRate(0), "edges 4 and 1: max(10, 6) / 2");
        assertEquals(4, p.spokeRate(2), "edges 1 and 3: max(6, 8) / 2");
        GridPattern s0 = p.subFace(0);
        assertEquals(2, s0.edgeRate(0), "half of base edge 0");
        assertEquals(5, s0.edgeRate(3), "half of base edge 4");
        assertEquals(p.spokeRate(0), s0.edgeRate(1));
        assertEquals(p.spokeRate(4), s0.edgeRate(2));
        assertEquals(-1, p.baseEdge(0, 1));
        assertEquals(4, p.baseEdge(0, 3));
        assertThrows(IllegalArgumentException.class, () -> p.basePoint(0, 2, 0));
        assertThrows(IllegalArgumentException.class, () -> FacePattern.polygon(4, 5, 2));
        assertThrows(IllegalArgumentException.class, () -> FacePattern.polygon(4, 4));
    }

    /** (c) for every sub-face, and (d): base-edge halves, midpoints, spokes and the centre. */
    @Test
    void subFacesMeetEachOtherAndTheNeighbouringQuads() {
        SplittableRandom rnd = new SplittableRandom(23);
        for (int[] rates : new int[][] {{4, 6, 2, 8, 10}, {2, 2, 2}, {16, 2, 6}, {2, 40, 2, 12, 2, 8}, {4096, 2, 4096, 2, 2}}) {
            FacePattern p = FacePattern.polygon(rates);
            int n = rates.length;
            for (int k = 0; k < n; k++) {
                GridPattern s = p.subFace(k), next = p.subFace((k + 1) % n);
                if (s.vertexCount() < 5000) Triangulations.check(Triangulations.of(s), rnd, 2);
                // The centre is corner 2 of every sub-face.
                assertEquals(1.0, s.u(s.columns(), s.rows()));
                assertEquals(1.0, s.v(s.columns(), s.rows()));
                // Edge k's midpoint: corner 1 of sub-face k, corner 3 of sub-face k + 1, point R / 2 of the edge.
                assertEquals(rates[k] / 2, p.basePoint(k, 0, s.gridRate(0)));
                assertEquals(rates[k] / 2, p.basePoint((k + 1) % n, 3, 0));
                assertEquals(1.0, s.u(s.columns(), 0));
                assertEquals(0.0, s.v(s.columns(), 0));
                assertEquals(0.0, next.u(0, next.rows()));
                assertEquals(1.0, next.v(0, next.rows()));
                // The spoke from edge k's midpoint: sub-face k's edge 1 (v rising) and sub-face k + 1's
                // edge 2 read backwards (u rising), the same vertices at the same parameters.
                int spoke = p.spokeRate(k);
                assertEquals(spoke, s.rows());
                assertEquals(spoke, next.columns());
                assertTrue(!s.isSnapped(1) && !s.isSnapped(2) && !next.isSnapped(1) && !next.isSnapped(2), "spokes are never transition edges");
                for (int m = 0; m <= spoke; m++) {
                    assertEquals(Double.doubleToRawLongBits(s.v(s.columns(), m)), Double.doubleToRawLongBits(next.u(m, next.rows())), "spoke " + k + " vertex " + m);
                }
                // Base edge k, in the face's direction: the first half then the second, every point once, in order.
                List<Integer> along = basePoints(p, k);
                assertEquals(rates[k] + 1, along.size(), "base edge " + k + " of " + p);
                for (int c = 0; c <= rates[k]; c++) assertEquals(c, along.get(c));
                // A neighbouring quad across edge k (running it the other way, its other rates anything):
                // it takes the same points, and the same parameters c / R along the control edge.
                int slot = rnd.nextInt(4);
                int[] qr = {1 + rnd.nextInt(60), 1 + rnd.nextInt(60), 1 + rnd.nextInt(60), 1 + rnd.nextInt(60)};
                qr[slot] = rates[k];
                GridPattern quad = FacePattern.quad(qr[0], qr[1], qr[2], qr[3]).subFace(0);
                List<Long> fromQuad = GridPatternTest.bits(GridPatternTest.controlEdgeParameters(quad, slot, false));
                java.util.Collections.reverse(fromQuad);
                List<Long> fromPolygon = new ArrayList<>();
                for (int c : along) fromPolygon.add(Double.doubleToRawLongBits((double) c / rates[k]));
                assertEquals(fromPolygon, fromQuad, "edge " + k + " of " + p + " against " + quad);
            }
        }
    }

    /** The base edge's points along base edge k from the face's sub-faces, repeats dropped. */
    static List<Integer> basePoints(FacePattern p, int k) {
        int n = p.size();
        List<Integer> out = new ArrayList<>();
        GridPattern first = p.subFace(k), second = p.subFace((k + 1) % n);
        for (int m = 0; m <= first.gridRate(0); m++) add(out, p.basePoint(k, 0, m));
        for (int m = 0; m <= second.gridRate(3); m++) add(out, p.basePoint((k + 1) % n, 3, m));
        return out;
    }

    private static void add(List<Integer> out, int c) {
        if (out.isEmpty() || out.get(out.size() - 1) != c) {
            assertTrue(out.isEmpty() || c == out.get(out.size() - 1) + 1, "points in order: " + out + " then " + c);
            out.add(c);
        }
    }

    /** (e) The triangles of a few face shapes: the power-of-two level's against the rates'. */
    @Test
    void fewerTrianglesThanThePowerOfTwoLevel() {
        int[][] quads = {{68, 19, 68, 19}, {68, 19, 40, 12}, {100, 100, 100, 100}, {130, 130, 130, 130}, {200, 3, 200, 3}, {5, 5, 5, 5}, {1, 1, 1, 1}};
        StringBuilder table = new StringBuilder("FacePatternTest: triangles, power-of-two level -> rates (zero-area)\n");
        for (int[] r : quads) {
            FacePattern p = FacePattern.quad(r[0], r[1], r[2], r[3]);
            long old = FacePattern.powerOfTwoTriangles(r);
            assertTrue(p.triangleCount() <= old);
            table.append(String.format(Locale.ROOT, "  quad  %-20s %7d -> %6d (%d)%n", java.util.Arrays.toString(r), old, p.triangleCount(), p.zeroAreaTriangles()));
        }
        assertEquals(2 * 68 * 19, FacePattern.quad(68, 19, 68, 19).triangleCount());
        assertEquals(2L * 128 * 128, FacePattern.powerOfTwoTriangles(68, 19, 68, 19));
        assertEquals(2 * 200 * 3, FacePattern.quad(200, 3, 200, 3).triangleCount());
        assertEquals(2L * 256 * 256, FacePattern.powerOfTwoTriangles(200, 3, 200, 3));
        for (int[] r : new int[][] {{10, 20, 8, 30, 16}, {68, 20, 20}, {2, 2, 2, 2, 2, 2}}) {
            FacePattern p = FacePattern.polygon(r);
            long old = FacePattern.powerOfTwoTriangles(r);
            assertTrue(p.triangleCount() <= old);
            table.append(String.format(Locale.ROOT, "  %d-gon %-20s %7d -> %6d (%d)%n", r.length, java.util.Arrays.toString(r), old, p.triangleCount(), p.zeroAreaTriangles()));
        }
        // Loop: a triangle at level l has 4^l triangles.
        for (int[] r : new int[][] {{68, 19, 60}, {20, 20, 20}, {100, 3, 100}}) {
            TrianglePattern t = new TrianglePattern(r[0], r[1], r[2]);
            int l = 32 - Integer.numberOfLeadingZeros(t.rate() - 1);
            long old = 1L << (2 * l);
            assertTrue(t.triangleCount() <= old);
            table.append(String.format(Locale.ROOT, "  Loop  %-20s %7d -> %6d (%d)%n", java.util.Arrays.toString(r), old, t.triangleCount(), t.zeroAreaTriangles()));
        }
        System.out.print(table);
    }

    @Test
    void aLongNarrowFaceGetsItsOwnResolutionNotAPowerOfTwoSquare() {
        ViewFootprint v = ViewFootprint.of(PINHOLE, W, H);
        // A rectangle facing the camera at the image centre, 10 units away, about 68 x 19 pixels.
        double perUnit = v.subtendedPixels(1, 2, -7, 2, 2, -7, 4);
        double hw = 67.5 / perUnit / 2, hh = 18.6 / perUnit / 2;
        double[] pos = {1 - hw, 2 - hh, -7, 1 + hw, 2 - hh, -7, 1 + hw, 2 + hh, -7, 1 - hw, 2 + hh, -7};
        int[] ev = {0, 1, 1, 2, 2, 3, 3, 0};
        int[] rates = EdgeRates.perEdge(v, pos, ev, Placement.IDENTITY, 1, 4096, 4);
        for (int e : new int[] {0, 2}) assertTrue(rates[e] >= 68 && rates[e] <= 70, "long side " + rates[e]);
        for (int e : new int[] {1, 3}) assertTrue(rates[e] >= 19 && rates[e] <= 20, "short side " + rates[e]);
        FacePattern p = FacePattern.quad(rates[0], rates[1], rates[2], rates[3]);
        assertTrue(p.triangleCount() <= 1.1 * 68 * 19 * 2, p.triangleCount() + " triangles");
        assertEquals(0, p.zeroAreaTriangles());
        int[] levels = EdgeLevels.perEdge(v, pos, ev, Placement.IDENTITY, 1, 12, 4);
        int faceLevel = Math.max(Math.max(levels[0], levels[1]), Math.max(levels[2], levels[3]));
        assertEquals(7, faceLevel);
        assertEquals(2L * 128 * 128, FacePattern.powerOfTwoTriangles(rates));
        assertTrue(p.triangleCount() * 12 < FacePattern.powerOfTwoTriangles(rates), "more than 12 times fewer");
        System.out.println("FacePatternTest: a face of about 68 x 19 pixels at target 1: rates " + java.util.Arrays.toString(rates) + ", "
                + p.triangleCount() + " triangles; levels " + java.util.Arrays.toString(levels) + ", " + FacePattern.powerOfTwoTriangles(rates) + " triangles");
    }
}
