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
