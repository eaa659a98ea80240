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
    private final Map<Object, AdaptiveTessellation> tessellations = new LinkedHashMap<>();
    private ViewFootprint view;
    private PatchCache cache;
    /** Heap left for eager tessellation: the budget less the cache's share, less what earlier surfaces took. */
    private long eagerLeft;
    private boolean finished;

    BuildShared(AdaptiveSettings settings, Camera camera, int width, int height) {
        this.settings = settings;
        this.camera = camera;
        this.width = width;
        this.height = height;
        eagerLeft = settings.effectiveMemoryBytes() - settings.cacheBytes();
    }

    AdaptiveSettings settings() { return settings; }

    /** The tessellation registered under {@code key}, made by {@code make} the first time. */
    synchronized AdaptiveTessellation tessellation(Object key, Supplier<AdaptiveTessellation> make) {
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
        if (cache == null) cache = new PatchCache(settings.cacheBytes(), settings.lastTwoPatches() ? CachePolicy.LAST_TWO : CachePolicy.LRU);
        return cache;
    }

    /** Takes {@code bytes} of the eager budget if that much is left; false (nothing taken) otherwise. */
    synchronized boolean takeEager(long bytes) {
        if (bytes > eagerLeft) return false;
        eagerLeft -= bytes;
        return true;
    }

    /** Heap left for eager tessellation. */
    synchronized long eagerLeft() { return eagerLeft; }

    /** Finishes every registered tessellation, in registration order (so budgets are spent deterministically). */
    void finish(BuildContext root) {
        List<AdaptiveTessellation> all;
        synchronized (this) {
            finished = true;
            all = new ArrayList<>(tessellations.values());
        }
        for (AdaptiveTessellation t : all) t.finish(this, root);
    }

    /** The tessellations of this build, in registration order. */
    synchronized List<AdaptiveTessellation> tessellations() { return List.copyOf(tessellations.values()); }
}
