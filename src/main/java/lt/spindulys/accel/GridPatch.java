package lt.spindulys.accel;

import java.util.Arrays;
import lt.spindulys.adaptive.CachedPatch;
import lt.spindulys.math.Ray;

/**
 * A regular grid of vertices as a ray tracing primitive, in the spirit of Embree's {@code GridSOA}: nu x nv
 * float positions with implicit topology and a hierarchy cut from the grid by halving its index ranges, so that
 * nothing is sorted and no triangle index is stored.
 *
 * <p><b>Topology.</b> Vertex (i, j), 0 &lt;= i &lt; nu, 0 &lt;= j &lt; nv, is number {@code j * nu + i}. Cell (i, j)
 * spans vertices v0 = (i, j), v1 = (i + 1, j), v2 = (i + 1, j + 1), v3 = (i, j + 1), and each cell is cut along
 * its shorter diagonal, as uniform subdivision cuts its refined quads (so that at power-of-two rates the two give
 * the same triangles): along v0-v2 when |v0 - v2|² &lt;= |v1 - v3|² (a tie included), into triangle
 * A = (v0, v1, v2) and B = (v0, v2, v3), else along v1-v3, into A = (v0, v1, v3) and B = (v2, v3, v1); all
 * counter-clockwise in (i, j), numbered as {@code GridPattern} numbers its triangles ({@link #cutAlongV0V2}). The
 * squared lengths are computed in double from the stored floats when the grid is built, and the choice kept as one
 * bit per cell that the hit test, {@link #triangleVertex} and all that use it read: a function of the cell's four
 * floats alone, so a piece of a larger grid cuts its cells as the whole grid does.
 * Triangle
 * {@code sub = 2 * (j * (nu - 1) + i)} is A of cell (i, j), {@code sub + 1} its B ({@link #triangleVertex}).
 * Vertices may repeat (a grid snapped to a coarser edge): the triangles they make have no area and are never hit.
 *
 * <p><b>Hits.</b> The triangle test is {@link WatertightTriangles}'s, in double arithmetic on the float vertices,
 * with each vertex transformed once per cell row and each edge function (four per cell: bottom, right, top and
 * the cell's diagonal; the left one is the previous cell's right) computed once and negated (exactly) for the
 * neighbouring triangle. A triangle's edge function is therefore bit for bit the value
 * {@link WatertightTriangles#test} computes for the same corners, and two grids whose shared boundary vertices are
 * bit-identical floats are watertight against each other: a ray through a shared edge or vertex hits one side or
 * both, never neither. A hit fills {@link PrimitiveHit#t}, {@link PrimitiveHit#sub} (the triangle, as above) and
 * {@link PrimitiveHit#u}, {@link PrimitiveHit#v} (the weights of the triangle's second and third corner, as
 * {@link WatertightTriangles} does); {@link #parameters} turns them into the patch's (u, v) and {@link #normal}
 * interpolates the vertex normals. {@link PrimitiveHit#prim} is left to the caller (the face).
 *
 * <p><b>Hierarchy.</b> A vertex range larger than a leaf ({@link #leafSize()} vertices per side) is halved along
 * its longer side (in cells), and each half that is still larger than a leaf halved again along its own longer
 * side, three halvings deep (fewer at the root, so that the nodes below have full sets): up to eight children per node, the halves sharing their middle row or column of
 * vertices. One node is one contiguous record of {@value #NODE_INTS} ints: the eight children's boxes as float bits,
 * one row of eight per plane (min x, max x, min y, max y, min z, max z; from the float vertices, so exact), then
 * per child its vertex ranges (i0 | i1 &lt;&lt; 16, then j0 | j1 &lt;&lt; 16, inclusive) and its node index
 * ({@code LEAF} for a leaf, {@code EMPTY} for an unused slot, always after the used ones, whose box is inverted so
 * that no ray enters it). A node's eight boxes are tested together, with 8-lane float vectors ({@link SimdBoxes})
 * when the JDK's vector module is present and the hardware has them ({@link WideBvh#AVAILABLE}), else one by one
 * with the same float operations; the test is conservative (the origin moved outward, the distances widened), and
 * only the triangle test decides hits. A single child hit is entered directly, several are pushed on the caller's
 * {@link TraversalScratch#stack} with their entry distances, sorted nearest on top for a nearest hit.
 *
 * <p>Memory ({@link #bytes}): 12 bytes per vertex (about 6 per triangle), 288 per node and a bit per cell; with
 * the default leaves of 3 x 3 vertices about 11 bytes per triangle in all, with leaves of 5 x 5 about 7, plus 6
 * per triangle for float normals.
 *
 * <p><b>Every crossing.</b> {@link #visitTriangles} hands every triangle of every leaf whose box the ray's interval
 * crosses to a {@link GridTriangleVisitor}, each at most once (leaves share vertices, never cells), for a caller that
 * needs all the crossings of a line (CSG) and tests them itself, with {@link #cornerCoordinate}'s floats.
 *
 * <p>Immutable once made: any number of threads may trace one; all per-ray state is in the caller's
 * {@link TraversalScratch}, and a query allocates nothing.
 */
public final class GridPatch implements CachedPatch {
    /** The largest number of vertices per side (ranges are packed in 16 bits). */
    public static final int MAX_SIDE = 8193;
    /** Leaf size (vertices per side) used when none is given; chosen by measurement (see the tests' benchmark). */
    public static final int DEFAULT_LEAF_SIZE = 3;

    /**
     * A node record: the children's boxes as six rows of eight float bits (min x, max x, min y, max y, min z,
     * max z, as {@link SimdBoxes} reads them), then eight each of i ranges, j ranges and child references.
     */
    static final int NODE_INTS = 72, I_RANGES = 48, J_RANGES = 56, REFS = 64, WIDTH = 8;
    static final int LEAF = -1, EMPTY = -2;
    /** The relative widening of a slab interval (as {@link Bvh}'s). */
    private static final double PAD = 4 * 3 * 0x1p-53 / (1 - 3 * 0x1p-53);

    private final int nu, nv, leafSize;
    private final float[] pos, normals, uv;
    private final double u0, v0, u1, v1;
    private final int[] nodes;
    /**
     * Bit c set when cell c (j * (nu - 1) + i) is cut along its v1-v3 diagonal: decided once, when built, as computing
     * it per cell in the hit test costs a tenth to a fifth of the rays per second.
     */
    private final long[] alongV1V3;
    private final int nodeCount, depth;
    /** The whole grid's box, as float bits in the node-record order (min x, y, z, max x, y, z). */
    private final int[] box = new int[6];

    /**
     * A grid from double positions (as an evaluator computes them), stored as floats rounded to nearest: two grids
     * made from equal doubles on a shared edge store bit-identical floats there.
     *
     * @param nu vertices per row (2..{@value #MAX_SIDE})
     * @param nv rows (2..{@value #MAX_SIDE})
     * @param xyz x, y, z per vertex, vertex (i, j) at {@code 3 * (j * nu + i)}
     * @param normals x, y, z per vertex, or null
     * @param uv the patch parameters (u, v) per vertex, or null for parameters linear in the indices over
     *           [0, 1] x [0, 1]
     * @param leafSize vertices per side of a leaf (2..17)
     */
    public GridPatch(int nu, int nv, double[] xyz, float[] normals, float[] uv, int leafSize) {
        this(nu, nv, toFloat(xyz, nu, nv), normals, uv, 0, 0, 1, 1, leafSize);
    }

    /**
     * A grid from float positions, kept as given (not copied: the caller must not change them).
     *
     * @param nu vertices per row (2..{@value #MAX_SIDE})
     * @param nv rows (2..{@value #MAX_SIDE})
     * @param xyz x, y, z per vertex, vertex (i, j) at {@code 3 * (j * nu + i)}
     * @param normals x, y, z per vertex, or null
     * @param uv the patch parameters (u, v) per vertex, or null for parameters linear in the indices
     * @param u0 the parameter u of column 0 when {@code uv} is null
     * @param v0 the parameter v of row 0 when {@code uv} is null
     * @param u1 the parameter u of column nu - 1 when {@code uv} is null
     * @param v1 the parameter v of row nv - 1 when {@code uv} is null
     * @param leafSize vertices per side of a leaf (2..17)
     */
    public GridPatch(int nu, int nv, float[] xyz, float[] normals, float[] uv,
                     double u0, double v0, double u1, double v1, int leafSize) {
        check(nu, nv);
        if (leafSize < 2 || leafSize > 17) throw new IllegalArgumentException("leaf size " + leafSize + " is not in 2..17");
        int n = nu * nv;
        if (xyz.length != 3 * n) throw new IllegalArgumentException(xyz.length + " coordinates for " + n + " vertices");
        if (normals != null && normals.length != 3 * n) throw new IllegalArgumentException(normals.length + " normal coordinates for " + n + " vertices");
        if (uv != null && uv.length != 2 * n) throw new IllegalArgumentException(uv.length + " parameters for " + n + " vertices");
        this.nu = nu;
        this.nv = nv;
        this.leafSize = leafSize;
        this.pos = xyz;
        this.normals = normals;
        this.uv = uv;
        this.u0 = u0; this.v0 = v0; this.u1 = u1; this.v1 = v1;
        alongV1V3 = new long[((nu - 1) * (nv - 1) + 63) >> 6];
        for (int j = 0, c = 0; j < nv - 1; j++) {
            for (int i = 0; i < nu - 1; i++, c++) {
                if (!shorterAlongV0V2(3 * (j * nu + i))) alongV1V3[c >> 6] |= 1L << c;
            }
        }
        if (fits(nu - 1, nv - 1)) {
            nodes = new int[0];
            nodeCount = 0;
            depth = 0;
            leafBox(0, nu - 1, 0, nv - 1, box, 0);
        } else {
            Builder b = new Builder();
            b.build(0, nu - 1, 0, nv - 1, box, 0, 1);
            nodes = Arrays.copyOf(b.nodes, b.count * NODE_INTS);
            nodeCount = b.count;
            depth = b.depth;
        }
    }

    private static void check(int nu, int nv) {
        if (nu < 2 || nv < 2 || nu > MAX_SIDE || nv > MAX_SIDE) {
            throw new IllegalArgumentException("a grid of " + nu + " x " + nv + " vertices (each side 2.." + MAX_SIDE + ")");
        }
    }

    private static float[] toFloat(double[] xyz, int nu, int nv) {
        check(nu, nv);
        float[] f = new float[xyz.length];
        for (int k = 0; k < f.length; k++) f[k] = (float) xyz[k];
        return f;
    }

    public int nu() { return nu; }
    public int nv() { return nv; }
    public int leafSize() { return leafSize; }
    public int triangleCount() { return 2 * (nu - 1) * (nv - 1); }
    public int nodeCount() { return nodeCount; }
    /** Levels of inner nodes on the longest path from the root (0 when the grid is one leaf). */
    public int depth() { return depth; }
    public boolean hasNormals() { return normals != null; }

    /**
     * Whether cell (i, j) is cut along its (i, j)-(i + 1, j + 1) diagonal, else along its (i + 1, j)-(i, j + 1) one:
     * the shorter, by the squared lengths in double of the stored floats, (i, j)-(i + 1, j + 1) on a tie (see the
     * class comment).
     */
    public boolean cutAlongV0V2(int i, int j) {
        if (i < 0 || j < 0 || i >= nu - 1 || j >= nv - 1) throw new IndexOutOfBoundsException("cell " + i + ", " + j);
        return alongV0V2(j * (nu - 1) + i);
    }

    /** Whether cell c (j * (nu - 1) + i) is cut along its v0-v2 diagonal, as decided when built. */
    private boolean alongV0V2(int c) { return (alongV1V3[c >> 6] & 1L << c) == 0; }

    /**
     * Whether the cell whose corner v0 is at {@code pos[q]} is cut along its v0-v2 diagonal, written as the uniform
     * path's rule (RefinedTriangles): v0-v2 unless its square is not {@code <=} the other's, so that a NaN picks
     * v1-v3 in both.
     */
    private boolean shorterAlongV0V2(int q) {
        final float[] p = pos;
        final int r = q + 3 * nu; // v3
        return dist2(p, q, r + 3) <= dist2(p, q + 3, r);
    }

    /** The squared distance of the float vertices at p[a] and p[b], in double (no overflow for any finite floats). */
    private static double dist2(float[] p, int a, int b) {
        final double dx = (double) p[a] - p[b], dy = (double) p[a + 1] - p[b + 1], dz = (double) p[a + 2] - p[b + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    /**
     * The heap this grid retains: 128 bytes for the object and its six-int box (an 88-byte object with compressed
     * references, a 40-byte array), plus per array (positions, the node records, the cells' diagonal bits, and
     * normals and parameters when present) a 16-byte header and its elements rounded up to 8 bytes. For nu x nv
     * vertices, C = (nu - 1)(nv - 1) cells and N nodes that is 128 + 16 + 12 nu nv + 16 + 288 N + 16 + 8 ceil(C / 64)
     * (+ 16 + 12 nu nv with normals, + 16 + 8 nu nv with parameters), up to the rounding.
     *
     * @return bytes, for a cache's budget
     */
    @Override
    public long bytes() {
        return 128 + array(pos.length) + array(nodes.length) + array(2 * alongV1V3.length)
                + (normals == null ? 0 : array(normals.length))
                + (uv == null ? 0 : array(uv.length));
    }

    private static long array(int fourByteElements) { return 16 + ((4L * fourByteElements + 7) & ~7L); }

    /** The box of every vertex (min x, y, z, max x, y, z) into {@code out[0..5]}. */
    public void bounds(double[] out) {
        for (int k = 0; k < 6; k++) out[k] = Float.intBitsToFloat(box[k]);
    }

    /** Coordinate {@code axis} (0..2) of vertex (i, j). */
    public float x(int i, int j, int axis) { return pos[3 * (j * nu + i) + axis]; }

    /**
     * The vertex number (j * nu + i) of corner {@code corner} (0..2) of triangle {@code sub}, counter-clockwise in
     * (i, j) (see the class comment).
     */
    public int triangleVertex(int sub, int corner) {
        int cell = sub >> 1, i = cell % (nu - 1), j = cell / (nu - 1);
        int a = j * nu + i; // v0; v1 = a + 1, v2 = a + nu + 1, v3 = a + nu
        if (alongV0V2(cell)) { // (v0, v1, v2), (v0, v2, v3)
            if (corner == 0) return a;
            if ((sub & 1) == 0) return corner == 1 ? a + 1 : a + nu + 1;
            return corner == 1 ? a + nu + 1 : a + nu;
        }
        if ((sub & 1) == 0) return corner == 0 ? a : corner == 1 ? a + 1 : a + nu; // (v0, v1, v3)
        return corner == 0 ? a + nu + 1 : corner == 1 ? a + nu : a + 1;            // (v2, v3, v1)
    }

    /** Coordinate {@code axis} (0..2) of corner {@code corner} (0..2) of triangle {@code sub}: its stored float. */
    public float cornerCoordinate(int sub, int corner, int axis) { return pos[3 * triangleVertex(sub, corner) + axis]; }

    /** The cell column i of triangle {@code sub}. */
    public int cellI(int sub) { return (sub >> 1) % (nu - 1); }

    /** The cell row j of triangle {@code sub}. */
    public int cellJ(int sub) { return (sub >> 1) / (nu - 1); }

    /**
     * The patch parameters of the point of triangle {@code sub} with weights {@code b1}, {@code b2} of its second
     * and third corner (a hit's {@code u}, {@code v}): interpolated from the vertices' parameters, clamped to the
     * patch's range, into {@code out[0..1]}.
     */
    public void parameters(int sub, double b1, double b2, double[] out) {
        double b0 = 1 - b1 - b2;
        if (uv != null) {
            int a = triangleVertex(sub, 0), b = triangleVertex(sub, 1), c = triangleVertex(sub, 2);
            out[0] = b0 * uv[2 * a] + b1 * uv[2 * b] + b2 * uv[2 * c];
            out[1] = b0 * uv[2 * a + 1] + b1 * uv[2 * b + 1] + b2 * uv[2 * c + 1];
            return;
        }
        // local coordinates in the cell, from the triangle's corners there: along v0-v2, A has (0,0), (1,0), (1,1)
        // and B (0,0), (1,1), (0,1); along v1-v3, A has (0,0), (1,0), (0,1) and B (1,1), (0,1), (1,0)
        double cu, cv;
        int i = cellI(sub), j = cellJ(sub);
        if (alongV0V2(sub >> 1)) {
            cu = (sub & 1) == 0 ? b1 + b2 : b1;
            cv = (sub & 1) == 0 ? b2 : b1 + b2;
        } else {
            cu = (sub & 1) == 0 ? b1 : 1 - b1;
            cv = (sub & 1) == 0 ? b2 : 1 - b2;
        }
        double fu = (i + clamp01(cu)) / (nu - 1), fv = (j + clamp01(cv)) / (nv - 1);
        out[0] = u0 + (u1 - u0) * Math.min(1, fu);
        out[1] = v0 + (v1 - v0) * Math.min(1, fv);
    }

    private static double clamp01(double x) { return x < 0 ? 0 : x > 1 ? 1 : x; }

    /** The vertex normals interpolated at the point of triangle {@code sub} with weights b1, b2 (not normalized). */
    public void normal(int sub, double b1, double b2, double[] out) {
        if (normals == null) throw new IllegalStateException("this grid has no normals");
        double b0 = 1 - b1 - b2;
        int a = 3 * triangleVertex(sub, 0), b = 3 * triangleVertex(sub, 1), c = 3 * triangleVertex(sub, 2);
        for (int k = 0; k < 3; k++) out[k] = b0 * normals[a + k] + b1 * normals[b + k] + b2 * normals[c + k];
    }

    // ---- building ----

    private boolean fits(int cellsU, int cellsV) { return cellsU < leafSize && cellsV < leafSize; }

    /** The box of the vertices [i0..i1] x [j0..j1] as float bits into out[o..o+5]. */
    private void leafBox(int i0, int i1, int j0, int j1, int[] out, int o) {
        float x0 = Float.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Float.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int j = j0; j <= j1; j++) {
            for (int p = 3 * (j * nu + i0), e = 3 * (j * nu + i1); p <= e; p += 3) {
                float x = pos[p], y = pos[p + 1], z = pos[p + 2];
                if (x < x0) x0 = x;
                if (x > x1) x1 = x;
                if (y < y0) y0 = y;
                if (y > y1) y1 = y;
                if (z < z0) z0 = z;
                if (z > z1) z1 = z;
            }
        }
        out[o] = Float.floatToRawIntBits(x0); out[o + 1] = Float.floatToRawIntBits(y0); out[o + 2] = Float.floatToRawIntBits(z0);
        out[o + 3] = Float.floatToRawIntBits(x1); out[o + 4] = Float.floatToRawIntBits(y1); out[o + 5] = Float.floatToRawIntBits(z1);
    }

    private final class Builder {
        int[] nodes = new int[NODE_INTS * 16];
        int count, depth;
        private final int[] ranges = new int[4 * WIDTH];

        /** Builds the node of range [i0..i1] x [j0..j1] (larger than a leaf), its box into out[o..o+5]. */
        int build(int i0, int i1, int j0, int j1, int[] out, int o, int level) {
            depth = Math.max(depth, level);
            int n = count++;
            if (nodes.length < count * NODE_INTS) nodes = Arrays.copyOf(nodes, 2 * count * NODE_INTS);
            // the halvings down to the leaves dealt out three per level from the bottom up, the remainder at
            // this node, so that nodes near the leaves (the most numerous) have all eight children
            int children = split(i0, i1, j0, j1, ranges, 0, (halvings(i1 - i0, j1 - j0) - 1) % 3 + 1);
            int[] r = ranges.clone(); // the recursion reuses ranges; building is not per ray
            int base = n * NODE_INTS;
            int[] childBox = new int[6];
            float[] u = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY,
                Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
            for (int c = 0; c < WIDTH; c++) {
                int ref;
                if (c >= children) {
                    childBox[0] = childBox[1] = childBox[2] = Float.floatToRawIntBits(Float.POSITIVE_INFINITY);
                    childBox[3] = childBox[4] = childBox[5] = Float.floatToRawIntBits(Float.NEGATIVE_INFINITY);
                    ref = EMPTY;
                } else {
                    int a0 = r[4 * c], a1 = r[4 * c + 1], b0 = r[4 * c + 2], b1 = r[4 * c + 3];
                    nodes[base + I_RANGES + c] = a0 | a1 << 16;
                    nodes[base + J_RANGES + c] = b0 | b1 << 16;
                    if (fits(a1 - a0, b1 - b0)) {
                        leafBox(a0, a1, b0, b1, childBox, 0);
                        ref = LEAF;
                    } else {
                        ref = build(a0, a1, b0, b1, childBox, 0, level + 1);
                    }
                    // the node's own box: the union of its children's
                    for (int k = 0; k < 3; k++) {
                        u[k] = Math.min(u[k], Float.intBitsToFloat(childBox[k]));
                        u[k + 3] = Math.max(u[k + 3], Float.intBitsToFloat(childBox[k + 3]));
                    }
                }
                for (int k = 0; k < 3; k++) {
                    nodes[base + 16 * k + c] = childBox[k];
                    nodes[base + 16 * k + 8 + c] = childBox[k + 3];
                }
                nodes[base + REFS + c] = ref;
            }
            for (int k = 0; k < 6; k++) out[o + k] = Float.floatToRawIntBits(u[k]);
            return n;
        }

        /** How many halvings a range of cu x cv cells takes to leaves on its longest path. */
        private int halvings(int cu, int cv) {
            int h = 0;
            while (!fits(cu, cv)) {
                if (cu >= cv) cu = (cu + 1) >> 1;
                else cv = (cv + 1) >> 1;
                h++;
            }
            return h;
        }

        /**
         * Cuts [i0..i1] x [j0..j1] into up to 2^levels ranges (i0, i1, j0, j1 each) from r[4 * at]: halves along
         * the longer side in cells (u on a tie), then each half that is still larger than a leaf likewise, down
         * to {@code levels} halvings; returns how many.
         */
        private int split(int i0, int i1, int j0, int j1, int[] r, int at, int levels) {
            int k = at;
            int[] halves = new int[8];
            halve(i0, i1, j0, j1, halves, 0);
            for (int h = 0; h < 2; h++) {
                int a0 = halves[4 * h], a1 = halves[4 * h + 1], b0 = halves[4 * h + 2], b1 = halves[4 * h + 3];
                if (levels == 1 || fits(a1 - a0, b1 - b0)) {
                    r[4 * k] = a0; r[4 * k + 1] = a1; r[4 * k + 2] = b0; r[4 * k + 3] = b1;
                    k++;
                } else {
                    k += split(a0, a1, b0, b1, r, k, levels - 1);
                }
            }
            return k - at;
        }

        private void halve(int i0, int i1, int j0, int j1, int[] r, int o) {
            if (i1 - i0 >= j1 - j0) {
                int m = (i0 + i1) >>> 1;
                r[o] = i0; r[o + 1] = m; r[o + 2] = j0; r[o + 3] = j1;
                r[o + 4] = m; r[o + 5] = i1; r[o + 6] = j0; r[o + 7] = j1;
            } else {
                int m = (j0 + j1) >>> 1;
                r[o] = i0; r[o + 1] = i1; r[o + 2] = j0; r[o + 3] = m;
                r[o + 4] = i0; r[o + 5] = i1; r[o + 6] = m; r[o + 7] = j1;
            }
        }
    }

    // ---- queries ----

    /** Ints of traversal stack a query needs: four per entry, at most seven left behind per level. */
    private int stackNeed() { return 4 * ((WIDTH - 1) * depth + WIDTH); }

    /**
     * The nearest hit in (ray.tMin, ray.tMax), recorded in {@code hit} (t, sub, u, v; see the class comment).
     * Children whose boxes the ray crosses are visited nearest first, and a pending one whose entry lies beyond
     * the nearest hit found since is skipped. The ray is left as it was.
     *
     * @return whether a hit was found
     */
    public boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        return walk(ray, hit, ctx, null);
    }

    /** Whether anything blocks the ray in (ray.tMin, ray.tMax); stops at the first hit. The ray is left alone. */
    public boolean occluded(Ray ray, TraversalScratch ctx) {
        return walk(ray, null, ctx, null);
    }

    /**
     * Hands every triangle of every leaf whose box the ray's [tMin, tMax] crosses to {@code visitor}, each once, in
     * no particular order: a superset of the triangles the watertight test hits in that interval (the box tests are
     * conservative), which a caller after every crossing of a whole line passes as an infinite interval. The
     * visitor decides the crossings itself (with {@link #cornerCoordinate} and {@link WatertightTriangles}'s
     * test, for example) and may use {@code ctx} for traversals of its own, whose stack lies above this one's; it
     * must leave the ray as it found it. Allocates nothing.
     */
    public void visitTriangles(Ray ray, TraversalScratch ctx, GridTriangleVisitor visitor) {
        if (visitor == null) throw new NullPointerException("visitor");
        walk(ray, null, ctx, visitor);
    }

    /** Whether a node's eight boxes are tested with the JDK's vector API ({@link SimdBoxes}), else one by one. */
    private static final boolean SIMD = WideBvh.AVAILABLE;

    /**
     * The traversal of all three queries: the nearest hit when {@code hit} is given, any hit when it and
     * {@code visitor} are null, else every leaf's triangles handed to the visitor (the return value then means
     * nothing).
     */
    private boolean walk(Ray ray, PrimitiveHit hit, TraversalScratch ctx, GridTriangleVisitor visitor) {
        ctx.direction(ray);
        {
            final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
            if (Double.isNaN(Bvh.slabEntry(box, 0, ray.ox, ray.oy, ray.oz, ix, iy, iz, ix < 0 ? 3 : 0, iy < 0 ? 3 : 0,
                    iz < 0 ? 3 : 0, ray.tMin, ray.tMax))) {
                return false;
            }
        }
        final double saved = ray.tMax;
        if (nodeCount == 0) {
            if (visitor != null) {
                try {
                    visit(0, nu - 1, 0, nv - 1, ray, ctx, visitor);
                } finally {
                    ray.tMax = saved;
                }
                return false;
            }
            boolean any = leaf(0, nu - 1, 0, nv - 1, ray, hit, ctx);
            ray.tMax = saved;
            return any;
        }
        // the boxes are tested as WideBvh tests its own, in float with the origin moved two ulps outward and the
        // distances widened, so that rounding never drops a box the ray touches; unlike WideBvh's the inverse
        // direction is not clamped: a ray in a box's plane (a direction component zero, the origin on a halving
        // line) then gets infinite slab distances of the right sign from the moved origin, not tiny ones
        final float ix = (float) ctx.invX, iy = (float) ctx.invY, iz = (float) ctx.invZ;
        final float fox = (float) ray.ox, foy = (float) ray.oy, foz = (float) ray.oz;
        final float ex = ix >= 0 ? slack(fox) : -slack(fox), ey = iy >= 0 ? slack(foy) : -slack(foy),
                ez = iz >= 0 ? slack(foz) : -slack(foz);
        final float oxn = fox + ex, oxf = fox - ex, oyn = foy + ey, oyf = foy - ey, ozn = foz + ez, ozf = foz - ez;
        final int nx = ix >= 0 ? 0 : 8, ny = iy >= 0 ? 0 : 8, nz = iz >= 0 ? 0 : 8;
        final float tMin = Bvh.down(ray.tMin);
        float tMax = Bvh.up(ray.tMax);
        final float[] dist = ctx.lanes;
        final int base = ctx.stackTop, need = stackNeed();
        final int[] stack = ctx.stack(base + need);
        final int[] nodes = this.nodes;
        ctx.stackTop = base + need;
        boolean any = false;
        try {
            int sp = base;
            int n = 0, ir = 0, jr = 0; // the current entry: a node index, or LEAF with its ranges
            while (true) {
                if (n == LEAF) {
                    if (visitor != null) {
                        visit(ir & 0xffff, ir >>> 16, jr & 0xffff, jr >>> 16, ray, ctx, visitor);
                    } else if (leaf(ir & 0xffff, ir >>> 16, jr & 0xffff, jr >>> 16, ray, hit, ctx)) {
                        any = true;
                        if (hit == null) return true;
                        tMax = Bvh.up(ray.tMax);
                    }
                } else {
                    final int b = n * NODE_INTS;
                    if (TraversalScratch.COUNTING) ctx.nodesVisited[ctx.rayKind]++;
                    // an unused slot's box is inverted (min +inf, max -inf): no ray enters it
                    int bits = SIMD
                            ? SimdBoxes.test(nodes, b, nx, ny, nz, oxn, oxf, oyn, oyf, ozn, ozf, ix, iy, iz, tMin, tMax, dist)
                            : boxes(nodes, b, nx, ny, nz, oxn, oxf, oyn, oyf, ozn, ozf, ix, iy, iz, tMin, tMax, dist);
                    if (bits != 0) {
                        final int c0 = b + REFS;
                        if ((bits & (bits - 1)) == 0) { // one child: entered without the stack
                            final int c = Integer.numberOfTrailingZeros(bits);
                            n = nodes[c0 + c];
                            ir = nodes[b + I_RANGES + c];
                            jr = nodes[b + J_RANGES + c];
                            continue;
                        }
                        // several: pushed with their entry distances, those of this node kept sorted (for a
                        // nearest hit) with the nearest on top, which is taken at once
                        final int first = sp;
                        do {
                            final int c = Integer.numberOfTrailingZeros(bits);
                            bits &= bits - 1;
                            final float d = dist[c];
                            int at = sp;
                            if (hit != null) {
                                while (at > first && Float.intBitsToFloat(stack[at - 1]) < d) {
                                    stack[at] = stack[at - 4]; stack[at + 1] = stack[at - 3];
                                    stack[at + 2] = stack[at - 2]; stack[at + 3] = stack[at - 1];
                                    at -= 4;
                                }
                            }
                            stack[at] = nodes[c0 + c];
                            stack[at + 1] = nodes[b + I_RANGES + c];
                            stack[at + 2] = nodes[b + J_RANGES + c];
                            stack[at + 3] = Float.floatToRawIntBits(d);
                            sp += 4;
                        } while (bits != 0);
                        sp -= 4;
                        n = stack[sp]; ir = stack[sp + 1]; jr = stack[sp + 2];
                        continue;
                    }
                }
                // pop the next pending entry that may still hold something nearer than the best hit
                boolean found = false;
                while (sp > base) {
                    sp -= 4;
                    if (Float.intBitsToFloat(stack[sp + 3]) <= tMax) {
                        n = stack[sp]; ir = stack[sp + 1]; jr = stack[sp + 2];
                        found = true;
                        break;
                    }
                }
                if (!found) break;
            }
        } finally {
            ray.tMax = saved;
            ctx.stackTop = base;
        }
        return any;
    }

    private static float slack(float o) { return Bvh.slack(o); }

    /** {@link SimdBoxes}'s widening of a distance, for the scalar test. */
    private static final float GAMMA = 8 * 0x1p-24f;

    /**
     * The eight boxes of the node record at {@code o} tested one by one, with the float operations
     * {@link SimdBoxes#test(int[], int, int, int, int, float, float, float, float, float, float, float, float, float,
     * float, float, float[])} does per lane: the entry distances of those hit into dist, and their lanes as bits.
     */
    private static int boxes(int[] nodes, int o, int nx, int ny, int nz, float oxn, float oxf, float oyn, float oyf,
                             float ozn, float ozf, float ix, float iy, float iz, float tMin, float tMax, float[] dist) {
        int bits = 0;
        for (int c = 0; c < WIDTH; c++) {
            final int p = o + c;
            float t0 = (Float.intBitsToFloat(nodes[p + nx]) - oxn) * ix;
            float t1 = (Float.intBitsToFloat(nodes[p + 8 - nx]) - oxf) * ix;
            t0 = Math.max(t0, (Float.intBitsToFloat(nodes[p + 16 + ny]) - oyn) * iy);
            t1 = Math.min(t1, (Float.intBitsToFloat(nodes[p + 24 - ny]) - oyf) * iy);
            t0 = Math.max(t0, (Float.intBitsToFloat(nodes[p + 32 + nz]) - ozn) * iz);
            t1 = Math.min(t1, (Float.intBitsToFloat(nodes[p + 40 - nz]) - ozf) * iz);
            t0 = Math.max(t0, tMin);
            t1 = Math.min(t1, tMax);
            t0 = Math.abs(t0) * -GAMMA + t0;
            t1 = Math.abs(t1) * GAMMA + t1;
            if (t0 <= t1) {
                dist[c] = t0;
                bits |= 1 << c;
            }
        }
        return bits;
    }

    /**
     * The triangles of the cells of vertex range [i0..i1] x [j0..j1]: with {@code hit} null an any-hit test that
     * returns at the first hit; otherwise every hit nearer than ray.tMax is recorded and shrinks ray.tMax.
     * Each cell takes the transformed vertices and the edge function of its left side from its left neighbour.
     */
    private boolean leaf(int i0, int i1, int j0, int j1, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
        final float[] p = pos;
        final int kx = ctx.shearKx, ky = ctx.shearKy, kz = ctx.shearKz;
        final double sx = ctx.shearSx, sy = ctx.shearSy, sz = ctx.shearSz;
        final double okx = kx == 0 ? ray.ox : kx == 1 ? ray.oy : ray.oz;
        final double oky = ky == 0 ? ray.ox : ky == 1 ? ray.oy : ray.oz;
        final double okz = kz == 0 ? ray.ox : kz == 1 ? ray.oy : ray.oz;
        final double tMin = ray.tMin;
        final int row = 3 * nu;
        boolean any = false;
        for (int j = j0; j < j1; j++) {
            int q = 3 * (j * nu + i0);
            // p00 = (i, j), p01 = (i, j + 1)
            double z = p[q + kz] - okz;
            double x00 = p[q + kx] - okx - sx * z, y00 = p[q + ky] - oky - sy * z, z00 = sz * z;
            z = p[q + row + kz] - okz;
            double x01 = p[q + row + kx] - okx - sx * z, y01 = p[q + row + ky] - oky - sy * z, z01 = sz * z;
            double left = x01 * y00 - y01 * x00; // E(p00, p01)
            for (int i = i0; i < i1; i++) {
                final int sub = 2 * (j * (nu - 1) + i);
                final boolean v02 = alongV0V2(sub >> 1);
                q += 3;
                z = p[q + kz] - okz;
                final double x10 = p[q + kx] - okx - sx * z, y10 = p[q + ky] - oky - sy * z, z10 = sz * z;
                z = p[q + row + kz] - okz;
                final double x11 = p[q + row + kx] - okx - sx * z, y11 = p[q + row + ky] - oky - sy * z, z11 = sz * z;
                // E(p, q) = qx * py - qy * px; E(q, p) is exactly -E(p, q)
                final double bottom = x10 * y00 - y10 * x00; // E(p00, p10)
                final double right = x11 * y10 - y11 * x10;  // E(p10, p11)
                final double top = x11 * y01 - y11 * x01;    // E(p01, p11)
                final double diag = x11 * y00 - y11 * x00; // E(p00, p11)
                final double anti = x01 * y10 - y01 * x10; // E(p10, p01)
                // each triangle's U, V, W are the edge functions of the edges opposite its corners 0, 1, 2, picked
                // by the cell's diagonal without a branch: the diagonal follows the surface's shape, so a branch
                // on it is mispredicted often. Along v0-v2, A = (p00, p10, p11): U = E(p10, p11), V = E(p11, p00),
                // W = E(p00, p10), and B = (p00, p11, p01): U = E(p11, p01), V = E(p01, p00), W = E(p00, p11);
                // along v1-v3, A = (p00, p10, p01): U = E(p10, p01), V = E(p01, p00), W = E(p00, p10), and
                // B = (p11, p01, p10): U = E(p01, p10), V = E(p10, p11), W = E(p11, p01)
                final double au = v02 ? right : anti, av = v02 ? -diag : -left, azc = v02 ? z11 : z01;
                if (TraversalScratch.COUNTING) ctx.triangleTests[ctx.rayKind]++;
                if (triangle(au, av, bottom, z00, z10, azc, sub, tMin, ray, hit)) {
                    if (hit == null) return true;
                    any = true;
                }
                final double bu = v02 ? -top : -anti, bv = v02 ? -left : right, bw = v02 ? diag : -top;
                final double bza = v02 ? z00 : z11, bzb = v02 ? z11 : z01, bzc = v02 ? z01 : z10;
                if (TraversalScratch.COUNTING) ctx.triangleTests[ctx.rayKind]++;
                if (triangle(bu, bv, bw, bza, bzb, bzc, sub + 1, tMin, ray, hit)) {
                    if (hit == null) return true;
                    any = true;
                }
                x00 = x10; y00 = y10; z00 = z10;
                x01 = x11; y01 = y11; z01 = z11;
                left = right;
            }
        }
        return any;
    }

    /**
     * {@link WatertightTriangles#test}'s decision for one triangle from its edge functions {@code u}, {@code v},
     * {@code w} (of the edges opposite its corners 0, 1, 2) and its corners' sheared z, in the same operations and
     * order: whether it is hit in (tMin, ray.tMax); with {@code hit} given, the hit is recorded and shrinks ray.tMax.
     */
    private static boolean triangle(double u, double v, double w, double za, double zb, double zc, int sub,
                                    double tMin, Ray ray, PrimitiveHit hit) {
        if (Math.min(u, Math.min(v, w)) < 0 && Math.max(u, Math.max(v, w)) > 0) return false; // signs differ
        final double det = u + v + w;
        if (det == 0) return false;
        final double t = (u * za + v * zb + w * zc) / det;
        if (!(t > tMin && t < ray.tMax)) return false;
        if (hit != null) {
            final double inv = 1 / det;
            hit.t = t;
            hit.sub = sub;
            hit.u = v * inv;
            hit.v = w * inv;
            ray.tMax = t;
        }
        return true;
    }

    /** Hands both triangles of every cell of vertex range [i0..i1] x [j0..j1] to the visitor, row by row. */
    private void visit(int i0, int i1, int j0, int j1, Ray ray, TraversalScratch ctx, GridTriangleVisitor visitor) {
        if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
        for (int j = j0; j < j1; j++) {
            for (int i = i0, sub = 2 * (j * (nu - 1) + i0); i < i1; i++, sub += 2) {
                visitor.triangle(this, sub, ray, ctx);
                visitor.triangle(this, sub + 1, ray, ctx);
            }
        }
    }
}
