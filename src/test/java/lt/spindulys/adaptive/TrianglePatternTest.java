package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

class TrianglePatternTest {

    @Test
    void numberingAndCorners() {
        TrianglePattern p = new TrianglePattern(5, 3, 4);
        assertEquals(5, p.rate());
        assertEquals(21, p.vertexCount());
        assertEquals(25, p.triangleCount());
        for (int n = 0; n < p.vertexCount(); n++) {
            int[] ij = p.ij(n);
            assertEquals(n, p.vertex(ij[0], ij[1]));
        }
        // Triangles: every (i, j) decoded agrees with an explicit walk over the rows.
        int[] got = new int[6];
        int t = 0;
        for (int j = 0; j < 5; j++) {
            for (int i = 0; i < 5 - j; i++) {
                p.triangleIJ(t++, got);
                assertArrayEquals(new int[] {i, j, i + 1, j, i, j + 1}, got, "up " + i + ", " + j);
                if (i < 4 - j) {
                    p.triangleIJ(t++, got);
                    assertArrayEquals(new int[] {i + 1, j, i + 1, j + 1, i, j + 1}, got, "down " + i + ", " + j);
                }
            }
        }
        assertEquals(25, t);
        // Bfr's corners: (0, 0), (1, 0), (0, 1), on every edge they bound.
        assertEquals(0.0, p.u(0, 0));
        assertEquals(1.0, p.u(5, 0));
        assertEquals(0.0, p.v(5, 0));
        assertEquals(1.0, p.v(0, 5));
        assertEquals(0.0, p.u(0, 5));
        assertEquals(p.vertex(5, 0), p.edgeVertex(1, 0));
        assertEquals(p.vertex(0, 5), p.edgeVertex(2, 0));
        assertEquals(p.vertex(0, 0), p.edgeVertex(2, 5));
        assertThrows(IllegalArgumentException.class, () -> p.vertex(3, 3));
        assertThrows(IllegalArgumentException.class, () -> new TrianglePattern(1, 0, 1));
    }

    @Test
    void rowsAreFoundAtTheirBoundsForLargeRates() {
        int[] got = new int[6];
        for (int r : new int[] {1, 2, 3, 97, 4096}) {
            TrianglePattern p = new TrianglePattern(r, 1, r);
            for (int j = 0; j < r; j += Math.max(1, r / 50)) {
                int start = j * (2 * r - j);
                p.triangleIJ(start, got);
                assertArrayEquals(new int[] {0, j, 1, j, 0, j + 1}, got, "first of row " + j + " at rate " + r);
                if (j > 0) {
                    p.triangleIJ(start - 1, got);
                    assertArrayEquals(new int[] {r - j, j - 1, r - j + 1, j - 1, r - j, j}, got, "last of row " + (j - 1) + " at rate " + r);
                }
            }
            p.triangleIJ(r * r - 1, got);
            assertArrayEquals(new int[] {0, r - 1, 1, r - 1, 0, r}, got, "the top at rate " + r);
        }
    }

    /** (c) for Loop triangles. */
    @Test
    void theTrianglesCoverTheTriangleExactlyOnce() {
        SplittableRandom rnd = new SplittableRandom(17);
        int zero = 0;
        for (int a = 1; a <= 7; a++) for (int b = 1; b <= 7; b++) for (int c = 1; c <= 7; c++) {
            zero += Triangulations.check(Triangulations.of(new TrianglePattern(a, b, c)), rnd, 3);
        }
        assertTrue(zero > 0);
        for (int n = 0; n < 30; n++) {
            Triangulations.check(Triangulations.of(new TrianglePattern(1 + rnd.nextInt(30), 1 + rnd.nextInt(30), 1 + rnd.nextInt(30))), rnd, 2);
        }
        assertEquals(0, new TrianglePattern(9, 9, 9).zeroAreaTriangles());
        // Nearly equal rates: lattice scales near R³, exact only in 128-bit products.
        assertEquals(1 + 3, Triangulations.check(Triangulations.of(new TrianglePattern(64, 63, 61)), rnd, 0));
        TrianglePattern big = new TrianglePattern(4096, 4095, 4093);
        assertTrue(big.vScale() > 1L << 35, "scale " + big.vScale());
        assertEquals(1 + 3, big.zeroAreaTriangles(), "one per collapsed grid segment");
    }

    /** The points of triangle edge {@code edge}, as parameters c / R along the control edge. */
    static List<Long> controlEdgeParameters(TrianglePattern p, int edge, boolean forwards) {
        List<Long> out = new ArrayList<>();
        int r = p.edgeRate(edge);
        for (int k = 0; k <= p.rate(); k++) {
            int[] ij = p.ij(p.edgeVertex(edge, k));
            double u = p.u(ij[0], ij[1]), v = p.v(ij[0], ij[1]);
            // Along edge 0 u rises, along edge 1 v rises, along edge 2 v falls.
            double along = edge == 0 ? u : v;
            long n = Math.round(along * r);
            assertEquals(Double.doubleToRawLongBits((double) n / r), Double.doubleToRawLongBits(along), p + ": an exact quotient");
            if (edge == 1) assertEquals(Double.doubleToRawLongBits((double) (r - n) / r), Double.doubleToRawLongBits(u), p + ": u on edge 1");
            long local = edge < 2 ? n : r - n;
            long c = forwards ? local : r - local;
            long bits = Double.doubleToRawLongBits((double) c / r);
            if (out.isEmpty() || out.get(out.size() - 1) != bits) out.add(bits);
        }
        return out;
    }

    /** (a) for Loop triangles: two triangles sharing an edge, in every slot and both orientations. */
    @Test
    void aSharedEdgeHasTheSameParametersFromBothTriangles() {
        SplittableRandom rnd = new SplittableRandom(19);
        for (int shared : new int[] {1, 2, 4, 7, 30}) {
            for (int ea = 0; ea < 3; ea++) {
                for (int eb = 0; eb < 3; eb++) {
                    for (boolean opposite : new boolean[] {true, false}) {
                        int[] ra = {1 + rnd.nextInt(40), 1 + rnd.nextInt(40), 1 + rnd.nextInt(40)}, rb = {1 + rnd.nextInt(40), 1 + rnd.nextInt(40), 1 + rnd.nextInt(40)};
                        ra[ea] = shared;
                        rb[eb] = shared;
                        TrianglePattern a = new TrianglePattern(ra[0], ra[1], ra[2]), b = new TrianglePattern(rb[0], rb[1], rb[2]);
                        List<Long> pa = controlEdgeParameters(a, ea, true), pb = controlEdgeParameters(b, eb, !opposite);
                        if (opposite) Collections.reverse(pb);
                        assertEquals(shared + 1, pa.size());
                        assertEquals(pa, pb, a + " / " + b + " edges " + ea + ", " + eb);
                    }
                }
            }
        }
    }
}
