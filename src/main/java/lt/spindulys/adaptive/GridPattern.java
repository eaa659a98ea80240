package lt.spindulys.adaptive;

/**
 * The tessellation pattern of one quad (a quad face, or one quad sub-face of an n-gon) with four
 * integer edge rates: a regular grid of (Ru + 1) x (Rv + 1) vertices, Ru = max(rate 0, rate 2),
 * Rv = max(rate 1, rate 3), whose topology is implicit (vertex (i, j) is number j (Ru + 1) + i,
 * two triangles per cell), and whose vertices on an edge coarser than the grid are snapped onto
 * that edge's own points (Embree's transition edges). Immutable and O(1) in size: every
 * parameter is computed on request.
 *
 * <p><b>Parameterization</b> (OpenSubdiv Bfr's quad): corners 0, 1, 2, 3 at (u, v) = (0, 0),
 * (1, 0), (1, 1), (0, 1); edge k runs from corner k to corner k + 1, so edge 0 is v = 0 with u
 * rising, edge 1 is u = 1 with v rising, edge 2 is v = 1 with u falling and edge 3 is u = 0 with v
 * falling. An inner vertex (i, j) is at (i / Ru, j / Rv).
 *
 * <p><b>Snapping.</b> An edge with rate R below its grid resolution Rg (a transition edge) has
 * Rg + 1 grid vertices but only R + 1 points of its own, at t = c / R along the edge. The k-th
 * grid vertex along the edge (in the edge's direction) takes point c = floor((2kR + Rg) / (2Rg)),
 * the nearest (halves rounded forwards). The map is non-decreasing and steps by at most 1, so it
 * reaches every c from 0 to R whatever Rg is: the face on the other side of the edge, with the
 * same R and any grid, uses the same R + 1 points, each exactly once or repeatedly. The parameter
 * along the face is c / R, or (R - c) / R on edges 2 and 3, each the correctly rounded quotient
 * of two integers: bit for bit what the neighbour computes for the same point (it computes c' / R
 * with c' = c or R - c, the same two integers). Where two neighbouring grid vertices take the same
 * point, the cell's triangles along the edge have zero area; the grid stays regular, which is
 * what implicit-topology grid storage (and its halving hierarchy) needs. Cells next to a
 * transition edge are trapezoids or, at a corner between two, convex quads, so no triangle is
 * inverted ({@link #orientation}).
 *
 * <p><b>Triangles.</b> Cell (i, j), 0 &le; i &lt; Ru, 0 &le; j &lt; Rv, with corners v0 = (i, j),
 * v1 = (i + 1, j), v2 = (i + 1, j + 1), v3 = (i, j + 1), c = j Ru + i, is split here in a
 * checkerboard (the pattern has parameters, not positions): when i + j is even along its v0-v2
 * diagonal into triangles 2c = (v0, v1, v2) and 2c + 1 = (v0, v2, v3), when i + j is odd along its
 * v1-v3 diagonal into 2c = (v0, v1, v3) and 2c + 1 = (v2, v3, v1). All are counter-clockwise in
 * (u, v), and numbered as {@code GridPatch} numbers its triangles. Either diagonal of a convex
 * cell gives two triangles that are not inverted, so snapping is indifferent to the choice. The
 * checkerboard serves counting only: the rendered
 * grid ({@code GridPatch}) cuts each cell along its shorter diagonal in 3D, as the uniform
 * subdivision path cuts its quads, and {@link #zeroAreaTriangles} is the same for either diagonal.
 *
 * <p><b>Exact coordinates.</b> u (i, j) is {@link #uLattice} / {@link #uScale} exactly, with the
 * scale the least common multiple of Ru and the rates of edges 0 and 2 (at most 4096² for rates
 * up to {@link EdgeRates#MAX_RATE}); v likewise. The orientation of a triangle is computed from
 * these integers, so a zero-area triangle is told exactly.
 */
public final class GridPattern {
    private final int r0, r1, r2, r3, ru, rv;
    private final long uScale, vScale;

    /**
     * The pattern of a quad with the given edge rates, edge by edge from corner 0.
     *
     * @param r0 rate of edge 0 (corner 0 to 1), 1 to {@link EdgeRates#MAX_RATE}
     * @param r1 rate of edge 1 (corner 1 to 2)
     * @param r2 rate of edge 2 (corner 2 to 3)
     * @param r3 rate of edge 3 (corner 3 to 0)
     * @throws IllegalArgumentException if a rate is out of range
     */
    public GridPattern(int r0, int r1, int r2, int r3) {
        checkRate(r0, 0);
        checkRate(r1, 1);
        checkRate(r2, 2);
        checkRate(r3, 3);
        this.r0 = r0;
        this.r1 = r1;
        this.r2 = r2;
        this.r3 = r3;
        ru = Math.max(r0, r2);
        rv = Math.max(r1, r3);
        uScale = lcm(r0, r2);
        vScale = lcm(r1, r3);
    }

    static void checkRate(int rate, int edge) {
        if (rate < 1 || rate > EdgeRates.MAX_RATE) {
            throw new IllegalArgumentException("edge " + edge + " has rate " + rate + "; rates are 1 to " + EdgeRates.MAX_RATE);
        }
    }

    static long lcm(long a, long b) {
        long x = a, y = b;
        while (y != 0) {
            long t = x % y;
            x = y;
            y = t;
        }
        return a / x * b;
    }

    /**
     * The coarse point that the k-th of Rg + 1 grid vertices along an edge of rate R takes:
     * floor((2kR + Rg) / (2Rg)), the nearest of the edge's R + 1 points with halves rounded
     * forwards; k itself when R = Rg.
     *
     * @param k the grid vertex along the edge, 0 to gridRate
     * @param gridRate the grid's segments along the edge, at least edgeRate
     * @param edgeRate the edge's own segments, at least 1
     * @return the point, 0 to edgeRate
     */
    public static int snap(int k, int gridRate, int edgeRate) {
        if (edgeRate == gridRate) return k;
        return (int) ((2L * k * edgeRate + gridRate) / (2L * gridRate));
    }

    /** {@return the rate of edge {@code edge} (0 to 3)} */
    public int edgeRate(int edge) {
        switch (edge) {
            case 0: return r0;
            case 1: return r1;
            case 2: return r2;
            case 3: return r3;
            default: throw new IllegalArgumentException("a quad has edges 0 to 3, not " + edge);
        }
    }

    /** {@return the grid's segments along edge {@code edge}: Ru for edges 0 and 2, Rv for 1 and 3} */
    public int gridRate(int edge) { return (edge & 1) == 0 ? ru : rv; }

    /** {@return true if edge {@code edge} is a transition edge: its rate is below the grid's along it} */
    public boolean isSnapped(int edge) { return edgeRate(edge) < gridRate(edge); }

    /** {@return Ru, the grid's segments in u} */
    public int columns() { return ru; }

    /** {@return Rv, the grid's segments in v} */
    public int rows() { return rv; }

    /** {@return the grid's vertices, (Ru + 1)(Rv + 1)} */
    public int vertexCount() { return (ru + 1) * (rv + 1); }

    /** {@return the grid's triangles, 2 Ru Rv (zero-area ones included)} */
    public int triangleCount() { return 2 * ru * rv; }

    /**
     * The number of vertex (i, j).
     *
     * @param i column, 0 to Ru
     * @param j row, 0 to Rv
     * @return j (Ru + 1) + i
     */
    public int vertex(int i, int j) {
        checkVertex(i, j);
        return j * (ru + 1) + i;
    }

    private void checkVertex(int i, int j) {
        if (i < 0 || i > ru || j < 0 || j > rv) throw new IllegalArgumentException("vertex (" + i + ", " + j + ") is outside the " + ru + " x " + rv + " grid");
    }

    /**
     * The grid vertex that is k-th along edge {@code edge}, in the edge's direction.
     *
     * @param edge the edge, 0 to 3
     * @param k 0 to {@link #gridRate}(edge)
     * @return its vertex number
     */
    public int edgeVertex(int edge, int k) {
        int g = gridRate(edge);
        if (k < 0 || k > g) throw new IllegalArgumentException("edge " + edge + " has grid vertices 0 to " + g + ", not " + k);
        switch (edge) {
            case 0: return vertex(k, 0);
            case 1: return vertex(ru, k);
            case 2: return vertex(ru - k, rv);
            default: return vertex(0, rv - k);
        }
    }

    /**
     * The edge's own point (0 to its rate, in the edge's direction) that the k-th grid vertex
     * along it lies on: {@link #snap}(k, gridRate, rate).
     *
     * @param edge the edge, 0 to 3
     * @param k 0 to {@link #gridRate}(edge)
     * @return the point c, at t = c / rate along the edge
     */
    public int edgePoint(int edge, int k) {
        int g = gridRate(edge);
        if (k < 0 || k > g) throw new IllegalArgumentException("edge " + edge + " has grid vertices 0 to " + g + ", not " + k);
        return snap(k, g, edgeRate(edge));
    }

    /** {@return the denominator of the exact u coordinates: lcm(rate 0, rate 2), a multiple of Ru} */
    public long uScale() { return uScale; }

    /** {@return the denominator of the exact v coordinates: lcm(rate 1, rate 3), a multiple of Rv} */
    public long vScale() { return vScale; }

    /**
     * u of vertex (i, j) times {@link #uScale}: an exact integer.
     *
     * @param i column, 0 to Ru
     * @param j row, 0 to Rv
     * @return the numerator
     */
    public long uLattice(int i, int j) {
        checkVertex(i, j);
        if (j == 0 && r0 < ru) return snap(i, ru, r0) * (uScale / r0);
        if (j == rv && r2 < ru) return (r2 - snap(ru - i, ru, r2)) * (uScale / r2);
        return i * (uScale / ru);
    }

    /**
     * v of vertex (i, j) times {@link #vScale}: an exact integer.
     *
     * @param i column, 0 to Ru
     * @param j row, 0 to Rv
     * @return the numerator
     */
    public long vLattice(int i, int j) {
        checkVertex(i, j);
        if (i == ru && r1 < rv) return snap(j, rv, r1) * (vScale / r1);
        if (i == 0 && r3 < rv) return (r3 - snap(rv - j, rv, r3)) * (vScale / r3);
        return j * (vScale / rv);
    }

    /**
     * The u parameter of vertex (i, j): i / Ru inside, c / R (edge 0) or (R - c) / R (edge 2) on a
     * transition edge, each the correctly rounded quotient of its two integers.
     *
     * @param i column, 0 to Ru
     * @param j row, 0 to Rv
     * @return u in [0, 1]
     */
    public double u(int i, int j) {
        checkVertex(i, j);
        if (j == 0 && r0 < ru) return (double) snap(i, ru, r0) / r0;
        if (j == rv && r2 < ru) return (double) (r2 - snap(ru - i, ru, r2)) / r2;
        return (double) i / ru;
    }

    /**
     * The v parameter of vertex (i, j): j / Rv inside, c / R (edge 1) or (R - c) / R (edge 3) on a
     * transition edge, each the correctly rounded quotient of its two integers.
     *
     * @param i column, 0 to Ru
     * @param j row, 0 to Rv
     * @return v in [0, 1]
     */
    public double v(int i, int j) {
        checkVertex(i, j);
        if (i == ru && r1 < rv) return (double) snap(j, rv, r1) / r1;
        if (i == 0 && r3 < rv) return (double) (r3 - snap(rv - j, rv, r3)) / r3;
        return (double) j / rv;
    }

    /**
     * The three vertex numbers of triangle {@code t} (see the class comment for the checkerboard of
     * diagonals).
     *
     * @param t the triangle, 0 to {@link #triangleCount} - 1
     * @param out receives three vertex numbers, counter-clockwise in (u, v)
     */
    public void triangle(int t, int[] out) {
        if (t < 0 || t >= triangleCount()) throw new IllegalArgumentException("triangle " + t + " is not 0 to " + (triangleCount() - 1));
        int c = t >> 1, i = c % ru, j = c / ru, w = ru + 1;
        int v0 = j * w + i, v1 = v0 + 1, v3 = v0 + w, v2 = v3 + 1;
        if (((i + j) & 1) == 0) { // along v0-v2
            out[0] = v0;
            out[1] = (t & 1) == 0 ? v1 : v2;
            out[2] = (t & 1) == 0 ? v2 : v3;
        } else if ((t & 1) == 0) {
            out[0] = v0;
            out[1] = v1;
            out[2] = v3;
        } else {
            out[0] = v2;
            out[1] = v3;
            out[2] = v1;
        }
    }

    /**
     * The sign of triangle {@code t}'s area in (u, v), computed exactly: 1 counter-clockwise, 0
     * for a zero-area triangle (only in a cell next to a transition edge), -1 never.
     *
     * @param t the triangle
     * @return -1, 0 or 1
     */
    public int orientation(int t) {
        int[] v = new int[3];
        triangle(t, v);
        int w = ru + 1;
        long u0 = uLattice(v[0] % w, v[0] / w), u1 = uLattice(v[1] % w, v[1] / w), u2 = uLattice(v[2] % w, v[2] / w);
        long w0 = vLattice(v[0] % w, v[0] / w), w1 = vLattice(v[1] % w, v[1] / w), w2 = vLattice(v[2] % w, v[2] / w);
        // |differences| <= 4096², products <= 2^48: exact in a long.
        return Long.signum((u1 - u0) * (w2 - w0) - (u2 - u0) * (w1 - w0));
    }

    /**
     * The zero-area triangles, which snapping makes in cells along transition edges (only those
     * cells are looked at, so this is O(Ru + Rv)).
     *
     * @return their number
     */
    public int zeroAreaTriangles() {
        int count = 0;
        for (int j = 0; j < rv; j++) {
            for (int i = 0; i < ru; i++) {
                boolean border = (j == 0 && r0 < ru) || (j == rv - 1 && r2 < ru) || (i == ru - 1 && r1 < rv) || (i == 0 && r3 < rv);
                if (!border) {
                    // Skip to the last column (the only other border cell of this row), or past it.
                    if (i > 0 && i < ru - 1) i = ru - 2;
                    continue;
                }
                int c = j * ru + i;
                if (orientation(2 * c) == 0) count++;
                if (orientation(2 * c + 1) == 0) count++;
            }
        }
        return count;
    }

    @Override public String toString() {
        return "GridPattern[rates " + r0 + " " + r1 + " " + r2 + " " + r3 + ", grid " + ru + " x " + rv + "]";
    }
}
