package lt.spindulys.shading;

import java.util.Arrays;

/**
 * The lobes of {@link PrincipledBsdf}, allocated once and re-parameterised in place by
 * {@link #set}: the immutable BSDF sets a fresh instance once, {@link SurfaceBsdf} keeps one per
 * thread and sets it per hit, so both run the same code and agree bit for bit. Not thread-safe.
 *
 * <p>The diffuse base's F_avg (160 Fresnel evaluations) is the one costly parameter. It is kept
 * in a small direct-mapped cache keyed by the coat's index, rather than tabulated: a table would
 * interpolate and so differ from a fresh construction in the last bits, while the cache returns
 * exactly the value computed for that index. Several entries rather than just the last index,
 * because a path alternates between materials (a glass of 1.5 on a floor of 1.33 would miss a
 * one-entry cache at every bounce); in a scene with few distinct indices it practically always hits.
 */
final class PrincipledLobes implements LobeMixture.Estimator {
    private static final int METAL = 0, GLASS = 1, COAT = 2, DIFFUSE = 3;
    /** Floor of the metal and glass estimates relative to their weight, so a lobe that can contribute is never starved. */
    private static final double MIN_ESTIMATE = 0.02;
    /** Entries of the F_avg cache, a power of two. */
    private static final int CACHE_SIZE = 8;

    private final ConductorBsdf metal = new ConductorBsdf(1, 1, 1, 1);
    private final DielectricBsdf glass = new DielectricBsdf(1.5, 1, 1, 1, 1);
    private final DielectricSpecularLobe coat = new DielectricSpecularLobe(1.5, 1);
    private final FresnelDiffuseLobe diffuse = new FresnelDiffuseLobe(1, 1, 1, 1.5);
    /** The configured mixture: metal, glass, coat, diffuse; all weights zero until {@link #set}. */
    final LobeMixture mixture = new LobeMixture(
            new Bsdf[] {metal, glass, coat, diffuse}, new double[4], this);
    private double metallic, transmission, ior, meanBase;
    /** The coat's index, at least 1: see {@link PrincipledBsdf}. */
    private double coatIor = 1.5;
    // NaN keys never match, so an empty entry is simply a miss.
    private final double[] cachedIor = new double[CACHE_SIZE];
    private final double[] cachedAverage = new double[CACHE_SIZE];

    PrincipledLobes() {
        Arrays.fill(cachedIor, Double.NaN);
    }

    /**
     * Configures the lobes, as {@link PrincipledBsdf}'s constructor documents; arguments out of
     * range throw before anything changes.
     */
    void set(double baseR, double baseG, double baseB, double metallic, double roughness, double ior, double transmission) {
        DielectricBsdf.checkIor(ior);
        check("metallic", metallic);
        check("roughness", roughness);
        check("transmission", transmission);
        this.metallic = metallic; this.ior = ior; this.transmission = transmission;
        meanBase = (baseR + baseG + baseB) / 3;
        double rest = (1 - metallic) * (1 - transmission);
        coatIor = ior >= 1 ? ior : 1 / ior;
        metal.set(baseR, baseG, baseB, roughness);
        glass.set(ior, roughness, baseR, baseG, baseB);
        coat.set(coatIor, roughness);
        if (coat.isSpecular()) diffuse.set(baseR, baseG, baseB, coatIor, averageFresnel(coatIor));
        else diffuse.setUnderRoughCoat(baseR, baseG, baseB, coatIor, roughness * roughness);
        mixture.set(METAL, metal, metallic);
        mixture.set(GLASS, glass, (1 - metallic) * transmission);
        mixture.set(COAT, coat, rest);
        mixture.set(DIFFUSE, diffuse, rest);
        mixture.update();
    }

    /** {@return FresnelDiffuseLobe.averageFresnel(ior)}, from the cache when this index was seen recently. */
    private double averageFresnel(double ior) {
        long bits = Double.doubleToLongBits(ior);
        int slot = (int) ((bits * 0x9E3779B97F4A7C15L) >>> (64 - Integer.numberOfTrailingZeros(CACHE_SIZE)));
        if (cachedIor[slot] == ior) return cachedAverage[slot];
        double average = FresnelDiffuseLobe.averageFresnel(ior);
        cachedIor[slot] = ior;
        cachedAverage[slot] = average;
        return average;
    }

    private static void check(String name, double v) {
        if (!(v >= 0 && v <= 1)) throw new IllegalArgumentException(name + " must be in [0,1]: " + v);
    }

    /** Lobe selection estimate (unnormalised; {@link LobeMixture} divides by the sum). */
    @Override
    public double estimate(int lobe, double wox, double woy, double woz) {
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
}
