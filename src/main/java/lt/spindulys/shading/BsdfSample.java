package lt.spindulys.shading;

/**
 * One direction drawn by {@link Bsdf#sample}: a mutable record the caller allocates once and
 * reuses, so that sampling allocates nothing.
 *
 * <p>For a delta lobe ({@link #specular}) {@link #f} divided by {@link #pdf} is the path weight
 * before the cosine, and {@link #pdf} is the discrete probability of having chosen that lobe,
 * not a density.
 */
public final class BsdfSample {
    /** The sampled incident direction wi, x component, in the local shading frame. */
    public double wix;
    /** The sampled incident direction wi, y component. */
    public double wiy;
    /** The sampled incident direction wi, z component (cosine against the shading normal). */
    public double wiz;
    /** f(wo, wi) per RGB channel, not multiplied by the cosine. */
    public final double[] f = new double[3];
    /** Solid-angle density of wi, or the lobe probability when {@link #specular}. */
    public double pdf;
    /** Whether wi came from a delta lobe (a mirror or a smooth refraction). */
    public boolean specular;
    /** Relative index of refraction crossed by a transmission (incident side over outgoing side); 1 for reflection. */
    public double eta = 1;
    /** Scratch for a sampled microfacet normal: kept here, with the caller, so BSDFs stay immutable and shareable across threads. */
    final double[] microNormal = new double[3];

    /** Resets to "no sample": zero f and pdf, not specular, eta 1. */
    public void clear() {
        wix = 0; wiy = 0; wiz = 0;
        f[0] = 0; f[1] = 0; f[2] = 0;
        pdf = 0;
        specular = false;
        eta = 1;
    }

    /** {@return whether wi lies on the other side of the surface from wo} (given wo's z). */
    boolean isTransmission(double woz) { return woz * wiz < 0; }
}
