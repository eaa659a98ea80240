package lt.spindulys.trace;

import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.adaptive.RecentPatches;
import lt.spindulys.math.Affine;
import lt.spindulys.math.Ray;

/**
 * Per-thread scratch passed down explicitly through intersection and shading, so the inner loops
 * allocate nothing and share nothing: the acceleration structures' traversal scratch (inherited)
 * and the scene's own. One instance per render thread; never shared.
 */
public final class TraceContext extends TraversalScratch {
    /** Scratch ray for mapping a world ray into an object's space. */
    public final Ray localRay = new Ray();
    /** Scratch for a moving object's transform at the ray's time (see GObject#toLocal). */
    public final Affine placementAtTime = new Affine();
    /** Scratch hit for any-hit and helper queries. */
    public final Hit scratchHit = new Hit();
    /** Range output of bounds tests. */
    public final double[] range = new double[2];
    /** This thread's last two lazily refined patches (see lt.spindulys.adaptive.PatchCache). */
    public final RecentPatches recentPatches = new RecentPatches();

    /** Slots of the occluder cache: a power of two. */
    public static final int OCCLUDER_SLOTS = 1024;

    /**
     * The thread's shadow-ray occluder cache (see lt.spindulys.scene.Scene#occluded): per slot the
     * top-level object that last blocked a shadow ray of that slot and the part of it that did,
     * all of the scene {@link #occluderScene}. The caller picks the slot before each shadow ray
     * ({@link #occluderSlot}, below {@link #OCCLUDER_SLOTS}): the light and, for an area light,
     * the stratum of it, so that the same stratum seen from neighbouring points, which is often
     * blocked by the same triangle, finds it.
     */
    public Object occluderScene;
    public final TracedObject[] occluders = new TracedObject[OCCLUDER_SLOTS];
    public final int[] occluderParts = new int[OCCLUDER_SLOTS];
    public int occluderSlot;

    /**
     * The flat top-level object the current shadow rays leave from, or null: it cannot block
     * them (TracedObject#flat), so the shadow query skips it without a test. Set by the
     * integrator for one shaded point's lights and cleared after.
     */
    public TracedObject shadowReceiver;

    /** Grow-once scratch for the crossings of a line with a mesh (TriangleSpans), and how many are in it. */
    public double[] crossings = new double[64];
    public int crossingCount;
    /** The primitive whose part's crossings are being collected (a grid piece of an adaptive surface). */
    public int crossingPiece;

    private SpanBuffer[] spanPool = new SpanBuffer[8];
    private int spanDepth;

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
