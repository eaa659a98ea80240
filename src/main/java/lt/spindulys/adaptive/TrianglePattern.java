package lt.spindulys.adaptive;

/**
 * The tessellation pattern of one Loop triangle from its three edge rates: a regular triangular
 * grid of uniform inner rate R = the largest edge rate, with the vertices on coarser edges snapped
 * onto those edges' own points exactly as {@link GridPattern} does for quads (the same
 * {@link GridPattern#snap} rule, so an edge shared by two triangles gets the same points from
 * both). Topology implicit; immutable and O(1) in size.
 *
 * <p><b>Parameterization</b> (OpenSubdiv Bfr's triangle): corners 0, 1, 2 at (u, v) = (0, 0),
 * (1, 0), (0, 1); edge k from corner k to k + 1. Vertex (i, j), i + j &le; R, is at (i / R,
 * j / R); edge 0 is j = 0 (k-th vertex (k, 0)), edge 1 is i + j = R (k-th vertex (R - k, k)),
 * edge 2 is i = 0 (k-th vertex (0, R - k)). On a transition edge of rate r the k-th vertex takes
 * the edge's point c = snap(k, R, r): (c / r, 0) on edge 0, ((r - c) / r, c / r) on edge 1 and
 * (0, (r - c) / r) on edge 2, each coordinate a correctly rounded quotient of two integers.
 *
 * <p><b>Numbering.</b> Row j holds vertices (0, j) .. (R - j, j), numbered from j (R + 1) -
 * j (j - 1) / 2. Row j (0 &le; j &lt; R) holds 2 (R - j) - 1 triangles, from j (2R - j): the q-th,
 * q = 2i, is the upward (i, j), (i + 1, j), (i, j + 1), and q = 2i + 1 the downward (i + 1, j),
 * (i + 1, j + 1), (i, j + 1); all counter-clockwise in (u, v). R² triangles in all.
 */
public final class TrianglePattern {
    private final int r0, r1, r2, r;
    private final long uScale, vScale;

    /**
     * The pattern of a triangle with the given edge rates.
     *
     * @param r0 rate of edge 0 (corner 0 to 1), 1 to {@link EdgeRates#MAX_RATE}
     * @param r1 rate of edge 1 (corner 1 to 2)
     * @param r2 rate of edge 2 (corner 2 to 0)
     * @throws IllegalArgumentException if a rate is out of range
     */
    public TrianglePattern(int r0, int r1, int r2) {
        GridPattern.checkRate(r0, 0);
        GridPattern.checkRate(r1, 1);
        GridPattern.checkRate(r2, 2);
        this.r0 = r0;
        this.r1 = r1;
        this.r2 = r2;
        r = Math.max(r0, Math.max(r1, r2));
        uScale = GridPattern.lcm(GridPattern.lcm(r, r0), r1);
        vScale = GridPattern.lcm(GridPattern.lcm(r, r1), r2);
    }

    /** {@return R, the inner rate: the largest edge rate} */
    public int rate() { return r; }

    /** {@return the rate of edge {@code edge} (0 to 2)} */
    public int edgeRate(int edge) {
        switch (edge) {
            case 0: return r0;
            case 1: return r1;
            case 2: return r2;
            default: throw new IllegalArgumentException("a triangle has edges 0 to 2, not " + edge);
        }
    }

    /** {@return true if edge {@code edge} is a transition edge: its rate is below R} */
    public boolean isSnapped(int edge) { return edgeRate(edge) < r; }

    /** {@return the vertices, (R + 1)(R + 2) / 2} */
    public int vertexCount() { return (r + 1) * (r + 2) / 2; }

    /** {@return the triangles, R² (zero-area ones included)} */
    public int triangleCount() { return r * r; }

    /**
     * The number of vertex (i, j).
     *
     * @param i 0 to R - j
     * @param j 0 to R
     * @return its number
     */
    public int vertex(int i, int j) {
        checkVertex(i, j);
        return j * (r + 1) - j * (j - 1) / 2 + i;
    }

    private void checkVertex(int i, int j) {
        if (i < 0 || j < 0 || i + j > r) throw new IllegalArgumentException("vertex (" + i + ", " + j + ") is outside the triangle of rate " + r);
    }

    /** {@return (i, j) of vertex number {@code n}, as i in [0] and j in [1]} */
    public int[] ij(int n) {
        if (n < 0 || n >= vertexCount()) throw new IllegalArgumentException("vertex " + n + " is not 0 to " + (vertexCount() - 1));
        int j = 0;
        // Rows shrink by one each: at most R steps, only for callers that have just a number.
        while (n > r - j) {
            n -= r - j + 1;
            j++;
        }
        return new int[] {n, j};
    }

    /**
     * The vertex that is k-th along edge {@code edge}, in the edge's direction.
     *
     * @param edge the edge, 0 to 2
     * @param k 0 to R
     * @return its vertex number
     */
    public int edgeVertex(int edge, int k) {
        if (k < 0 || k > r) throw new IllegalArgumentException("an edge has grid vertices 0 to " + r + ", not " + k);
        switch (edge) {
            case 0: return vertex(k, 0);
            case 1: return vertex(r - k, k);
            case 2: return vertex(0, r - k);
            default: throw new IllegalArgumentException("a triangle has edges 0 to 2, not " + edge);
        }
    }

    /**
     * The edge's own point that the k-th grid vertex along it lies on.
     *
     * @param edge the edge, 0 to 2
     * @param k 0 to R
     * @return c, at t = c / rate along the edge
     */
    public int edgePoint(int edge, int k) {
        int rate = edgeRate(edge);
        if (k < 0 || k > r) throw new IllegalArgumentException("an edge has grid vertices 0 to " + r + ", not " + k);
        return GridPattern.snap(k, r, rate);
    }

    /** {@return the denominator of the exact u coordinates, lcm(R, rate 0, rate 1)} */
    public long uScale() { return uScale; }

    /** {@return the denominator of the exact v coordinates, lcm(R, rate 1, rate 2)} */
    public long vScale() { return vScale; }

    /** {@return u of vertex (i, j) times {@link #uScale}, exactly} */
    public long uLattice(int i, int j) {
        checkVertex(i, j);
        if (j == 0 && r0 < r) return GridPattern.snap(i, r, r0) * (uScale / r0);
        if (i + j == r && r1 < r) return (r1 - GridPattern.snap(j, r, r1)) * (uScale / r1);
        return i * (uScale / r);
    }

    /** {@return v of vertex (i, j) times {@link #vScale}, exactly} */
    public long vLattice(int i, int j) {
        checkVertex(i, j);
        if (i + j == r && r1 < r) return GridPattern.snap(j, r, r1) * (vScale / r1);
        if (i == 0 && r2 < r) return (r2 - GridPattern.snap(r - j, r, r2)) * (vScale / r2);
        return j * (vScale / r);
    }

    /** {@return the u parameter of vertex (i, j) (see the class comment)} */
    public double u(int i, int j) {
        checkVertex(i, j);
        if (j == 0 && r0 < r) return (double) GridPattern.snap(i, r, r0) / r0;
        if (i + j == r && r1 < r) return (double) (r1 - GridPattern.snap(j, r, r1)) / r1;
        return (double) i / r;
    }

    /** {@return the v parameter of vertex (i, j) (see the class comment)} */
    public double v(int i, int j) {
        checkVertex(i, j);
        if (i + j == r && r1 < r) return (double) GridPattern.snap(j, r, r1) / r1;
        if (i == 0 && r2 < r) return (double) (r2 - GridPattern.snap(r - j, r, r2)) / r2;
        return (double) j / r;
    }

    /**
     * The three vertices of triangle {@code t}, as (i, j) pairs.
     *
     * @param t 0 to R² - 1
     * @param out receives i0, j0, i1, j1, i2, j2, counter-clockwise in (u, v)
     */
    public void triangleIJ(int t, int[] out) {
        if (t < 0 || t >= triangleCount()) throw new IllegalArgumentException("triangle " + t + " is not 0 to " + (triangleCount() - 1));
        // Row j starts at j (2R - j): solve for j, then correct the rounding.
        int j = (int) Math.max(0, Math.floor(r - Math.sqrt((double) r * r - t)));
        while (j > 0 && j * (2 * r - j) > t) j--;
        while ((j + 1) * (2 * r - j - 1) <= t) j++;
        int q = t - j * (2 * r - j), i = q >> 1;
        if ((q & 1) == 0) {
            out[0] = i; out[1] = j; out[2] = i + 1; out[3] = j; out[4] = i; out[5] = j + 1;
        } else {
            out[0] = i + 1; out[1] = j; out[2] = i + 1; out[3] = j + 1; out[4] = i; out[5] = j + 1;
        }
    }

    /**
     * The three vertex numbers of triangle {@code t}.
     *
     * @param t 0 to R² - 1
     * @param out receives three vertex numbers, counter-clockwise in (u, v)
     */
    public void triangle(int t, int[] out) {
        int[] ij = new int[6];
        triangleIJ(t, ij);
        for (int k = 0; k < 3; k++) out[k] = vertex(ij[2 * k], ij[2 * k + 1]);
    }

    /**
     * The sign of triangle {@code t}'s area in (u, v), computed exactly: 1 counter-clockwise, 0
     * for a zero-area triangle (only next to a transition edge), -1 never.
     *
     * @param t the triangle
     * @return -1, 0 or 1
     */
    public int orientation(int t) {
        int[] ij = new int[6];
        triangleIJ(t, ij);
        long u0 = uLattice(ij[0], ij[1]), u1 = uLattice(ij[2], ij[3]), u2 = uLattice(ij[4], ij[5]);
        long v0 = vLattice(ij[0], ij[1]), v1 = vLattice(ij[2], ij[3]), v2 = vLattice(ij[4], ij[5]);
        // The scales reach 2^36, so the products need 128 bits.
        return compareProducts(u1 - u0, v2 - v0, u2 - u0, v1 - v0);
    }

    /** The sign of a b - c d, exactly (128-bit products). */
    static int compareProducts(long a, long b, long c, long d) {
        long hi1 = Math.multiplyHigh(a, b), hi2 = Math.multiplyHigh(c, d);
        if (hi1 != hi2) return hi1 < hi2 ? -1 : 1;
        return Integer.signum(Long.compareUnsigned(a * b, c * d));
    }

    /**
     * The zero-area triangles that snapping makes; only the rows and diagonals along transition
     * edges are looked at (O(R)).
     *
     * @return their number
     */
    public int zeroAreaTriangles() {
        int count = 0;
        int[] ij = new int[6];
        for (int t = 0, n = triangleCount(); t < n; t++) {
            triangleIJ(t, ij);
            boolean border = false;
            for (int k = 0; k < 6 && !border; k += 2) {
                int i = ij[k], j = ij[k + 1];
                border = (j == 0 && r0 < r) || (i + j == r && r1 < r) || (i == 0 && r2 < r);
            }
            if (border && orientation(t) == 0) count++;
            // Inside a row, skip from the first two triangles to the last two (the only others at a border).
            int rowStart = ij[1] * (2 * r - ij[1]), rowEnd = (ij[1] + 1) * (2 * r - ij[1] - 1);
            if (!(ij[1] == 0 && r0 < r) && t - rowStart >= 1 && t < rowEnd - 3) t = rowEnd - 3;
        }
        return count;
    }

    @Override public String toString() {
        return "TrianglePattern[rates " + r0 + " " + r1 + " " + r2 + ", inner " + r + "]";
    }
}
