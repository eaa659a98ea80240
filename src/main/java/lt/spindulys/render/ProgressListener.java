package lt.spindulys.render;

/** Told how far a render has come; called from render threads, so implementations synchronise. */
@FunctionalInterface
public interface ProgressListener {
    ProgressListener NONE = (done, total) -> { };

    void progress(long donePixels, long totalPixels);
}
