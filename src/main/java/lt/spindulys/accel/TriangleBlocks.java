package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * Indexed triangles copied into leaf-ordered blocks of four, in float SoA, for a four-wide
 * watertight ray test (as Embree's Triangle4 leaves, but storing the corners themselves). Block
 * {@code b} is {@code BLOCK} floats from {@code 36 b}: the x of the first corner of its four
 * triangles, then that corner's y, z, then the second and third corners likewise; its triangle
 * indices are {@code ids[4 b .. 4 b + 3]}. A leaf's triangles fill consecutive blocks, the last
 * one padded with NaN corners and id -1, which no ray hits. Corners are the double positions
 * rounded to nearest float, so triangles sharing a position share its floats bit for bit.
 *
 * <p>The test is Woop, Benthin and Wald's ("Watertight Ray/Triangle Intersection", JCGT 2013) in
 * float, as {@link WatertightTriangles} does it in double. Corners are translated by the
 * float-rounded ray origin and sheared in float. The rounded origin moves the ray by at most half
 * a float ulp of each origin coordinate (2^-24 relative), and each translated coordinate carries
 * another 2^-24 of |corner - origin|: hits near the origin stay accurate, but a ray starting
 * far from the world's origin sees the triangles shifted by up to 6e-8 |origin| (the caller's
 * ray epsilons must exceed that). Translating in double and rounding afterwards would remove
 * the first error, but costs a widening to double per corner. Neither error breaks
 * watertightness: a corner is transformed identically by every triangle that uses it. Where a
 * lane's edge function is exactly 0 (and the lane is not already outside), the three functions
 * are recomputed in double from the same float coordinates (the paper's fallback): products of
 * floats are exact in double, so the sign is right and shared edges decide consistently.
 *
 * <p>Uses 128-bit vectors ({@link SimdTriangles}) when {@link WideBvh#AVAILABLE}, else a scalar
 * loop doing the same float operations; the two give bit-identical hits. Immutable after
 * construction; thread-safe (per-thread state lives in the {@link TraversalScratch}).
 */
public final class TriangleBlocks {
    /** Floats per block: three corners, three coordinates, four lanes. */
    public static final int BLOCK = 36;
    /** Floats of per-thread scratch the test needs ({@link TraversalScratch#blockLanes}). */
    static final int SCRATCH = 16;
    /** Scratch offsets of the test's outputs, four lanes each. */
    static final int T = 0, V = 4, W = 8, DET = 12;

    private static final boolean SIMD = WideBvh.AVAILABLE;

    private final float[] corners;
    private final int[] ids;
    /** Leaf l's blocks are [blockStart[l], blockStart[l + 1]). */
    private final int[] blockStart;

    /**
     * Blocks of the triangles {@code perm[leafBounds[l] .. leafBounds[l + 1])} for each leaf l.
     *
     * @param tri three position indices per triangle
     * @param pos three coordinates per position
     * @param perm the triangles in leaf order, or null for 0, 1, 2, ...
     * @param leafBounds ascending offsets into perm, from 0 to its length: leaf l is [leafBounds[l], leafBounds[l + 1])
     */
    public TriangleBlocks(int[] tri, double[] pos, int[] perm, int[] leafBounds) {
        int leaves = leafBounds.length - 1;
        blockStart = new int[leaves + 1];
        for (int l = 0; l < leaves; l++) blockStart[l + 1] = blockStart[l] + (leafBounds[l + 1] - leafBounds[l] + 3) / 4;
        int blocks = blockStart[leaves];
        corners = new float[BLOCK * blocks];
        ids = new int[4 * blocks];
        java.util.Arrays.fill(corners, Float.NaN);
        java.util.Arrays.fill(ids, -1);
        for (int l = 0; l < leaves; l++) {
            for (int k = leafBounds[l]; k < leafBounds[l + 1]; k++) {
                int n = k - leafBounds[l], b = blockStart[l] + n / 4, lane = n % 4;
                int i = perm == null ? k : perm[k];
                ids[4 * b + lane] = i;
                for (int c = 0; c < 3; c++) {
                    int p = 3 * tri[3 * i + c];
                    for (int a = 0; a < 3; a++) corners[BLOCK * b + 12 * c + 4 * a + lane] = (float) pos[p + a];
                }
            }
        }
    }

    /** The number of leaves. */
    public int leafCount() { return blockStart.length - 1; }

    /** The first block of leaf {@code l}. */
    public int blockStart(int l) { return blockStart[l]; }

    /** One past the last block of leaf {@code l}. */
    public int blockEnd(int l) { return blockStart[l + 1]; }

    /** The number of blocks. */
    public int blockCount() { return ids.length / 4; }

    /** Bytes of the blocks' arrays (corners and ids, without array headers). */
    public long bytes() { return 4L * corners.length + 4L * ids.length + 4L * blockStart.length; }

    /**
     * The nearest hit among blocks [from, to) with t in (ray.tMin, ray.tMax), as
     * {@link WatertightTriangles#test} records it: t, the triangle index as prim, the weights of
     * its second and third corner as u, v; ray.tMax shrinks to t.
     *
     * @return whether a hit was recorded
     */
    public boolean intersect(int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        return test(from, to, ray, hit, ctx, SIMD);
    }

    /**
     * Whether any triangle of blocks [from, to) is hit with t in (ray.tMin, ray.tMax); the one
     * found is left in {@link TraversalScratch#blockingPrimitive}.
     */
    public boolean occluded(int from, int to, Ray ray, TraversalScratch ctx) {
        return test(from, to, ray, null, ctx, SIMD);
    }

    /** The test, with the vector or scalar kernel (for the tests that they agree). */
    boolean test(int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx, boolean simd) {
        ctx.direction(ray);
        final int kx = ctx.shearKx, ky = ctx.shearKy, kz = ctx.shearKz;
        final float sx = (float) ctx.shearSx, sy = (float) ctx.shearSy, sz = (float) ctx.shearSz;
        final float ox = (float) (kx == 0 ? ray.ox : kx == 1 ? ray.oy : ray.oz);
        final float oy = (float) (ky == 0 ? ray.ox : ky == 1 ? ray.oy : ray.oz);
        final float oz = (float) (kz == 0 ? ray.ox : kz == 1 ? ray.oy : ray.oz);
        // float t > tMin exactly when (double) t > ray.tMin, and likewise for tMax, so the float
        // compares decide as the double ones would
        final float tMin = down(ray.tMin);
        float tMax = up(ray.tMax);
        final float[] s = ctx.blockLanes;
        final float[] f = corners;
        boolean any = false;
        for (int b = from; b < to; b++) {
            int bits = simd ? SimdTriangles.test(f, BLOCK * b, kx, ky, kz, ox, oy, oz, sx, sy, sz, tMin, tMax, s) : -1;
            if (bits < 0) bits = testScalar(f, BLOCK * b, kx, ky, kz, ox, oy, oz, sx, sy, sz, tMin, tMax, s);
            if (bits == 0) continue;
            if (hit == null) {
                ctx.blockingPrimitive = ids[4 * b + Integer.numberOfTrailingZeros(bits)];
                return true;
            }
            int lane = 0;
            float t = s[T];
            for (int l = 1; l < 4; l++) if (s[T + l] < t) { t = s[T + l]; lane = l; }
            double inv = 1 / (double) s[DET + lane];
            hit.t = t;
            hit.prim = ids[4 * b + lane];
            hit.u = s[V + lane] * inv;
            hit.v = s[W + lane] * inv;
            ray.tMax = t;
            tMax = t;
            any = true;
        }
        return any;
    }

    /**
     * The four triangles of the block at {@code f[o .. o + 35]} against a ray whose axes are
     * permuted to (kx, ky, kz), translated by (ox, oy, oz) (in that permuted order) and sheared by
     * (sx, sy, sz). Returns the lanes hit with t in (tMin, tMax) as bits; when nonzero, their t
     * (infinity for the others), V, W and det are in {@code s} at {@link #T}, {@link #V},
     * {@link #W}, {@link #DET}.
     */
    static int testScalar(float[] f, int o, int kx, int ky, int kz, float ox, float oy, float oz,
                          float sx, float sy, float sz, float tMin, float tMax, float[] s) {
        int bits = 0;
        for (int l = 0; l < 4; l++) {
            int p = o + l;
            float az = f[p + 4 * kz] - oz, bz = f[p + 12 + 4 * kz] - oz, cz = f[p + 24 + 4 * kz] - oz;
            float ax = f[p + 4 * kx] - ox - az * sx, ay = f[p + 4 * ky] - oy - az * sy;
            float bx = f[p + 12 + 4 * kx] - ox - bz * sx, by = f[p + 12 + 4 * ky] - oy - bz * sy;
            float cx = f[p + 24 + 4 * kx] - ox - cz * sx, cy = f[p + 24 + 4 * ky] - oy - cz * sy;
            float u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
            boolean in = !outside(u, v, w);
            if (in && (u == 0 || v == 0 || w == 0)) {
                u = edge(cx, by, cy, bx);
                v = edge(ax, cy, ay, cx);
                w = edge(bx, ay, by, ax);
                in = !outside(u, v, w);
            }
            float det = u + v + w;
            float t = (u * (az * sz) + v * (bz * sz) + w * (cz * sz)) / det;
            boolean hit = in && det != 0 && t > tMin && t < tMax;
            s[T + l] = hit ? t : Float.POSITIVE_INFINITY;
            s[V + l] = v;
            s[W + l] = w;
            s[DET + l] = det;
            bits |= (hit ? 1 : 0) << l;
        }
        return bits;
    }

    /** p * q - r * w in double (the products are exact), rounded to float: the sign is exact. */
    private static float edge(float p, float q, float r, float w) {
        return (float) ((double) p * q - (double) r * w);
    }

    private static boolean outside(float u, float v, float w) {
        return (u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0);
    }

    /** The largest float at most d. */
    static float down(double d) {
        float f = (float) d;
        return f > d ? Math.nextDown(f) : f;
    }

    /** The smallest float at least d. */
    static float up(double d) {
        float f = (float) d;
        return f < d ? Math.nextUp(f) : f;
    }
}
