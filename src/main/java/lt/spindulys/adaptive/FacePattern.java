package lt.spindulys.adaptive;

import java.util.Objects;

/**
 * The tessellation pattern of one Catmull-Clark or bilinear face from its edges' rates: one
 * {@link GridPattern} for a quad, and for any other polygon (a triangle or an n-gon) N quad
 * sub-faces in OpenSubdiv's parameterization (Bfr's {@code QUAD_SUBFACES}). Immutable.
 *
 * <p><b>Sub-faces.</b> Sub-face k of an N-gon is the quad from corner k to the midpoint of edge
 * k, the face's centre and the midpoint of edge k - 1, with its own (u, v) in [0, 1]² (Bfr's
 * normalized sub-face coordinates, origin at corner k, u towards edge k's midpoint). Its four
 * edges are: 0, the first half of base edge k; 1, the spoke from edge k's midpoint to the centre;
 * 2, the spoke from the centre to edge k - 1's midpoint; 3, the second half of base edge k - 1.
 * A base edge of rate R (even: {@link EdgeRates#evenAroundPolygons}) gives each half R / 2, so
 * its points c / R, c = 0..R, are exactly the halves' points: the first half's c' is c, the
 * second half's c'' is c - R / 2. The spoke from edge k's midpoint gets max(R(k - 1), R(k + 1)) / 2,
 * half the larger rate of the two base edges beside it, which both sub-faces along it compute
 * alike; as that is at least the halves next to it, a sub-face's grid is spoke by spoke
 * (Ru = spoke k - 1, Rv = spoke k) and spokes are never transition edges: the sub-faces' grids
 * agree along them vertex for vertex, parameter j / spoke rate in both.
 *
 * <p><b>Base-edge points.</b> {@link #baseEdge} and {@link #basePoint} say which control edge a
 * sub-face edge lies on and which of its R + 1 points (counted in the face's direction along
 * it) each grid vertex there takes: the exact integer data by which the faces on both sides of an
 * edge share its points (a neighbour running the other way counts c as R - c).
 */
public final class FacePattern {
    private final int[] rates;
    private final GridPattern[] grids;
    private final int[] spokes;

    private FacePattern(int[] rates, GridPattern[] grids, int[] spokes) {
        this.rates = rates;
        this.grids = grids;
        this.spokes = spokes;
    }

    /**
     * The pattern of a quad face.
     *
     * @param r0 rate of edge 0 (corner 0 to 1), 1 to {@link EdgeRates#MAX_RATE}
     * @param r1 rate of edge 1
     * @param r2 rate of edge 2
     * @param r3 rate of edge 3
     * @return the pattern: one grid
     */
    public static FacePattern quad(int r0, int r1, int r2, int r3) {
        return new FacePattern(new int[] {r0, r1, r2, r3}, new GridPattern[] {new GridPattern(r0, r1, r2, r3)}, null);
    }

    /**
     * The pattern of a face with {@code rates.length} corners: a quad's grid for 4, else N quad
     * sub-faces (see the class comment), for which every rate must be even.
     *
     * @param rates the rate of each edge, edge k from corner k to k + 1
     * @return the pattern
     * @throws IllegalArgumentException for fewer than 3 edges, a rate out of 1 to
     *         {@link EdgeRates#MAX_RATE}, or an odd rate of a non-quad
     */
    public static FacePattern polygon(int... rates) {
        Objects.requireNonNull(rates, "rates");
        int n = rates.length;
        if (n < 3) throw new IllegalArgumentException("a face has at least 3 edges, found " + n);
        if (n == 4) return quad(rates[0], rates[1], rates[2], rates[3]);
        for (int k = 0; k < n; k++) {
            GridPattern.checkRate(rates[k], k);
            if ((rates[k] & 1) != 0) {
                throw new IllegalArgumentException("edge " + k + " of a " + n + "-sided face has odd rate " + rates[k]
                        + "; sub-faces halve the edges, so their rates must be even (EdgeRates.evenAroundPolygons)");
            }
        }
        int[] spokes = new int[n];
        for (int k = 0; k < n; k++) spokes[k] = Math.max(rates[(k + n - 1) % n], rates[(k + 1) % n]) / 2;
        GridPattern[] grids = new GridPattern[n];
        for (int k = 0; k < n; k++) {
            int prev = (k + n - 1) % n;
            grids[k] = new GridPattern(rates[k] / 2, spokes[k], spokes[prev], rates[prev] / 2);
        }
        return new FacePattern(rates.clone(), grids, spokes);
    }

    /** {@return the face's corners (and edges)} */
    public int size() { return rates.length; }

    /** {@return the rate of base edge {@code edge}} */
    public int rate(int edge) { return rates[edge]; }

    /** {@return true for a polygon split into quad sub-faces (any face but a quad)} */
    public boolean hasSubFaces() { return spokes != null; }

    /** {@return the number of grids: 1 for a quad, N for an N-gon} */
    public int subFaceCount() { return grids.length; }

    /** {@return sub-face {@code k}'s grid (the quad's own grid for k = 0 of a quad)} */
    public GridPattern subFace(int k) { return grids[k]; }

    /**
     * The rate of the spoke from base edge k's midpoint to the centre.
     *
     * @param k the base edge
     * @return the rate
     * @throws IllegalStateException for a quad (no spokes)
     */
    public int spokeRate(int k) {
        if (spokes == null) throw new IllegalStateException("a quad has no sub-faces");
        return spokes[k];
    }

    /**
     * The base edge that edge {@code subEdge} of sub-face {@code subFace} lies on, or -1 for a
     * spoke.
     *
     * @param subFace the sub-face (0 for a quad)
     * @param subEdge its edge, 0 to 3
     * @return the base edge, or -1
     */
    public int baseEdge(int subFace, int subEdge) {
        if (subFace < 0 || subFace >= grids.length) throw new IllegalArgumentException("no sub-face " + subFace);
        if (subEdge < 0 || subEdge > 3) throw new IllegalArgumentException("a sub-face has edges 0 to 3, not " + subEdge);
        if (spokes == null) return subEdge;
        int n = rates.length;
        return subEdge == 0 ? subFace : subEdge == 3 ? (subFace + n - 1) % n : -1;
    }

    /**
     * The point of the base edge (0 to its rate, counted in the face's direction along it) that
     * the k-th grid vertex along edge {@code subEdge} of sub-face {@code subFace} lies on.
     *
     * @param subFace the sub-face (0 for a quad)
     * @param subEdge its edge, on a base edge ({@link #baseEdge} not -1)
     * @param k the grid vertex along the sub-face's edge, in that edge's direction
     * @return the base edge's point c, at t = c / rate along it
     * @throws IllegalArgumentException for a spoke
     */
    public int basePoint(int subFace, int subEdge, int k) {
        int base = baseEdge(subFace, subEdge);
        if (base < 0) throw new IllegalArgumentException("edge " + subEdge + " of sub-face " + subFace + " is a spoke, not on a base edge");
        int c = grids[subFace].edgePoint(subEdge, k);
        // The second half of a base edge starts at its midpoint.
        return spokes != null && subEdge == 3 ? rates[base] / 2 + c : c;
    }

    /** {@return the triangles of every grid, zero-area ones included} */
    public long triangleCount() {
        long t = 0;
        for (GridPattern g : grids) t += g.triangleCount();
        return t;
    }

    /** {@return the grids' vertices, counting those on spokes and the centre once per sub-face} */
    public long vertexCount() {
        long t = 0;
        for (GridPattern g : grids) t += g.vertexCount();
        return t;
    }

    /** {@return the zero-area triangles that snapping makes, over every grid} */
    public long zeroAreaTriangles() {
        long t = 0;
        for (GridPattern g : grids) t += g.zeroAreaTriangles();
        return t;
    }

    /**
     * The triangles of the power-of-two tessellation the same face gets from levels today: the
     * face's level is that of its finest edge, l = ceil(log2(max rate)) for rates from the same
     * lengths, and a quad at level l has 2 * 4^l triangles, an N-gon N quads of 4^(l - 1) each.
     *
     * @param rates the face's edge rates
     * @return the triangles at the matching level
     */
    public static long powerOfTwoTriangles(int... rates) {
        int max = 1;
        for (int r : rates) max = Math.max(max, r);
        int l = 32 - Integer.numberOfLeadingZeros(max - 1); // ceil(log2(max)), 0 for 1
        int n = rates.length;
        if (l == 0) return n - 2;
        return n == 4 ? 2L << (2 * l) : 2L * n << (2 * (l - 1));
    }

    @Override public String toString() {
        return "FacePattern[" + rates.length + " edges, " + grids.length + (grids.length == 1 ? " grid" : " sub-faces") + ", " + triangleCount() + " triangles]";
    }
}
