package lt.spindulys.shading;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.Scene;

/**
 * How the light seen along a camera ray is gathered, chosen by the scene's settings
 * ({@link IntegratorKind}): the thesis's {@link WhittedIntegrator} or the {@link PathIntegrator}.
 * Immutable and shared by the render threads; everything a ray needs lives in the thread's
 * {@link TracerScratch}, made by {@link #newScratch} under a heap reservation the renderer holds.
 */
public sealed interface Integrator permits WhittedIntegrator, PathIntegrator {
    /**
     * The integrator the scene's settings ask for.
     *
     * @param scene the frozen scene
     * @return its integrator
     */
    static Integrator of(Scene scene) {
        return scene.settings().integrator() == IntegratorKind.PATH ? new PathIntegrator(scene) : new WhittedIntegrator(scene);
    }

    /**
     * A scratch for one render thread, made under a reservation the caller holds, which must
     * cover {@link #scratchBytes scratchBytes(samplesPerPixel)}; that much of it is released once
     * the scratch is made.
     *
     * @param reservation heap reserved for this scratch among others
     * @return the scratch
     */
    TracerScratch newScratch(HeapBudget.Reservation reservation);

    /**
     * Heap one thread's scratch holds at {@code samplesPerPixel} pixel samples.
     *
     * @param samplesPerPixel the pixel samples of a pass
     * @return bytes, saturating
     */
    long scratchBytes(int samplesPerPixel);

    /**
     * What makes the scratch large, for a message.
     *
     * @param samplesPerPixel the pixel samples of a pass
     * @return a phrase naming the settings that size it
     */
    String scratchSizedBy(int samplesPerPixel);

    /**
     * The colour seen along a camera ray, written to out[0..2], for the pixel sample the scratch
     * was last set to ({@link TracerScratch#setSample}).
     *
     * @param ray the camera ray
     * @param s   the thread's scratch
     * @param out receives r, g, b
     */
    void traceCamera(Ray ray, TracerScratch s, double[] out);

    /**
     * What a render pass sees along {@code ray}: its first hit only. Writes to out[0] the
     * distance along the ray's direction made unit (+Infinity if nothing is hit) and to
     * out[1..3] the unit world-space shading normal turned to face the ray (0 0 0 if nothing is
     * hit).
     *
     * @param ray the ray
     * @param s   the thread's scratch
     * @param out receives the distance and the normal
     * @return the {@link lt.spindulys.scene.GObject#id()} of the object hit, or -1
     */
    int traceFirstHit(Ray ray, TracerScratch s, double[] out);
}
