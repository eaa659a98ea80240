package lt.spindulys.accel;

import java.util.Arrays;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;

/**
 * An octree over a {@link PrimitiveSet} (the thesis's "Octobox"): a cube around everything,
 * split recursively into eight equal cubes, each primitive referenced from every leaf its bounds
 * overlap. Stored flat: two ints per node (an inner node holds its first child and an 8-bit mask
 * of the children that exist, stored consecutively; a leaf holds a range of the reference list)
 * and one int per reference. Immutable after construction; thread-safe.
 *
 * <p>Cells are never stored: a cell is named by its level and integer coordinates, and its
 * planes are computed as {@code min + i * (side / 2^level)}, which gives a plane shared by
 * neighbouring cells, at any levels, exactly the same value. Traversal walks the cells front to
 * back (children in the ray's entry order) and stops once the nearest hit found lies before the
 * current leaf's exit: a primitive hit beyond the leaf it was found in is kept but does not end
 * the walk, since a nearer one may wait in the next cell. A primitive in several leaves the ray
 * passes is tested in each (no mailbox: the structure stays free of per-ray state).
 *
 * <p>Memory stays bounded for any input: the tree is at most maxDepth levels deep (default
 * {@link #DEFAULT_MAX_DEPTH}; identical tiny primitives, which no split separates, make a chain to
 * that depth), a node is not split when its children would hold more than {@link #SPLIT_GROWTH}
 * times its references (primitives as large as the children gain nothing from splitting), and the build stops splitting once all references would exceed
 * {@link #REFS_PER_PRIMITIVE} per primitive. The build is breadth first, so that budget goes to
 * the shallow levels of every region before the deep levels of any one.
 */
public final class Octree implements Accelerator {
    /** A node with at most this many primitives is not split. */
    public static final int DEFAULT_LEAF_SIZE = 8;
    public static final int DEFAULT_MAX_DEPTH = 16;
    /** Deepest allowed level: cell coordinates and their plane products must stay exact in ints and doubles. */
    public static final int DEPTH_LIMIT = 24;
    /** A split is refused when the children would hold more than this many times the node's references. */
    static final double SPLIT_GROWTH = 4;
    /** Total references allowed, per primitive indexed. */
    static final int REFS_PER_PRIMITIVE = 8;
    /** Relative widening of each cell's ray interval, as in {@link Bvh}: slab rounding must not lose a cell. */
    private static final double PAD = 4 * 3 * 0x1p-53 / (1 - 3 * 0x1p-53);
    /**
     * Ints per pending cell on the traversal stack: node, level, x, y, z, entry t (rounded down
     * to a float) and exit t (rounded down): both roundings err on the side of visiting. An inner
     * node replaces itself by at most four children, so a walk needs 3 * depth + 1 entries.
     */
    private static final int ENTRY = 7;

    private final PrimitiveSet set;
    /** The root cube: corner and side. */
    private final double minX, minY, minZ, side;
    /** Two ints per node; see the class comment. Node 0 is the root. */
    private final int[] node;
    /** Primitive indices of the leaves, each leaf a contiguous range. */
    private final int[] refs;
    private final int nodeCount, depth, primitiveCount;
    private final int stackNeed;
    /** Side of a cell at each level, side / 2^level (exact), so the walk need not compute it. */
    private final double[] cellSide;

    public Octree(PrimitiveSet set) { this(set, DEFAULT_LEAF_SIZE, DEFAULT_MAX_DEPTH); }

    /**
     * Builds the tree. Primitives with empty bounds can never be hit and are left out; non-finite
     * bounds are an error (unbounded objects belong outside any structure).
     */
    public Octree(PrimitiveSet set, int maxLeafSize, int maxDepth) {
        if (maxLeafSize < 1) throw new IllegalArgumentException("leaf size must be at least 1, got " + maxLeafSize);
        if (maxDepth < 0 || maxDepth > DEPTH_LIMIT) throw new IllegalArgumentException("depth must be between 0 and " + DEPTH_LIMIT + ", got " + maxDepth);
        this.set = set;
        Builder b = new Builder(set, maxLeafSize, maxDepth);
        b.build();
        minX = b.minX; minY = b.minY; minZ = b.minZ; side = b.side;
        node = Arrays.copyOf(b.node, 2 * b.count);
        refs = Arrays.copyOf(b.refs, b.refCount);
        nodeCount = b.count;
        depth = b.depth;
        primitiveCount = b.m;
        stackNeed = ENTRY * (3 * depth + 1);
        cellSide = new double[depth + 2];
        for (int l = 0; l < cellSide.length; l++) cellSide[l] = Math.scalb(side, -l);
    }

    public PrimitiveSet set() { return set; }
    public int nodeCount() { return nodeCount; }
    /** Number of primitives indexed (those with non-empty bounds). */
    public int primitiveCount() { return primitiveCount; }
    /** Number of primitive references held by the leaves (a primitive counts once per leaf). */
    public int referenceCount() { return refs.length; }
    /** Level of the deepest node (0 when the root is a leaf). */
    public int depth() { return depth; }

    /** The root cube ({@link Bounds#EMPTY} when nothing is indexed). */
    public Bounds rootCell() {
        if (nodeCount == 0) return Bounds.EMPTY;
        return new Bounds(minX, minY, minZ, minX + side, minY + side, minZ + side);
    }

    /** Bytes held by the flat arrays. */
    @Override
    public long memoryBytes() { return 4L * node.length + 4L * refs.length; }

    private static final int INTERSECT = 0, OCCLUDED = 1, VISIT = 2;

    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        return traverse(ray, hit, ctx, INTERSECT, null);
    }

    @Override
    public boolean occluded(Ray ray, TraversalScratch ctx) {
        return traverse(ray, null, ctx, OCCLUDED, null);
    }

    /**
     * Calls {@code visitor} for every primitive of every leaf the ray passes within [ray.tMin,
     * ray.tMax] (infinite limits allowed). A primitive in several such leaves is visited once for
     * each; the visitor must not change the ray.
     */
    @Override
    public void visit(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor) {
        traverse(ray, null, ctx, VISIT, visitor);
    }

    /** The one walk behind intersect, occluded and visit: front to back, with a stack from the context. */
    private boolean traverse(Ray ray, PrimitiveHit hit, TraversalScratch ctx, int mode, PrimitiveVisitor visitor) {
        if (nodeCount == 0) return false;
        final double ox = ray.ox, oy = ray.oy, oz = ray.oz;
        final double ix = 1 / ray.dx, iy = 1 / ray.dy, iz = 1 / ray.dz;
        final boolean nx = ix < 0, ny = iy < 0, nz = iz < 0;
        // Children are named in a frame flipped on every axis the ray runs down, where each
        // coordinate only grows along the ray: child = bits ^ flip.
        final int flip = (nx ? 1 : 0) | (ny ? 2 : 0) | (nz ? 4 : 0);
        final double saved = ray.tMax;
        final int base = ctx.stackTop;
        final int[] stack = ctx.stack(base + stackNeed);
        ctx.stackTop = base + stackNeed;
        boolean any = false;
        try {
            // The root's slab test, written out like the children's below.
            double near = Double.NEGATIVE_INFINITY, far = Double.POSITIVE_INFINITY;
            double e = (minX - ox) * ix, f = (minX + side - ox) * ix;
            if (nx) { double s = e; e = f; f = s; }
            if (e > near) near = e;
            if (f < far) far = f;
            e = (minY - oy) * iy; f = (minY + side - oy) * iy;
            if (ny) { double s = e; e = f; f = s; }
            if (e > near) near = e;
            if (f < far) far = f;
            e = (minZ - oz) * iz; f = (minZ + side - oz) * iz;
            if (nz) { double s = e; e = f; f = s; }
            if (e > near) near = e;
            if (f < far) far = f;
            double pn = near * (near > 0 ? 1 - PAD : 1 + PAD), pf = far * (far > 0 ? 1 + PAD : 1 - PAD);
            if (!(pn <= pf && pn <= ray.tMax && pf >= ray.tMin)) return false;
            int sp = base;
            stack[sp] = 0; stack[sp + 1] = 0; stack[sp + 2] = 0; stack[sp + 3] = 0; stack[sp + 4] = 0;
            stack[sp + 5] = floatDown(pn);
            stack[sp + 6] = floatDown(far);
            sp += ENTRY;
            while (sp > base) {
                sp -= ENTRY;
                // The nearest hit so far may have moved in front of this cell since it was pushed.
                if (Float.intBitsToFloat(stack[sp + 5]) > ray.tMax) continue;
                final int n = stack[sp], info = node[2 * n + 1];
                if (info < 0) {
                    for (int k = node[2 * n], end = k - info; k < end; k++) {
                        int prim = refs[k];
                        if (mode == INTERSECT) {
                            if (set.intersect(prim, ray, hit, ctx)) {
                                any = true;
                                ray.tMax = hit.t;
                            }
                        } else if (mode == OCCLUDED) {
                            if (set.occluded(prim, ray, ctx)) return true;
                        } else {
                            visitor.visit(prim, ray, ctx);
                        }
                    }
                    // Every point of the ray before this cell's exit lies in a cell already
                    // walked, so no untested primitive can be nearer than a hit found before it.
                    if (any && ray.tMax <= Float.intBitsToFloat(stack[sp + 6])) break;
                    continue;
                }
                final int level = stack[sp + 1] + 1;
                final int cx = 2 * stack[sp + 2], cy = 2 * stack[sp + 3], cz = 2 * stack[sp + 4];
                final double h = cellSide[level];
                // Where the ray crosses the node's low, middle and high plane on each axis (NaN
                // when it runs inside a plane: the comparisons below then ignore it, as in Bvh).
                double x0 = (minX + cx * h - ox) * ix, xm = (minX + (cx + 1) * h - ox) * ix, x1 = (minX + (cx + 2) * h - ox) * ix;
                double y0 = (minY + cy * h - oy) * iy, ym = (minY + (cy + 1) * h - oy) * iy, y1 = (minY + (cy + 2) * h - oy) * iy;
                double z0 = (minZ + cz * h - oz) * iz, zm = (minZ + (cz + 1) * h - oz) * iz, z1 = (minZ + (cz + 2) * h - oz) * iz;
                near = Double.NEGATIVE_INFINITY;
                far = Double.POSITIVE_INFINITY;
                e = nx ? x1 : x0; f = nx ? x0 : x1;
                if (e > near) near = e;
                if (f < far) far = f;
                e = ny ? y1 : y0; f = ny ? y0 : y1;
                if (e > near) near = e;
                if (f < far) far = f;
                e = nz ? z1 : z0; f = nz ? z0 : z1;
                if (e > near) near = e;
                if (f < far) far = f;
                // The node's padded interval clipped to the ray's: its children split it at the
                // middle-plane crossings, so together they cover every t of it.
                double t = Math.max(near * (near > 0 ? 1 - PAD : 1 + PAD), ray.tMin);
                final double end = Math.min(far * (far > 0 ? 1 + PAD : 1 - PAD), ray.tMax);
                if (!(t <= end)) continue;
                // In the flipped frame a bit is set once the ray is past that middle plane; each
                // crossing sets one (several at once through an edge or corner), so at most four
                // children are visited, in order.
                int bits = (xm < t ? 1 : 0) | (ym < t ? 2 : 0) | (zm < t ? 4 : 0);
                final int first = node[2 * n], from = sp;
                while (true) {
                    double next = end;
                    if ((bits & 1) == 0 && xm < next) next = xm;
                    if ((bits & 2) == 0 && ym < next) next = ym;
                    if ((bits & 4) == 0 && zm < next) next = zm;
                    int c = bits ^ flip;
                    if ((info & (1 << c)) != 0) {
                        stack[sp] = first + Integer.bitCount(info & ((1 << c) - 1));
                        stack[sp + 1] = level;
                        stack[sp + 2] = cx + (c & 1);
                        stack[sp + 3] = cy + ((c >> 1) & 1);
                        stack[sp + 4] = cz + (c >> 2);
                        stack[sp + 5] = floatDown(t);
                        stack[sp + 6] = floatDown(next);
                        sp += ENTRY;
                    }
                    if (!(next < end)) break;
                    if ((bits & 1) == 0 && xm == next) bits |= 1;
                    if ((bits & 2) == 0 && ym == next) bits |= 2;
                    if ((bits & 4) == 0 && zm == next) bits |= 4;
                    t = next;
                }
                // Pushed in ray order; reversed so that the first child is popped first.
                for (int a = from, b = sp - ENTRY; a < b; a += ENTRY, b -= ENTRY) {
                    for (int k = 0; k < ENTRY; k++) {
                        int v = stack[a + k];
                        stack[a + k] = stack[b + k];
                        stack[b + k] = v;
                    }
                }
            }
        } finally {
            ray.tMax = saved;
            ctx.stackTop = base;
        }
        return any;
    }

    /** The bits of the largest float not above {@code v}. */
    private static int floatDown(double v) {
        float f = (float) v;
        if (f > v) f = Math.nextDown(f);
        return Float.floatToRawIntBits(f);
    }

    /** Build state; discarded once the flat arrays are made. */
    private static final class Builder {
        final PrimitiveSet set;
        final int leafSize, maxDepth;
        /** Bounds of each indexed primitive, six per slot, and the primitive index of each slot. */
        double[] pb;
        int[] ids;
        int m;
        double minX, minY, minZ, side, eps;
        int[] node = new int[64];
        int count;
        int[] refs = new int[64];
        int refCount;
        int depth;

        Builder(PrimitiveSet set, int leafSize, int maxDepth) {
            this.set = set;
            this.leafSize = leafSize;
            this.maxDepth = maxDepth;
        }

        void build() {
            int n = set.size();
            pb = new double[6 * n];
            ids = new int[n];
            double[] tmp = new double[6];
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            for (int i = 0; i < n; i++) {
                set.bounds(i, tmp);
                if (tmp[0] > tmp[3] || tmp[1] > tmp[4] || tmp[2] > tmp[5]) continue; // empty: never hit
                for (double v : tmp) {
                    if (!Double.isFinite(v)) throw new IllegalArgumentException("primitive " + i + " has non-finite bounds " + Arrays.toString(tmp));
                }
                System.arraycopy(tmp, 0, pb, 6 * m, 6);
                ids[m++] = i;
                x0 = Math.min(x0, tmp[0]); y0 = Math.min(y0, tmp[1]); z0 = Math.min(z0, tmp[2]);
                x1 = Math.max(x1, tmp[3]); y1 = Math.max(y1, tmp[4]); z1 = Math.max(z1, tmp[5]);
            }
            if (m == 0) return;
            // A cube anchored at the low corner: a flat scene then lies on the low faces of its
            // cells instead of straddling every middle plane, and thin scenes are split where
            // they have extent rather than sliced through their thickness at every level.
            minX = x0; minY = y0; minZ = z0;
            side = Math.max(x1 - x0, Math.max(y1 - y0, z1 - z0));
            if (!(side > 0)) side = 1;
            double top = Math.max(Math.max(Math.abs(x0), Math.abs(x1)), Math.max(Math.max(Math.abs(y0), Math.abs(y1)), Math.max(Math.abs(z0), Math.abs(z1))));
            // Primitives within eps of a cell count as overlapping it: a hit point that rounding
            // puts just outside its primitive's cells still finds the primitive in the cell it is in.
            eps = side * 0x1p-40 + 64 * Math.ulp(top);
            count = 1;
            bfs();
        }

        private void bfs() {
            // The current level's nodes (index and cell coordinates) and their slot lists.
            int curN = 1;
            int[] curNode = {0}, curX = {0}, curY = {0}, curZ = {0};
            int[] curStart = {0, m};
            int[] curRefs = new int[m];
            for (int i = 0; i < m; i++) curRefs[i] = i;
            long pending = m;
            final long budget = (long) REFS_PER_PRIMITIVE * m + 8L * leafSize;
            byte[] mask = new byte[m];
            int[] childCount = new int[8], childAt = new int[8];
            for (int level = 0; curN > 0; level++) {
                int nextN = 0, nextRefN = 0;
                int[] nextNode = new int[Math.max(8, 2 * curN)], nextX = new int[nextNode.length], nextY = new int[nextNode.length], nextZ = new int[nextNode.length];
                int[] nextStart = new int[nextNode.length + 1];
                int[] nextRefs = new int[Math.max(8, curRefs.length)];
                final double h = Math.scalb(side, -(level + 1));
                for (int j = 0; j < curN; j++) {
                    final int s = curStart[j], e = curStart[j + 1], cnt = e - s, nd = curNode[j];
                    if (level > depth) depth = level;
                    boolean split = cnt > leafSize && level < maxDepth;
                    int sum = 0;
                    if (split) {
                        double xm = minX + (2 * curX[j] + 1) * h, ym = minY + (2 * curY[j] + 1) * h, zm = minZ + (2 * curZ[j] + 1) * h;
                        Arrays.fill(childCount, 0);
                        for (int k = s; k < e; k++) {
                            int o = 6 * curRefs[k];
                            int mx = (pb[o] <= xm + eps ? 0x55 : 0) | (pb[o + 3] >= xm - eps ? 0xAA : 0);
                            int my = (pb[o + 1] <= ym + eps ? 0x33 : 0) | (pb[o + 4] >= ym - eps ? 0xCC : 0);
                            int mz = (pb[o + 2] <= zm + eps ? 0x0F : 0) | (pb[o + 5] >= zm - eps ? 0xF0 : 0);
                            int bits = mx & my & mz;
                            mask[k - s] = (byte) bits;
                            sum += Integer.bitCount(bits);
                            for (int c = 0; c < 8; c++) childCount[c] += (bits >> c) & 1;
                        }
                        split = sum <= SPLIT_GROWTH * cnt && refCount + pending + (sum - cnt) <= budget;
                    }
                    if (!split) {
                        node[2 * nd] = refCount;
                        node[2 * nd + 1] = -cnt;
                        if (refCount + cnt > refs.length) refs = Arrays.copyOf(refs, Math.max(refCount + cnt, 2 * refs.length));
                        for (int k = s; k < e; k++) refs[refCount++] = ids[curRefs[k]];
                        pending -= cnt;
                        continue;
                    }
                    int present = 0;
                    for (int c = 0; c < 8; c++) if (childCount[c] > 0) present |= 1 << c;
                    int first = count, kids = Integer.bitCount(present);
                    count += kids;
                    if (2 * count > node.length) node = Arrays.copyOf(node, Math.max(2 * count, 2 * node.length));
                    node[2 * nd] = first;
                    node[2 * nd + 1] = present;
                    if (nextN + kids > nextNode.length) {
                        int cap = Math.max(nextN + kids, 2 * nextNode.length);
                        nextNode = Arrays.copyOf(nextNode, cap);
                        nextX = Arrays.copyOf(nextX, cap);
                        nextY = Arrays.copyOf(nextY, cap);
                        nextZ = Arrays.copyOf(nextZ, cap);
                        nextStart = Arrays.copyOf(nextStart, cap + 1);
                    }
                    if (nextRefN + sum > nextRefs.length) nextRefs = Arrays.copyOf(nextRefs, Math.max(nextRefN + sum, 2 * nextRefs.length));
                    int at = nextRefN, r = 0;
                    for (int c = 0; c < 8; c++) {
                        if (childCount[c] == 0) continue;
                        nextNode[nextN] = first + r++;
                        nextX[nextN] = 2 * curX[j] + (c & 1);
                        nextY[nextN] = 2 * curY[j] + ((c >> 1) & 1);
                        nextZ[nextN] = 2 * curZ[j] + (c >> 2);
                        nextStart[nextN] = at;
                        childAt[c] = at;
                        at += childCount[c];
                        nextN++;
                    }
                    for (int k = s; k < e; k++) {
                        int bits = mask[k - s] & 0xFF;
                        for (int c = 0; c < 8; c++) if ((bits >> c & 1) != 0) nextRefs[childAt[c]++] = curRefs[k];
                    }
                    nextRefN = at;
                    nextStart[nextN] = at;
                    pending += sum - cnt;
                }
                curN = nextN;
                curNode = nextNode; curX = nextX; curY = nextY; curZ = nextZ;
                curStart = nextStart;
                curRefs = nextRefs;
            }
        }
    }
}
