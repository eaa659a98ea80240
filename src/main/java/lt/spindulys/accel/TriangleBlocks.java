package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * The triangles of a wide tree's leaves copied into the leaves: per leaf one block of up to
 * {@link #LANES} triangles, their corners in float, structure of arrays (a row of eight x of the
 * first corners, then their y, ...), so that one pass of 256-bit vectors tells which of the
 * leaf's triangles the ray certainly misses. Those it may hit are then tested exactly, in double,
 * by the set's own test ({@link TriangleSet#intersectRange}): a hit, its distance and its
 * barycentrics are bit for bit what the double test gives alone, so every image and every
 * agreement between structures is unchanged, and watertightness is the double test's.
 *
 * <p>The float test is conservative. Corners, origin and shear are rounded to float; each 2D
 * coordinate of the sheared frame is then within {@code delta = 12 eps (P + O)} of its exact
 * value (eps = 2^-24, P the largest coordinate of the mesh, O of the ray's origin), and each edge
 * function within {@code 4 eps S^2 + 4 delta S + 2 delta^2} (S the lane's largest coordinate).
 * A lane is dropped only when its edge functions have strictly mixed signs beyond twice that
 * bound, where the exact test also finds mixed signs.
 */
public final class TriangleBlocks {
    /** Triangles per block (the lanes of one 256-bit float vector). */
    public static final int LANES = 8;
    /** Floats per block: three corners, three coordinates, eight lanes. */
    public static final int BLOCK = 9 * LANES;

    private final float[] corners;
    /** The first leaf slot of each block; its triangles are those of slots first .. first + count - 1. */
    private final int[] first;
    /** The triangle of each leaf slot, or null when slot k holds triangle k. */
    private final int[] perm;
    /** The triangles, whose own test confirms each hit the float test keeps. */
    private final TriangleSet set;
    /** One triangle's corners, while copying. */
    private final double[] corner = new double[9];
    /** The largest absolute coordinate of any corner. */
    private final double maxAbs;
    private int count;

    /** Bytes of {@code blocks} blocks (what {@link #bytes()} will say), to check before making them. */
    static long bytes(long blocks) { return blocks * (4L * BLOCK + 4); }

    /**
     * Room for {@code blocks} blocks of {@code set}'s triangles, leaf slot k holding triangle
     * {@code perm[k]} (or k when perm is null); filled by {@link #add}.
     */
    TriangleBlocks(TriangleSet set, int[] perm, int blocks) {
        this.perm = perm;
        corners = new float[BLOCK * blocks];
        first = new int[blocks];
        this.set = set;
        maxAbs = set.maxAbsCoordinate();
    }

    /** Copies leaf slots [from, from + n) into the next block; returns its index. */
    int add(int from, int n) {
        int b = count++;
        first[b] = from;
        int o = BLOCK * b;
        for (int l = 0; l < n; l++) {
            set.corners(perm == null ? from + l : perm[from + l], corner);
            for (int k = 0; k < 9; k++) corners[o + LANES * k + l] = (float) corner[k];
        }
        return b;
    }

    /** The first leaf slot of block b. */
    int first(int b) { return first[b]; }

    long bytes() { return 4L * corners.length + 4L * first.length; }

    /**
     * The ray's constants of the float test, once per traversal, into {@code ctx.blockRay}: the
     * origin in the permuted axes, the shear, and the error bound of a sheared coordinate.
     */
    void prepare(Ray ray, TraversalScratch ctx) {
        ctx.direction(ray);
        final int kx = ctx.shearKx, ky = ctx.shearKy, kz = ctx.shearKz;
        final double okx = kx == 0 ? ray.ox : kx == 1 ? ray.oy : ray.oz;
        final double oky = ky == 0 ? ray.ox : ky == 1 ? ray.oy : ray.oz;
        final double okz = kz == 0 ? ray.ox : kz == 1 ? ray.oy : ray.oz;
        double o = Math.max(Math.abs(okx), Math.max(Math.abs(oky), Math.abs(okz)));
        float[] r = ctx.blockRay;
        r[0] = (float) okx;
        r[1] = (float) oky;
        r[2] = (float) okz;
        r[3] = (float) ctx.shearSx;
        r[4] = (float) ctx.shearSy;
        r[5] = (float) (12 * 0x1p-24 * (maxAbs + o));
    }

    /** The closest hit among block b's n triangles, as the set's own test records it ({@link #prepare} first). */
    boolean intersect(int b, int n, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        int bits = candidates(b, ctx) & ((1 << n) - 1);
        boolean any = false;
        int f = first[b];
        while (bits != 0) {
            int k = f + Integer.numberOfTrailingZeros(bits);
            bits &= bits - 1;
            if (set.intersectRange(perm, k, k + 1, ray, hit, ctx)) any = true;
        }
        return any;
    }

    /** Whether any of block b's n triangles blocks the ray ({@link #prepare} first). */
    boolean occluded(int b, int n, Ray ray, TraversalScratch ctx) {
        int bits = candidates(b, ctx) & ((1 << n) - 1);
        int f = first[b];
        while (bits != 0) {
            int k = f + Integer.numberOfTrailingZeros(bits);
            bits &= bits - 1;
            if (set.occludedRange(perm, k, k + 1, ray, ctx)) return true;
        }
        return false;
    }

    /** The lanes of block b (all eight, whatever its count) that the ray may hit, as bits (for tests). */
    int candidates(int b, Ray ray, TraversalScratch ctx) {
        prepare(ray, ctx);
        return candidates(b, ctx);
    }

    private int candidates(int b, TraversalScratch ctx) {
        float[] r = ctx.blockRay;
        return SimdTriangles.candidates(corners, BLOCK * b, ctx.shearKx, ctx.shearKy, ctx.shearKz, r[0], r[1], r[2], r[3], r[4], r[5], ctx.lanes);
    }
}
