package lt.spindulys.render;

/**
 * What a render did: rays traced by kind and the wall time of the render phase.
 *
 * @param cameraRays     rays from the camera, one per sample (plus one per pixel for render passes)
 * @param shadowRays     rays towards lights
 * @param reflectionRays mirror rays
 * @param refractionRays rays through transparent surfaces
 * @param seconds        wall-clock seconds spent tracing (camera rays to finished frame)
 * @param traversal      nodes, leaves and triangle tests by ray kind, summed over the threads, or
 *                       null unless the counters are on ({@link lt.spindulys.accel.TraversalScratch#COUNTING})
 * @param meanSamples    the pixel samples taken per pixel rendered, summed over the time steps:
 *                       the samples per pixel, or fewer where adaptive sampling stopped pixels early;
 *                       0 when not counted
 */
public record RenderStats(long cameraRays, long shadowRays, long reflectionRays, long refractionRays, double seconds,
                          TraversalCounts traversal, double meanSamples) {
    /** Stats without traversal counts or samples. */
    public RenderStats(long cameraRays, long shadowRays, long reflectionRays, long refractionRays, double seconds) {
        this(cameraRays, shadowRays, reflectionRays, refractionRays, seconds, null, 0);
    }

    /** Stats without samples. */
    public RenderStats(long cameraRays, long shadowRays, long reflectionRays, long refractionRays, double seconds, TraversalCounts traversal) {
        this(cameraRays, shadowRays, reflectionRays, refractionRays, seconds, traversal, 0);
    }

    /**
     * All rays traced.
     *
     * @return the sum of the four kinds
     */
    public long totalRays() { return cameraRays + shadowRays + reflectionRays + refractionRays; }

    /**
     * Millions of rays per second of the render phase.
     *
     * @return the rate, or 0 when no time was measured
     */
    public double mraysPerSecond() { return seconds > 0 ? totalRays() / seconds / 1e6 : 0; }
}
