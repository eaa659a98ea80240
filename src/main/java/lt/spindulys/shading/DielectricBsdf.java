package lt.spindulys.shading;

import lt.spindulys.math.Color;

/**
 * Glass and other dielectric interfaces: reflection and refraction weighted by the exact
 * unpolarised Fresnel reflectance, for wo on either side (the relative index flips when wo is
 * inside, wo.z &lt; 0, and total internal reflection reflects everything).
 *
 * <p>An effectively smooth interface has two delta lobes, chosen with probabilities R and
 * T = 1 - R, so each sample's weight f |cos wi| / pdf is 1 for reflection and tint / eta'^2 for
 * refraction. A rough one is a GGX microfacet interface (Walter et al. 2007) with the generalized
 * half vector; microfacets facing away from wo or wi contribute nothing. Transmission carries
 * radiance, so it is divided by eta'^2 (eta' the index on wi's side over wo's side), and the
 * sample reports eta' so a path tracer can undo that for Russian roulette. The tint applies to
 * transmission only. An index of exactly 1 is an invisible interface: wi = -wo with weight tint.
 *
 * <p>A single-scattering microfacet model loses the light that scatters between microfacets
 * (at roughness 0.3 and index 1.5 about 2 % at cosine 0.3, 8 % at 0.1; far more when rougher),
 * so rough glass would darken in a white furnace. As Cycles does, the rough lobes are therefore
 * divided by the single-scattering directional albedo E(|cos wo|, roughness, eta') of wo's side,
 * tabulated offline ({@link MicrofacetAlbedo}): each interaction then keeps all the energy, to
 * the table's accuracy, neither darkening nor brightening. The pdf is unchanged. The price is
 * reciprocity: f(wo, wi) E(wo) = f(wi, wo) E(wi), not f(wo, wi) = f(wi, wo).
 */
public final class DielectricBsdf implements Bsdf {
    // Not final only so that SurfaceBsdf can re-parameterise its own instance (set); public users cannot.
    private double eta;
    private double tintR, tintG, tintB;
    private final MicrofacetDistribution distribution = new MicrofacetDistribution(1);
    private boolean smooth;
    private boolean passThrough;
    /** Whether the rough lobes are divided by their albedo; only the table's generator turns it off. */
    private final boolean compensated;
    // Table coordinates of the configuration, for wo outside (wo.z > 0) and inside.
    private double roughnessCoord, indexCoordOutside, indexCoordInside;
    private int tableOutside, tableInside;

    /**
     * A dielectric interface.
     *
     * @param ior index of refraction inside (below the surface, z &lt; 0) over outside; positive
     * @param roughness perceptual roughness in [0,1] (alpha = roughness squared)
     * @param tintR red factor on transmitted light
     * @param tintG green factor on transmitted light
     * @param tintB blue factor on transmitted light
     */
    public DielectricBsdf(double ior, double roughness, double tintR, double tintG, double tintB) {
        this(ior, roughness, tintR, tintG, tintB, true);
    }

    private DielectricBsdf(double ior, double roughness, double tintR, double tintG, double tintB, boolean compensated) {
        this.compensated = compensated;
        set(ior, roughness, tintR, tintG, tintB);
    }

    /** The single-scattering interface without the energy compensation: what the albedo table tabulates. */
    static DielectricBsdf uncompensated(double ior, double roughness) {
        return new DielectricBsdf(ior, roughness, 1, 1, 1, false);
    }

    /** Re-parameterises in place, exactly as the constructor does; on a bad index nothing changes. */
    void set(double ior, double roughness, double tintR, double tintG, double tintB) {
        checkIor(ior);
        this.eta = ior;
        this.tintR = tintR; this.tintG = tintG; this.tintB = tintB;
        distribution.setRoughness(roughness);
        smooth = distribution.isEffectivelySmooth();
        passThrough = ior == 1;
        if (compensated && !smooth && !passThrough) {
            roughnessCoord = MicrofacetAlbedo.roughnessCoordinate(distribution.alpha());
            // From outside the relative index is eta, from inside 1/eta; the tables take it as n >= 1.
            tableOutside = eta >= 1 ? MicrofacetAlbedo.GLASS_ENTERING : MicrofacetAlbedo.GLASS_LEAVING;
            tableInside = eta >= 1 ? MicrofacetAlbedo.GLASS_LEAVING : MicrofacetAlbedo.GLASS_ENTERING;
            double n = eta >= 1 ? eta : 1 / eta;
            indexCoordOutside = MicrofacetAlbedo.indexCoordinate(tableOutside, n);
            indexCoordInside = MicrofacetAlbedo.indexCoordinate(tableInside, n);
        }
    }

    /** {@return 1 / E, the energy compensation of the rough lobes for wo at cosine woz} */
    private double compensation(double woz) {
        if (!compensated) return 1;
        double mu = MicrofacetAlbedo.muCoordinate(woz, distribution.alpha());
        double e = woz > 0
                ? MicrofacetAlbedo.lookup(tableOutside, indexCoordOutside, roughnessCoord, mu)
                : MicrofacetAlbedo.lookup(tableInside, indexCoordInside, roughnessCoord, mu);
        return e > 0 ? 1 / e : 1;
    }

    /** Rejects an index of refraction that is not positive and finite (shared by the lobes that refract). */
    static void checkIor(double ior) {
        if (!(ior > 0) || Double.isInfinite(ior)) throw new IllegalArgumentException("index of refraction must be positive and finite: " + ior);
    }

    /**
     * A dielectric interface.
     *
     * @param ior index of refraction inside over outside
     * @param roughness perceptual roughness in [0,1]
     * @param tint factor on transmitted light
     */
    public DielectricBsdf(double ior, double roughness, Color tint) {
        this(ior, roughness, tint.r(), tint.g(), tint.b());
    }

    /** {@return the microfacet distribution} */
    public MicrofacetDistribution distribution() { return distribution; }

    @Override
    public boolean isSpecular() { return smooth || passThrough; }

    /**
     * Unpolarised Fresnel reflectance of a dielectric interface.
     *
     * @param cosI cosine between the incident direction (pointing away from the surface) and
     *             the normal; negative when it comes from the inside
     * @param eta index of the inside over the outside
     * @return the reflected fraction in [0,1], 1 under total internal reflection
     */
    public static double fresnel(double cosI, double eta) {
        cosI = Math.max(-1, Math.min(1, cosI));
        if (cosI < 0) { // seen from inside: the roles of the two media swap
            eta = 1 / eta;
            cosI = -cosI;
        }
        double sin2T = (1 - cosI * cosI) / (eta * eta);
        if (sin2T >= 1) return 1;
        double cosT = Math.sqrt(1 - sin2T);
        double parallel = (eta * cosI - cosT) / (eta * cosI + cosT);
        double perpendicular = (cosI - eta * cosT) / (cosI + eta * cosT);
        return 0.5 * (parallel * parallel + perpendicular * perpendicular);
    }

    @Override
    public void eval(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        evaluate(wox, woy, woz, wix, wiy, wiz, rgbOut);
    }

    @Override
    public double pdf(double wox, double woy, double woz, double wix, double wiy, double wiz) {
        return evaluate(wox, woy, woz, wix, wiy, wiz, null);
    }

    /**
     * The rough lobes: writes f to rgbOut when it is not null and returns the pdf, both zero
     * for delta-only interfaces and degenerate configurations.
     */
    private double evaluate(double wox, double woy, double woz, double wix, double wiy, double wiz, double[] rgbOut) {
        if (rgbOut != null) { rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0; }
        if (smooth || passThrough || woz == 0 || wiz == 0) return 0;
        boolean reflection = woz * wiz > 0;
        double etap = reflection ? 1 : woz > 0 ? eta : 1 / eta;
        // Generalized half vector: the microfacet normal that maps wo to wi, facing outwards.
        double hx = wix * etap + wox, hy = wiy * etap + woy, hz = wiz * etap + woz;
        double len2 = hx * hx + hy * hy + hz * hz;
        if (!(len2 > 0)) return 0;
        double inv = (hz < 0 ? -1 : 1) / Math.sqrt(len2);
        hx *= inv; hy *= inv; hz *= inv;
        double dotO = wox * hx + woy * hy + woz * hz;
        double dotI = wix * hx + wiy * hy + wiz * hz;
        // A microfacet seen from its back by wo or wi cannot scatter between them.
        if (dotO * woz <= 0 || dotI * wiz <= 0) return 0;
        double d = distribution.d(hx, hy, hz);
        if (d == 0) return 0;
        double r = fresnel(dotO, eta), t = 1 - r;
        double visible = distribution.visibleNormalPdf(wox, woy, woz, hx, hy, hz);
        double pdf;
        if (reflection) {
            if (rgbOut != null) {
                double f = d * distribution.g(wox, woy, woz, wix, wiy, wiz) * r / (4 * Math.abs(woz * wiz)) * compensation(woz);
                rgbOut[0] = f; rgbOut[1] = f; rgbOut[2] = f;
            }
            pdf = visible / (4 * Math.abs(dotO)) * r;
        } else {
            double root = dotI + dotO / etap;
            double denom = root * root;
            if (!(denom > 0)) return 0;
            if (rgbOut != null) {
                double f = d * t * distribution.g(wox, woy, woz, wix, wiy, wiz)
                        * Math.abs(dotI * dotO / (wiz * woz * denom)) / (etap * etap) * compensation(woz);
                rgbOut[0] = f * tintR; rgbOut[1] = f * tintG; rgbOut[2] = f * tintB;
            }
            pdf = visible * Math.abs(dotI) / denom * t; // |d wm / d wi| of refraction
        }
        if (!(pdf > 0) || Double.isInfinite(pdf)) {
            if (rgbOut != null) { rgbOut[0] = 0; rgbOut[1] = 0; rgbOut[2] = 0; }
            return 0;
        }
        return pdf;
    }

    @Override
    public boolean sample(double wox, double woy, double woz, double uc, double u1, double u2, BsdfSample out) {
        out.clear();
        if (woz == 0) return false;
        if (passThrough) {
            double weight = 1 / Math.abs(woz);
            out.wix = -wox; out.wiy = -woy; out.wiz = -woz;
            out.f[0] = tintR * weight; out.f[1] = tintG * weight; out.f[2] = tintB * weight;
            out.pdf = 1;
            out.specular = true;
            return true;
        }
        if (smooth) return sampleSmooth(wox, woy, woz, uc, out);
        double[] wm = out.microNormal;
        distribution.sampleVisibleNormal(wox, woy, woz, u1, u2, wm);
        double mx = wm[0], my = wm[1], mz = wm[2];
        double cosOM = wox * mx + woy * my + woz * mz;
        double r = fresnel(cosOM, eta);
        double wix, wiy, wiz;
        boolean transmission = !(uc < r);
        double etap = 1;
        if (!transmission) {
            double k = 2 * cosOM;
            wix = k * mx - wox; wiy = k * my - woy; wiz = k * mz - woz;
            if (!(woz * wiz > 0)) return false;
        } else {
            // Refract through the microfacet, from wo's side of it.
            double cos = cosOM;
            etap = eta;
            if (cos < 0) { etap = 1 / eta; cos = -cos; mx = -mx; my = -my; mz = -mz; }
            double sin2T = (1 - cos * cos) / (etap * etap);
            if (sin2T >= 1) return false;
            double cosT = Math.sqrt(1 - sin2T);
            double k = cos / etap - cosT;
            wix = -wox / etap + k * mx; wiy = -woy / etap + k * my; wiz = -woz / etap + k * mz;
            if (!(woz * wiz < 0)) return false;
        }
        // Evaluating through the same code as eval and pdf keeps the sample consistent with them.
        double pdf = evaluate(wox, woy, woz, wix, wiy, wiz, out.f);
        if (pdf == 0) { out.clear(); return false; }
        out.wix = wix; out.wiy = wiy; out.wiz = wiz;
        out.pdf = pdf;
        out.eta = etap;
        return true;
    }

    private boolean sampleSmooth(double wox, double woy, double woz, double uc, BsdfSample out) {
        double r = fresnel(woz, eta), t = 1 - r;
        if (uc < r) {
            double f = r / Math.abs(woz);
            out.wix = -wox; out.wiy = -woy; out.wiz = woz;
            out.f[0] = f; out.f[1] = f; out.f[2] = f;
            out.pdf = r;
            out.specular = true;
            return true;
        }
        double cos = woz, nz = 1, etap = eta;
        if (cos < 0) { etap = 1 / eta; cos = -cos; nz = -1; }
        double sin2T = (1 - cos * cos) / (etap * etap);
        if (sin2T >= 1 || !(t > 0)) return false;
        double cosT = Math.sqrt(1 - sin2T);
        double wiz = -woz / etap + (cos / etap - cosT) * nz;
        double wix = -wox / etap, wiy = -woy / etap;
        double f = t / (Math.abs(wiz) * etap * etap);
        out.wix = wix; out.wiy = wiy; out.wiz = wiz;
        out.f[0] = f * tintR; out.f[1] = f * tintG; out.f[2] = f * tintB;
        out.pdf = t;
        out.specular = true;
        out.eta = etap;
        return true;
    }
}
