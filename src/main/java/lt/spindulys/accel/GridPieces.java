package lt.spindulys.accel;

/**
 * A face's vertex grid (nu x nv) cut into pieces of at most {@link #maxSide()} vertices per side, each a
 * {@link GridPatch} of its own, so that a cache can hold (and a ray build) pieces rather than whole faces.
 * Neighbouring pieces share their boundary row or column of vertices: a piece is built from the face's vertices
 * [i0..i1] x [j0..j1], so a shared vertex comes from the same evaluation in both and is the same float, and the
 * pieces are as watertight against each other as the cells of one grid.
 *
 * <p>The cells are spread evenly: {@code ceil((nu - 1) / (maxSide - 1))} columns of pieces, their cell counts
 * differing by at most one, and likewise for rows. Piece {@code k} is column {@code k % columns()}, row
 * {@code k / columns()}. Immutable; describes the pieces only, and holds no vertices.
 */
public final class GridPieces {
    /** The usual largest piece side: 17 x 17 vertices, 512 triangles. */
    public static final int DEFAULT_MAX_SIDE = 17;

    /** Evaluates a face's grid vertices for a piece. Must be pure: the same range gives the same values. */
    public interface Source {
        /**
         * Fills {@code xyz} with the positions of the face's vertices [i0, i0 + nu) x [j0, j0 + nv): vertex
         * (i0 + a, j0 + b) at {@code 3 * (b * nu + a)}.
         */
        void positions(int i0, int j0, int nu, int nv, double[] xyz);

        /** Fills {@code out} (3 per vertex, as above) with normals and returns true, or returns false for none. */
        default boolean normals(int i0, int j0, int nu, int nv, float[] out) { return false; }

        /**
         * Fills {@code out} (2 per vertex) with the vertices' parameters in the face and returns true, or returns
         * false when they are linear in the indices (vertex (i, j) at (i / (faceNu - 1), j / (faceNv - 1))).
         */
        default boolean parameters(int i0, int j0, int nu, int nv, float[] out) { return false; }
    }

    /**
     * A conservative box of the face's surface over the vertices [i0..i1] x [j0..j1], known without evaluating
     * them (from the control points' Bezier hull, for example): every vertex the {@link Source} gives for the
     * range must lie inside it.
     */
    @FunctionalInterface
    public interface BoundSupplier {
        /** The box (min x, y, z, max x, y, z) into {@code out[0..5]}. */
        void bound(int i0, int j0, int i1, int j1, double[] out);
    }

    private final int nu, nv, maxSide, columns, rows;

    /**
     * @param nu the face's vertices per row (2..{@value GridPatch#MAX_SIDE})
     * @param nv the face's rows (2..{@value GridPatch#MAX_SIDE})
     * @param maxSide most vertices per piece side (2..{@value GridPatch#MAX_SIDE})
     */
    public GridPieces(int nu, int nv, int maxSide) {
        if (nu < 2 || nv < 2 || nu > GridPatch.MAX_SIDE || nv > GridPatch.MAX_SIDE) {
            throw new IllegalArgumentException("a grid of " + nu + " x " + nv + " vertices (each side 2.." + GridPatch.MAX_SIDE + ")");
        }
        if (maxSide < 2 || maxSide > GridPatch.MAX_SIDE) throw new IllegalArgumentException("piece side " + maxSide);
        this.nu = nu;
        this.nv = nv;
        this.maxSide = maxSide;
        columns = (nu - 2) / (maxSide - 1) + 1;
        rows = (nv - 2) / (maxSide - 1) + 1;
    }

    public int nu() { return nu; }
    public int nv() { return nv; }
    public int maxSide() { return maxSide; }
    public int columns() { return columns; }
    public int rows() { return rows; }
    public int count() { return columns * rows; }

    /** First vertex column of piece {@code k}. */
    public int i0(int k) { return start(k % columns, columns, nu - 1); }
    /** Last vertex column of piece {@code k} (inclusive; the next piece's first). */
    public int i1(int k) { return start(k % columns + 1, columns, nu - 1); }
    /** First vertex row of piece {@code k}. */
    public int j0(int k) { return start(k / columns, rows, nv - 1); }
    /** Last vertex row of piece {@code k} (inclusive). */
    public int j1(int k) { return start(k / columns + 1, rows, nv - 1); }

    /** The first cell of part {@code p} of {@code cells} cells cut into {@code parts} even parts. */
    private static int start(int p, int parts, int cells) { return (int) ((long) p * cells / parts); }

    /** The piece holding cell (i, j) of the face (0 <= i < nu - 1, 0 <= j < nv - 1). */
    public int pieceOfCell(int i, int j) {
        return part(j, rows, nv - 1) * columns + part(i, columns, nu - 1);
    }

    private static int part(int cell, int parts, int cells) {
        int p = (int) ((long) cell * parts / cells);
        while (p + 1 < parts && start(p + 1, parts, cells) <= cell) p++;
        while (p > 0 && start(p, parts, cells) > cell) p--;
        return p;
    }

    /**
     * The bound of piece {@code k} before it is built: the supplier's box for its vertex range, widened outward to
     * floats so that it holds the built piece's float vertices.
     */
    public void bound(int k, BoundSupplier supplier, double[] out) {
        supplier.bound(i0(k), j0(k), i1(k), j1(k), out);
        for (int a = 0; a < 3; a++) {
            out[a] = Bvh.down(out[a]);
            out[a + 3] = Bvh.up(out[a + 3]);
        }
    }

    /**
     * Builds piece {@code k}: evaluates its vertices with {@code source} and makes their grid, with parameters
     * those of the face (so a hit's {@link GridPatch#parameters} are face parameters). A cell's diagonal follows
     * from its four vertices alone ({@link GridPatch#cutAlongV0V2}), so the pieces hold exactly the face grid's
     * triangles.
     *
     * @param leafSize the piece's leaf size ({@link GridPatch#GridPatch(int, int, double[], float[], float[], int)})
     */
    public GridPatch build(int k, Source source, int leafSize) {
        int a0 = i0(k), a1 = i1(k), b0 = j0(k), b1 = j1(k);
        int pu = a1 - a0 + 1, pv = b1 - b0 + 1, n = pu * pv;
        double[] xyz = new double[3 * n];
        source.positions(a0, b0, pu, pv, xyz);
        float[] f = new float[3 * n];
        for (int q = 0; q < f.length; q++) f[q] = (float) xyz[q];
        float[] normals = new float[3 * n];
        if (!source.normals(a0, b0, pu, pv, normals)) normals = null;
        float[] uv = new float[2 * n];
        if (!source.parameters(a0, b0, pu, pv, uv)) uv = null;
        return new GridPatch(pu, pv, f, normals, uv,
                (double) a0 / (nu - 1), (double) b0 / (nv - 1), (double) a1 / (nu - 1), (double) b1 / (nv - 1), leafSize);
    }
}
