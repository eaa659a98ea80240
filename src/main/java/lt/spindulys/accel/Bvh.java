package lt.spindulys.accel;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.Hit;
import lt.spindulys.scene.TraceContext;

/**
 * Bounding volume hierarchy over a {@link PrimitiveSet}, built with the binned surface-area
 * heuristic and stored flat: six doubles of bounds and two ints per node in depth-first order
 * (a node's left child directly follows it), and a permutation of the primitive indices so each
 * leaf owns a contiguous range. Immutable after construction; thread-safe.
 *
 * <p>The build is iterative (an explicit task stack), so millions of primitives cannot overflow
 * the Java stack, and splits fall back to the median when the tree grows deep, which bounds the
 * traversal stack each ray needs.
 */
public final class Bvh implements Accelerator {
    /** Largest number of primitives in a leaf. */
    public static final int DEFAULT_LEAF_SIZE = 4;
    private static final int BINS = 16;
    /** Below this depth SAH decides; beyond it splits are medians, so depth <= this + log2(n). */
    private static final int SAH_DEPTH_LIMIT = 48;
    /**
     * Relative widening of each box's ray interval: the slab test's rounding (a few ulps of t)
     * must never reject a box whose triangle the watertight test accepts on the box's surface.
     */
    private static final double PAD = 4 * 3 * 0x1p-53 / (1 - 3 * 0x1p-53);

    private final PrimitiveSet set;
    /** minX, minY, minZ, maxX, maxY, maxZ per node. */
    private final double[] box;
    /**
     * Two ints per node: a leaf holds (first index into {@link #perm}, count > 0); an inner node
     * holds (right child index, -1 - split axis). The left child of node i is node i + 1.
     */
    private final int[] node;
    private final int[] perm;
    private final int nodeCount;
    private final int depth;

    /** Called for each primitive of {@link #visit}. */
    @FunctionalInterface
    public interface Visitor {
        void visit(int prim, Ray ray, TraceContext ctx);
    }

    public Bvh(PrimitiveSet set) { this(set, DEFAULT_LEAF_SIZE); }

    /**
     * Builds the hierarchy. Primitives with empty bounds can never be hit and are left out;
     * non-finite bounds are an error (unbounded objects belong outside any hierarchy).
     */
    public Bvh(PrimitiveSet set, int maxLeafSize) {
        if (maxLeafSize < 1) throw new IllegalArgumentException("leaf size must be at least 1, got " + maxLeafSize);
        this.set = set;
        Builder b = new Builder(set, maxLeafSize);
        b.build();
        box = java.util.Arrays.copyOf(b.box, 6 * b.count);
        node = java.util.Arrays.copyOf(b.node, 2 * b.count);
        perm = b.perm;
        nodeCount = b.count;
        depth = b.maxDepth;
    }

    public PrimitiveSet set() { return set; }
    public int nodeCount() { return nodeCount; }
    /** Number of primitives indexed (those with non-empty bounds). */
    public int primitiveCount() { return perm.length; }
    /** Length of the longest root-to-leaf path (0 for a single leaf). */
    public int depth() { return depth; }

    /** Bounds of everything indexed ({@link Bounds#EMPTY} when nothing is). */
    public Bounds bounds() {
        if (nodeCount == 0) return Bounds.EMPTY;
        return new Bounds(box[0], box[1], box[2], box[3], box[4], box[5]);
    }

    /** Bytes held by the node bounds, node links and primitive permutation (array headers left out). */
    public long memoryBytes() {
        return 8L * box.length + 4L * node.length + 4L * perm.length;
    }

    private int stackNeed() { return depth + 2; }

    @Override
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) {
        if (nodeCount == 0) return false;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        final double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        final boolean nx = ix < 0, ny = iy < 0, nz = iz < 0;
        final double saved = ray.tMax;
        final int base = ctx.stackTop;
        final int[] stack = ctx.stack(base + stackNeed());
        ctx.stackTop = base + stackNeed();
        boolean any = false;
        try {
            int sp = base, n = 0;
            while (true) {
                if (boxHit(n, ox, oy, oz, ix, iy, iz, nx, ny, nz, ray.tMin, ray.tMax)) {
                    int count = node[2 * n + 1];
                    if (count > 0) {
                        for (int k = node[2 * n], end = k + count; k < end; k++) {
                            if (set.intersect(perm[k], ray, hit, ctx)) {
                                any = true;
                                ray.tMax = hit.t;
                            }
                        }
                    } else {
                        // Descend into the child on the ray's near side of the split first.
                        int axis = -1 - count;
                        boolean neg = axis == 0 ? nx : axis == 1 ? ny : nz;
                        if (neg) {
                            stack[sp++] = n + 1;
                            n = node[2 * n];
                        } else {
                            stack[sp++] = node[2 * n];
                            n = n + 1;
                        }
                        continue;
                    }
                }
                if (sp == base) break;
                n = stack[--sp];
            }
        } finally {
            ray.tMax = saved;
            ctx.stackTop = base;
        }
        return any;
    }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) {
        if (nodeCount == 0) return false;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        final double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        final boolean nx = ix < 0, ny = iy < 0, nz = iz < 0;
        final int base = ctx.stackTop;
        final int[] stack = ctx.stack(base + stackNeed());
        ctx.stackTop = base + stackNeed();
        try {
            int sp = base, n = 0;
            while (true) {
                if (boxHit(n, ox, oy, oz, ix, iy, iz, nx, ny, nz, ray.tMin, ray.tMax)) {
                    int count = node[2 * n + 1];
                    if (count > 0) {
                        for (int k = node[2 * n], end = k + count; k < end; k++) {
                            if (set.occluded(perm[k], ray, ctx)) return true;
                        }
                    } else {
                        stack[sp++] = node[2 * n];
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
    public void visit(Ray ray, TraceContext ctx, Visitor visitor) {
        if (nodeCount == 0) return;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        final double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        final boolean nx = ix < 0, ny = iy < 0, nz = iz < 0;
        final int base = ctx.stackTop;
        final int[] stack = ctx.stack(base + stackNeed());
        ctx.stackTop = base + stackNeed();
        try {
            int sp = base, n = 0;
            while (true) {
                if (boxHit(n, ox, oy, oz, ix, iy, iz, nx, ny, nz, ray.tMin, ray.tMax)) {
                    int count = node[2 * n + 1];
                    if (count > 0) {
                        for (int k = node[2 * n], end = k + count; k < end; k++) visitor.visit(perm[k], ray, ctx);
                    } else {
                        stack[sp++] = node[2 * n];
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

    /**
     * Slab test of node {@code n} against [tMin, tMax], widened by {@link #PAD}. A zero direction
     * component gives an infinite inverse; when the origin lies exactly on that slab plane the
     * product is NaN, which the comparisons below ignore (the ray runs inside the plane).
     */
    private boolean boxHit(int n, double ox, double oy, double oz, double ix, double iy, double iz,
                           boolean nx, boolean ny, boolean nz, double tMin, double tMax) {
        final double[] b = box;
        final int o = 6 * n;
        double near = Double.NEGATIVE_INFINITY, far = Double.POSITIVE_INFINITY;
        double t0 = ((nx ? b[o + 3] : b[o]) - ox) * ix;
        double t1 = ((nx ? b[o] : b[o + 3]) - ox) * ix;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        t0 = ((ny ? b[o + 4] : b[o + 1]) - oy) * iy;
        t1 = ((ny ? b[o + 1] : b[o + 4]) - oy) * iy;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        t0 = ((nz ? b[o + 5] : b[o + 2]) - oz) * iz;
        t1 = ((nz ? b[o + 2] : b[o + 5]) - oz) * iz;
        if (t0 > near) near = t0;
        if (t1 < far) far = t1;
        near *= near > 0 ? 1 - PAD : 1 + PAD;
        far *= far > 0 ? 1 + PAD : 1 - PAD;
        return near <= far && near <= tMax && far >= tMin;
    }

    /** Build state; discarded once the flat arrays are made. */
    private static final class Builder {
        final int leafSize;
        /**
         * Bounds of the primitive in each slot of {@link #perm}, six per slot, moved along with
         * perm so that every pass over a node reads memory in order (2M primitives' bounds do not
         * fit in any cache, and following perm into them would miss on nearly every access).
         */
        final double[] pb;
        final int[] perm;
        double[] box;
        int[] node;
        int count, maxDepth;
        // Binning scratch, reused for every node: per axis and bin, a count and bounds.
        final int[] binCount = new int[3 * BINS];
        final double[] binBox = new double[3 * BINS * 6];
        final double[] rightArea = new double[BINS];
        final int[] rightCount = new int[BINS];
        final double[] scale = new double[3];

        Builder(PrimitiveSet set, int leafSize) {
            this.leafSize = leafSize;
            int n = set.size();
            double[] bb = new double[6 * n];
            int[] p = new int[n];
            int m = 0;
            double[] tmp = new double[6];
            for (int i = 0; i < n; i++) {
                set.bounds(i, tmp);
                if (tmp[0] > tmp[3] || tmp[1] > tmp[4] || tmp[2] > tmp[5]) continue; // empty: never hit
                for (double v : tmp) {
                    if (!Double.isFinite(v)) {
                        throw new IllegalArgumentException("primitive " + i + " has non-finite bounds " + java.util.Arrays.toString(tmp));
                    }
                }
                System.arraycopy(tmp, 0, bb, 6 * m, 6);
                p[m++] = i;
            }
            perm = m == n ? p : java.util.Arrays.copyOf(p, m);
            pb = m == n ? bb : java.util.Arrays.copyOf(bb, 6 * m);
            int cap = Math.max(1, 2 * (m / Math.max(1, leafSize)) + 1);
            box = new double[6 * cap];
            node = new int[2 * cap];
        }

        /** Centroid coordinate of the primitive in slot k. */
        private double centroid(int k, int axis) {
            return 0.5 * (pb[6 * k + axis] + pb[6 * k + 3 + axis]);
        }

        private void swap(int i, int j) {
            int t = perm[i]; perm[i] = perm[j]; perm[j] = t;
            for (int a = 6 * i, b = 6 * j, end = a + 6; a < end; a++, b++) {
                double d = pb[a]; pb[a] = pb[b]; pb[b] = d;
            }
        }

        void build() {
            if (perm.length == 0) return;
            // Pending right subtrees: start, end, the parent whose right-child link to patch, depth.
            int[] tasks = new int[4 * 64];
            int nt = 0;
            tasks[nt++] = 0; tasks[nt++] = perm.length; tasks[nt++] = -1; tasks[nt++] = 0;
            double[] cb = new double[6];
            while (nt > 0) {
                int d = tasks[--nt], parent = tasks[--nt], e = tasks[--nt], s = tasks[--nt];
                while (true) {
                    int n = count++;
                    if (2 * count > node.length) {
                        node = java.util.Arrays.copyOf(node, 2 * node.length);
                        box = java.util.Arrays.copyOf(box, 2 * box.length);
                    }
                    if (parent >= 0) node[2 * parent] = n;
                    parent = -1;
                    nodeBounds(s, e, n, cb);
                    if (d > maxDepth) maxDepth = d;
                    if (e - s <= leafSize) {
                        node[2 * n] = s;
                        node[2 * n + 1] = e - s;
                        break;
                    }
                    long split = split(s, e, n, cb, d);
                    int mid = (int) (split >> 2), axis = (int) (split & 3);
                    node[2 * n + 1] = -1 - axis;
                    if (nt + 4 > tasks.length) tasks = java.util.Arrays.copyOf(tasks, 2 * tasks.length);
                    tasks[nt++] = mid; tasks[nt++] = e; tasks[nt++] = n; tasks[nt++] = d + 1;
                    e = mid;
                    d++;
                }
            }
        }

        /** Writes node n's bounds and the bounds of its primitives' centroids into cb. */
        private void nodeBounds(int s, int e, int n, double[] cb) {
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            double cx0 = x0, cy0 = x0, cz0 = x0, cx1 = x1, cy1 = x1, cz1 = x1;
            for (int k = s; k < e; k++) {
                int o = 6 * k;
                double a = pb[o], b = pb[o + 1], c = pb[o + 2], A = pb[o + 3], B = pb[o + 4], C = pb[o + 5];
                if (a < x0) x0 = a;
                if (b < y0) y0 = b;
                if (c < z0) z0 = c;
                if (A > x1) x1 = A;
                if (B > y1) y1 = B;
                if (C > z1) z1 = C;
                double mx = 0.5 * (a + A), my = 0.5 * (b + B), mz = 0.5 * (c + C);
                if (mx < cx0) cx0 = mx;
                if (my < cy0) cy0 = my;
                if (mz < cz0) cz0 = mz;
                if (mx > cx1) cx1 = mx;
                if (my > cy1) cy1 = my;
                if (mz > cz1) cz1 = mz;
            }
            int o = 6 * n;
            box[o] = x0; box[o + 1] = y0; box[o + 2] = z0; box[o + 3] = x1; box[o + 4] = y1; box[o + 5] = z1;
            cb[0] = cx0; cb[1] = cy0; cb[2] = cz0; cb[3] = cx1; cb[4] = cy1; cb[5] = cz1;
        }

        private static double area(double dx, double dy, double dz) {
            return dx * dy + dy * dz + dz * dx; // half the surface area; only ratios matter
        }

        private static int bin(double c, double min, double scale) {
            int b = (int) ((c - min) * scale);
            return b < BINS ? b : BINS - 1;
        }

        /**
         * Chooses and performs the split of perm[s, e): returns (mid << 2) | axis with both
         * halves non-empty. Binned SAH over the centroid bounds; the median of the widest centroid
         * axis when SAH finds no split cheaper than keeping the node whole, or below the depth limit.
         */
        private long split(int s, int e, int n, double[] cb, int d) {
            int wide = 0;
            double wideExtent = -1;
            for (int a = 0; a < 3; a++) {
                double ext = cb[3 + a] - cb[a];
                if (ext > wideExtent) { wideExtent = ext; wide = a; }
            }
            if (!(wideExtent > 0)) {
                // Every centroid coincides: no ordering helps, any halving is as good as another.
                return ((long) ((s + e) >>> 1) << 2) | wide;
            }
            if (d < SAH_DEPTH_LIMIT) {
                long sah = sahSplit(s, e, n, cb);
                if (sah >= 0) return sah;
            }
            int mid = (s + e) >>> 1;
            select(s, e, mid, wide);
            return ((long) mid << 2) | wide;
        }

        /** Binned SAH; -1 when no split is better than the unsplit node. */
        private long sahSplit(int s, int e, int n, double[] cb) {
            java.util.Arrays.fill(binCount, 0);
            for (int i = 0; i < 3 * BINS; i++) {
                int o = 6 * i;
                binBox[o] = binBox[o + 1] = binBox[o + 2] = Double.POSITIVE_INFINITY;
                binBox[o + 3] = binBox[o + 4] = binBox[o + 5] = Double.NEGATIVE_INFINITY;
            }
            for (int a = 0; a < 3; a++) {
                double ext = cb[3 + a] - cb[a];
                scale[a] = ext > 0 ? BINS / ext : 0;
            }
            for (int k = s; k < e; k++) {
                int po = 6 * k;
                double x0 = pb[po], y0 = pb[po + 1], z0 = pb[po + 2], x1 = pb[po + 3], y1 = pb[po + 4], z1 = pb[po + 5];
                for (int a = 0; a < 3; a++) {
                    if (scale[a] == 0) continue;
                    double c = a == 0 ? 0.5 * (x0 + x1) : a == 1 ? 0.5 * (y0 + y1) : 0.5 * (z0 + z1);
                    int bi = a * BINS + bin(c, cb[a], scale[a]);
                    binCount[bi]++;
                    int o = 6 * bi;
                    binBox[o] = Math.min(binBox[o], x0);
                    binBox[o + 1] = Math.min(binBox[o + 1], y0);
                    binBox[o + 2] = Math.min(binBox[o + 2], z0);
                    binBox[o + 3] = Math.max(binBox[o + 3], x1);
                    binBox[o + 4] = Math.max(binBox[o + 4], y1);
                    binBox[o + 5] = Math.max(binBox[o + 5], z1);
                }
            }
            int o6 = 6 * n;
            double leafCost = (e - s) * area(box[o6 + 3] - box[o6], box[o6 + 4] - box[o6 + 1], box[o6 + 5] - box[o6 + 2]);
            double best = leafCost;
            int bestAxis = -1, bestBin = -1;
            for (int a = 0; a < 3; a++) {
                if (scale[a] == 0) continue;
                // Sweep from the right: area and count of bins i+1..BINS-1 for a split after bin i.
                double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
                int cnt = 0;
                for (int i = BINS - 1; i > 0; i--) {
                    int bi = a * BINS + i, o = 6 * bi;
                    if (binCount[bi] > 0) {
                        cnt += binCount[bi];
                        x0 = Math.min(x0, binBox[o]); y0 = Math.min(y0, binBox[o + 1]); z0 = Math.min(z0, binBox[o + 2]);
                        x1 = Math.max(x1, binBox[o + 3]); y1 = Math.max(y1, binBox[o + 4]); z1 = Math.max(z1, binBox[o + 5]);
                    }
                    rightCount[i - 1] = cnt;
                    rightArea[i - 1] = cnt > 0 ? area(x1 - x0, y1 - y0, z1 - z0) : 0;
                }
                x0 = Double.POSITIVE_INFINITY; y0 = x0; z0 = x0; x1 = Double.NEGATIVE_INFINITY; y1 = x1; z1 = x1;
                cnt = 0;
                for (int i = 0; i < BINS - 1; i++) {
                    int bi = a * BINS + i, o = 6 * bi;
                    if (binCount[bi] > 0) {
                        cnt += binCount[bi];
                        x0 = Math.min(x0, binBox[o]); y0 = Math.min(y0, binBox[o + 1]); z0 = Math.min(z0, binBox[o + 2]);
                        x1 = Math.max(x1, binBox[o + 3]); y1 = Math.max(y1, binBox[o + 4]); z1 = Math.max(z1, binBox[o + 5]);
                    }
                    if (cnt == 0 || rightCount[i] == 0) continue;
                    double cost = cnt * area(x1 - x0, y1 - y0, z1 - z0) + rightCount[i] * rightArea[i];
                    if (cost < best) { best = cost; bestAxis = a; bestBin = i; }
                }
            }
            if (bestAxis < 0) return -1;
            // Partition in place: primitives whose centroid bin is <= bestBin go left.
            double min = cb[bestAxis], sc = scale[bestAxis];
            int i = s, j = e - 1;
            while (i <= j) {
                if (bin(centroid(i, bestAxis), min, sc) <= bestBin) {
                    i++;
                } else {
                    swap(i, j);
                    j--;
                }
            }
            return ((long) i << 2) | bestAxis;
        }

        /** Reorders perm[s, e) so perm[k] has the k-th smallest centroid on the axis (quickselect). */
        private void select(int s, int e, int k, int axis) {
            int lo = s, hi = e - 1;
            while (hi - lo > 16) {
                int m = (lo + hi) >>> 1;
                // Median of three as the pivot keeps sorted inputs from degrading to quadratic time.
                double a = centroid(lo, axis), b = centroid(m, axis), c = centroid(hi, axis);
                double pivot = Math.max(Math.min(a, b), Math.min(Math.max(a, b), c));
                int i = lo, j = hi;
                while (i <= j) {
                    while (centroid(i, axis) < pivot) i++;
                    while (centroid(j, axis) > pivot) j--;
                    if (i <= j) {
                        swap(i, j);
                        i++;
                        j--;
                    }
                }
                if (k <= j) hi = j;
                else if (k >= i) lo = i;
                else return;
            }
            for (int i = lo + 1; i <= hi; i++) {
                for (int j = i; j > lo && centroid(j - 1, axis) > centroid(j, axis); j--) swap(j - 1, j);
            }
        }
    }
}
