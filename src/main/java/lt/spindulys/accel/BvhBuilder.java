package lt.spindulys.accel;

import java.util.concurrent.ForkJoinPool;
import java.util.concurrent.RecursiveTask;

import lt.spindulys.math.Bounds;

/**
 * Builds a {@link Bvh}'s flat arrays with the binned surface-area heuristic; the state is
 * discarded once they are made, and traversal never sees this class. Large ranges are split on the
 * calling thread and their two halves built as parallel fork/join tasks into separate
 * parts, which are then laid out depth-first in one array. Every split depends only on the
 * primitives in its range, so the tree is the same whatever the number of threads.
 */
final class BvhBuilder {
    /** Ranges at least this large are split and their halves built in parallel. */
    static final int PARALLEL_GRAIN = 8192;
    final int leafSize;
    /**
     * The SAH counts primitives in blocks of this many (1: one by one): a leaf's cost is its
     * area times its number of blocks, as for leaves whose primitives are tested a block at a
     * time ({@link TriangleBlocks}).
     */
    final int costBlock;
    /**
     * Bounds of the primitive in each slot of {@link #perm} (floats rounded outward), six
     * per slot, moved along with perm so that every pass over a range reads memory in order
     * (2M primitives' bounds do not fit in any cache, and following perm into them would
     * miss on nearly every access).
     */
    final float[] pb;
    final int[] perm;
    int[] node;
    int count, maxDepth;
    Bounds exact = Bounds.EMPTY;

    /** The root's box and centroid bounds, twelve floats as {@link Splitter#bounds} writes them. */
    final float[] rootBounds = new float[12];
    /** The pool large ranges are split across, or null to build on the calling thread alone. */
    final ForkJoinPool pool;
    /** The first primitive with non-finite bounds, or -1; nothing is built when there is one. */
    final int nonFinite;

    /**
     * Reads every primitive's bounds, in blocks on the pool when there is one (called
     * inside it then, so the blocks can fork), and finds the root's bounds on the way.
     */
    BvhBuilder(PrimitiveSet set, int leafSize, int costBlock, ForkJoinPool pool) {
        this.leafSize = leafSize;
        this.costBlock = costBlock;
        this.pool = pool;
        int n = set.size();
        float[] bb = new float[6 * n];
        int[] p = new int[n];
        Prep all = pool == null ? Prep.range(set, bb, p, 0, n) : new PrepTask(set, bb, p, 0, n).invoke();
        nonFinite = all.firstBad;
        if (nonFinite >= 0) {
            // Reported by the caller, on its own thread: an exception thrown inside the pool
            // would reach it wrapped, with a different message.
            perm = new int[0];
            pb = new float[0];
            return;
        }
        int m = n - all.empty;
        if (m < n) {
            // Empty primitives can never be hit: close the gaps they left (rare, so serial).
            for (int i = 0, k = 0; i < n; i++) {
                if (Float.isNaN(bb[6 * i])) continue;
                System.arraycopy(bb, 6 * i, bb, 6 * k, 6);
                p[k++] = i;
            }
        }
        perm = m == n ? p : java.util.Arrays.copyOf(p, m);
        pb = m == n ? bb : java.util.Arrays.copyOf(bb, 6 * m);
        if (m > 0) exact = new Bounds(all.ex[0], all.ex[1], all.ex[2], all.ex[3], all.ex[4], all.ex[5]);
        System.arraycopy(all.bc, 0, rootBounds, 0, 12);
    }

    void build() {
        int n = perm.length;
        if (n == 0) {
            node = new int[0];
            return;
        }
        Part root;
        if (pool != null) {
            root = pool.invoke(new Task(this, 0, n, 0, rootBounds));
        } else {
            Chunk c = new Chunk(pb, perm, leafSize, costBlock);
            c.build(0, n, 0, rootBounds);
            root = new Part(c);
        }
        count = root.nodes;
        node = new int[8 * count];
        place(root, 0);
    }

    /** Writes part p with its first node at index at (depth-first, left child next). */
    private void place(Part p, int at) {
        if (p.chunk != null) {
            Chunk c = p.chunk;
            for (int k = 0; k < c.count; k++) {
                int o = 8 * (at + k);
                for (int j = 0; j < 6; j++) node[o + j] = Float.floatToRawIntBits(c.box[6 * k + j]);
                int link = c.node[2 * k], cnt = c.node[2 * k + 1];
                // Inner nodes link their right child by chunk-local index; leaves point into perm.
                node[o + 6] = cnt > 0 ? link : link + at;
                node[o + 7] = cnt;
            }
            maxDepth = Math.max(maxDepth, c.maxDepth);
            return;
        }
        for (int j = 0; j < 6; j++) node[8 * at + j] = Float.floatToRawIntBits(p.box[j]);
        int right = at + 1 + p.left.nodes;
        node[8 * at + 6] = right;
        node[8 * at + 7] = -1 - p.axis;
        maxDepth = Math.max(maxDepth, p.depth);
        place(p.left, at + 1);
        place(p.right, right);
    }

    private static final int BINS = 16;
    /** Below this depth SAH decides; beyond it splits are medians, so depth <= this + log2(n). */
    private static final int SAH_DEPTH_LIMIT = 48;

    /**
     * What reading a block of primitives' bounds found: how many were empty, the first with
     * non-finite bounds (-1 if none), the exact (double) bounds, and the float box and doubled
     * centroid bounds of the block's slots as {@link Splitter#bounds} computes them.
     */
    private static final class Prep {
        int empty, firstBad = -1;
        final double[] ex = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        final float[] bc = new float[12];

        /**
         * Reads primitives [lo, hi) into slots [lo, hi) of bb and p; an empty one gets a NaN
         * in its first float, for the caller to leave out.
         */
        static Prep range(PrimitiveSet set, float[] bb, int[] p, int lo, int hi) {
            Prep r = new Prep();
            double[] tmp = new double[6];
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            for (int i = lo; i < hi; i++) {
                set.bounds(i, tmp);
                int o = 6 * i;
                if (tmp[0] > tmp[3] || tmp[1] > tmp[4] || tmp[2] > tmp[5]) { // empty: never hit
                    bb[o] = Float.NaN;
                    r.empty++;
                    continue;
                }
                if (r.firstBad < 0) {
                    for (double v : tmp) {
                        if (!Double.isFinite(v)) r.firstBad = i;
                    }
                }
                x0 = Math.min(x0, tmp[0]); y0 = Math.min(y0, tmp[1]); z0 = Math.min(z0, tmp[2]);
                x1 = Math.max(x1, tmp[3]); y1 = Math.max(y1, tmp[4]); z1 = Math.max(z1, tmp[5]);
                bb[o] = Bvh.down(tmp[0]); bb[o + 1] = Bvh.down(tmp[1]); bb[o + 2] = Bvh.down(tmp[2]);
                bb[o + 3] = Bvh.up(tmp[3]); bb[o + 4] = Bvh.up(tmp[4]); bb[o + 5] = Bvh.up(tmp[5]);
                p[i] = i;
            }
            r.ex[0] = x0; r.ex[1] = y0; r.ex[2] = z0; r.ex[3] = x1; r.ex[4] = y1; r.ex[5] = z1;
            boxAndCentroids(bb, lo, hi, r.bc, 0);
            return r;
        }

        /**
         * The box and doubled-centroid bounds of slots [lo, hi) (empty slots, marked NaN, left
         * out), with {@link Splitter#bounds}'s strict comparisons: the first of equal values
         * (+0 or -0) is kept, as a scan of the whole range in order would keep it.
         */
        static void boxAndCentroids(float[] p, int lo, int hi, float[] out, int o) {
            float x0 = Float.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Float.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            float cx0 = x0, cy0 = x0, cz0 = x0, cx1 = x1, cy1 = x1, cz1 = x1;
            for (int k = lo; k < hi; k++) {
                int q = 6 * k;
                float a = p[q], b = p[q + 1], c = p[q + 2], A = p[q + 3], B = p[q + 4], C = p[q + 5];
                if (a != a) continue;
                if (a < x0) x0 = a;
                if (b < y0) y0 = b;
                if (c < z0) z0 = c;
                if (A > x1) x1 = A;
                if (B > y1) y1 = B;
                if (C > z1) z1 = C;
                float mx = a + A, my = b + B, mz = c + C;
                if (mx < cx0) cx0 = mx;
                if (my < cy0) cy0 = my;
                if (mz < cz0) cz0 = mz;
                if (mx > cx1) cx1 = mx;
                if (my > cy1) cy1 = my;
                if (mz > cz1) cz1 = mz;
            }
            out[o] = x0; out[o + 1] = y0; out[o + 2] = z0; out[o + 3] = x1; out[o + 4] = y1; out[o + 5] = z1;
            out[o + 6] = cx0; out[o + 7] = cy0; out[o + 8] = cz0; out[o + 9] = cx1; out[o + 10] = cy1; out[o + 11] = cz1;
        }

        /** Joins the block after this one into this one (the order keeps the first of equal values). */
        Prep then(Prep r) {
            empty += r.empty;
            if (firstBad < 0) firstBad = r.firstBad;
            for (int a = 0; a < 3; a++) {
                ex[a] = Math.min(ex[a], r.ex[a]);
                ex[3 + a] = Math.max(ex[3 + a], r.ex[3 + a]);
                if (r.bc[a] < bc[a]) bc[a] = r.bc[a];
                if (r.bc[3 + a] > bc[3 + a]) bc[3 + a] = r.bc[3 + a];
                if (r.bc[6 + a] < bc[6 + a]) bc[6 + a] = r.bc[6 + a];
                if (r.bc[9 + a] > bc[9 + a]) bc[9 + a] = r.bc[9 + a];
            }
            return this;
        }
    }

    /** Reads a range of primitives' bounds, halves of large ranges in parallel. */
    private static final class PrepTask extends RecursiveTask<Prep> {
        /** Blocks of at most this many primitives are read by one thread. */
        private static final int BLOCK = 1 << 16;
        private final PrimitiveSet set;
        private final float[] bb;
        private final int[] p;
        private final int lo, hi;

        PrepTask(PrimitiveSet set, float[] bb, int[] p, int lo, int hi) { this.set = set; this.bb = bb; this.p = p; this.lo = lo; this.hi = hi; }

        @Override
        protected Prep compute() {
            if (hi - lo <= BLOCK) return Prep.range(set, bb, p, lo, hi);
            int mid = (lo + hi) >>> 1;
            PrepTask right = new PrepTask(set, bb, p, mid, hi);
            right.fork();
            Prep left = new PrepTask(set, bb, p, lo, mid).compute();
            return left.then(right.join());
        }
    }

    /** A built piece of the tree: a serially built chunk, or one inner node over two parts. */
    private static final class Part {
        final Chunk chunk;
        final float[] box;
        final int axis, depth, nodes;
        final Part left, right;

        Part(Chunk c) {
            chunk = c; box = null; axis = 0; depth = 0; left = right = null; nodes = c.count;
        }

        Part(float[] box, int axis, int depth, Part left, Part right) {
            chunk = null; this.box = box; this.axis = axis; this.depth = depth; this.left = left; this.right = right;
            nodes = 1 + left.nodes + right.nodes;
        }
    }

    /** Fork/join step: split a large range here and build both halves as subtasks. */
    private static final class Task extends RecursiveTask<Part> {
        private final BvhBuilder b;
        private final int s, e, d;
        /** The range's box and centroid bounds (twelve floats), computed by the parent's split. */
        private final float[] bc;

        Task(BvhBuilder b, int s, int e, int d, float[] bc) { this.b = b; this.s = s; this.e = e; this.d = d; this.bc = bc; }

        @Override
        protected Part compute() {
            if (e - s < BvhBuilder.PARALLEL_GRAIN) {
                Chunk c = new Chunk(b.pb, b.perm, b.leafSize, b.costBlock);
                c.build(s, e, d, bc);
                return new Part(c);
            }
            Splitter sp = new Splitter(b.pb, b.perm, b.costBlock);
            sp.forkBins = true;
            float[] lr = new float[24];
            long split = sp.split(s, e, bc, 0, d, lr, 0);
            int mid = (int) (split >> 2), axis = (int) (split & 3);
            Task left = new Task(b, s, mid, d + 1, java.util.Arrays.copyOfRange(lr, 0, 12));
            Task right = new Task(b, mid, e, d + 1, java.util.Arrays.copyOfRange(lr, 12, 24));
            right.fork();
            Part l = left.compute();
            Part r = right.join();
            return new Part(java.util.Arrays.copyOf(bc, 6), axis, d, l, r);
        }
    }

    /**
     * Bins a large range in blocks on the fork/join pool (the root's 2M primitives would
     * otherwise be read by one thread while the others wait): each half into bins of its own,
     * then merged into the splitter's. How the range is cut depends on its size alone.
     */
    private static final class BinTask extends java.util.concurrent.RecursiveAction {
        /** Ranges of fewer than twice this many primitives are binned by one thread. */
        static final int BLOCK = 1 << 17;
        private final Splitter into;
        private final int s, e, nb;
        private final float mx, my, mz, sx, sy, sz;

        BinTask(Splitter into, int s, int e, int nb, float mx, float my, float mz, float sx, float sy, float sz) {
            this.into = into; this.s = s; this.e = e; this.nb = nb;
            this.mx = mx; this.my = my; this.mz = mz; this.sx = sx; this.sy = sy; this.sz = sz;
        }

        @Override
        protected void compute() {
            if (e - s < 2 * BLOCK) {
                into.binRange(s, e, nb, mx, my, mz, sx, sy, sz);
                return;
            }
            int mid = (s + e) >>> 1;
            Splitter other = new Splitter(into.pb, into.perm, into.costBlock);
            BinTask right = new BinTask(other, mid, e, nb, mx, my, mz, sx, sy, sz);
            right.fork();
            new BinTask(into, s, mid, nb, mx, my, mz, sx, sy, sz).compute();
            right.join();
            into.mergeBins(other, nb);
        }
    }

    /** A subtree built serially with an explicit task stack, in chunk-local node indices. */
    private static final class Chunk {
        final Splitter sp;
        final int leafSize;
        float[] box;
        int[] node;
        int count, maxDepth;

        Chunk(float[] pb, int[] perm, int leafSize, int costBlock) {
            sp = new Splitter(pb, perm, costBlock);
            this.leafSize = leafSize;
        }

        /** Builds slots [s0, e0) at depth d0, whose box and centroid bounds are bc0[0..11]. */
        void build(int s0, int e0, int d0, float[] bc0) {
            int cap = Math.max(1, 2 * ((e0 - s0) / Math.max(1, leafSize)) + 1);
            box = new float[6 * cap];
            node = new int[2 * cap];
            // Pending right subtrees: start, end, the parent whose right-child link to patch, depth.
            int[] tasks = new int[4 * 64];
            int nt = 0;
            // Each pending task's box and centroid bounds, twelve floats, found by its parent's split.
            float[] taskBounds = new float[12 * 64];
            tasks[nt++] = s0; tasks[nt++] = e0; tasks[nt++] = -1; tasks[nt++] = d0;
            System.arraycopy(bc0, 0, taskBounds, 0, 12);
            // The current node's bounds (0..11) and its split's children's (12..23, 24..35).
            float[] cur = new float[36];
            while (nt > 0) {
                System.arraycopy(taskBounds, 12 * (nt / 4 - 1), cur, 0, 12);
                int d = tasks[--nt], parent = tasks[--nt], e = tasks[--nt], s = tasks[--nt];
                while (true) {
                    int n = count++;
                    if (2 * count > node.length) {
                        node = java.util.Arrays.copyOf(node, 2 * node.length);
                        box = java.util.Arrays.copyOf(box, 2 * box.length);
                    }
                    if (parent >= 0) node[2 * parent] = n;
                    parent = -1;
                    System.arraycopy(cur, 0, box, 6 * n, 6);
                    if (d > maxDepth) maxDepth = d;
                    if (e - s <= leafSize) {
                        node[2 * n] = s;
                        node[2 * n + 1] = e - s;
                        break;
                    }
                    long split = sp.split(s, e, cur, 0, d, cur, 12);
                    int mid = (int) (split >> 2), axis = (int) (split & 3);
                    node[2 * n + 1] = -1 - axis;
                    if (nt + 4 > tasks.length) {
                        tasks = java.util.Arrays.copyOf(tasks, 2 * tasks.length);
                        taskBounds = java.util.Arrays.copyOf(taskBounds, 2 * taskBounds.length);
                    }
                    System.arraycopy(cur, 24, taskBounds, 12 * (nt / 4), 12);
                    tasks[nt++] = mid; tasks[nt++] = e; tasks[nt++] = n; tasks[nt++] = d + 1;
                    System.arraycopy(cur, 12, cur, 0, 12);
                    e = mid;
                    d++;
                }
            }
        }
    }

    /**
     * Split decisions on ranges of the shared slot arrays, with its own binning scratch. Tasks
     * on disjoint ranges may run on different threads.
     */
    private static final class Splitter {
        final float[] pb;
        final int[] perm;
        // Binning scratch, reused for every node: per axis and bin, a count and bounds.
        // Two sets of 3 * BINS (see sahSplit), merged into the first before the sweep.
        static final int TWO_SETS_MIN = 64;
        final int[] binCount = new int[2 * 3 * BINS];
        final float[] binBox = new float[2 * 3 * BINS * 6];
        final double[] rightArea = new double[BINS];
        final int[] rightCount = new int[BINS];
        /** Whether large ranges are binned in blocks on the fork/join pool this runs in. */
        boolean forkBins;

        /** Primitives per block of the cost ({@link BvhBuilder#costBlock}). */
        final int costBlock;

        Splitter(float[] pb, int[] perm, int costBlock) { this.pb = pb; this.perm = perm; this.costBlock = costBlock; }

        /** The cost units of n primitives: blocks of {@link #costBlock}, the last one partial. */
        private long blocks(int n) {
            return costBlock == 1 ? n : (n + costBlock - 1) / costBlock;
        }

        /** Centroid coordinate (times two: only order matters) of the primitive in slot k. */
        private float centroid(int k, int axis) {
            return pb[6 * k + axis] + pb[6 * k + 3 + axis];
        }

        private void swap(int i, int j) {
            int t = perm[i]; perm[i] = perm[j]; perm[j] = t;
            for (int a = 6 * i, b = 6 * j, end = a + 6; a < end; a++, b++) {
                float d = pb[a]; pb[a] = pb[b]; pb[b] = d;
            }
        }

        /**
         * Writes the bounds of slots [s, e) to out[o..o+5] and of their doubled centroids to
         * out[o+6..o+11].
         */
        void bounds(int s, int e, float[] out, int o) {
            // The slots hold no empty primitive here (they were left out when read), so the
            // reader's scan, which skips them, gives exactly these bounds.
            Prep.boxAndCentroids(pb, s, e, out, o);
        }

        private static double area(double dx, double dy, double dz) {
            return dx * dy + dy * dz + dz * dx; // half the surface area; only ratios matter
        }

        private static int bin(float c, float min, float scale, int bins) {
            int b = (int) ((c - min) * scale);
            return b < bins ? b : bins - 1;
        }

        /**
         * Chooses and performs the split of slots [s, e) whose box and centroid bounds are
         * bc[o..o+11] ({@link #bounds}): returns (mid << 2) | axis with both halves non-empty, and
         * writes the left half's bounds to out[oo..oo+11] and the right half's to
         * out[oo+12..oo+23], so that no child needs a pass of its own to find them. Binned SAH
         * over the centroid bounds; the median of the widest centroid axis when SAH finds no
         * split cheaper than keeping the node whole, or below the depth limit.
         */
        long split(int s, int e, float[] bc, int o, int d, float[] out, int oo) {
            int wide = 0;
            float wideExtent = -1;
            for (int a = 0; a < 3; a++) {
                float ext = bc[o + 9 + a] - bc[o + 6 + a];
                if (ext > wideExtent) { wideExtent = ext; wide = a; }
            }
            int mid;
            if (!(wideExtent > 0)) {
                // Every centroid coincides: no ordering helps, any halving is as good as another.
                mid = (s + e) >>> 1;
            } else {
                if (d < SAH_DEPTH_LIMIT) {
                    long sah = sahSplit(s, e, bc, o, out, oo);
                    if (sah >= 0) return sah;
                }
                mid = (s + e) >>> 1;
                select(s, e, mid, wide);
            }
            bounds(s, mid, out, oo);
            bounds(mid, e, out, oo + 12);
            return ((long) mid << 2) | wide;
        }

        /**
         * Binned SAH; -1 when no split is better than the unsplit node. The halves' boxes are the
         * unions of their bins' boxes, and their centroid bounds are gathered while partitioning,
         * so a split reads its range twice (bin, partition) rather than three times.
         */
        private long sahSplit(int s, int e, float[] bc, int o6, float[] out, int oo) {
            final int[] cnt0 = binCount;
            final float[] bb = binBox;
            // Small ranges get as many bins as primitives: more would be mostly empty, and
            // clearing and sweeping them would dominate the many small nodes near the leaves.
            final int nb = Math.min(BINS, e - s);
            // An axis whose centroids all coincide gets scale 0: everything lands in its bin 0,
            // and the sweep below finds no split with both sides non-empty on it.
            float ex = bc[o6 + 9] - bc[o6 + 6], ey = bc[o6 + 10] - bc[o6 + 7], ez = bc[o6 + 11] - bc[o6 + 8];
            float sx = ex > 0 ? nb / ex : 0, sy = ey > 0 ? nb / ey : 0, sz = ez > 0 ? nb / ez : 0;
            float mx = bc[o6 + 6], my = bc[o6 + 7], mz = bc[o6 + 8];
            if (forkBins && e - s >= 2 * BinTask.BLOCK) {
                new BinTask(this, s, e, nb, mx, my, mz, sx, sy, sz).invoke();
            } else {
                binRange(s, e, nb, mx, my, mz, sx, sy, sz);
            }
            double leafCost = (double) blocks(e - s) * area((double) bc[o6 + 3] - bc[o6], (double) bc[o6 + 4] - bc[o6 + 1], (double) bc[o6 + 5] - bc[o6 + 2]);
            double best = leafCost;
            int bestAxis = -1, bestBin = -1;
            for (int a = 0; a < 3; a++) {
                if ((a == 0 ? sx : a == 1 ? sy : sz) == 0) continue;
                // Sweep from the right: area and count of bins i+1..nb-1 for a split after bin i.
                float x0 = Float.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Float.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
                int cnt = 0;
                for (int i = nb - 1; i > 0; i--) {
                    int bi = a * BINS + i, o = 6 * bi;
                    if (cnt0[bi] > 0) {
                        cnt += cnt0[bi];
                        x0 = Math.min(x0, bb[o]); y0 = Math.min(y0, bb[o + 1]); z0 = Math.min(z0, bb[o + 2]);
                        x1 = Math.max(x1, bb[o + 3]); y1 = Math.max(y1, bb[o + 4]); z1 = Math.max(z1, bb[o + 5]);
                    }
                    rightCount[i - 1] = cnt;
                    rightArea[i - 1] = cnt > 0 ? area((double) x1 - x0, (double) y1 - y0, (double) z1 - z0) : 0;
                }
                x0 = Float.POSITIVE_INFINITY; y0 = x0; z0 = x0; x1 = Float.NEGATIVE_INFINITY; y1 = x1; z1 = x1;
                cnt = 0;
                for (int i = 0; i < nb - 1; i++) {
                    int bi = a * BINS + i, o = 6 * bi;
                    if (cnt0[bi] > 0) {
                        cnt += cnt0[bi];
                        x0 = Math.min(x0, bb[o]); y0 = Math.min(y0, bb[o + 1]); z0 = Math.min(z0, bb[o + 2]);
                        x1 = Math.max(x1, bb[o + 3]); y1 = Math.max(y1, bb[o + 4]); z1 = Math.max(z1, bb[o + 5]);
                    }
                    if (cnt == 0 || rightCount[i] == 0) continue;
                    double cost = blocks(cnt) * area((double) x1 - x0, (double) y1 - y0, (double) z1 - z0) + blocks(rightCount[i]) * rightArea[i];
                    if (cost < best) { best = cost; bestAxis = a; bestBin = i; }
                }
            }
            if (bestAxis < 0) return -1;
            // The halves' boxes: the unions of bins 0..bestBin and of the rest on the chosen axis.
            unionBins(bestAxis * BINS, bestAxis * BINS + bestBin + 1, out, oo);
            unionBins(bestAxis * BINS + bestBin + 1, bestAxis * BINS + nb, out, oo + 12);
            int i = partition(s, e, bestAxis, bestAxis == 0 ? mx : bestAxis == 1 ? my : mz,
                    bestAxis == 0 ? sx : bestAxis == 1 ? sy : sz, nb, bestBin, out, oo);
            return ((long) i << 2) | bestAxis;
        }

        /**
         * Clears the bins and counts and bounds slots [s, e) into them: per axis, nb bins over
         * the centroid bounds starting at (mx, my, mz) with scales (sx, sy, sz). A method of its
         * own, as is {@link #partition}: small methods are compiled sooner and each on its own,
         * which matters in a new JVM, where the first passes over millions of primitives run.
         */
        void binRange(int s, int e, int nb, float mx, float my, float mz, float sx, float sy, float sz) {
            final int[] cnt0 = binCount;
            final float[] bb = binBox;
            // Small ranges use one set: a second would cost more to clear and merge than it saves.
            final boolean two = e - s >= TWO_SETS_MIN;
            for (int set = 0, sets = two ? 2 : 1; set < sets; set++) {
                for (int a = 0; a < 3; a++) {
                    for (int i = (3 * set + a) * BINS, end = i + nb; i < end; i++) {
                        int o = 6 * i;
                        cnt0[i] = 0;
                        bb[o] = bb[o + 1] = bb[o + 2] = Float.POSITIVE_INFINITY;
                        bb[o + 3] = bb[o + 4] = bb[o + 5] = Float.NEGATIVE_INFINITY;
                    }
                }
            }
            final float[] p = pb;
            // Neighbouring primitives mostly fall in the same bins; alternating between two sets
            // of bins halves the chains of loads waiting on the previous primitive's stores.
            // Min and max are exact, so merging the two sets gives the very same bin boxes.
            int k = s;
            for (int pairEnd = two ? e - 1 : s; k < pairEnd; k += 2) {
                int q = 6 * k;
                float x0 = p[q], y0 = p[q + 1], z0 = p[q + 2], x1 = p[q + 3], y1 = p[q + 4], z1 = p[q + 5];
                float u0 = p[q + 6], v0 = p[q + 7], w0 = p[q + 8], u1 = p[q + 9], v1 = p[q + 10], w1 = p[q + 11];
                int bx = bin(x0 + x1, mx, sx, nb), by = BINS + bin(y0 + y1, my, sy, nb), bz = 2 * BINS + bin(z0 + z1, mz, sz, nb);
                int cx = 3 * BINS + bin(u0 + u1, mx, sx, nb), cy = 4 * BINS + bin(v0 + v1, my, sy, nb), cz = 5 * BINS + bin(w0 + w1, mz, sz, nb);
                cnt0[bx]++; cnt0[by]++; cnt0[bz]++;
                cnt0[cx]++; cnt0[cy]++; cnt0[cz]++;
                grow(bb, 6 * bx, x0, y0, z0, x1, y1, z1);
                grow(bb, 6 * cx, u0, v0, w0, u1, v1, w1);
                grow(bb, 6 * by, x0, y0, z0, x1, y1, z1);
                grow(bb, 6 * cy, u0, v0, w0, u1, v1, w1);
                grow(bb, 6 * bz, x0, y0, z0, x1, y1, z1);
                grow(bb, 6 * cz, u0, v0, w0, u1, v1, w1);
            }
            for (; k < e; k++) {
                int q = 6 * k;
                float x0 = p[q], y0 = p[q + 1], z0 = p[q + 2], x1 = p[q + 3], y1 = p[q + 4], z1 = p[q + 5];
                int bx = bin(x0 + x1, mx, sx, nb), by = BINS + bin(y0 + y1, my, sy, nb), bz = 2 * BINS + bin(z0 + z1, mz, sz, nb);
                cnt0[bx]++; cnt0[by]++; cnt0[bz]++;
                grow(bb, 6 * bx, x0, y0, z0, x1, y1, z1);
                grow(bb, 6 * by, x0, y0, z0, x1, y1, z1);
                grow(bb, 6 * bz, x0, y0, z0, x1, y1, z1);
            }
            for (int i = 0, end = two ? 3 * BINS : 0; i < end; i++) {
                int j = i + 3 * BINS;
                if (i % BINS >= nb || cnt0[j] == 0) continue; // bins past nb hold stale values
                cnt0[i] += cnt0[j];
                grow(bb, 6 * i, bb[6 * j], bb[6 * j + 1], bb[6 * j + 2], bb[6 * j + 3], bb[6 * j + 4], bb[6 * j + 5]);
            }
        }

        /**
         * Adds the first nb bins per axis of {@code o} (binned by {@link #binRange} with the same
         * grid) into this one's. Counts add and min/max are exact, so bins filled block by block
         * and merged are the very bins one pass over the whole range fills.
         */
        void mergeBins(Splitter o, int nb) {
            final int[] cnt0 = binCount;
            final float[] bb = binBox, ob = o.binBox;
            for (int i = 0; i < 3 * BINS; i++) {
                if (i % BINS >= nb || o.binCount[i] == 0) continue;
                cnt0[i] += o.binCount[i];
                grow(bb, 6 * i, ob[6 * i], ob[6 * i + 1], ob[6 * i + 2], ob[6 * i + 3], ob[6 * i + 4], ob[6 * i + 5]);
            }
        }

        /**
         * Partitions slots [s, e) in place: those whose centroid bin on {@code axis} is at most
         * {@code bestBin} go left. Each primitive is read once where its side becomes final,
         * and its centroid joins that side's centroid bounds, written to out[oo+6..oo+11] (left)
         * and out[oo+18..oo+23] (right). Returns the first slot of the right side.
         */
        private int partition(int s, int e, int bestAxis, float min, float sc, int nb, int bestBin, float[] out, int oo) {
            final float[] p = pb;
            float lx0 = Float.POSITIVE_INFINITY, ly0 = lx0, lz0 = lx0, lx1 = Float.NEGATIVE_INFINITY, ly1 = lx1, lz1 = lx1;
            float rx0 = lx0, ry0 = lx0, rz0 = lx0, rx1 = lx1, ry1 = lx1, rz1 = lx1;
            int i = s, j = e - 1;
            while (i <= j) {
                int q = 6 * i;
                float cx = p[q] + p[q + 3], cy = p[q + 1] + p[q + 4], cz = p[q + 2] + p[q + 5];
                if (bin(bestAxis == 0 ? cx : bestAxis == 1 ? cy : cz, min, sc, nb) <= bestBin) {
                    lx0 = Math.min(lx0, cx); ly0 = Math.min(ly0, cy); lz0 = Math.min(lz0, cz);
                    lx1 = Math.max(lx1, cx); ly1 = Math.max(ly1, cy); lz1 = Math.max(lz1, cz);
                    i++;
                } else {
                    rx0 = Math.min(rx0, cx); ry0 = Math.min(ry0, cy); rz0 = Math.min(rz0, cz);
                    rx1 = Math.max(rx1, cx); ry1 = Math.max(ry1, cy); rz1 = Math.max(rz1, cz);
                    swap(i, j);
                    j--;
                }
            }
            out[oo + 6] = lx0; out[oo + 7] = ly0; out[oo + 8] = lz0; out[oo + 9] = lx1; out[oo + 10] = ly1; out[oo + 11] = lz1;
            out[oo + 18] = rx0; out[oo + 19] = ry0; out[oo + 20] = rz0; out[oo + 21] = rx1; out[oo + 22] = ry1; out[oo + 23] = rz1;
            return i;
        }

        /** Writes the union of the boxes of bins [from, to) (empty bins left out) to out[o..o+5]. */
        private void unionBins(int from, int to, float[] out, int o) {
            float x0 = Float.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Float.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            final float[] bb = binBox;
            for (int i = from; i < to; i++) {
                if (binCount[i] == 0) continue;
                int b = 6 * i;
                x0 = Math.min(x0, bb[b]); y0 = Math.min(y0, bb[b + 1]); z0 = Math.min(z0, bb[b + 2]);
                x1 = Math.max(x1, bb[b + 3]); y1 = Math.max(y1, bb[b + 4]); z1 = Math.max(z1, bb[b + 5]);
            }
            out[o] = x0; out[o + 1] = y0; out[o + 2] = z0; out[o + 3] = x1; out[o + 4] = y1; out[o + 5] = z1;
        }

        /** Branch-free (min/max are intrinsics): which bin box grows is unpredictable. */
        private static void grow(float[] bb, int o, float x0, float y0, float z0, float x1, float y1, float z1) {
            bb[o] = Math.min(bb[o], x0);
            bb[o + 1] = Math.min(bb[o + 1], y0);
            bb[o + 2] = Math.min(bb[o + 2], z0);
            bb[o + 3] = Math.max(bb[o + 3], x1);
            bb[o + 4] = Math.max(bb[o + 4], y1);
            bb[o + 5] = Math.max(bb[o + 5], z1);
        }

        /** Reorders slots [s, e) so slot k has the k-th smallest centroid on the axis (quickselect). */
        private void select(int s, int e, int k, int axis) {
            int lo = s, hi = e - 1;
            while (hi - lo > 16) {
                int m = (lo + hi) >>> 1;
                // Median of three as the pivot keeps sorted inputs from degrading to quadratic time.
                float a = centroid(lo, axis), b = centroid(m, axis), c = centroid(hi, axis);
                float pivot = Math.max(Math.min(a, b), Math.min(Math.max(a, b), c));
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
