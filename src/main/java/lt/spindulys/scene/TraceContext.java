package lt.spindulys.scene;

import lt.spindulys.math.Ray;

/**
 * Per-thread scratch passed down explicitly through intersection and shading, so the inner loops
 * allocate nothing and share nothing. One instance per render thread; never shared.
 */
public final class TraceContext {
    /** Scratch ray for mapping a world ray into an object's space. */
    public final Ray localRay = new Ray();
    /** Scratch hit for any-hit and helper queries. */
    public final Hit scratchHit = new Hit();
    /** Range output of bounds tests. */
    public final double[] range = new double[2];

    /**
     * Entries of {@link #stack(int)} below this index belong to traversals further up the call
     * chain (a scene BVH whose primitive is a mesh with its own BVH): a traversal uses the entries
     * from here on and raises it while it calls its primitives.
     */
    public int stackTop;

    /**
     * Per-ray constants of the watertight triangle test (TriangleMesh), valid while the ray
     * direction equals (shearDx, shearDy, shearDz): the axis permutation and the shear.
     */
    public double shearDx = Double.NaN, shearDy = Double.NaN, shearDz = Double.NaN;
    public double shearSx, shearSy, shearSz;
    public int shearKx, shearKy, shearKz;

    /** Grow-once scratch for the crossings of a line with a mesh (TriangleMesh spans), and how many are in it. */
    public double[] crossings = new double[64];
    public int crossingCount;

    private int[] stack = new int[64];
    private SpanBuffer[] spanPool = new SpanBuffer[8];
    private int spanDepth;

    /** A traversal stack of at least {@code size} entries (grown once, then reused). */
    public int[] stack(int size) {
        if (stack.length < size) stack = new int[Math.max(size, stack.length * 2)];
        return stack;
    }

    /** Borrows a cleared span buffer; give it back with {@link #releaseSpans()} in LIFO order. */
    public SpanBuffer acquireSpans() {
        if (spanDepth == spanPool.length) spanPool = java.util.Arrays.copyOf(spanPool, spanPool.length * 2);
        SpanBuffer b = spanPool[spanDepth];
        if (b == null) b = spanPool[spanDepth] = new SpanBuffer();
        spanDepth++;
        b.clear();
        return b;
    }

    public void releaseSpans() { spanDepth--; }
}
