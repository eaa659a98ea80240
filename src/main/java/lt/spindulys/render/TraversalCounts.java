package lt.spindulys.render;

import lt.spindulys.accel.TraversalScratch;

/**
 * A render's traversal counts by ray kind ({@link TraversalScratch#CAMERA}, {@link TraversalScratch#SHADOW},
 * {@link TraversalScratch#SECONDARY}), summed over its threads: inner nodes visited, leaves entered and
 * ray/triangle tests (see {@link TraversalScratch#nodesVisited}). Only gathered when the counters are on
 * ({@code -Dspindulys.counters=true}). Immutable.
 */
public final class TraversalCounts {
    /** Longs per thread in the renderer's sums: three counts for each kind. */
    static final int SIZE = 3 * TraversalScratch.KINDS;

    private final long[] counts;

    private TraversalCounts(long[] counts) { this.counts = counts; }

    /** Writes {@code ctx}'s counts to {@code out[at .. at + SIZE)}, as {@link #of} reads them. */
    static void copy(TraversalScratch ctx, long[] out, int at) {
        for (int k = 0; k < TraversalScratch.KINDS; k++) {
            out[at + 3 * k] = ctx.nodesVisited[k];
            out[at + 3 * k + 1] = ctx.leavesEntered[k];
            out[at + 3 * k + 2] = ctx.triangleTests[k];
        }
    }

    /** The counts at {@code sums[at .. at + SIZE)}, as {@link #copy} wrote them. */
    static TraversalCounts of(long[] sums, int at) {
        return new TraversalCounts(java.util.Arrays.copyOfRange(sums, at, at + SIZE));
    }

    /** Inner nodes visited by rays of {@code kind} (a node: the box tests of its children). */
    public long nodes(int kind) { return counts[3 * kind]; }

    /** Leaves entered by rays of {@code kind}. */
    public long leaves(int kind) { return counts[3 * kind + 1]; }

    /** Ray/triangle tests of rays of {@code kind}. */
    public long triangleTests(int kind) { return counts[3 * kind + 2]; }
}
