package lt.spindulys.shading;

import lt.spindulys.material.Material;

/**
 * The BSDF of the current hit for one render thread: a single mutable object, re-parameterised
 * per hit by {@link #setWhitted} or {@link #setPrincipled} and then queried like any other
 * {@link Bsdf}, so that a path tracer whose textures change the terms at every hit still
 * allocates nothing per ray. Every lobe either material model can need is allocated once, here.
 *
 * <p>After a set, eval, pdf, sample and isSpecular give bit for bit what a freshly built
 * {@link WhittedMaterialBsdf#fromWhittedTerms} or {@link PrincipledBsdf} with the same arguments
 * gives: both run the same code (the lobe sets those classes build once). Until the first set it
 * scatters nothing.
 *
 * <p>Confined to one thread: it is neither thread-safe nor meant to be shared or kept. Each render
 * thread owns one, and whatever the last set configured is only valid until the next set.
 */
public final class SurfaceBsdf extends MixtureBsdf {
    private final WhittedLobes whitted = new WhittedLobes();
    private final PrincipledLobes principled = new PrincipledLobes();

    /** A reusable BSDF that scatters nothing until it is set. */
    public SurfaceBsdf() { mixture = whitted.mixture; } // the mixture of whichever model was set last

    /**
     * Configures the Whitted material terms at a hit, by the rule of
     * {@link WhittedMaterialBsdf#fromWhittedTerms} (same parameters). Allocates nothing.
     *
     * @throws IllegalArgumentException when ior is not positive and finite (the previous
     *         configuration then stays)
     */
    public void setWhitted(double colourR, double colourG, double colourB, double kd, double ks, double shininess,
            double kr, double kt, double ior, double filterR, double filterG, double filterB, boolean fresnel) {
        whitted.set(colourR, colourG, colourB, kd, ks, shininess, kr, kt, ior, filterR, filterG, filterB, fresnel);
        mixture = whitted.mixture;
    }

    /**
     * Configures a material's Whitted terms at a hit whose textures gave the colour, ks, kr and
     * kt there, as {@link WhittedMaterialBsdf#fromMaterial(Material, double, double, double, double, double, double)}.
     */
    public void setWhitted(Material m, double r, double g, double b, double ks, double kr, double kt) {
        setWhitted(r, g, b, m.kd(), ks, m.shininess(), kr, kt, m.ior(),
                m.filter().r(), m.filter().g(), m.filter().b(), m.fresnel());
    }

    /**
     * Configures a principled surface, as {@link PrincipledBsdf}'s constructor does (same
     * parameters). Allocates nothing; the diffuse base's hemispherical Fresnel average is cached
     * for the few indices of refraction seen most recently rather than recomputed per hit.
     *
     * @throws IllegalArgumentException when ior is not positive and finite or metallic,
     *         roughness or transmission is outside [0,1] (the previous configuration then stays)
     */
    public void setPrincipled(double baseR, double baseG, double baseB, double metallic, double roughness,
            double ior, double transmission) {
        principled.set(baseR, baseG, baseB, metallic, roughness, ior, transmission);
        mixture = principled.mixture;
    }
}
