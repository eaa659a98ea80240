package lt.spindulys.viewer;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import lt.spindulys.scene.RenderSettings;

/**
 * The passes of a progressive preview of a scene: an eighth, a quarter and a half of the scene's
 * size at one sample per pixel, the full size at one sample, then the full size at the scene's own
 * settings, which is the picture {@code render scene.dat} makes. Each pass is a whole render that
 * replaces the picture when it is done; a pass that would repeat the one before (a small image,
 * one sample) is left out. While the view is being dragged only the {@link Pass#coarse()} ones run.
 */
final class PreviewPlan {
    private PreviewPlan() {}

    /** The fractions of the scene's size the first passes render, coarsest first. */
    private static final int[] DIVISORS = {8, 4, 2};
    /** Passes at this fraction of the size or smaller are coarse: the ones that keep up with a drag. */
    private static final int COARSE_DIVISOR = 4;

    /**
     * One pass.
     *
     * @param width   pixels across
     * @param height  pixels down
     * @param samples samples per pixel; the scene's own in the last pass
     * @param coarse  true for the passes that run while the view is dragged
     * @param last    true for the last pass, rendered with the scene's settings
     */
    record Pass(int width, int height, int samples, boolean coarse, boolean last) {
        /**
         * The settings to render this pass with: the scene's, at this pass's size and samples
         * (one time step and no adaptive sampling, so one sample is allowed whatever the scene's
         * time steps and minimum samples, and no denoising, which one sample gives nothing to
         * go on), without render passes (the preview shows only the picture, which passes do not
         * change).
         */
        RenderSettings apply(RenderSettings scene) {
            RenderSettings.Builder b = scene.toBuilder().aovs(Set.of());
            if (!last) b.size(width, height).timeSteps(1).samplesPerPixel(samples).noiseThreshold(0).minSamples(0).denoise(false);
            return b.build();
        }

        /** "160x120, 1 sample", for the status line. */
        String describe() { return width + "x" + height + ", " + samples + (samples == 1 ? " sample" : " samples"); }
    }

    /**
     * The passes for a scene's settings.
     *
     * @param scene the settings the scene file gives
     * @return the passes, coarsest first; the last renders the scene's own settings
     */
    static List<Pass> of(RenderSettings scene) {
        int w = scene.width(), h = scene.height(), spp = scene.samplesPerPixel();
        List<Pass> passes = new ArrayList<>();
        for (int d : DIVISORS) {
            // Rounded up, so that no side is 0; an image already this small is not made smaller.
            int pw = (w + d - 1) / d, ph = (h + d - 1) / d;
            Pass p = new Pass(pw, ph, 1, d >= COARSE_DIVISOR, false);
            if ((pw < w || ph < h) && (passes.isEmpty() || !same(passes.get(passes.size() - 1), p))) passes.add(p);
        }
        if (spp > 1) passes.add(new Pass(w, h, 1, false, false));
        passes.add(new Pass(w, h, spp, false, true));
        return List.copyOf(passes);
    }

    private static boolean same(Pass a, Pass b) { return a.width() == b.width() && a.height() == b.height() && a.samples() == b.samples(); }
}
