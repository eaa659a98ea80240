package lt.spindulys.scene;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Supplier;

import lt.spindulys.adaptive.CachePolicy;
import lt.spindulys.adaptive.PatchCache;
import lt.spindulys.adaptive.ViewFootprint;
import lt.spindulys.camera.Camera;
import lt.spindulys.limits.HeapBudget;

/**
 * What all objects of one scene build share (one per {@link Scene} built, reached through every
 * {@link BuildContext} of that build): the adaptive surfaces' tessellations, one per surface
 * geometry and options however many instances place it, the lazy patches' cache, and the heap
 * budget of eager tessellation. Objects register here while they are frozen; the scene finishes
 * every tessellation once all objects are placed, so that a tessellation shared by instances
 * knows every placement before it chooses its levels.
 */
final class BuildShared {
    private final AdaptiveSettings settings;
    private final Camera camera;
    private final int width, height;
    private final Map<Object, SurfaceTessellation> tessellations = new LinkedHashMap<>();
    private ViewFootprint view;
    private PatchCache cache;
    /** Heap left for eager tessellation: the budget less the cache's share, less what earlier surfaces took; -1 until the budget is set. */
    private long eagerLeft = -1;
    /** The cache's size within the budget, set with it. */
    private long cacheBytes;
    /** What --stats says of budgets changed to fit (capped by the heap, the cache shrunk to the memory). */
    private final List<String> budgetNotes = new ArrayList<>();
    private boolean finished;

    BuildShared(AdaptiveSettings settings, Camera camera, int width, int height) {
        this.settings = settings;
        this.camera = camera;
        this.width = width;
        this.height = height;
    }

    /** Heap the frame will take per pixel, allocated after the build (FrameBuffer.bytesToRender without passes). */
    static final long FRAME_BYTES_PER_PIXEL = 36;

    /** The least the subdivision memory is cut to by the heap: a cache this small still renders, if slowly. */
    static final long MIN_BYTES = 1L << 20;

    /**
     * Sets the budget the first time an adaptive surface needs it (scenes without one never do):
     * the subdivision memory asked for, but at most half of what the heap can still give, less
     * the frame to come; the other half is left for the render threads' buffers, the structures
     * over the patches and what nothing counts. The cache gets its size from it, at most all of it.
     */
    private void budget() {
        if (eagerLeft >= 0) return;
        long asked = settings.effectiveMemoryBytes();
        long heap = Math.max(0, HeapBudget.spare() - HeapBudget.product(width, height, FRAME_BYTES_PER_PIXEL)) / 2;
        long memory = Math.min(asked, Math.max(heap, MIN_BYTES));
        if (memory < asked) {
            budgetNotes.add("subdivision memory " + mib(asked) + " asked" + (settings.memoryBytes() == 0 ? " (a quarter of the heap)" : "")
                    + ", capped to " + mib(memory) + " by the heap (half of what it could still give when the scene was built)");
        }
        cacheBytes = Math.min(settings.cacheBytes(), memory);
        if (cacheBytes < settings.cacheBytes()) {
            budgetNotes.add("subdivision cache " + mib(settings.cacheBytes()) + " asked, shrunk to " + mib(cacheBytes) + ", the whole subdivision memory"
                    + (memory < asked ? " the heap allows" : ""));
        }
        eagerLeft = memory - cacheBytes;
    }

    /** "3072 MiB", "0.5 MiB": a budget as the options and keys give it. */
    private static String mib(long bytes) {
        double m = bytes / (double) (1 << 20);
        return (m == Math.rint(m) ? Long.toString((long) m) : String.format(java.util.Locale.ROOT, "%.1f", m)) + " MiB";
    }

    /** What the budget became where it differs from what was asked, one line each for --stats; empty when it is as asked. */
    synchronized List<String> budgetNotes() { return List.copyOf(budgetNotes); }

    AdaptiveSettings settings() { return settings; }

    /** The tessellation registered under {@code key}, made by {@code make} the first time. */
    synchronized SurfaceTessellation tessellation(Object key, Supplier<SurfaceTessellation> make) {
        if (finished) throw new IllegalStateException("the scene's tessellations are finished");
        return tessellations.computeIfAbsent(key, k -> make.get());
    }

    /** The view levels are chosen for. */
    synchronized ViewFootprint view() {
        if (view == null) view = ViewFootprint.of(camera, width, height);
        return view;
    }

    /** The scene's cache of lazily refined patches, made on first use. */
    synchronized PatchCache cache() {
        budget();
        if (cache == null) cache = new PatchCache(cacheBytes, settings.lastTwoPatches() ? CachePolicy.LAST_TWO : CachePolicy.LRU);
        return cache;
    }

    /** Takes {@code bytes} of the eager budget if that much is left; false (nothing taken) otherwise. */
    synchronized boolean takeEager(long bytes) {
        budget();
        if (bytes > eagerLeft) return false;
        eagerLeft -= bytes;
        return true;
    }

    /**
     * The combined method's choice: the cheapest of the items (by {@code cost}, ties by index)
     * while their sum fits in the eager budget left, taken from it.
     *
     * @return the chosen items' indices, or an empty array when none fits
     */
    synchronized int[] takeCheapest(long[] cost) {
        budget();
        Integer[] order = new Integer[cost.length];
        for (int i = 0; i < cost.length; i++) order[i] = i;
        java.util.Arrays.sort(order, (a, b) -> cost[a] != cost[b] ? Long.compare(cost[a], cost[b]) : Integer.compare(a, b));
        int take = 0;
        long sum = 0;
        while (take < order.length && HeapBudget.sum(sum, cost[order[take]]) <= eagerLeft) sum += cost[order[take++]];
        if (take == 0 || !HeapBudget.fits(sum)) return new int[0];
        eagerLeft -= sum;
        int[] chosen = new int[take];
        for (int k = 0; k < take; k++) chosen[k] = order[k];
        return chosen;
    }

    /** Heap left for eager tessellation. */
    synchronized long eagerLeft() {
        budget();
        return eagerLeft;
    }

    /** Finishes every registered tessellation, in registration order (so budgets are spent deterministically). */
    void finish(BuildContext root) {
        List<SurfaceTessellation> all;
        synchronized (this) {
            finished = true;
            all = new ArrayList<>(tessellations.values());
        }
        for (SurfaceTessellation t : all) t.finish(this, root);
    }

    /** The tessellations of this build, in registration order. */
    synchronized List<SurfaceTessellation> tessellations() { return List.copyOf(tessellations.values()); }
}
