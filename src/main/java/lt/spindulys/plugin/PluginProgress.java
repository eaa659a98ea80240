package lt.spindulys.plugin;

/**
 * The host's side of a running plugin: where progress and previews go, and whether the user
 * cancelled. Methods are called from the thread that runs the plugin (or threads it starts), so a
 * host hands the values over to its user-interface thread itself.
 */
public interface PluginProgress {
    /** Reports nothing and never cancels: for hosts without a user interface. */
    PluginProgress NONE = new PluginProgress() {
        @Override public void progress(double fraction, String stage) { }
        @Override public boolean isCancelled() { return false; }
    };

    /**
     * How far the run has come.
     *
     * @param fraction from 0 to 1, not decreasing within a stage
     * @param stage    what is being done, a few words ("rendering the preview")
     */
    void progress(double fraction, String stage);

    /**
     * Whether the user asked to stop; a plugin asks often and then throws
     * {@link java.util.concurrent.CancellationException} without writing anything.
     *
     * @return true once cancelled
     */
    boolean isCancelled();

    /**
     * A picture of the output so far, for a plugin that makes one: first coarse previews, then the
     * final picture. The array belongs to the host after the call. The default ignores it.
     *
     * @param width  the picture's width in pixels
     * @param height the picture's height in pixels
     * @param argb   {@code width * height} pixels, row after row from the top, 0xAARRGGBB
     * @param last   true for the final picture
     */
    default void preview(int width, int height, int[] argb, boolean last) { }
}
