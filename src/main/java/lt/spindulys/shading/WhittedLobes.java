package lt.spindulys.shading;

/**
 * The lobes of {@link WhittedMaterialBsdf}, allocated once and re-parameterised in place by
 * {@link #set}: the immutable BSDF sets a fresh instance once, {@link SurfaceBsdf} keeps one per
 * thread and sets it per hit, so both run the same code and agree bit for bit. Not thread-safe.
 */
final class WhittedLobes implements LobeMixture.Estimator {
    private final LambertBsdf diffuse = new LambertBsdf(0, 0, 0);
    private final ConductorBsdf gloss = new ConductorBsdf(1, 1, 1, 1);
    private final ConductorBsdf mirror = new ConductorBsdf(1, 1, 1, 0);
    // Both transmission lobes are kept so that switching the Fresnel flag between hits allocates nothing.
    private final PerfectRefractionLobe refraction = new PerfectRefractionLobe(1, 1, 1, 1);
    private final DielectricBsdf fresnelRefraction = new DielectricBsdf(1, 0, 1, 1, 1);
    /** Fixed lobe selection estimates, one per lobe (they do not depend on wo). */
    private final double[] selection = new double[4];
    /** The configured mixture: diffuse, gloss, mirror, transmission; all weights zero until {@link #set}. */
    final LobeMixture mixture = new LobeMixture(
            new Bsdf[] {diffuse, gloss, mirror, refraction}, new double[4], this);
    private double glossAlpha;
    private double scale = 1;

    /**
     * Configures the lobes for these terms, as {@link WhittedMaterialBsdf#fromWhittedTerms}
     * documents. A bad index of refraction throws before anything changes.
     */
    void set(double r, double g, double b, double kd, double ks, double shininess,
            double kr, double kt, double ior, double fr, double fg, double fb, boolean fresnel) {
        kd = Math.max(0, kd); ks = Math.max(0, ks); kr = Math.max(0, kr); kt = Math.max(0, kt);
        double sum = kd + ks + kr + kt;
        double scale = sum > 1 ? 1 / sum : 1;
        r = clamp(r); g = clamp(g); b = clamp(b);
        fr = clamp(fr); fg = clamp(fg); fb = clamp(fb);
        // The transmission lobe first: it is the one that can reject its arguments.
        Bsdf transmission;
        if (fresnel) {
            fresnelRefraction.set(ior, 0, fr, fg, fb);
            transmission = fresnelRefraction;
        } else {
            refraction.set(ior, fr, fg, fb);
            transmission = refraction;
        }
        this.scale = scale;
        glossAlpha = WhittedMaterialBsdf.glossAlpha(shininess);
        diffuse.set(r, g, b);
        gloss.set(1, 1, 1, Math.sqrt(glossAlpha)); // alpha = roughness^2
        double wd = kd * scale, ws = ks * scale, wr = kr * scale, wt = kt * scale;
        mixture.set(0, diffuse, wd);
        mixture.set(1, gloss, ws);
        mixture.set(2, mirror, wr);
        mixture.set(3, transmission, wt);
        mixture.update();
        // Fixed selection: weight times the lobe's mean tint, floored so a black-tinted but weighted lobe is still reachable.
        double meanColour = (r + g + b) / 3, meanFilter = (fr + fg + fb) / 3;
        selection[0] = wd * Math.max(0.02, meanColour);
        selection[1] = ws;
        selection[2] = wr;
        selection[3] = wt * Math.max(0.02, fresnel ? Math.max(0.1, meanFilter) : meanFilter);
    }

    @Override
    public double estimate(int lobe, double wox, double woy, double woz) { return selection[lobe]; }

    /** {@return the GGX alpha of the glossy lobe} */
    double glossAlpha() { return glossAlpha; }

    /** {@return the factor all four weights were multiplied by} */
    double scale() { return scale; }

    private static double clamp(double v) { return Math.min(1, Math.max(0, v)); }
}
