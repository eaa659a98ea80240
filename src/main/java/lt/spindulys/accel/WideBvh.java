package lt.spindulys.accel;

import lt.spindulys.math.Ray;
import lt.spindulys.scene.Hit;
import lt.spindulys.scene.TraceContext;

/**
 * A {@link Bvh} collapsed to eight children per node, whose eight boxes are tested together with
 * the JDK's Vector API ({@link SimdBoxes}). Used in place of the binary tree when the
 * {@code jdk.incubator.vector} module is present and the machine has 256-bit vectors.
 */
public final class WideBvh implements Accelerator {
    /** Whether the vector test can run here: the module is resolved and the hardware is wide enough. */
    public static final boolean AVAILABLE = probe();

    private static final int FLOATS = 48;
    /** Relative widening of every computed distance: three float roundings, with room to spare. */
    private static final float GAMMA = 8 * 0x1p-24f;
    private static final float INV_LIMIT = 1e20f;
    private static final int NONE = Integer.MIN_VALUE;

    private final PrimitiveSet set;
    private final int[] perm;
    /**
     * Per node 48 floats: minX of its eight children, then maxX, minY, maxY, minZ, maxZ; empty
     * lanes hold +inf minima and -inf maxima, which no ray enters.
     */
    private final float[] box;
    /** Per node eight links: a node index (>= 0), or -1 - (first << 4 | count) for a leaf. */
    private final int[] child;
    private final int nodeCount, depth;

    private static boolean probe() {
        if (ModuleLayer.boot().findModule("jdk.incubator.vector").isEmpty()) return false;
        try {
            // One real test of an empty node, so that a JDK whose incubating API differs from
            // the one compiled against falls back here rather than failing in the render.
            float[] node = new float[FLOATS];
            for (int i = 0; i < FLOATS; i++) node[i] = (i / 8) % 2 == 0 ? Float.POSITIVE_INFINITY : Float.NEGATIVE_INFINITY;
            return SimdBoxes.supported()
                    && SimdBoxes.test(node, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0, Float.POSITIVE_INFINITY, GAMMA, new float[8]) == 0;
        } catch (LinkageError | RuntimeException e) {
            return false;
        }
    }

    /** Whether {@code bvh} can be collapsed: an inner root and leaves of at most 15 primitives. */
    static boolean canCollapse(Bvh bvh) {
        return bvh.nodeCount() > 1 && bvh.maxLeafCount() <= 15 && bvh.primitiveCount() < (1 << 26);
    }

    WideBvh(Bvh bvh) {
        this.set = bvh.set();
        this.perm = bvh.perm();
        int[] node = bvh.nodes();
        int cap = Math.max(1, bvh.nodeCount() / 3);
        Collapser c = new Collapser(node, cap);
        c.build(0, 0);
        box = java.util.Arrays.copyOf(c.box, FLOATS * c.count);
        child = java.util.Arrays.copyOf(c.child, 8 * c.count);
        nodeCount = c.count;
        depth = c.maxDepth;
    }

    public int nodeCount() { return nodeCount; }

    /** How many leaves reference each of the first {@code slots} leaf slots (for tests). */
    int[] leafSlotCounts(int slots) {
        int[] seen = new int[slots];
        for (int i = 0; i < 8 * nodeCount; i++) {
            int c = child[i];
            boolean empty = box[FLOATS * (i / 8) + i % 8] == Float.POSITIVE_INFINITY;
            if (c < 0 && !empty) {
                int code = -1 - c;
                for (int k = code >>> 4, end = k + (code & 15); k < end; k++) seen[k]++;
            }
        }
        return seen;
    }

    @Override
    public long memoryBytes() { return 4L * box.length + 4L * child.length + (perm == null ? 0 : 4L * perm.length); }

    private int stackNeed() { return 2 * (7 * (depth + 1) + 2); }

    private static float inv(double v) {
        float f = (float) v;
        return f > INV_LIMIT ? INV_LIMIT : f < -INV_LIMIT ? -INV_LIMIT : f;
    }

    private static float slack(float o) { return 2 * Math.ulp(Math.abs(o)); }

    /**
     * The ray's constants for the float box test, in ctx's scratch: the inverse direction
     * (clamped, so never zero or infinite), then for x, y, z the origin moved two ulps towards
     * the near and towards the far side of every slab (which covers its rounding to float).
     */
    private static float[] prepare(Ray ray, TraceContext ctx) {
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
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) {
        final float[] r = prepare(ray, ctx);
        final float ix = r[0], iy = r[1], iz = r[2], oxn = r[3], oxf = r[4], oyn = r[5], oyf = r[6], ozn = r[7], ozf = r[8];
        final int nx = ix >= 0 ? 0 : 8, ny = iy >= 0 ? 0 : 8, nz = iz >= 0 ? 0 : 8;
        final float tMin = Bvh.down(ray.tMin);
        float tMax = Bvh.up(ray.tMax);
        final double saved = ray.tMax;
        final int base = ctx.stackTop, need = stackNeed();
        final int[] stack = ctx.stack(base + need);
        final float[] dist = ctx.lanes;
        final float[] box = this.box;
        final int[] child = this.child;
        ctx.stackTop = base + need;
        boolean any = false;
        try {
            int sp = base, n = 0;
            while (true) {
                if (n >= 0) {
                    int bits = SimdBoxes.test(box, FLOATS * n, nx, ny, nz, oxn, oxf, oyn, oyf, ozn, ozf, ix, iy, iz, tMin, tMax, GAMMA, dist);
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
                    int code = -1 - n;
                    int first = code >>> 4;
                    if (set.intersectRange(perm, first, first + (code & 15), ray, hit, ctx)) {
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
    public boolean occluded(Ray ray, TraceContext ctx) { return walk(ray, ctx, null); }

    @Override
    public void visit(Ray ray, TraceContext ctx, Bvh.Visitor visitor) { walk(ray, ctx, visitor); }

    /**
     * Every leaf the ray passes through in [ray.tMin, ray.tMax] (infinite limits allowed), in
     * no order: with a visitor, each of its primitives is offered to it; without one, the walk
     * is the any-hit query and stops at the first leaf that blocks the ray.
     */
    private boolean walk(Ray ray, TraceContext ctx, Bvh.Visitor visitor) {
        final float[] r = prepare(ray, ctx);
        final float ix = r[0], iy = r[1], iz = r[2], oxn = r[3], oxf = r[4], oyn = r[5], oyf = r[6], ozn = r[7], ozf = r[8];
        final int nx = ix >= 0 ? 0 : 8, ny = iy >= 0 ? 0 : 8, nz = iz >= 0 ? 0 : 8;
        final float tMin = Math.max(-Float.MAX_VALUE, Bvh.down(ray.tMin)), tMax = Math.min(Float.MAX_VALUE, Bvh.up(ray.tMax));
        final int base = ctx.stackTop, need = stackNeed();
        final int[] stack = ctx.stack(base + need);
        final float[] dist = ctx.lanes;
        final float[] box = this.box;
        final int[] child = this.child;
        ctx.stackTop = base + need;
        try {
            int sp = base, n = 0;
            while (true) {
                if (n >= 0) {
                    int bits = SimdBoxes.test(box, FLOATS * n, nx, ny, nz, oxn, oxf, oyn, oyf, ozn, ozf, ix, iy, iz, tMin, tMax, GAMMA, dist);
                    int c0 = 8 * n;
                    while (bits != 0) {
                        stack[sp++] = child[c0 + Integer.numberOfTrailingZeros(bits)];
                        bits &= bits - 1;
                    }
                } else {
                    int code = -1 - n;
                    int first = code >>> 4, end = first + (code & 15);
                    if (visitor == null) {
                        if (set.occludedRange(perm, first, end, ray, ctx)) return true;
                    } else {
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

    /** Builds the wide nodes depth-first from the binary ones. */
    private static final class Collapser {
        final int[] node;
        float[] box;
        int[] child;
        int count, maxDepth;

        Collapser(int[] node, int cap) {
            this.node = node;
            box = new float[FLOATS * cap];
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
                box = java.util.Arrays.copyOf(box, 2 * box.length);
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
            int o = FLOATS * w;
            for (int i = 0; i < 8; i++) {
                if (i < k) {
                    int c = kids[i];
                    box[o + i] = f(c, 0); box[o + 8 + i] = f(c, 3);
                    box[o + 16 + i] = f(c, 1); box[o + 24 + i] = f(c, 4);
                    box[o + 32 + i] = f(c, 2); box[o + 40 + i] = f(c, 5);
                } else {
                    box[o + i] = box[o + 16 + i] = box[o + 32 + i] = Float.POSITIVE_INFINITY;
                    box[o + 8 + i] = box[o + 24 + i] = box[o + 40 + i] = Float.NEGATIVE_INFINITY;
                }
            }
            for (int i = 0; i < k; i++) {
                int c = kids[i];
                child[8 * w + i] = leaf(c) ? -1 - (node[8 * c + 6] << 4 | node[8 * c + 7]) : build(c, d + 1);
            }
            return w;
        }
    }
}
