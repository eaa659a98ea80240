package lt.spindulys.shading;

import lt.spindulys.material.Material;

/**
 * The thesis's Whitted material terms at a hit, read as a BSDF so that every existing scene renders
 * under a path tracer. The rule, per term (colour, kd, ks, shininess, kr, kt, ior, filter):
 * <ul>
 * <li>{@code kd * colour}: a Lambert lobe of that albedo, reflecting kd colour / pi times the
 *     irradiance. The Whitted diffuse term, kd colour times the light times the cosine, has the
 *     same shape without the 1 / pi: a scene lit for the Whitted tracer shows its diffuse
 *     surfaces pi times darker under a path tracer, unless its lights are made pi times
 *     brighter;</li>
 * <li>{@code ks} with Phong exponent n: a GGX glossy reflection of weight ks, untinted and
 *     Fresnel-free (a {@link ConductorBsdf} with F0 = 1), with alpha = sqrt(2 / (n + 2)), the
 *     usual Blinn-Phong to Beckmann/GGX width correspondence (n = 2 / alpha^2 - 2); so n = 0 is
 *     alpha 1 and a large n a mirror. The lobe is normalised where the Whitted highlight
 *     ks (n.h)^n is not, so the highlight's shape carries over but its absolute height changes
 *     with n; a path tracer cannot keep an unnormalised lobe without breaking energy;</li>
 * <li>{@code kr}: a perfect mirror of weight kr, untinted (Whitted reflection is);</li>
 * <li>{@code kt}: a perfect refraction of weight kt by Snell's law with the material's ior
 *     (the index entered over the index left, which the path tracer finds from the media it is
 *     in, as the Whitted tracer does), tinted by the filter, with
 *     no Fresnel reflection and total internal reflection turned into an untinted mirror, as
 *     in {@link WhittedIntegrator}; {@code fresnel} set instead gives a smooth
 *     {@link DielectricBsdf} (exact Fresnel in place of the thesis's Schlick).</li>
 * </ul>
 * The Whitted tracer lets kd + ks + kr + kt exceed 1; here the four weights are scaled down by
 * the same factor when their sum exceeds 1, so the material never creates energy (colour and
 * filter are clamped to [0,1] for the same reason). Emission is not a BSDF and stays with the
 * caller. Lobes are picked with probability proportional to weight times the lobe's mean tint.
 */
public final class WhittedMaterialBsdf extends MixtureBsdf {
    private final double glossAlpha;
    private final double scale;

    private WhittedMaterialBsdf(double r, double g, double b, double kd, double ks, double shininess,
            double kr, double kt, double ior, double fr, double fg, double fb, boolean fresnel) {
        // The same lobe set SurfaceBsdf re-parameterises per hit, set once: one code path for both.
        WhittedLobes lobes = new WhittedLobes();
        lobes.set(r, g, b, kd, ks, shininess, kr, kt, ior, fr, fg, fb, fresnel);
        glossAlpha = lobes.glossAlpha();
        scale = lobes.scale();
        mixture = lobes.mixture;
    }

    /**
     * The BSDF for the Whitted terms at a hit (textures already applied).
     *
     * @param r red surface colour
     * @param g green surface colour
     * @param b blue surface colour
     * @param kd diffuse coefficient
     * @param ks specular (highlight) coefficient
     * @param shininess Phong exponent, at least 0
     * @param kr mirror reflection coefficient
     * @param kt transmission coefficient
     * @param ior index of refraction inside over outside
     * @param fr red transmission filter
     * @param fg green transmission filter
     * @param fb blue transmission filter
     * @param fresnel whether the material splits transmission by Fresnel reflectance
     * @return the equivalent BSDF
     */
    public static WhittedMaterialBsdf fromWhittedTerms(double r, double g, double b, double kd, double ks, double shininess,
            double kr, double kt, double ior, double fr, double fg, double fb, boolean fresnel) {
        return new WhittedMaterialBsdf(r, g, b, kd, ks, shininess, kr, kt, ior, fr, fg, fb, fresnel);
    }

    /**
     * The BSDF for a material's terms at a hit whose textures have given the colour and the
     * ks, kr and kt there ({@link WhittedIntegrator} reads them per hit the same way).
     *
     * @param m the material (kd, shininess, ior, filter and the Fresnel switch come from it)
     * @param r red surface colour at the hit
     * @param g green surface colour at the hit
     * @param b blue surface colour at the hit
     * @param ks specular coefficient at the hit
     * @param kr mirror coefficient at the hit
     * @param kt transmission coefficient at the hit
     * @return the equivalent BSDF
     */
    public static WhittedMaterialBsdf fromMaterial(Material m, double r, double g, double b, double ks, double kr, double kt) {
        return new WhittedMaterialBsdf(r, g, b, m.kd(), ks, m.shininess(), kr, kt, m.ior(),
                m.filter().r(), m.filter().g(), m.filter().b(), m.fresnel());
    }

    /**
     * The BSDF for an untextured material.
     *
     * @param m the material
     * @return the equivalent BSDF
     */
    public static WhittedMaterialBsdf fromMaterial(Material m) {
        return fromMaterial(m, m.color().r(), m.color().g(), m.color().b(), m.ks(), m.kr(), m.kt());
    }

    /** {@return the GGX alpha matching Phong exponent n}: sqrt(2 / (n + 2)), 1 for n &lt;= 0. */
    public static double glossAlpha(double shininess) {
        return Math.sqrt(2 / (Math.max(0, shininess) + 2));
    }

    /** {@return the GGX alpha of the glossy lobe} */
    public double glossyAlpha() { return glossAlpha; }

    /** {@return the factor all four weights were multiplied by: 1, or 1 / (kd + ks + kr + kt) when that sum exceeds 1} */
    public double weightScale() { return scale; }
}
