package lt.spindulys.shading;

import lt.spindulys.math.Color;

/**
 * A metal: GGX microfacet reflection with Schlick's Fresnel from the base colour as the
 * reflectance at normal incidence, F = F0 + (1 - F0)(1 - cos)^5 with cos = |wo.wm|. An effectively
 * smooth surface (see {@link MicrofacetDistribution#isEffectivelySmooth}) is a perfect mirror,
 * a delta lobe; a rough one is f = D F G / (4 |cos wo| |cos wi|), sampled by drawing a visible
 * normal and reflecting wo about it. Reflection only, on wo's side of the surface.
 */
public final class ConductorBsdf implements Bsdf {
    // Not final only so that SurfaceBsdf can re-parameterise its own instance (set); public users cannot.
    private double f0r, f0g, f0b;
    private final MicrofacetDistribution distribution = new MicrofacetDistribution(1);
    private boolean smooth;

    /**
     * A metal.
     *
     * @param r red reflectance at normal incidence, in [0,1]
     * @param g green reflectance at normal incidence
     * @param b blue reflectance at normal incidence
     * @param roughness perceptual roughness in [0,1] (alpha = roughness squared)
     */
    public ConductorBsdf(double r, double g, double b, double roughness) {
        set(r, g, b, roughness);
    }

    /** Re-parameterises in place, exactly as the constructor does. */
    void set(double r, double g, double b, double roughness) {
        f0r = r; f0g = g; f0b = b;
        distribution.setRoughness(roughness);
        smooth = distribution.isEffectivelySmooth();
    }

    /**
     * A metal.
     *
     * @param baseColor reflectance at normal incidence
     * @param roughness perceptual roughness in [0,1]
     */
    public ConductorBsdf(Color baseColor, double roughness) {
        this(baseColor.r(), baseColor.g(), baseColor.b(), roughness);
    }

    /** {@return the microfacet distribution} */
    public MicrofacetDistribution distribution() { return distribution; }

    @Override
    public boolean isSpecular() { return smooth; }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0;
        if (smooth) return;
        double common = distribution.reflection(wox, woy, woz, wix, wiy, wiz, rgbOut); // |wo . h| in rgbOut[0]
        if (common == 0) return;
        double schlick = schlickWeight(rgbOut[0]);
        rgbOut[0] = common * (f0r + (1 - f0r) * schlick);
        rgbOut[1] = common * (f0g + (1 - f0g) * schlick);
        rgbOut[2] = common * (f0b + (1 - f0b) * schlick);
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return smooth ? 0 : distribution.reflectionPdf(wox, woy, woz, wix, wiy, wiz);
    }


    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        out.clear();
        if (woz == 0) return false;
        if (smooth) {
            double schlick = schlickWeight(Math.abs(woz));
            double inv = 1 / Math.abs(woz);
            out.wix = -wox; out.wiy = -woy; out.wiz = woz;
            out.f[0] = (f0r + (1 - f0r) * schlick) * inv;
            out.f[1] = (f0g + (1 - f0g) * schlick) * inv;
            out.f[2] = (f0b + (1 - f0b) * schlick) * inv;
            out.pdf = 1;
            out.specular = true;
            return true;
        }
        double[] wm = out.microNormal;
        distribution.sampleVisibleNormal(wox, woy, woz, u1, u2, wm);
        double k = 2 * (wox * wm[0] + woy * wm[1] + woz * wm[2]);
        double wix = k * wm[0] - wox, wiy = k * wm[1] - woy, wiz = k * wm[2] - woz;
        if (!(woz * wiz > 0)) return false; // reflected through the surface: shadowed
        // Evaluating through eval and pdf keeps the sample bit-for-bit consistent with them.
        double pdf = pdf(wox, woy, woz, wix, wiy, wiz);
        if (!(pdf > 0) || Double.isInfinite(pdf)) return false;
        eval(wox, woy, woz, wix, wiy, wiz, out.f);
        out.wix = wix; out.wiy = wiy; out.wiz = wiz;
        out.pdf = pdf;
        return true;
    }

    /** (1 - cos)^5, Schlick's interpolation weight between F0 and 1. */
    private static double schlickWeight(double cos) {
        double m = Math.max(0, 1 - cos), m2 = m * m;
        return m2 * m2 * m;
    }
}
