package lt.spindulys.scene;

import lt.spindulys.limits.HeapBudget;

/**
 * The scene-wide settings of adaptive subdivision (a {@link SubdivisionSurface} whose
 * {@link AdaptiveSubdivisionSurface.Method method} is not uniform): how much heap its tessellations may
 * hold, how much of that the lazy patches' cache gets, the cache's policy, and an override of
 * every surface's target edge length. None of them changes the image: a patch is the same
 * whether it was kept, evicted and rebuilt, or built eagerly.
 *
 * @param memoryBytes    heap all adaptive tessellations of a scene may hold, eager and cached
 *                       together; 0 for automatic, a quarter of the JVM's maximum heap
 * @param cacheBytes     the lazy patches' cache, a part of {@code memoryBytes}: a cache larger than
 *                       the memory is shrunk to it when the scene is built (and --stats says so)
 * @param lastTwoPatches the thesis's policy (each render thread keeps the last two patches it
 *                       used, nothing shared) instead of the shared least-recently-used cache
 * @param targetPixels   target edge length in pixels for every adaptive surface, overriding
 *                       their own; NaN for none
 */
public record AdaptiveSettings(long memoryBytes, long cacheBytes, boolean lastTwoPatches, double targetPixels) {
    /** Automatic memory, a 64 MiB shared cache, no target override. */
    public static final AdaptiveSettings DEFAULT = new AdaptiveSettings(0, 64L << 20, false, Double.NaN);

    /** The most a budget may name: far above any heap, so a typo is caught, not obeyed. */
    public static final long MAX_BYTES = 1L << 44;

    /** The smallest and largest target edge length, in pixels. */
    public static final double MIN_TARGET = 0.01, MAX_TARGET = 1e6;

    /**
     * Checks the values.
     *
     * @param memoryBytes    heap for all adaptive tessellations, 0 for automatic
     * @param cacheBytes     the lazy cache's share
     * @param lastTwoPatches the thesis's last-two-patches policy
     * @param targetPixels   target edge length override, NaN for none
     * @throws IllegalArgumentException if a value is out of range
     */
    public AdaptiveSettings {
        if (memoryBytes < 0 || memoryBytes > MAX_BYTES) {
            throw new IllegalArgumentException("subdivision memory must be between 0 (automatic) and " + HeapBudget.format(MAX_BYTES) + ", found " + memoryBytes);
        }
        if (cacheBytes < 1 || cacheBytes > MAX_BYTES) {
            throw new IllegalArgumentException("subdivision cache must be between 1 byte and " + HeapBudget.format(MAX_BYTES) + ", found " + cacheBytes);
        }
        if (!Double.isNaN(targetPixels)) checkTarget(targetPixels);
    }

    /**
     * Refuses a target edge length that is not a number between {@link #MIN_TARGET} and {@link #MAX_TARGET} pixels.
     *
     * @param pixels the target edge length
     * @return {@code pixels}, unchanged
     * @throws IllegalArgumentException "target edge length must be between 0.01 and 1000000 pixels, found 0"
     */
    public static double checkTarget(double pixels) {
        if (!(pixels >= MIN_TARGET && pixels <= MAX_TARGET)) {
            throw new IllegalArgumentException("target edge length must be between " + MIN_TARGET + " and 1000000 pixels, found " + pixels);
        }
        return pixels;
    }

    /**
     * The heap budget asked for in bytes: {@link #memoryBytes()}, or a quarter of the JVM's
     * maximum heap when automatic. When the scene is built it is capped by what the heap can
     * give, and the cache is shrunk to fit in it.
     *
     * @return the budget asked for all adaptive tessellations of a scene
     */
    public long effectiveMemoryBytes() {
        return memoryBytes > 0 ? memoryBytes : Runtime.getRuntime().maxMemory() / 4;
    }

    /**
     * These settings with another memory budget.
     *
     * @param bytes the new budget, 0 for automatic
     * @return new settings
     */
    public AdaptiveSettings withMemory(long bytes) { return new AdaptiveSettings(bytes, cacheBytes, lastTwoPatches, targetPixels); }

    /**
     * These settings with another cache size.
     *
     * @param bytes the new cache size
     * @return new settings
     */
    public AdaptiveSettings withCache(long bytes) { return new AdaptiveSettings(memoryBytes, bytes, lastTwoPatches, targetPixels); }

    /**
     * These settings with the cache policy chosen.
     *
     * @param lastTwo true for the thesis's last-two-patches policy, false for the shared cache
     * @return new settings
     */
    public AdaptiveSettings withLastTwoPatches(boolean lastTwo) { return new AdaptiveSettings(memoryBytes, cacheBytes, lastTwo, targetPixels); }

    /**
     * These settings with a target edge length override.
     *
     * @param pixels the target for every adaptive surface, NaN for none
     * @return new settings
     */
    public AdaptiveSettings withTarget(double pixels) { return new AdaptiveSettings(memoryBytes, cacheBytes, lastTwoPatches, pixels); }
}
