package lt.spindulys.render;

/**
 * What a render did: rays traced by kind and the wall time of the render phase.
 *
 * @param seconds wall-clock seconds spent tracing (camera rays to finished frame)
 */
public record RenderStats(long cameraRays, long shadowRays, long reflectionRays, long refractionRays, double seconds) {
    public long totalRays() { return cameraRays + shadowRays + reflectionRays + refractionRays; }

    /** Millions of rays per second of the render phase. */
    public double mraysPerSecond() { return seconds > 0 ? totalRays() / seconds / 1e6 : 0; }
}
