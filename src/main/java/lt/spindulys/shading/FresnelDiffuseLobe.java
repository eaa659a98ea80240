package lt.spindulys.shading;

/**
 * The diffuse base under a {@link DielectricSpecularLobe} coat: Lambert reflection of the base
 * colour, of the light the coat's Fresnel lets in and lets back out,
 * f = c / pi * (1 - F(|cos wo|)) * (1 - F(|cos wi|)) / (1 - F_avg), with F the smooth-interface
 * dielectric Fresnel reflectance of the coat's index and F_avg = 2 int_0^1 F(mu) mu dmu its
 * cosine-weighted hemispherical average.
 *
 * <p>Why this form: it is symmetric in wo and wi, so reciprocal; and the normalisation makes its
 * albedo exactly c (1 - F(|cos wo|)), since int (1 - F(cos wi)) cos wi dwi / pi = 1 - F_avg. The
 * coat above reflects exactly F(|cos wo|) when smooth, so a smooth coat plus a white base is
 * exactly 1. A rough single-scattering GGX coat reflects less than F (masking loses energy and
 * the microfacets wo sees are on average less grazing: 3 % of the light at roughness 1), so
 * under a rough coat F is replaced by the coat's own tabulated albedo E
 * ({@link #setUnderRoughCoat}): what the coat does not reflect, the base receives, and a white
 * principled surface again reflects everything, to the table's accuracy. The coat's index is at
 * least 1 ({@link PrincipledBsdf}); above the table's 3 it is clamped.
 * Sampled with the cosine-weighted hemisphere on wo's side; two-sided.
 */
final class FresnelDiffuseLobe implements Bsdf {
    // Not final only so that SurfaceBsdf can re-parameterise its own instance (set).
    private double ior;
    private double fr, fg, fb;
    /** Whether the coat is rough: then 1 - E of the coat's albedo table replaces 1 - F. */
    private boolean roughCoat;
    private double coatAlpha, coatIndexCoord, coatRoughnessCoord;

    FresnelDiffuseLobe(double r, double g, double b, double ior) {
        set(r, g, b, ior, averageFresnel(ior));
    }

    /**
     * Re-parameterises in place, as the constructor does, with F_avg passed in: it costs 160
     * Fresnel evaluations, too many per hit, so a reusable caller keeps it from earlier hits.
     *
     * @param averageFresnel {@link #averageFresnel}(ior), exactly
     */
    void set(double r, double g, double b, double ior, double averageFresnel) {
        this.ior = ior;
        roughCoat = false;
        scale(r, g, b, 1 - averageFresnel);
    }

    /**
     * Re-parameterises under a rough coat of the given GGX alpha: the base takes 1 - E(|cos|)
     * on either side, E the coat's tabulated albedo ({@link MicrofacetAlbedo}), normalised by
     * 1 - E_avg, so the coat and a white base add up to 1 whatever the coat loses to single
     * scattering, and f stays symmetric.
     */
    void setUnderRoughCoat(double r, double g, double b, double ior, double alpha) {
        this.ior = ior;
        roughCoat = true;
        coatAlpha = alpha;
        coatIndexCoord = MicrofacetAlbedo.indexCoordinate(MicrofacetAlbedo.COAT, ior);
        coatRoughnessCoord = MicrofacetAlbedo.roughnessCoordinate(alpha);
        scale(r, g, b, 1 - MicrofacetAlbedo.coatAverage(coatIndexCoord, coatRoughnessCoord));
    }

    private void scale(double r, double g, double b, double transmitted) {
        // When almost nothing crosses the coat there is nothing to scatter: no diffuse at all rather than 0/0.
        double scale = transmitted > 1e-12 ? 1 / (Math.PI * transmitted) : 0;
        fr = r * scale; fg = g * scale; fb = b * scale;
    }

    /**
     * {@return F_avg = 2 int_0^1 F(mu, ior) mu dmu}, by five-point Gauss-Legendre on 32 panels:
     * F is smooth for ior &gt; 1; for ior &lt; 1 its kink at the critical angle costs well under 1e-4.
     */
    static double averageFresnel(double ior) {
        final int panels = 32;
        double h = 1.0 / panels, sum = 0;
        for (int p = 0; p < panels; p++) {
            double mid = (p + 0.5) * h;
            for (int i = 0; i < GAUSS_NODES.length; i++) {
                double mu = mid + 0.5 * h * GAUSS_NODES[i];
                sum += GAUSS_WEIGHTS[i] * DielectricBsdf.fresnel(mu, ior) * mu;
            }
        }
        return 2 * sum * 0.5 * h;
    }

    private static final double[] GAUSS_NODES = {
        -0.9061798459386640, -0.5384693101056831, 0, 0.5384693101056831, 0.9061798459386640};
    private static final double[] GAUSS_WEIGHTS = {
        0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665, 0.2369268850561891};

    @Override
    public boolean isSpecular() { return false; }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        if (!(woz * wiz > 0)) { rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0; return; }
        double t = transmitted(woz) * transmitted(wiz);
        rgbOut[0] = fr * t; rgbOut[1] = fg * t; rgbOut[2] = fb * t;
    }

    /** {@return what the coat lets through at cosine cos}: 1 - F, or 1 - E under a rough coat. */
    private double transmitted(double cos) {
        if (!roughCoat) return 1 - DielectricBsdf.fresnel(Math.abs(cos), ior);
        return 1 - MicrofacetAlbedo.lookup(MicrofacetAlbedo.COAT, coatIndexCoord, coatRoughnessCoord,
                MicrofacetAlbedo.muCoordinate(cos, coatAlpha));
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return woz * wiz > 0 ? Math.abs(wiz) / Math.PI : 0;
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        if (!LambertBsdf.sampleCosine(woz, u1, u2, out)) return false;
        eval(wox, woy, woz, out.wix, out.wiy, out.wiz, out.f);
        return true;
    }
}
