package lt.spindulys.shading;

/**
 * The Whitted tracer's refraction as a delta lobe: all of the light is refracted by Snell's law,
 * with no Fresnel reflection (the thesis applies none unless a material asks for it), tinted by
 * the filter; under total internal reflection it is mirrored untinted instead, as
 * {@link WhittedIntegrator} hands the transmitted share to the reflection. Like
 * {@link DielectricBsdf} the transmitted f is divided by eta'^2 (radiance is compressed into the
 * denser medium) and the sample reports eta'; entering and leaving a closed object cancel, so a
 * path tracer sees through it what the Whitted tracer does.
 */
final class PerfectRefractionLobe implements Bsdf {
    // Not final only so that SurfaceBsdf can re-parameterise its own instance (set).
    private double eta;
    private double tintR, tintG, tintB;

    PerfectRefractionLobe(double ior, double tintR, double tintG, double tintB) {
        set(ior, tintR, tintG, tintB);
    }

    /** Re-parameterises in place, exactly as the constructor does; on a bad index nothing changes. */
    void set(double ior, double tintR, double tintG, double tintB) {
        DielectricBsdf.checkIor(ior);
        eta = ior;
        this.tintR = tintR; this.tintG = tintG; this.tintB = tintB;
    }

    @Override
    public boolean isSpecular() { return true; }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0;
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) { return 0; }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        out.clear();
        if (woz == 0) return false;
        double cos = woz, nz = 1, etap = eta;
        if (cos < 0) { etap = 1 / eta; cos = -cos; nz = -1; }
        double sin2T = (1 - cos * cos) / (etap * etap);
        out.specular = true;
        out.pdf = 1;
        if (sin2T >= 1) {
            double f = 1 / cos;
            out.wix = -wox; out.wiy = -woy; out.wiz = woz;
            out.f[0] = f; out.f[1] = f; out.f[2] = f;
            return true;
        }
        double cosT = Math.sqrt(1 - sin2T);
        out.wix = -wox / etap;
        out.wiy = -woy / etap;
        out.wiz = -woz / etap + (cos / etap - cosT) * nz;
        double f = 1 / (cosT * etap * etap);
        out.f[0] = f * tintR; out.f[1] = f * tintG; out.f[2] = f * tintB;
        out.eta = etap;
        return true;
    }
}
