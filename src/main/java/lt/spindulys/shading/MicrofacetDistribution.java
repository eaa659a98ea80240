package lt.spindulys.shading;

/**
 * The isotropic GGX (Trowbridge-Reitz) microfacet distribution with the height-correlated Smith
 * masking-shadowing term and sampling of the visible normals (Heitz 2018, "Sampling the GGX
 * Distribution of Visible Normals", JCGT 7(4)). Directions are in the local shading frame, unit
 * length; microfacet normals wm have wm.z &gt; 0.
 *
 * <p>Immutable to other packages; inside this one a per-thread {@link SurfaceBsdf} resets the
 * width of its own instances per hit, which is why the fields are not final.
 */
public final class MicrofacetDistribution {
    /** Smallest alpha kept, so that D and Lambda stay finite and free of 0/0. */
    public static final double MIN_ALPHA = 1e-4;
    /** Below this alpha the surface is treated as a delta (mirror or smooth refraction). */
    public static final double SMOOTH_ALPHA = 1e-3;

    private double alpha;
    private double alpha2;

    /**
     * A distribution of the given width.
     *
     * @param alpha GGX alpha, clamped to at least {@link #MIN_ALPHA}
     */
    public MicrofacetDistribution(double alpha) {
        set(alpha);
    }

    /** Re-parameterises in place, exactly as the constructor does (for the per-thread reusable BSDF). */
    void set(double alpha) {
        this.alpha = Math.max(MIN_ALPHA, alpha);
        this.alpha2 = this.alpha * this.alpha;
    }

    /** Re-parameterises in place, exactly as {@link #fromRoughness} does. */
    void setRoughness(double roughness) {
        set(roughness * roughness);
    }

    /**
     * A distribution from artist roughness, alpha = roughness squared (Burley 2012, as Cycles).
     *
     * @param roughness perceptual roughness in [0,1]
     * @return the distribution
     */
    public static MicrofacetDistribution fromRoughness(double roughness) {
        return new MicrofacetDistribution(roughness * roughness);
    }

    /** {@return the (clamped) GGX alpha} */
    public double alpha() { return alpha; }

    /** {@return whether alpha is so small that the surface should be treated as perfectly smooth} */
    public boolean isEffectivelySmooth() { return alpha < SMOOTH_ALPHA; }

    /**
     * {@return the normal distribution D(wm)}: density of microfacet normals per unit solid angle
     * and unit projected macro-surface area. Zero below the horizon.
     */
    public double d(double wmx, double wmy, double wmz) {
        if (wmz <= 0) return 0;
        // For a unit wm, alpha^2 cos^4 (1 + tan^2/alpha^2)^2 = (sin^2/alpha^2 + cos^2)^2 alpha^2:
        // no division by cos, finite at the horizon.
        double t = (wmx * wmx + wmy * wmy) / alpha2 + wmz * wmz;
        return 1 / (Math.PI * alpha2 * t * t);
    }

    /** {@return Smith's Lambda(w)}: 0 at normal incidence, growing towards grazing; infinite at cos 0. */
    public double lambda(double wx, double wy, double wz) {
        double cos2 = wz * wz;
        if (cos2 == 0) return Double.POSITIVE_INFINITY;
        double alpha2Tan2 = alpha2 * (wx * wx + wy * wy) / cos2;
        // sqrt(1+x)-1 written as x/(sqrt(1+x)+1) keeps precision when x is tiny.
        return 0.5 * alpha2Tan2 / (Math.sqrt(1 + alpha2Tan2) + 1);
    }

    /** {@return the masking term G1(w) = 1 / (1 + Lambda(w))}, 0 at grazing. */
    public double g1(double wx, double wy, double wz) {
        return 1 / (1 + lambda(wx, wy, wz));
    }

    /** {@return the height-correlated masking-shadowing G(wo, wi) = 1 / (1 + Lambda(wo) + Lambda(wi))} */
    public double g(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return 1 / (1 + lambda(wox, woy, woz) + lambda(wix, wiy, wiz));
    }

    /**
     * {@return the density of visible normals D_w(wm) = G1(w) / |cos w| * D(wm) * max(0, w.wm)},
     * the solid-angle density of {@link #sampleVisibleNormal}'s output; 0 when w is on the horizon.
     * As in sampling, a w below the horizon stands for its opposite.
     */
    public double visibleNormalPdf(double wx, double wy, double wz, double wmx, double wmy, double wmz) {
        double cos = Math.abs(wz);
        if (cos == 0) return 0;
        double facing = (wx * wmx + wy * wmy + wz * wmz) * Math.signum(wz);
        if (!(facing > 0)) return 0; // w sees the back of such a microfacet
        double d = d(wmx, wmy, wmz);
        if (d == 0) return 0;
        return g1(wx, wy, wz) / cos * d * facing;
    }

    /**
     * What scales wo + wi to the unit half vector on the +z side: 0 when wo and wi lie on
     * different sides or their sum vanishes (the half vector is then undefined).
     */
    private static double halfScale(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        if (!(woz * wiz > 0)) return 0;
        double hx = wox + wix, hy = woy + wiy, hz = woz + wiz;
        double len2 = hx * hx + hy * hy + hz * hz;
        return len2 > 0 ? (hz < 0 ? -1 : 1) / Math.sqrt(len2) : 0;
    }

    /**
     * The single-scattering GGX reflection term D(h) G(wo, wi) / (4 |cos wo| |cos wi|) for wo and
     * wi on the same side, h their half vector, without the Fresnel factor, which the caller
     * applies at |wo . h|, written to {@code cosHalf[0]}.
     *
     * @param cosHalf receives |wo . h| in its first entry (left alone when the term is 0)
     * @return the term, 0 when wo and wi lie on different sides or h is undefined
     */
    double reflection(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] cosHalf) {
        double inv = halfScale(wox, woy, woz, wix, wiy, wiz);
        if (inv == 0) return 0;
        double hx = (wox + wix) * inv, hy = (woy + wiy) * inv, hz = (woz + wiz) * inv;
        double d = d(hx, hy, hz);
        if (d == 0) return 0;
        cosHalf[0] = Math.abs(wox * hx + woy * hy + woz * hz);
        return d * g(wox, woy, woz, wix, wiy, wiz) / (4 * Math.abs(woz) * Math.abs(wiz));
    }

    /**
     * The density of a reflection lobe that draws a visible normal and mirrors wo about it: the
     * visible-normal density of the half vector of wo and wi times the Jacobian 1 / (4 |wo.wm|)
     * of the mirroring. 0 unless wo and wi lie on the same side, and where the half vector is
     * undefined or on the horizon of wo.
     */
    public double reflectionPdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        double inv = halfScale(wox, woy, woz, wix, wiy, wiz);
        if (inv == 0) return 0;
        double hx = (wox + wix) * inv, hy = (woy + wiy) * inv, hz = (woz + wiz) * inv;
        double cosOM = Math.abs(wox * hx + woy * hy + woz * hz);
        if (cosOM == 0) return 0;
        return visibleNormalPdf(wox, woy, woz, hx, hy, hz) / (4 * cosOM);
    }

    /**
     * Draws a microfacet normal visible from w, with density {@link #visibleNormalPdf}. A w below
     * the horizon is treated as its opposite, so the normal is always in the upper hemisphere.
     *
     * @param u1 first uniform in [0,1)
     * @param u2 second uniform in [0,1)
     * @param wmOut receives the unit normal, wmOut[2] &gt; 0
     */
    public void sampleVisibleNormal(double wx, double wy, double wz, double u1, double u2, double[] wmOut) {
        // Stretch w into the configuration where the distribution is the unit hemisphere.
        double hx = alpha * wx, hy = alpha * wy, hz = wz;
        double hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
        hx /= hl; hy /= hl; hz /= hl;
        if (hz < 0) { hx = -hx; hy = -hy; hz = -hz; }
        // Frame around the stretched view direction (t1 horizontal).
        double lenSq = hx * hx + hy * hy;
        double t1x, t1y;
        if (lenSq > 0) {
            double inv = 1 / Math.sqrt(lenSq);
            t1x = -hy * inv; t1y = hx * inv;
        } else {
            t1x = 1; t1y = 0;
        }
        // t2 = h x t1 (t1.z = 0)
        double t2x = -hz * t1y, t2y = hz * t1x, t2z = hx * t1y - hy * t1x;
        // A uniform disk point, squeezed onto the part of the disk the visible hemisphere projects to.
        double r = Math.sqrt(u1), phi = 2 * Math.PI * u2;
        double p1 = r * Math.cos(phi), p2 = r * Math.sin(phi);
        double s = 0.5 * (1 + hz);
        p2 = (1 - s) * Math.sqrt(Math.max(0, 1 - p1 * p1)) + s * p2;
        double pz = Math.sqrt(Math.max(0, 1 - p1 * p1 - p2 * p2));
        double nx = p1 * t1x + p2 * t2x + pz * hx;
        double ny = p1 * t1y + p2 * t2y + pz * hy;
        double nz = p2 * t2z + pz * hz;
        // Unstretch; the floor keeps the normal strictly above the horizon.
        double mx = alpha * nx, my = alpha * ny, mz = Math.max(1e-6, nz);
        double ml = Math.sqrt(mx * mx + my * my + mz * mz);
        wmOut[0] = mx / ml; wmOut[1] = my / ml; wmOut[2] = mz / ml;
    }
}
