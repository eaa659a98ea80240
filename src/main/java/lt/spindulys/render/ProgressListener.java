package lt.spindulys.render;

/** Told how far a render has come; called from render threads, so implementations synchronise. */
@FunctionalInterface
public interface ProgressListener {
    /** A listener that ignores every report. */
    ProgressListener NONE = (done, total) -> { };

    /**
     * Reports the pixels finished so far (over every time step of the render).
     *
     * @param donePixels  pixels finished, from 0 to {@code totalPixels}; reports from several
     *                    threads may arrive out of order
     * @param totalPixels pixels the render will finish in all
     */
    void progress(long donePixels, long totalPixels);
}
