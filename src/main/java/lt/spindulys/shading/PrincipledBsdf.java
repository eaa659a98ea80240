package lt.spindulys.shading;

import lt.spindulys.math.Color;

/**
 * The part of Blender's Principled BSDF a path tracer needs, layered as Cycles does: base colour,
 * metallic, roughness, ior and transmission, everything but ior in [0,1]; alpha = roughness
 * squared for every microfacet lobe.
 * <ul>
 * <li>metal, weight {@code metallic}: a GGX {@link ConductorBsdf} with Schlick Fresnel,
 *     F0 = base colour;</li>
 * <li>glass, weight {@code (1 - metallic) transmission}: a {@link DielectricBsdf} of index ior,
 *     smooth or rough by roughness, its transmission tinted by the base colour;</li>
 * <li>the rest, weight {@code (1 - metallic)(1 - transmission)}: an untinted GGX dielectric
 *     coat (reflection only, exact Fresnel from ior) over a Lambert base of the base colour that
 *     receives what the coat lets through, both ways ({@link FresnelDiffuseLobe}: the smooth
 *     Fresnel transmittance, under a rough coat 1 - its tabulated albedo; that keeps the pair
 *     reciprocal and a white one's albedo 1).</li>
 * </ul>
 * The weights add up to 1 and each part conserves energy, so the whole does. An opaque part has
 * no inside, so its coat uses max(ior, 1/ior): the same reflectance at normal incidence, but no
 * total internal reflection from outside. Rough glass is divided by its single-scattering albedo
 * ({@link DielectricBsdf}), so it too loses nothing to the single-scattering model.
 *
 * <p>Sampling picks one lobe with probability proportional to its weight times a cheap per-wo
 * estimate of its albedo (Schlick reflectance for metal, R + (1 - R) tint for glass, F(cos wo)
 * for the coat, (1 - F(cos wo)) times the mean base colour for the diffuse), see
 * {@link LobeMixture} for what the sample then reports. At roughness below about 0.03 the metal,
 * glass and coat lobes are delta lobes; only the diffuse base then has a density.
 */
public final class PrincipledBsdf extends MixtureBsdf {
    private final double baseR, baseG, baseB;
    private final double metallic, roughness, ior, transmission;

    /**
     * A principled surface.
     *
     * @param baseR red base colour in [0,1]
     * @param baseG green base colour
     * @param baseB blue base colour
     * @param metallic metal fraction in [0,1]
     * @param roughness perceptual roughness in [0,1]
     * @param ior index of refraction inside over outside, positive (1.5 for glass and plastic)
     * @param transmission glass fraction of the non-metal part, in [0,1]
     */
    public PrincipledBsdf(double baseR, double baseG, double baseB, double metallic, double roughness, double ior, double transmission) {
        // The same lobe set SurfaceBsdf re-parameterises per hit, set once: one code path for both.
        PrincipledLobes lobes = new PrincipledLobes();
        lobes.set(baseR, baseG, baseB, metallic, roughness, ior, transmission);
        this.baseR = baseR; this.baseG = baseG; this.baseB = baseB;
        this.metallic = metallic; this.roughness = roughness; this.ior = ior; this.transmission = transmission;
        mixture = lobes.mixture;
    }

    /**
     * A principled surface.
     *
     * @param baseColor base colour
     * @param metallic metal fraction in [0,1]
     * @param roughness perceptual roughness in [0,1]
     * @param ior index of refraction inside over outside
     * @param transmission glass fraction of the non-metal part
     */
    public PrincipledBsdf(Color baseColor, double metallic, double roughness, double ior, double transmission) {
        this(baseColor.r(), baseColor.g(), baseColor.b(), metallic, roughness, ior, transmission);
    }

    /** {@return the metal fraction} */
    public double metallic() { return metallic; }
    /** {@return the perceptual roughness} */
    public double roughness() { return roughness; }
    /** {@return the index of refraction} */
    public double ior() { return ior; }
    /** {@return the glass fraction of the non-metal part} */
    public double transmission() { return transmission; }

    @Override
    public String toString() {
        return "Principled(base " + baseR + " " + baseG + " " + baseB + ", metallic " + metallic + ", roughness " + roughness
                + ", ior " + ior + ", transmission " + transmission + ")";
    }
}
