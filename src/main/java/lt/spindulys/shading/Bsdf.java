package lt.spindulys.shading;

/**
 * A bidirectional scattering distribution function in the local shading frame: z is the shading
 * normal, directions are unit vectors pointing away from the surface, wo towards the viewer and
 * wi towards the light. Implementations allocate nothing per call so they can sit in the inner
 * loop of a path tracer; outputs go to caller-owned arrays and {@link BsdfSample}s.
 *
 * <p>{@link #eval} and {@link #pdf} describe only the non-delta lobes: for a delta lobe they
 * return zero, and only {@link #sample} can produce its direction.
 */
public interface Bsdf {
    /**
     * Evaluates f(wo, wi) per RGB channel, without the cosine factor.
     *
     * @param rgbOut receives the three channels (zeros when wi cannot be scattered into from wo)
     */
    void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut);

    /**
     * {@return the solid-angle density with which {@link #sample} draws wi given wo} Zero for
     * directions only a delta lobe reaches. The integral over the sphere is the probability that
     * sampling succeeds, at most 1.
     */
    double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz);

    /**
     * Draws an incident direction for wo.
     *
     * @param uc uniform in [0,1) choosing a lobe
     * @param u1 first uniform in [0,1) for the direction
     * @param u2 second uniform in [0,1) for the direction
     * @param out receives wi, f, pdf, the specular flag and eta; cleared when there is no sample
     * @return false when no direction was produced (out then holds zero f and pdf)
     */
    boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out);

    /** {@return whether every lobe is a delta lobe, so that eval and pdf are always zero} */
    boolean isSpecular();
}
