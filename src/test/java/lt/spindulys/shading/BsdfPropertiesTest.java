package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Properties every BSDF must have besides sampling its pdf: consistency, energy, reciprocity, Fresnel, no NaNs. */
class BsdfPropertiesTest {
    private static final List<Bsdf> ROUGH = List.of(
            new LambertBsdf(0.8, 0.5, 0.2),
            new ConductorBsdf(0.9, 0.6, 0.3, 0.3),
            new ConductorBsdf(0.9, 0.6, 0.3, 0.7),
            new DielectricBsdf(1.5, 0.3, 0.9, 0.8, 0.7),
            new DielectricBsdf(1.5, 0.7, 1, 1, 1),
            new DielectricBsdf(1 / 1.33, 0.5, 1, 1, 1));

    @Test
    void sampledFAndPdfEqualEvalAndPdf() {
        SplittableRandom rng = new SplittableRandom(1);
        BsdfSample s = new BsdfSample();
        double[] f = new double[3];
        for (Bsdf bsdf : ROUGH) {
            int produced = 0;
            for (int i = 0; i < 20_000; i++) {
                double[] wo = SphereChiSquare.uniformDirection(rng);
                if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) {
                    assertEquals(0, s.pdf, 0);
                    continue;
                }
                produced++;
                assertFalse(s.specular);
                assertTrue(s.pdf > 0 && Double.isFinite(s.pdf));
                assertEquals(1, s.wix * s.wix + s.wiy * s.wiy + s.wiz * s.wiz, 1e-9);
                SphereChiSquare.assertRelative(bsdf.pdf(wo[0], wo[1], wo[2], s.wix, s.wiy, s.wiz), s.pdf, 1e-9, bsdf + " pdf");
                bsdf.eval(wo[0], wo[1], wo[2], s.wix, s.wiy, s.wiz, f);
                for (int c = 0; c < 3; c++) {
                    assertTrue(s.f[c] >= 0 && Double.isFinite(s.f[c]));
                    SphereChiSquare.assertRelative(f[c], s.f[c], 1e-9, bsdf + " f");
                }
                boolean transmitted = wo[2] * s.wiz < 0;
                if (transmitted) assertTrue(s.eta != 1 && s.eta > 0);
                else assertEquals(1, s.eta, 0);
            }
            assertTrue(produced > 10_000, bsdf + " produced " + produced);
        }
    }

    @Test
    void albedoIsAtMostOne() {
        SplittableRandom rng = new SplittableRandom(2);
        BsdfSample s = new BsdfSample();
        int n = 100_000;
        List<Bsdf> all = new java.util.ArrayList<>(ROUGH);
        all.add(new ConductorBsdf(1, 1, 1, 0));
        all.add(new DielectricBsdf(1.5, 0, 1, 1, 1));
        all.add(new DielectricBsdf(1.5, 0.5, 1, 1, 1));
        for (Bsdf bsdf : all) {
            for (double cos : new double[] {1, 0.7, 0.3, 0.1, -0.1, -0.5, -1}) {
                double[] wo = BsdfChiSquareTest.wo(cos);
                double sum = 0, sumSq = 0;
                for (int i = 0; i < n; i++) {
                    if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) continue;
                    // Undo the radiance scaling of transmission (1/eta'^2), which is not an energy change.
                    double w = s.f[1] * Math.abs(s.wiz) / s.pdf * s.eta * s.eta;
                    sum += w;
                    sumSq += w * w;
                }
                double mean = sum / n, sigma = Math.sqrt(Math.max(0, sumSq / n - mean * mean) / n);
                // The rough dielectric is divided by its tabulated albedo: 1 to the table's accuracy.
                assertTrue(mean <= 1 + 4 * sigma + 3e-3, bsdf + " cos " + cos + ": albedo " + mean + " +- " + sigma);
            }
        }
    }

    @Test
    void whiteLambertReflectsEverything() {
        LambertBsdf white = new LambertBsdf(1, 1, 1);
        SplittableRandom rng = new SplittableRandom(3);
        BsdfSample s = new BsdfSample();
        for (int i = 0; i < 10_000; i++) {
            double[] wo = SphereChiSquare.uniformDirection(rng);
            if (!white.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) continue;
            for (int c = 0; c < 3; c++) assertEquals(1, s.f[c] * Math.abs(s.wiz) / s.pdf, 1e-12);
            assertTrue(wo[2] * s.wiz > 0);
        }
    }

    @Test
    void smoothDielectricSplitsEnergyByFresnel() {
        SplittableRandom rng = new SplittableRandom(4);
        DielectricBsdf glass = new DielectricBsdf(1.5, 0, 1, 1, 1);
        assertTrue(glass.isSpecular());
        BsdfSample s = new BsdfSample();
        for (double cos : new double[] {1, 0.5, 0.1, -0.3, -0.9}) {
            double[] wo = BsdfChiSquareTest.wo(cos);
            int reflected = 0, n = 50_000;
            for (int i = 0; i < n; i++) {
                assertTrue(glass.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s));
                assertTrue(s.specular);
                assertEquals(0, glass.pdf(wo[0], wo[1], wo[2], s.wix, s.wiy, s.wiz), 0);
                boolean transmitted = wo[2] * s.wiz < 0;
                if (!transmitted) reflected++;
                // Every path weight is 1 once the radiance scaling is undone: R and T add up to 1.
                assertEquals(1, s.f[0] * Math.abs(s.wiz) / s.pdf * s.eta * s.eta, 1e-12);
                if (transmitted) { // Snell's law
                    double sinO = Math.sqrt(1 - wo[2] * wo[2]), sinI = Math.sqrt(1 - s.wiz * s.wiz);
                    double etaOutside = 1, etaInside = 1.5;
                    assertEquals(wo[2] > 0 ? etaOutside * sinO : etaInside * sinO, wo[2] > 0 ? etaInside * sinI : etaOutside * sinI, 1e-12);
                    assertEquals(wo[2] > 0 ? 1.5 : 1 / 1.5, s.eta, 1e-15);
                }
            }
            double r = DielectricBsdf.fresnel(cos, 1.5);
            assertEquals(r, (double) reflected / n, 4 * Math.sqrt(r * (1 - r) / n) + 1e-9, "cos " + cos);
        }
    }

    @Test
    void fresnelReflectanceAndTransmittanceAddToOne() {
        for (double eta : new double[] {1.33, 1.5, 2.4, 1 / 1.5}) {
            for (int k = 1; k <= 100; k++) {
                double cosI = k / 100.0;
                double sin2T = (1 - cosI * cosI) / (eta * eta);
                double r = DielectricBsdf.fresnel(cosI, eta);
                if (sin2T >= 1) { assertEquals(1, r, 0); continue; }
                double cosT = Math.sqrt(1 - sin2T);
                // Transmittance from the amplitude transmission coefficients, independently of R.
                double tPerp = 2 * cosI / (cosI + eta * cosT), tPar = 2 * cosI / (eta * cosI + cosT);
                double t = eta * cosT / cosI * 0.5 * (tPerp * tPerp + tPar * tPar);
                assertEquals(1, r + t, 1e-12);
            }
        }
    }

    @Test
    void fresnelSpecialCases() {
        for (double eta : new double[] {1.33, 1.5, 2.4}) {
            double normal = (eta - 1) / (eta + 1);
            assertEquals(normal * normal, DielectricBsdf.fresnel(1, eta), 1e-15);
            assertEquals(normal * normal, DielectricBsdf.fresnel(-1, eta), 1e-15);
            assertEquals(1, DielectricBsdf.fresnel(0, eta), 1e-12); // grazing
            double critical = Math.sqrt(1 - 1 / (eta * eta)); // cosine of the critical angle inside
            assertEquals(1, DielectricBsdf.fresnel(-(critical - 1e-3), eta), 0); // beyond it: total internal reflection
            assertTrue(DielectricBsdf.fresnel(-(critical + 1e-3), eta) < 1);
            for (int k = 1; k <= 50; k++) {
                double cosI = k / 50.0;
                // From inside equals the flipped interface from outside.
                assertEquals(DielectricBsdf.fresnel(cosI, 1 / eta), DielectricBsdf.fresnel(-cosI, eta), 1e-15);
                // Stokes: the same pair of angles reflects the same fraction from either side.
                double cosT = Math.sqrt(1 - (1 - cosI * cosI) / (eta * eta));
                assertEquals(DielectricBsdf.fresnel(cosI, eta), DielectricBsdf.fresnel(-cosT, eta), 1e-12);
            }
        }
        assertEquals(0, DielectricBsdf.fresnel(0.5, 1), 0);
    }

    /**
     * Reflection is reciprocal. The rough dielectric is tested without its energy compensation:
     * dividing by the albedo of wo's direction, as Cycles does, gives up exact reciprocity
     * (f(wo, wi) E(wo) = f(wi, wo) E(wi)) for energy conservation.
     */
    @Test
    void reflectionIsReciprocal() {
        SplittableRandom rng = new SplittableRandom(5);
        double[] a = new double[3], b = new double[3];
        List<Bsdf> cores = new java.util.ArrayList<>(ROUGH.subList(0, 3));
        cores.add(DielectricBsdf.uncompensated(1.5, 0.3));
        cores.add(DielectricBsdf.uncompensated(1.5, 0.7));
        cores.add(DielectricBsdf.uncompensated(1 / 1.33, 0.5));
        for (Bsdf bsdf : cores) {
            for (int i = 0; i < 20_000; i++) {
                double[] wo = SphereChiSquare.uniformDirection(rng), wi = SphereChiSquare.uniformDirection(rng);
                if (wo[2] * wi[2] < 0) { wi[2] = -wi[2]; }
                bsdf.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], a);
                bsdf.eval(wi[0], wi[1], wi[2], wo[0], wo[1], wo[2], b);
                for (int c = 0; c < 3; c++) {
                    assertTrue(a[c] >= 0 && Double.isFinite(a[c]));
                    SphereChiSquare.assertRelative(a[c], b[c], 1e-9, bsdf + " reciprocity");
                }
            }
        }
    }

    /** Stratified estimate of the energy albedo (transmission's 1/eta'^2 undone) for wo at signed cosine cos. */
    private static double albedo(Bsdf bsdf, double cos) {
        double[] wo = BsdfChiSquareTest.wo(cos);
        SplittableRandom rng = new SplittableRandom(Double.doubleToLongBits(cos));
        int strata = 160;
        BsdfSample s = new BsdfSample();
        double sum = 0;
        for (int i = 0; i < strata; i++) {
            for (int j = 0; j < strata; j++) {
                if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), (i + rng.nextDouble()) / strata, (j + rng.nextDouble()) / strata, s)) continue;
                sum += s.f[1] * Math.abs(s.wiz) / s.pdf * s.eta * s.eta;
            }
        }
        return sum / (strata * strata);
    }

    /**
     * The rough dielectric, divided by its single-scattering albedo, keeps all the energy from
     * either side, down to grazing, where the uncompensated one loses up to a half.
     */
    @Test
    void compensatedRoughDielectricConservesEnergy() {
        for (double ior : new double[] {1.5, 1.33, 2.4, 1 / 1.5}) {
            for (double roughness : new double[] {0.1, 0.3, 0.6, 1}) {
                for (double cos : new double[] {1, 0.5, 0.2, 0.05, -0.05, -0.3, -0.8}) {
                    DielectricBsdf glass = new DielectricBsdf(ior, roughness, 1, 1, 1);
                    assertEquals(1, albedo(glass, cos), 3e-3, "ior " + ior + " roughness " + roughness + " cos " + cos
                            + " (uncompensated " + albedo(DielectricBsdf.uncompensated(ior, roughness), cos) + ")");
                }
            }
        }
    }

    /** Across the smooth threshold the albedo stays 1: no jump between the delta lobes and the compensated rough ones. */
    @Test
    void compensatedDielectricJoinsTheSmoothOne() {
        double threshold = Math.sqrt(MicrofacetDistribution.SMOOTH_ALPHA);
        DielectricBsdf rough = new DielectricBsdf(1.5, threshold * 1.0001, 1, 1, 1), smooth = new DielectricBsdf(1.5, threshold * 0.9999, 1, 1, 1);
        assertFalse(rough.isSpecular());
        assertTrue(smooth.isSpecular());
        for (double cos : new double[] {1, 0.4, 0.1, 0.02, -0.9, -0.5}) {
            assertEquals(1, albedo(smooth, cos), 1e-12, "smooth, cos " + cos);
            assertEquals(1, albedo(rough, cos), 3e-3, "rough, cos " + cos);
        }
    }

    @Test
    void smoothConductorIsAMirror() {
        ConductorBsdf mirror = new ConductorBsdf(0.9, 0.6, 0.3, 0.01);
        assertTrue(mirror.isSpecular());
        BsdfSample s = new BsdfSample();
        double[] wo = BsdfChiSquareTest.wo(0.4);
        assertTrue(mirror.sample(wo[0], wo[1], wo[2], 0.3, 0.2, 0.1, s));
        assertTrue(s.specular);
        assertEquals(-wo[0], s.wix, 0);
        assertEquals(-wo[1], s.wiy, 0);
        assertEquals(wo[2], s.wiz, 0);
        double schlick = Math.pow(1 - 0.4, 5);
        assertEquals(0.9 + 0.1 * schlick, s.f[0] * s.wiz / s.pdf, 1e-12);
        assertEquals(0.3 + 0.7 * schlick, s.f[2] * s.wiz / s.pdf, 1e-12);
        assertEquals(0, mirror.pdf(wo[0], wo[1], wo[2], -wo[0], -wo[1], wo[2]), 0);
        double[] f = new double[3];
        mirror.eval(wo[0], wo[1], wo[2], -wo[0], -wo[1], wo[2], f);
        assertEquals(0, f[0] + f[1] + f[2], 0);
    }

    @Test
    void indexOneIsAPassThrough() {
        DielectricBsdf air = new DielectricBsdf(1, 0.5, 0.5, 0.6, 0.7);
        assertTrue(air.isSpecular());
        BsdfSample s = new BsdfSample();
        double[] wo = BsdfChiSquareTest.wo(-0.3);
        assertTrue(air.sample(wo[0], wo[1], wo[2], 0.9, 0.4, 0.6, s));
        assertTrue(s.specular);
        assertEquals(-wo[2], s.wiz, 0);
        assertEquals(0.6, s.f[1] * Math.abs(s.wiz) / s.pdf, 1e-15);
        assertEquals(1, s.eta, 0);
    }

    @Test
    void degenerateDirectionsGiveNoSampleAndNoNaN() {
        BsdfSample s = new BsdfSample();
        double[] f = new double[3];
        List<Bsdf> all = new java.util.ArrayList<>(ROUGH);
        all.add(new ConductorBsdf(1, 1, 1, 0));
        all.add(new DielectricBsdf(1.5, 0, 1, 1, 1));
        all.add(new DielectricBsdf(1.5, 1e-9, 1, 1, 1));
        all.add(new ConductorBsdf(1, 1, 1, 1));
        double[][] special = {{1, 0, 0}, {0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {Math.sqrt(1 - 1e-20), 0, 1e-10}};
        SplittableRandom rng = new SplittableRandom(6);
        for (Bsdf bsdf : all) {
            for (double[] wo : special) {
                for (double[] wi : special) {
                    bsdf.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], f);
                    double pdf = bsdf.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]);
                    assertTrue(pdf >= 0 && Double.isFinite(pdf), bsdf + " pdf " + pdf);
                    for (double v : f) assertTrue(v >= 0 && Double.isFinite(v), bsdf + " f " + v);
                    if (pdf == 0) assertEquals(0, f[0] + f[1] + f[2], 0, bsdf + ": f without pdf");
                }
                for (int i = 0; i < 200; i++) {
                    boolean ok = bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s);
                    if (wo[2] == 0) assertFalse(ok, bsdf + " sampled from the horizon");
                    if (!ok) { assertEquals(0, s.pdf, 0); continue; }
                    assertTrue(s.pdf > 0 && Double.isFinite(s.pdf) && Double.isFinite(s.wiz));
                    for (double v : s.f) assertTrue(v >= 0 && Double.isFinite(v));
                }
            }
        }
    }
}
