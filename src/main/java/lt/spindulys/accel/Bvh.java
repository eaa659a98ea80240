package lt.spindulys.accel;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.ForkJoinTask;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;

/**
 * Bounding volume hierarchy over a {@link PrimitiveSet}, built with the binned surface-area
 * heuristic and stored flat: eight ints per node, six float bounds (rounded outward, as bits) and
 * two links, in depth-first order (a node's left child directly follows it), and a permutation of the primitive indices so each
 * leaf owns a contiguous range. Immutable after construction; thread-safe.
 *
 * <p>The build is iterative (an explicit task stack), so millions of primitives cannot overflow
 * the Java stack, and splits fall back to the median when the tree grows deep, which bounds the
 * traversal stack each ray needs.
 */
public final class Bvh implements Accelerator {
    /** Largest number of primitives in a leaf. */
    public static final int DEFAULT_LEAF_SIZE = 4;
    /**
     * Relative widening of each box's ray interval: the slab test's rounding (a few ulps of t)
     * must never reject a box whose triangle the watertight test accepts on the box's surface.
     */
    private static final double PAD = 4 * 3 * 0x1p-53 / (1 - 3 * 0x1p-53);

    private final PrimitiveSet set;
    /**
     * Eight ints per node, so that one node is one 32-byte record (one memory fetch where a
     * separate link array would need a second): minX, minY, minZ, maxX, maxY, maxZ as the bits
     * of floats rounded outward from the exact double bounds (half the memory of doubles; a box
     * that only grows keeps every primitive inside it, so the watertight primitive tests are
     * unaffected), then two links: a leaf holds (first index into {@link #perm}, count > 0); an
     * inner node holds (right child index, -1 - split axis). The left child of node i is node i + 1.
     */
    private final int[] node;
    /**
     * Primitive index of each leaf slot, or null when the set renumbered its primitives into
     * leaf order ({@link PrimitiveSet#reorder}), so that slot k holds primitive k.
     */
    private final int[] perm;
    private final int primitiveCount;
    /** The exact (double) bounds of everything indexed, which the float root box only encloses. */
    private final Bounds bounds;
    private final int nodeCount;
    private final int depth;

    public Bvh(PrimitiveSet set) { this(set, DEFAULT_LEAF_SIZE); }

    /**
     * Builds the hierarchy. Primitives with empty bounds can never be hit and are left out;
     * non-finite bounds are an error (unbounded objects belong outside any hierarchy).
     */
    public Bvh(PrimitiveSet set, int maxLeafSize) { this(set, maxLeafSize, true); }

    /**
     * Builds the hierarchy, on the calling thread alone when {@code parallel} is false (a render
     * thread refining a patch: the render threads are the parallelism then, and a pool per patch
     * would cost more than the build).
     *
     * @param set the primitives
     * @param maxLeafSize most primitives in a leaf
     * @param parallel whether large builds may split across a pool of threads
     */
    public Bvh(PrimitiveSet set, int maxLeafSize, boolean parallel) {
        this(set, maxLeafSize, 1, parallel ? Runtime.getRuntime().availableProcessors() : 1);
    }

    /**
     * As {@link #Bvh(PrimitiveSet, int, boolean)}, with the surface-area heuristic counting
     * primitives in blocks of {@code costBlock} (a leaf costs its area times its number of
     * blocks), for leaves whose primitives are tested a block at a time.
     */
    public Bvh(PrimitiveSet set, int maxLeafSize, int costBlock, boolean parallel) {
        this(set, maxLeafSize, costBlock, parallel ? Runtime.getRuntime().availableProcessors() : 1);
    }

    Bvh(PrimitiveSet set, int maxLeafSize, int threads) { this(set, maxLeafSize, 1, threads); }

    /**
     * Builds the hierarchy on at most {@code threads} threads (1: the calling thread alone). The
     * tree is the same for every thread count: how work is divided depends on range sizes only.
     */
    Bvh(PrimitiveSet set, int maxLeafSize, int costBlock, int threads) {
        if (costBlock < 1) throw new IllegalArgumentException("cost block must be at least 1, got " + costBlock);
        if (maxLeafSize < 1) throw new IllegalArgumentException("leaf size must be at least 1, got " + maxLeafSize);
        this.set = set;
        int n = set.size();
        // A pool of our own: forks must not land in the common pool, whose size is not ours to choose.
        ForkJoinPool pool = threads > 1 && n >= BvhBuilder.PARALLEL_GRAIN ? new ForkJoinPool(threads) : null;
        try {
            // Made inside the pool, so that reading the bounds can fork.
            BvhBuilder b = pool == null ? new BvhBuilder(set, maxLeafSize, costBlock, null)
                    : pool.invoke(ForkJoinTask.adapt(() -> new BvhBuilder(set, maxLeafSize, costBlock, pool)));
            if (b.nonFinite >= 0) {
                double[] tmp = new double[6];
                set.bounds(b.nonFinite, tmp);
                throw new IllegalArgumentException("primitive " + b.nonFinite + " has non-finite bounds " + java.util.Arrays.toString(tmp));
            }
            b.build();
            node = b.node;
            // Inside the pool a set may split its renumbering across it (TriangleMesh does).
            boolean reordered = b.perm.length == n
                    && (pool == null ? set.reorder(b.perm) : pool.invoke(ForkJoinTask.adapt(() -> set.reorder(b.perm))));
            perm = reordered ? null : b.perm;
            primitiveCount = b.perm.length;
            bounds = b.exact;
            nodeCount = b.count;
            depth = b.maxDepth;
        } finally {
            if (pool != null) pool.shutdown();
        }
    }

    public PrimitiveSet set() { return set; }
    public int nodeCount() { return nodeCount; }
    /** Number of primitives indexed (those with non-empty bounds). */
    public int primitiveCount() { return primitiveCount; }
    /** Length of the longest root-to-leaf path (0 for a single leaf). */
    public int depth() { return depth; }

    /** The node records (see {@link #node}); shared, not copied: callers must not change them. */
    int[] nodes() { return node; }

    /** The leaf-slot permutation, or null when slot k holds primitive k. */
    int[] perm() { return perm; }

    /** Largest primitive count of any leaf. */
    int maxLeafCount() {
        int m = 0;
        for (int i = 0; i < nodeCount; i++) m = Math.max(m, node[8 * i + 7]);
        return m;
    }

    /**
     * The tree's surface-area-heuristic cost, with a box test and a primitive test both costing
     * one: the sum over inner nodes of their box area, plus over leaves of area times primitive
     * count, all over the root's area. Lower is a better tree for rays from everywhere; it is
     * how a faster build shows that it kept (or improved) the tree's quality.
     *
     * @return the cost, or 0 for an empty tree
     */
    @Override
    public double sahCost() {
        if (nodeCount == 0) return 0;
        double root = nodeArea(0), sum = 0;
        if (!(root > 0)) return 0;
        for (int i = 0; i < nodeCount; i++) {
            int count = node[8 * i + 7];
            sum += nodeArea(i) * (count > 0 ? count : 1);
        }
        return sum / root;
    }

    /** Half the surface area of node i's float box, in double. */
    private double nodeArea(int i) {
        double dx = (double) Float.intBitsToFloat(node[8 * i + 3]) - Float.intBitsToFloat(node[8 * i]);
        double dy = (double) Float.intBitsToFloat(node[8 * i + 4]) - Float.intBitsToFloat(node[8 * i + 1]);
        double dz = (double) Float.intBitsToFloat(node[8 * i + 5]) - Float.intBitsToFloat(node[8 * i + 2]);
        return dx * dy + dy * dz + dz * dx;
    }

    /** Bounds of everything indexed ({@link Bounds#EMPTY} when nothing is). */
    public Bounds bounds() { return bounds; }

    /** Bytes held by the node bounds, node links and primitive permutation (array headers left out). */
    @Override
    public long memoryBytes() {
        return 4L * node.length + (perm == null ? 0 : 4L * perm.length);
    }

    private int stackNeed() { return depth + 2; }

    /**
     * Nearest hit. At an inner node both children's boxes are tested; the nearer one is entered
     * and the other pushed with its entry distance (rounded down to a float, so the stack stays
     * an int array of (node, distance bits) pairs), and a popped node whose entry lies beyond the
     * nearest hit found since is skipped without touching its box.
     */
    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        if (nodeCount == 0) return false;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        ctx.direction(ray);
        final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        final int xn = ix < 0 ? 3 : 0, yn = iy < 0 ? 3 : 0, zn = iz < 0 ? 3 : 0;
        if (Double.isNaN(entry(0, ox, oy, oz, ix, iy, iz, xn, yn, zn, ray.tMin, ray.tMax))) return false;
        final double saved = ray.tMax;
        final int base = ctx.stackTop, need = 2 * stackNeed();
        final int[] stack = ctx.stack(base + need);
        final int[] node = this.node;
        ctx.stackTop = base + need;
        boolean any = false;
        try {
            int sp = base, n = 0;
            while (true) {
                int count = node[8 * n + 7];
                if (count > 0) {
                    if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
                    int k = node[8 * n + 6];
                    if (set.intersectRange(perm, k, k + count, ray, hit, ctx)) any = true;
                } else {
                    if (TraversalScratch.COUNTING) ctx.nodesVisited[ctx.rayKind]++;
                    int l = n + 1, r = node[8 * n + 6];
                    double tMin = ray.tMin, tMax = ray.tMax;
                    double tl = entry(l, ox, oy, oz, ix, iy, iz, xn, yn, zn, tMin, tMax);
                    double tr = entry(r, ox, oy, oz, ix, iy, iz, xn, yn, zn, tMin, tMax);
                    boolean hl = !Double.isNaN(tl), hr = !Double.isNaN(tr);
                    if (hl && hr) {
                        boolean leftFirst = tl <= tr;
                        stack[sp] = leftFirst ? r : l;
                        stack[sp + 1] = Float.floatToRawIntBits(down(leftFirst ? tr : tl));
                        sp += 2;
                        n = leftFirst ? l : r;
                        continue;
                    }
                    if (hl || hr) {
                        n = hl ? l : r;
                        continue;
                    }
                }
                // Pop the next pending node that may still hold something nearer than the best hit.
                n = -1;
                while (sp > base) {
                    sp -= 2;
                    if (Float.intBitsToFloat(stack[sp + 1]) <= ray.tMax) {
                        n = stack[sp];
                        break;
                    }
                }
                if (n < 0) break;
            }
        } finally {
            ray.tMax = saved;
            ctx.stackTop = base;
        }
        return any;
    }

    @Override
    public boolean occluded(Ray ray, TraversalScratch ctx) {
        if (nodeCount == 0) return false;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        ctx.direction(ray);
        final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        final boolean nx = ix < 0, ny = iy < 0, nz = iz < 0;
        final int base = ctx.stackTop;
        final int[] stack = ctx.stack(base + stackNeed());
        ctx.stackTop = base + stackNeed();
        try {
            int sp = base, n = 0;
            while (true) {
                if (boxHit(n, ox, oy, oz, ix, iy, iz, nx, ny, nz, ray.tMin, ray.tMax)) {
                    int count = node[8 * n + 7];
                    if (count > 0) {
                        if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
                        int k = node[8 * n + 6];
                        if (set.occludedRange(perm, k, k + count, ray, ctx)) return true;
                    } else {
                        // Its box is hit and its children's are tested next: a visit, as intersect counts them.
                        if (TraversalScratch.COUNTING) ctx.nodesVisited[ctx.rayKind]++;
                        stack[sp++] = node[8 * n + 6];
                        n = n + 1;
                        continue;
                    }
                }
                if (sp == base) break;
                n = stack[--sp];
            }
        } finally {
            ctx.stackTop = base;
        }
        return false;
    }

    /**
     * Calls {@code visitor} for every primitive in a leaf whose box the ray passes through within
     * [ray.tMin, ray.tMax] (infinite limits allowed), in no particular order. The visitor may test
     * the primitive in any way but must not change the ray.
     */
    @Override
    public void visit(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor) {
        if (nodeCount == 0) return;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        ctx.direction(ray);
        final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        final boolean nx = ix < 0, ny = iy < 0, nz = iz < 0;
        final int base = ctx.stackTop;
        final int[] stack = ctx.stack(base + stackNeed());
        ctx.stackTop = base + stackNeed();
        try {
            int sp = base, n = 0;
            while (true) {
                if (boxHit(n, ox, oy, oz, ix, iy, iz, nx, ny, nz, ray.tMin, ray.tMax)) {
                    int count = node[8 * n + 7];
                    if (count > 0) {
                        if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
                        for (int k = node[8 * n + 6], end = k + count; k < end; k++) visitor.visit(perm == null ? k : perm[k], ray, ctx);
                    } else {
                        if (TraversalScratch.COUNTING) ctx.nodesVisited[ctx.rayKind]++;
                        stack[sp++] = node[8 * n + 6];
                        n = n + 1;
                        continue;
                    }
                }
                if (sp == base) break;
                n = stack[--sp];
            }
        } finally {
            ctx.stackTop = base;
        }
    }

    private boolean boxHit(int n, double ox, double oy, double oz, double ix, double iy, double iz,
                           boolean nx, boolean ny, boolean nz, double tMin, double tMax) {
        return !Double.isNaN(entry(n, ox, oy, oz, ix, iy, iz, nx ? 3 : 0, ny ? 3 : 0, nz ? 3 : 0, tMin, tMax));
    }

    /**
     * Slab test of node {@code n} against [tMin, tMax], widened by {@link #PAD}: the distance
     * at which the ray enters the box, or NaN if it misses. {@code xn} is 3 when the ray runs
     * towards -x (its near x plane is the box's max) and 0 otherwise; likewise yn, zn. A zero
     * direction component gives an infinite inverse; when the origin lies exactly on that slab
     * plane the product is NaN, which the comparisons below ignore (the ray runs inside the plane).
     */
    private double entry(int n, double ox, double oy, double oz, double ix, double iy, double iz,
                         int xn, int yn, int zn, double tMin, double tMax) {
        return slabEntry(node, 8 * n, ox, oy, oz, ix, iy, iz, xn, yn, zn, tMin, tMax);
    }

    /**
     * The slab test of {@link #entry} for the box whose six floats' bits (min x, y, z, max x, y,
     * z) start at {@code b[o]}; shared with {@link BoxList}.
     */
    static double slabEntry(int[] b, int o, double ox, double oy, double oz, double ix, double iy, double iz,
                            int xn, int yn, int zn, double tMin, double tMax) {
        double near = Double.NEGATIVE_INFINITY, far = Double.POSITIVE_INFINITY;
        double t0 = (Float.intBitsToFloat(b[o + xn]) - ox) * ix;
        double t1 = (Float.intBitsToFloat(b[o + 3 - xn]) - ox) * ix;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        t0 = (Float.intBitsToFloat(b[o + 1 + yn]) - oy) * iy;
        t1 = (Float.intBitsToFloat(b[o + 4 - yn]) - oy) * iy;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        t0 = (Float.intBitsToFloat(b[o + 2 + zn]) - oz) * iz;
        t1 = (Float.intBitsToFloat(b[o + 5 - zn]) - oz) * iz;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        near *= near > 0 ? 1 - PAD : 1 + PAD;
        far *= far > 0 ? 1 + PAD : 1 - PAD;
        return near <= far && near <= tMax && far >= tMin ? near : Double.NaN;
    }

    /**
     * Twice the ulp of |o|: how far the wide and grid box tests move a float ray origin outward.
     * The ulp of a normal float is its exponent's power of two over 2^23, taken from the bits
     * (Math.ulp costs several times as much in the traversal's setup); zero, subnormal and
     * non-finite values go through Math.ulp.
     */
    static float slack(float o) {
        int e = Float.floatToRawIntBits(o) & 0x7f800000;
        if (e <= (24 << 23) || e == 0x7f800000) return 2 * Math.ulp(Math.abs(o));
        return Float.intBitsToFloat(e - (22 << 23));
    }

    /** Largest float not above v: node bounds must never shrink when narrowed from double. */
    static float down(double v) {
        float f = (float) v;
        return f > v ? Math.nextDown(f) : f;
    }

    /** Smallest float not below v. */
    static float up(double v) {
        float f = (float) v;
        return f < v ? Math.nextUp(f) : f;
    }
}
