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
 *     receives what the coat's Fresnel lets through, both ways ({@link FresnelDiffuseLobe}: that
 *     keeps the pair reciprocal and its albedo at most 1).</li>
 * </ul>
 * The weights add up to 1 and each part conserves energy, so the whole does. An opaque part has
 * no inside, so its coat uses max(ior, 1/ior): the same reflectance at normal incidence, but no
 * total internal reflection from outside, which would let a rough coat reflect more than the
 * smooth-interface Fresnel the diffuse base is scaled by (measured: up to 6% too much at 0.7).
 *
 * <p>Sampling picks one lobe with probability proportional to its weight times a cheap per-wo
 * estimate of its albedo (Schlick reflectance for metal, R + (1 - R) tint for glass, F(cos wo)
 * for the coat, (1 - F(cos wo)) times the mean base colour for the diffuse), see
 * {@link LobeMixture} for what the sample then reports. At roughness below about 0.03 the metal,
 * glass and coat lobes are delta lobes; only the diffuse base then has a density.
 */
public final class PrincipledBsdf extends MixtureBsdf {
    private static final int METAL = 0, GLASS = 1, COAT = 2, DIFFUSE = 3;
    /** Floor of the metal and glass estimates relative to their weight, so a lobe that can contribute is never starved. */
    private static final double MIN_ESTIMATE = 0.02;

    private final double baseR, baseG, baseB;
    private final double metallic, roughness, ior, transmission;
    private final double meanBase;
    /** The coat's index, at least 1: see the class comment. */
    private final double coatIor;

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
        if (!(ior > 0) || Double.isInfinite(ior)) throw new IllegalArgumentException("index of refraction must be positive and finite: " + ior);
        check("metallic", metallic);
        check("roughness", roughness);
        check("transmission", transmission);
        this.baseR = baseR; this.baseG = baseG; this.baseB = baseB;
        this.metallic = metallic; this.roughness = roughness; this.ior = ior; this.transmission = transmission;
        meanBase = (baseR + baseG + baseB) / 3;
        double rest = (1 - metallic) * (1 - transmission);
        coatIor = ior >= 1 ? ior : 1 / ior;
        mixture = new LobeMixture(
                new Bsdf[] {
                    new ConductorBsdf(baseR, baseG, baseB, roughness),
                    new DielectricBsdf(ior, roughness, baseR, baseG, baseB),
                    new DielectricSpecularLobe(coatIor, roughness),
                    new FresnelDiffuseLobe(baseR, baseG, baseB, coatIor)},
                new double[] {metallic, (1 - metallic) * transmission, rest, rest},
                this::estimate);
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

    private static void check(String name, double v) {
        if (!(v >= 0 && v <= 1)) throw new IllegalArgumentException(name + " must be in [0,1]: " + v);
    }

    /** {@return the metal fraction} */
    public double metallic() { return metallic; }
    /** {@return the perceptual roughness} */
    public double roughness() { return roughness; }
    /** {@return the index of refraction} */
    public double ior() { return ior; }
    /** {@return the glass fraction of the non-metal part} */
    public double transmission() { return transmission; }

    /** Lobe selection estimate (unnormalised; {@link LobeMixture} divides by the sum). */
    private double estimate(int lobe, double wox, double woy, double woz) {
        double cos = Math.abs(woz);
        switch (lobe) {
            case METAL: {
                if (!(metallic > 0)) return 0;
                double m = Math.max(0, 1 - cos), s = m * m * m * m * m;
                return metallic * Math.max(MIN_ESTIMATE, meanBase + (1 - meanBase) * s);
            }
            case GLASS: {
                double w = (1 - metallic) * transmission;
                if (!(w > 0)) return 0;
                double r = DielectricBsdf.fresnel(woz, ior); // signed: from inside, total internal reflection counts
                return w * Math.max(MIN_ESTIMATE, r + (1 - r) * meanBase);
            }
            case COAT:
                return (1 - metallic) * (1 - transmission) * DielectricBsdf.fresnel(cos, coatIor);
            case DIFFUSE:
                return (1 - metallic) * (1 - transmission) * meanBase * (1 - DielectricBsdf.fresnel(cos, coatIor));
            default:
                return 0;
        }
    }

    @Override
    public String toString() {
        return "Principled(base " + baseR + " " + baseG + " " + baseB + ", metallic " + metallic + ", roughness " + roughness
                + ", ior " + ior + ", transmission " + transmission + ")";
    }
}
