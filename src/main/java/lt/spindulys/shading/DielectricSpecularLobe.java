package lt.spindulys.shading;

/**
 * The specular coat of an opaque dielectric (plastic, paint): GGX reflection weighted by the exact
 * dielectric Fresnel reflectance F(|wo.wm|, ior), untinted, with no transmitted lobe: the light
 * Fresnel lets through is what {@link FresnelDiffuseLobe} scatters. Two-sided like
 * {@link LambertBsdf}: a wo below the surface sees the same coat mirrored. Effectively smooth
 * roughness gives a delta mirror lobe of weight F(|cos wo|).
 */
final class DielectricSpecularLobe implements Bsdf {
    // Not final only so that SurfaceBsdf can re-parameterise its own instance (set).
    private double ior;
    private final MicrofacetDistribution distribution = new MicrofacetDistribution(1);
    private boolean smooth;

    DielectricSpecularLobe(double ior, double roughness) {
        set(ior, roughness);
    }

    /** Re-parameterises in place, exactly as the constructor does. */
    void set(double ior, double roughness) {
        this.ior = ior;
        distribution.setRoughness(roughness);
        smooth = distribution.isEffectivelySmooth();
    }

    @Override
    public boolean isSpecular() { return smooth; }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0;
        if (smooth) return;
        double common = distribution.reflection(wox, woy, woz, wix, wiy, wiz, rgbOut); // |wo . h| in rgbOut[0]
        if (common == 0) return;
        double f = common * DielectricBsdf.fresnel(rgbOut[0], ior);
        rgbOut[0] = 0;
        if (!(f > 0) || Double.isInfinite(f)) return;
        rgbOut[0] = f; rgbOut[1] = f; rgbOut[2] = f;
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        if (smooth) return 0;
        double pdf = distribution.reflectionPdf(wox, woy, woz, wix, wiy, wiz);
        return pdf > 0 && Double.isFinite(pdf) ? pdf : 0;
    }


    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        out.clear();
        if (woz == 0) return false;
        if (smooth) {
            double fresnel = DielectricBsdf.fresnel(Math.abs(woz), ior);
            if (!(fresnel > 0)) return false;
            double f = fresnel / Math.abs(woz);
            out.wix = -wox; out.wiy = -woy; out.wiz = woz;
            out.f[0] = f; out.f[1] = f; out.f[2] = f;
            out.pdf = 1;
            out.specular = true;
            return true;
        }
        double[] wm = out.microNormal;
        distribution.sampleVisibleNormal(wox, woy, woz, u1, u2, wm);
        double k = 2 * (wox * wm[0] + woy * wm[1] + woz * wm[2]);
        double wix = k * wm[0] - wox, wiy = k * wm[1] - woy, wiz = k * wm[2] - woz;
        if (!(woz * wiz > 0)) return false;
        double pdf = pdf(wox, woy, woz, wix, wiy, wiz);
        if (!(pdf > 0)) return false;
        eval(wox, woy, woz, wix, wiy, wiz, out.f);
        out.wix = wix; out.wiy = wiy; out.wiz = wiz;
        out.pdf = pdf;
        return true;
    }
}
