package lt.spindulys.shading;

import lt.spindulys.math.Color;

/**
 * Ideal diffuse reflection: f = albedo / pi on wo's side of the surface, sampled with a cosine
 * weighted hemisphere there, so every sample's weight f |cos wi| / pdf is exactly the albedo.
 */
public final class LambertBsdf implements Bsdf {
    // Not final only so that SurfaceBsdf can re-parameterise its own instance (set); public users cannot.
    private double fr, fg, fb;

    /**
     * A Lambertian reflector.
     *
     * @param r red albedo (reflected fraction, normally in [0,1])
     * @param g green albedo
     * @param b blue albedo
     */
    public LambertBsdf(double r, double g, double b) {
        set(r, g, b);
    }

    /** Re-parameterises in place, exactly as the constructor does. */
    void set(double r, double g, double b) {
        fr = r / Math.PI;
        fg = g / Math.PI;
        fb = b / Math.PI;
    }

    /**
     * A Lambertian reflector.
     *
     * @param albedo reflected fraction per channel
     */
    public LambertBsdf(Color albedo) { this(albedo.r(), albedo.g(), albedo.b()); }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        if (woz * wiz > 0) {
            rgbOut[0] = fr; rgbOut[1] = fg; rgbOut[2] = fb;
        } else {
            rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0;
        }
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return woz * wiz > 0 ? Math.abs(wiz) / Math.PI : 0;
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        if (!sampleCosine(woz, u1, u2, out)) return false;
        out.f[0] = fr; out.f[1] = fg; out.f[2] = fb;
        return true;
    }

    /**
     * A cosine-distributed direction on wo's side into out (wi and pdf; f left zero), shared by
     * the diffuse lobes: a uniform disk point projected up onto the hemisphere (Malley).
     *
     * @return false (out cleared) when wo lies in the surface or the point falls on the horizon
     */
    static boolean sampleCosine(double woz, double u1, double u2, BsdfSample out) {
        out.clear();
        if (woz == 0) return false;
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double z = Math.sqrt(Math.max(0, 1 - u1));
        if (z == 0) return false; // zero density on the horizon
        // One cosine and a square root instead of two trigonometric calls (a path's every
        // diffuse bounce pays for them); the sine is positive for phi below pi.
        double cos = Math.cos(phi), sin = Math.sqrt(Math.max(0, 1 - cos * cos));
        out.wix = r * cos;
        out.wiy = r * (u2 < 0.5 ? sin : -sin);
        out.wiz = woz > 0 ? z : -z;
        out.pdf = z / Math.PI;
        return true;
    }

    @Override
    public boolean isSpecular() { return false; }
}
