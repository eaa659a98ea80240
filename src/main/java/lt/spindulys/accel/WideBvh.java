package lt.spindulys.accel;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.math.Ray;

/**
 * A {@link Bvh} collapsed to eight children per node, whose eight boxes are tested together with
 * the JDK's Vector API ({@link SimdBoxes}). Used in place of the binary tree when the
 * {@code jdk.incubator.vector} module is present and the machine has 256-bit vectors. A node is
 * 104 bytes: its children's boxes as bytes on a grid over its own box (48), the grid (6 floats)
 * and eight links. Over triangles ({@link #build}) each leaf may also hold its triangles'
 * corners in float ({@link TriangleBlocks}), tested eight at a time before the exact test
 * confirms a hit, so a leaf's possible misses cost no trip to the mesh's arrays. Immutable
 * after construction; thread-safe.
 */
public final class WideBvh implements Accelerator {
    /** Whether the vector test can run here: the module is resolved and the hardware is wide enough. */
    public static final boolean AVAILABLE = probe();

    /** Plane bytes per node: six rows (min x, max x, min y, max y, min z, max z) of eight children. */
    private static final int PLANES = 48;
    private static final float INV_LIMIT = 1e20f;
    private static final int NONE = Integer.MIN_VALUE;

    private final PrimitiveSet set;
    private final int[] perm;
    /**
     * Per node 48 signed bytes: the children's planes on the node's grid ({@link #decode}), in
     * rows of eight (min x, max x, min y, max y, min z, max z), each rounded outward so the
     * decoded box holds the child's; an empty lane has min 127 and max -128, a box no ray enters.
     * A quarter of the memory of float planes, at no cost in speed (figures in
     * docs/performance.md, the wide vector BVH).
     */
    private final byte[] q;
    /** Per node six floats: the base and the scale of its planes' grid on x, y and z. */
    private final float[] frame;
    /**
     * Per node eight links: a node index (>= 0), or -1 - (first << 4 | count) for a leaf, where
     * first is the leaf's first slot, or its block in {@link #blocks} when the leaves hold their
     * triangles.
     */
    private final int[] child;
    private final int nodeCount, depth;
    /** The leaves' triangles copied into the leaves, or null: then links name leaf slots. */
    private final TriangleBlocks blocks;
    /** The SAH cost of the binary tree this one was collapsed from (a linear pass over its nodes). */
    private final double sah;

    private static boolean probe() {
        // From the module path this module requires the vector module only statically, so it reads
        // it only when the JVM resolved it (--add-modules); from the class path it reads every module.
        java.util.Optional<Module> vector = ModuleLayer.boot().findModule("jdk.incubator.vector");
        if (vector.isEmpty() || !WideBvh.class.getModule().canRead(vector.get())) return false;
        try {
            // One real test of an empty node, so that a JDK whose incubating API differs from
            // the one compiled against falls back here rather than failing in the render.
            byte[] node = new byte[PLANES];
            for (int i = 0; i < PLANES; i++) node[i] = (i / 8) % 2 == 0 ? Byte.MAX_VALUE : Byte.MIN_VALUE;
            float[] frame = {0, 0, 0, 1, 1, 1};
            return SimdBoxes.supported()
                    && SimdBoxes.test(node, 0, frame, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, Float.POSITIVE_INFINITY, new float[8]) == 0;
        } catch (LinkageError | RuntimeException e) {
            return false;
        }
    }

    /**
     * {@code bvh} collapsed to a wide tree when the vector test can run here and the tree allows
     * it ({@link #AVAILABLE}, {@link #canCollapse}); otherwise {@code bvh} itself. Leaves keep
     * naming their primitives: the compact layout.
     */
    public static Accelerator widen(Bvh bvh) {
        return AVAILABLE && canCollapse(bvh) ? new WideBvh(bvh, false) : bvh;
    }

    /**
     * The default structure over {@code set}: for triangles ({@link TriangleSet}) where the
     * vector tests can run, a tree built with leaves of up to {@link TriangleBlocks#LANES}
     * triangles, costed in blocks, collapsed to eight children per node, each leaf's triangles
     * copied into it ({@link TriangleBlocks}) when the heap has room for the copies; otherwise
     * {@link #widen} of the usual tree.
     *
     * @param parallel whether the build may use a pool of threads
     */
    public static Accelerator build(PrimitiveSet set, boolean parallel) {
        if (AVAILABLE && set instanceof TriangleSet) {
            Bvh bvh = new Bvh(set, TriangleBlocks.LANES, TriangleBlocks.LANES, parallel);
            if (canCollapse(bvh)) return new WideBvh(bvh, true);
            return bvh;
        }
        return widen(new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, parallel));
    }

    /** Whether {@code bvh} can be collapsed: an inner root and leaves of at most 15 primitives. */
    static boolean canCollapse(Bvh bvh) {
        return bvh.nodeCount() > 1 && bvh.maxLeafCount() <= 15 && bvh.primitiveCount() < (1 << 26);
    }

    WideBvh(Bvh bvh) { this(bvh, false); }

    /** Collapses {@code bvh}; with {@code blocks}, copies the leaves' triangles into them when they fit the heap. */
    WideBvh(Bvh bvh, boolean blocks) {
        this.set = bvh.set();
        this.perm = bvh.perm();
        int[] node = bvh.nodes();
        int cap = Math.max(1, bvh.nodeCount() / 3);
        Collapser c = new Collapser(node, cap);
        c.build(0, 0);
        q = java.util.Arrays.copyOf(c.q, PLANES * c.count);
        frame = java.util.Arrays.copyOf(c.frame, 6 * c.count);
        child = java.util.Arrays.copyOf(c.child, 8 * c.count);
        nodeCount = c.count;
        depth = c.maxDepth;
        sah = bvh.sahCost();
        this.blocks = blocks && set instanceof TriangleSet ts && leavesFit() ? copyLeaves(ts) : null;
    }

    @Override
    public double sahCost() { return sah; }

    /** Whether every leaf fits one block. */
    private boolean leavesFit() {
        for (int c : child) if (c < 0 && ((-1 - c) & 15) > TriangleBlocks.LANES) return false;
        return true;
    }

    /**
     * Copies every leaf's triangles into a block, and links the leaves to their blocks; null,
     * leaving the leaves as they are, when the heap has no room for the copies (the compact layout).
     */
    private TriangleBlocks copyLeaves(TriangleSet ts) {
        int leaves = 0;
        for (int c : child) if (c < 0 && ((-1 - c) & 15) > 0) leaves++;
        TriangleBlocks b;
        try (HeapBudget.Reservation r = HeapBudget.reserve(TriangleBlocks.bytes(leaves), "the leaf blocks of " + ts.size() + " triangles")) {
            b = new TriangleBlocks(ts, perm, leaves);
        } catch (InsufficientMemoryException e) {
            return null;
        }
        for (int i = 0; i < child.length; i++) {
            int c = child[i];
            if (c < 0 && ((-1 - c) & 15) > 0) {
                int code = -1 - c, n = code & 15;
                child[i] = -1 - (b.add(code >>> 4, n) << 4 | n);
            }
        }
        return b;
    }

    public int nodeCount() { return nodeCount; }

    /** Whether the leaves hold their triangles' corners ({@link TriangleBlocks}), or name them only (compact). */
    public boolean hasLeafBlocks() { return blocks != null; }

    /** The node arrays, shared, not copied (for tests comparing collapses). */
    byte[] planes() { return q; }
    float[] frames() { return frame; }
    int[] links() { return child; }

    /** How many leaves reference each of the first {@code slots} leaf slots (for tests). */
    int[] leafSlotCounts(int slots) {
        int[] seen = new int[slots];
        for (int i = 0; i < 8 * nodeCount; i++) {
            int c = child[i];
            int row = PLANES * (i / 8) + i % 8;
            boolean empty = q[row] > q[row + 8]; // an empty lane's min x lies above its max x
            if (c < 0 && !empty) {
                int code = -1 - c, first = blocks == null || (code & 15) == 0 ? code >>> 4 : blocks.first(code >>> 4);
                for (int k = first, end = k + (code & 15); k < end; k++) seen[k]++;
            }
        }
        return seen;
    }

    @Override
    public long memoryBytes() { return q.length + 4L * frame.length + 4L * child.length + (perm == null ? 0 : 4L * perm.length) + (blocks == null ? 0 : blocks.bytes()); }

    private int stackNeed() { return 2 * (7 * (depth + 1) + 2); }

    private static float inv(double v) {
        float f = (float) v;
        return f > INV_LIMIT ? INV_LIMIT : f < -INV_LIMIT ? -INV_LIMIT : f;
    }

    private static float slack(float o) { return Bvh.slack(o); }

    /**
     * The ray's constants for the float box test, in ctx's scratch: the inverse direction
     * (clamped, so never zero or infinite), then for x, y, z the origin moved two ulps towards
     * the near and towards the far side of every slab (which covers its rounding to float).
     */
    private static float[] prepare(Ray ray, TraversalScratch ctx) {
        ctx.direction(ray);
        float[] r = ctx.wideRay;
        float ix = inv(ctx.invX), iy = inv(ctx.invY), iz = inv(ctx.invZ);
        float ox = (float) ray.ox, oy = (float) ray.oy, oz = (float) ray.oz;
        float ex = ix >= 0 ? slack(ox) : -slack(ox), ey = iy >= 0 ? slack(oy) : -slack(oy), ez = iz >= 0 ? slack(oz) : -slack(oz);
        r[0] = ix; r[1] = iy; r[2] = iz;
        r[3] = ox + ex; r[4] = ox - ex; r[5] = oy + ey; r[6] = oy - ey; r[7] = oz + ez; r[8] = oz - ez;
        return r;
    }

    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        final float[] r = prepare(ray, ctx);
        final float ix = r[0], iy = r[1], iz = r[2], oxn = r[3], oxf = r[4], oyn = r[5], oyf = r[6], ozn = r[7], ozf = r[8];
        final TriangleBlocks blocks = this.blocks;
        if (blocks != null) blocks.prepare(ray, ctx);
        final int nx = ix >= 0 ? 0 : 8, ny = iy >= 0 ? 0 : 8, nz = iz >= 0 ? 0 : 8;
        final float tMin = Bvh.down(ray.tMin);
        float tMax = Bvh.up(ray.tMax);
        final double saved = ray.tMax;
        final int base = ctx.stackTop, need = stackNeed();
        final int[] stack = ctx.stack(base + need);
        final float[] dist = ctx.lanes;
        final byte[] q = this.q;
        final float[] frame = this.frame;
        final int[] child = this.child;
        ctx.stackTop = base + need;
        boolean any = false;
        try {
            int sp = base, n = 0;
            while (true) {
                if (n >= 0) {
                    if (TraversalScratch.COUNTING) ctx.nodesVisited[ctx.rayKind]++;
                    int bits = SimdBoxes.test(q, PLANES * n, frame, 6 * n, nx, ny, nz, oxn, oxf, oyn, oyf, ozn, ozf, ix, iy, iz, tMin, tMax, dist);
                    if (bits != 0) {
                        int c0 = 8 * n;
                        if ((bits & (bits - 1)) == 0) {
                            n = child[c0 + Integer.numberOfTrailingZeros(bits)];
                            continue;
                        }
                        // Push every child hit, keeping the new entries sorted farthest first,
                        // then take the nearest off the top.
                        int start = sp;
                        do {
                            int i = Integer.numberOfTrailingZeros(bits);
                            bits &= bits - 1;
                            float d = dist[i];
                            int j = sp;
                            while (j > start && Float.intBitsToFloat(stack[j - 1]) < d) {
                                stack[j] = stack[j - 2];
                                stack[j + 1] = stack[j - 1];
                                j -= 2;
                            }
                            stack[j] = child[c0 + i];
                            stack[j + 1] = Float.floatToRawIntBits(d);
                            sp += 2;
                        } while (bits != 0);
                        sp -= 2;
                        n = stack[sp];
                        continue;
                    }
                } else {
                    if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
                    int code = -1 - n;
                    int first = code >>> 4;
                    if (blocks != null ? blocks.intersect(first, code & 15, ray, hit, ctx)
                            : set.intersectRange(perm, first, first + (code & 15), ray, hit, ctx)) {
                        any = true;
                        tMax = Bvh.up(ray.tMax);
                    }
                }
                n = NONE;
                while (sp > base) {
                    sp -= 2;
                    if (Float.intBitsToFloat(stack[sp + 1]) <= tMax) {
                        n = stack[sp];
                        break;
                    }
                }
                if (n == NONE) break;
            }
        } finally {
            ray.tMax = saved;
            ctx.stackTop = base;
        }
        return any;
    }

    @Override
    public boolean occluded(Ray ray, TraversalScratch ctx) { return walk(ray, ctx, null); }

    @Override
    public void visit(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor) { walk(ray, ctx, visitor); }

    /**
     * Every leaf the ray passes through in [ray.tMin, ray.tMax] (infinite limits allowed), in
     * no order: with a visitor, each of its primitives is offered to it; without one, the walk
     * is the any-hit query and stops at the first leaf that blocks the ray.
     */
    private boolean walk(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor) {
        final float[] r = prepare(ray, ctx);
        final float ix = r[0], iy = r[1], iz = r[2], oxn = r[3], oxf = r[4], oyn = r[5], oyf = r[6], ozn = r[7], ozf = r[8];
        final TriangleBlocks blocks = this.blocks;
        if (blocks != null) blocks.prepare(ray, ctx);
        final int nx = ix >= 0 ? 0 : 8, ny = iy >= 0 ? 0 : 8, nz = iz >= 0 ? 0 : 8;
        final float tMin = Bvh.down(ray.tMin), tMax = Bvh.up(ray.tMax);
        final int base = ctx.stackTop, need = stackNeed();
        final int[] stack = ctx.stack(base + need);
        final float[] dist = ctx.lanes;
        final byte[] q = this.q;
        final float[] frame = this.frame;
        final int[] child = this.child;
        ctx.stackTop = base + need;
        try {
            int sp = base, n = 0;
            while (true) {
                if (n >= 0) {
                    if (TraversalScratch.COUNTING) ctx.nodesVisited[ctx.rayKind]++;
                    int bits = SimdBoxes.test(q, PLANES * n, frame, 6 * n, nx, ny, nz, oxn, oxf, oyn, oyf, ozn, ozf, ix, iy, iz, tMin, tMax, dist);
                    int c0 = 8 * n;
                    while (bits != 0) {
                        stack[sp++] = child[c0 + Integer.numberOfTrailingZeros(bits)];
                        bits &= bits - 1;
                    }
                } else {
                    if (TraversalScratch.COUNTING) ctx.leavesEntered[ctx.rayKind]++;
                    int code = -1 - n;
                    int first = code >>> 4, end = first + (code & 15);
                    if (visitor == null) {
                        if (blocks != null ? blocks.occluded(first, code & 15, ray, ctx) : set.occludedRange(perm, first, end, ray, ctx)) return true;
                    } else {
                        if (blocks != null) { first = blocks.first(first); end = first + (code & 15); }
                        for (int k = first; k < end; k++) visitor.visit(perm == null ? k : perm[k], ray, ctx);
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

    /** A plane's value: base + q * scale, in float, exactly as {@link SimdBoxes} computes it. */
    static float decode(int q, float base, float scale) {
        return q * scale + base;
    }

    /**
     * The grid step of an axis over [lo, hi]: (hi - lo) / 253 rounded up, and at least four ulps
     * of the coordinates, so that each rounding of {@link #decode} (half an ulp) is small beside a
     * step. With the base one step below 127 steps above lo ({@link #gridBase}), -128 then decodes
     * below lo and 127 above hi. Zero for a flat axis: every plane decodes to lo exactly.
     */
    static float gridStep(float lo, float hi) {
        if (!(hi > lo)) return 0;
        float s = Math.nextUp((float) (((double) hi - lo) / 253));
        return Math.max(s, 4 * Math.ulp(Math.max(Math.abs(lo), Math.abs(hi))));
    }

    /** The grid base of an axis over [lo, hi] with step {@code step}: 127 steps above lo. */
    static float gridBase(float lo, float step) {
        return lo + 127 * step;
    }

    /** The largest q whose plane is at or below v (v on the grid's axis range). */
    static int gridDown(float v, float base, float step) {
        if (step == 0) return Byte.MIN_VALUE;
        int k = (int) Math.floor(((double) v - base) / step);
        k = Math.max(Byte.MIN_VALUE, Math.min(Byte.MAX_VALUE, k));
        while (k > Byte.MIN_VALUE && decode(k, base, step) > v) k--;
        if (decode(k, base, step) > v) throw new IllegalStateException("plane " + v + " below its node's grid");
        return k;
    }

    /** The smallest q whose plane is at or above v (v on the grid's axis range). */
    static int gridUp(float v, float base, float step) {
        if (step == 0) return Byte.MAX_VALUE;
        int k = (int) Math.ceil(((double) v - base) / step);
        k = Math.max(Byte.MIN_VALUE, Math.min(Byte.MAX_VALUE, k));
        while (k < Byte.MAX_VALUE && decode(k, base, step) < v) k++;
        if (decode(k, base, step) < v) throw new IllegalStateException("plane " + v + " above its node's grid");
        return k;
    }

    /** Builds the wide nodes depth-first from the binary ones. */
    private static final class Collapser {
        final int[] node;
        byte[] q;
        float[] frame;
        int[] child;
        int count, maxDepth;

        Collapser(int[] node, int cap) {
            this.node = node;
            q = new byte[PLANES * cap];
            frame = new float[6 * cap];
            child = new int[8 * cap];
        }

        private float area(int b) {
            float dx = f(b, 3) - f(b, 0), dy = f(b, 4) - f(b, 1), dz = f(b, 5) - f(b, 2);
            return dx * dy + dy * dz + dz * dx;
        }

        private float f(int b, int j) { return Float.intBitsToFloat(node[8 * b + j]); }

        private boolean leaf(int b) { return node[8 * b + 7] > 0; }

        /** Makes a wide node of binary inner node {@code b}'s subtree; returns its index. */
        int build(int b, int d) {
            int w = count++;
            if (count * 8 > child.length) {
                child = java.util.Arrays.copyOf(child, 2 * child.length);
                q = java.util.Arrays.copyOf(q, 2 * q.length);
                frame = java.util.Arrays.copyOf(frame, 2 * frame.length);
            }
            if (d > maxDepth) maxDepth = d;
            int[] kids = new int[8];
            int k = 0;
            kids[k++] = b + 1;
            kids[k++] = node[8 * b + 6];
            // Open the largest inner child until there are eight: big boxes are the ones rays
            // enter most often, so their children are the ones worth testing together.
            while (k < 8) {
                int best = -1;
                float bestArea = -1;
                for (int i = 0; i < k; i++) {
                    if (!leaf(kids[i]) && area(kids[i]) > bestArea) { bestArea = area(kids[i]); best = i; }
                }
                if (best < 0) break;
                int open = kids[best];
                kids[best] = open + 1;
                kids[k++] = node[8 * open + 6];
            }
            // The node's grid per axis spans its own box, b's (which holds all of its children).
            int o = PLANES * w;
            for (int a = 0; a < 3; a++) {
                float lo = f(b, a), hi = f(b, 3 + a), sc = gridStep(lo, hi), base = gridBase(lo, sc);
                frame[6 * w + a] = base;
                frame[6 * w + 3 + a] = sc;
                for (int i = 0; i < 8; i++) {
                    int row = o + 16 * a + i;
                    if (i < k) {
                        q[row] = (byte) gridDown(f(kids[i], a), base, sc);
                        q[row + 8] = (byte) gridUp(f(kids[i], 3 + a), base, sc);
                    } else {
                        q[row] = Byte.MAX_VALUE;
                        q[row + 8] = Byte.MIN_VALUE;
                    }
                }
            }
            for (int i = 0; i < k; i++) {
                int c = kids[i];
                child[8 * w + i] = leaf(c) ? -1 - (node[8 * c + 6] << 4 | node[8 * c + 7]) : build(c, d + 1);
            }
            // An empty lane is missed, except on a node whose box is one point (every axis flat);
            // then it is an empty leaf, never a link back to the root.
            for (int i = k; i < 8; i++) child[8 * w + i] = -1;
            return w;
        }
    }
}
