package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigInteger;
import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;

/**
 * Checks that a tessellation pattern's triangles tile its parameter domain exactly once, in exact
 * integer arithmetic on the patterns' lattice coordinates.
 */
final class Triangulations {
    private Triangulations() {}

    /** A pattern seen as vertices with exact coordinates U / uScale, V / vScale and triangles. */
    interface View {
        int vertexCount();
        int triangleCount();
        void triangle(int t, int[] out);
        long u(int vertex);
        long v(int vertex);
        long uScale();
        long vScale();
        double uDouble(int vertex);
        double vDouble(int vertex);
        /** Doubled area of the domain: 2 for the unit square, 1 for the unit triangle. */
        int doubledDomainArea();
        /** Corners of the domain: (0,0), (1,0), (1,1), (0,1) or (0,0), (1,0), (0,1). */
        int edges();
        int gridRate(int edge);
        int edgeVertex(int edge, int k);
        boolean isSnapped(int edge);
        int orientation(int t);
        int zeroAreaTriangles();
    }

    static View of(GridPattern g) {
        int w = g.columns() + 1;
        return new View() {
            public int vertexCount() { return g.vertexCount(); }
            public int triangleCount() { return g.triangleCount(); }
            public void triangle(int t, int[] out) { g.triangle(t, out); }
            public long u(int n) { return g.uLattice(n % w, n / w); }
            public long v(int n) { return g.vLattice(n % w, n / w); }
            public long uScale() { return g.uScale(); }
            public long vScale() { return g.vScale(); }
            public double uDouble(int n) { return g.u(n % w, n / w); }
            public double vDouble(int n) { return g.v(n % w, n / w); }
            public int doubledDomainArea() { return 2; }
            public int edges() { return 4; }
            public int gridRate(int e) { return g.gridRate(e); }
            public int edgeVertex(int e, int k) { return g.edgeVertex(e, k); }
            public boolean isSnapped(int e) { return g.isSnapped(e); }
            public int orientation(int t) { return g.orientation(t); }
            public int zeroAreaTriangles() { return g.zeroAreaTriangles(); }
            @Override public String toString() { return g.toString(); }
        };
    }

    static View of(TrianglePattern p) {
        return new View() {
            public int vertexCount() { return p.vertexCount(); }
            public int triangleCount() { return p.triangleCount(); }
            public void triangle(int t, int[] out) { p.triangle(t, out); }
            public long u(int n) { int[] ij = p.ij(n); return p.uLattice(ij[0], ij[1]); }
            public long v(int n) { int[] ij = p.ij(n); return p.vLattice(ij[0], ij[1]); }
            public long uScale() { return p.uScale(); }
            public long vScale() { return p.vScale(); }
            public double uDouble(int n) { int[] ij = p.ij(n); return p.u(ij[0], ij[1]); }
            public double vDouble(int n) { int[] ij = p.ij(n); return p.v(ij[0], ij[1]); }
            public int doubledDomainArea() { return 1; }
            public int edges() { return 3; }
            public int gridRate(int e) { return p.rate(); }
            public int edgeVertex(int e, int k) { return p.edgeVertex(e, k); }
            public boolean isSnapped(int e) { return p.isSnapped(e); }
            public int orientation(int t) { return p.orientation(t); }
            public int zeroAreaTriangles() { return p.zeroAreaTriangles(); }
            @Override public String toString() { return p.toString(); }
        };
    }

    private static long key(int a, int b) { return (long) a << 32 | b; }

    /**
     * Checks: the exact signed areas sum to the domain's, none is negative; every directed edge
     * is used once at most, an interior edge once each way and a boundary segment once, in the
     * domain's counter-clockwise direction; zero-area triangles touch a transition edge and are
     * counted by the pattern; every vertex coordinate is its lattice value as a double, bit for bit
     * the quotient of its integers; random points lie in exactly one positive triangle.
     *
     * @return the zero-area triangles
     */
    static int check(View p, SplittableRandom rnd, int samples) {
        int n = p.triangleCount(), nv = p.vertexCount();
        long su = p.uScale(), sv = p.vScale();
        long[] u = new long[nv], v = new long[nv];
        boolean[] snapped = new boolean[nv];
        for (int i = 0; i < nv; i++) {
            u[i] = p.u(i);
            v[i] = p.v(i);
            assertTrue(u[i] >= 0 && u[i] <= su && v[i] >= 0 && v[i] <= sv, p + ": vertex " + i + " inside the domain");
            assertEquals(Double.doubleToRawLongBits((double) u[i] / su), Double.doubleToRawLongBits(p.uDouble(i)), p + ": u of " + i);
            assertEquals(Double.doubleToRawLongBits((double) v[i] / sv), Double.doubleToRawLongBits(p.vDouble(i)), p + ": v of " + i);
        }
        Map<Long, Integer> directed = new HashMap<>();
        for (int e = 0; e < p.edges(); e++) {
            for (int k = 0; k <= p.gridRate(e); k++) if (p.isSnapped(e)) snapped[p.edgeVertex(e, k)] = true;
        }
        BigInteger sum = BigInteger.ZERO;
        int[] t3 = new int[3];
        int zero = 0;
        for (int t = 0; t < n; t++) {
            p.triangle(t, t3);
            BigInteger cross = BigInteger.valueOf(u[t3[1]] - u[t3[0]]).multiply(BigInteger.valueOf(v[t3[2]] - v[t3[0]]))
                    .subtract(BigInteger.valueOf(u[t3[2]] - u[t3[0]]).multiply(BigInteger.valueOf(v[t3[1]] - v[t3[0]])));
            assertTrue(cross.signum() >= 0, p + ": triangle " + t + " is inverted");
            assertEquals(cross.signum(), p.orientation(t), p + ": orientation of " + t);
            if (cross.signum() == 0) {
                zero++;
                assertTrue(snapped[t3[0]] || snapped[t3[1]] || snapped[t3[2]], p + ": zero-area triangle " + t + " away from transition edges");
            }
            sum = sum.add(cross);
            for (int k = 0; k < 3; k++) {
                Integer old = directed.put(key(t3[k], t3[(k + 1) % 3]), t);
                assertTrue(old == null, p + ": directed edge " + t3[k] + "-" + t3[(k + 1) % 3] + " in triangles " + old + " and " + t);
            }
        }
        assertEquals(BigInteger.valueOf(su).multiply(BigInteger.valueOf(sv)).multiply(BigInteger.valueOf(p.doubledDomainArea())), sum, p + ": total area");
        assertEquals(zero, p.zeroAreaTriangles(), p + ": zero-area count");
        // Boundary: each segment along the edges once, in the edge's direction, never the other way.
        int boundary = 0;
        for (int e = 0; e < p.edges(); e++) {
            for (int k = 0; k < p.gridRate(e); k++) {
                int a = p.edgeVertex(e, k), b = p.edgeVertex(e, k + 1);
                assertTrue(directed.containsKey(key(a, b)), p + ": boundary segment " + e + "/" + k);
                assertTrue(!directed.containsKey(key(b, a)), p + ": boundary segment " + e + "/" + k + " used from outside");
                boundary++;
            }
        }
        // Interior: every other directed edge has its twin.
        int unpaired = 0;
        for (long k : directed.keySet()) if (!directed.containsKey(key((int) k, (int) (k >>> 32)))) unpaired++;
        assertEquals(boundary, unpaired, p + ": edges used by one triangle are exactly the boundary segments");
        // Random points: in exactly one triangle of positive area (barycentric test in doubles,
        // margins far above rounding).
        for (int s = 0; s < samples; s++) {
            double x = rnd.nextDouble(), y = rnd.nextDouble();
            if (p.edges() == 3 && x + y > 1) { x = 1 - x; y = 1 - y; }
            int inside = 0;
            for (int t = 0; t < n; t++) {
                p.triangle(t, t3);
                double ax = p.uDouble(t3[0]), ay = p.vDouble(t3[0]), bx = p.uDouble(t3[1]), by = p.vDouble(t3[1]), cx = p.uDouble(t3[2]), cy = p.vDouble(t3[2]);
                double d = (bx - ax) * (cy - ay) - (cx - ax) * (by - ay);
                if (!(d > 0)) continue;
                double l1 = ((bx - x) * (cy - y) - (cx - x) * (by - y)) / d, l2 = ((cx - x) * (ay - y) - (ax - x) * (cy - y)) / d, l3 = 1 - l1 - l2;
                if (l1 > 1e-9 && l2 > 1e-9 && l3 > 1e-9) inside++;
                else if (l1 > -1e-9 && l2 > -1e-9 && l3 > -1e-9) { inside = -1000; break; } // on an edge: skip the sample
            }
            if (inside >= 0) assertEquals(1, inside, p + ": point " + x + ", " + y);
        }
        return zero;
    }
}
