package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** The Whitted material terms read as a BSDF: the documented rule, sampled as its pdf claims, never creating energy. */
class WhittedMappingTest {
    private static final int ATTEMPTS = 300_000;

    /** kd 0.6, ks 0.3, shininess 20 on an orange colour: the typical thesis plastic. */
    private static WhittedMaterialBsdf plastic() {
        return WhittedMaterialBsdf.fromWhittedTerms(0.8, 0.4, 0.2, 0.6, 0.3, 20, 0, 0, 1, 1, 1, 1, false);
    }

    @ParameterizedTest(name = "cos wo {0}")
    @ValueSource(doubles = {0.9, 0.4, 0.1, -0.6})
    void samplerMatchesPdf(double cosWo) {
        WhittedMaterialBsdf bsdf = plastic();
        double[] wo = BsdfChiSquareTest.wo(cosWo);
        SphereChiSquare.Result r = SphereChiSquare.run(BsdfChiSquareTest.sampler(bsdf, wo),
                (x, y, z) -> bsdf.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 0x3A11L + Double.hashCode(cosWo));
        r.assertFits("cos " + cosWo, 0.01, 4);
    }

    @Test
    void phongExponentMapsToGgxWidth() {
        assertEquals(1, WhittedMaterialBsdf.glossAlpha(0), 0);
        assertEquals(Math.sqrt(2.0 / 22), WhittedMaterialBsdf.glossAlpha(20), 1e-15);
        assertEquals(Math.sqrt(2.0 / 22), plastic().glossyAlpha(), 1e-15);
        assertEquals(1, WhittedMaterialBsdf.glossAlpha(-3), 0); // a negative exponent is read as 0
        double previous = 2;
        for (double n = 0; n < 1e6; n = n * 2 + 1) {
            double alpha = WhittedMaterialBsdf.glossAlpha(n);
            assertTrue(alpha < previous);
            // Inverse relation n = 2 / alpha^2 - 2.
            assertEquals(n, 2 / (alpha * alpha) - 2, 1e-9 * Math.max(1, n));
            previous = alpha;
        }
        // Large exponents become a mirror: every sample is a delta.
        WhittedMaterialBsdf shiny = WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 0, 1, 1e9, 0, 0, 1, 1, 1, 1, false);
        assertTrue(shiny.isSpecular());
    }

    @Test
    void nonDeltaSamplesReportTheWholeMixturesFAndPdf() {
        SplittableRandom rng = new SplittableRandom(31);
        BsdfSample s = new BsdfSample();
        double[] f = new double[3];
        List<WhittedMaterialBsdf> materials = List.of(plastic(),
                WhittedMaterialBsdf.fromWhittedTerms(0.2, 0.7, 0.3, 0.5, 0.2, 5, 0.2, 0.3, 1.5, 0.9, 0.9, 1, false));
        for (WhittedMaterialBsdf bsdf : materials) {
            int produced = 0;
            for (int i = 0; i < 20_000; i++) {
                double z = 2 * rng.nextDouble() - 1, phi = 2 * Math.PI * rng.nextDouble(), r = Math.sqrt(1 - z * z);
                double wox = r * Math.cos(phi), woy = r * Math.sin(phi);
                if (!bsdf.sample(wox, woy, z, rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s) || s.specular) continue;
                produced++;
                double pdf = bsdf.pdf(wox, woy, z, s.wix, s.wiy, s.wiz);
                assertEquals(pdf, s.pdf, 1e-9 * pdf);
                bsdf.eval(wox, woy, z, s.wix, s.wiy, s.wiz, f);
                for (int c = 0; c < 3; c++) assertEquals(f[c], s.f[c], 1e-9 * f[c]);
            }
            assertTrue(produced > 5_000, "produced " + produced);
        }
    }

    @Test
    void diffuseTermIsLambertOfKdTimesColour() {
        WhittedMaterialBsdf matte = WhittedMaterialBsdf.fromWhittedTerms(0.8, 0.4, 0.2, 0.5, 0, 10, 0, 0, 1, 1, 1, 1, false);
        BsdfSample s = new BsdfSample();
        SplittableRandom rng = new SplittableRandom(32);
        double[] wo = BsdfChiSquareTest.wo(0.7);
        for (int i = 0; i < 1000; i++) {
            assertTrue(matte.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s));
            assertEquals(0.4, s.f[0] * s.wiz / s.pdf, 1e-12);
            assertEquals(0.1, s.f[2] * s.wiz / s.pdf, 1e-12);
        }
    }

    @Test
    void mirrorAndRefractionFollowTheWhittedTracer() {
        BsdfSample s = new BsdfSample();
        double[] wo = BsdfChiSquareTest.wo(0.6);
        WhittedMaterialBsdf mirror = WhittedMaterialBsdf.fromWhittedTerms(0.8, 0.4, 0.2, 0, 0, 10, 0.7, 0, 1, 1, 1, 1, false);
        assertTrue(mirror.isSpecular());
        assertTrue(mirror.sample(wo[0], wo[1], wo[2], 0.5, 0.5, 0.5, s));
        assertTrue(s.specular);
        assertEquals(wo[2], s.wiz, 0);
        assertEquals(0.7, s.f[0] * s.wiz / s.pdf, 1e-12); // untinted, weight kr
        assertEquals(0.7, s.f[2] * s.wiz / s.pdf, 1e-12);

        WhittedMaterialBsdf glass = WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 0, 0, 10, 0, 0.9, 1.5, 1, 0.5, 0.25, false);
        assertTrue(glass.sample(wo[0], wo[1], wo[2], 0.5, 0.5, 0.5, s));
        assertTrue(s.specular && s.wiz < 0);
        double sinO = Math.sqrt(1 - wo[2] * wo[2]), sinI = Math.sqrt(1 - s.wiz * s.wiz);
        assertEquals(sinO, 1.5 * sinI, 1e-12); // Snell
        assertEquals(1.5, s.eta, 0);
        // No Fresnel: all of kt goes through, tinted by the filter (radiance scaling undone).
        assertEquals(0.9 * 0.5, s.f[1] * Math.abs(s.wiz) / s.pdf * s.eta * s.eta, 1e-12);
        // From inside beyond the critical angle the transmitted share is mirrored, untinted.
        double[] inside = BsdfChiSquareTest.wo(-0.3);
        assertTrue(glass.sample(inside[0], inside[1], inside[2], 0.5, 0.5, 0.5, s));
        assertEquals(inside[2], s.wiz, 0);
        assertEquals(0.9, s.f[2] * Math.abs(s.wiz) / s.pdf, 1e-12);
        assertEquals(1, s.eta, 0);
    }

    @Test
    void fresnelMaterialsSplitTransmissionByFresnel() {
        WhittedMaterialBsdf glass = WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 0, 0, 10, 0, 1, 1.5, 1, 1, 1, true);
        BsdfSample s = new BsdfSample();
        SplittableRandom rng = new SplittableRandom(33);
        double[] wo = BsdfChiSquareTest.wo(0.3);
        int reflected = 0, n = 50_000;
        for (int i = 0; i < n; i++) {
            assertTrue(glass.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s));
            if (s.wiz > 0) reflected++;
        }
        double r = DielectricBsdf.fresnel(0.3, 1.5);
        assertEquals(r, (double) reflected / n, 4 * Math.sqrt(r * (1 - r) / n));
    }

    @Test
    void weightsAboveOneAreScaledDownProportionally() {
        WhittedMaterialBsdf bright = WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 1, 1, 8, 0.5, 0.5, 1.5, 1, 1, 1, false);
        assertEquals(1 / 3.0, bright.weightScale(), 1e-15);
        assertEquals(1, plastic().weightScale(), 0); // 0.6 + 0.3 <= 1: kept as given
        SplittableRandom rng = new SplittableRandom(34);
        BsdfSample s = new BsdfSample();
        List<WhittedMaterialBsdf> materials = List.of(bright, plastic(),
                WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 2, 2, 0, 0, 0, 1, 1, 1, 1, false),
                WhittedMaterialBsdf.fromWhittedTerms(1.5, 1, 1, 1, 0, 0, 0, 1, 1.3, 2, 1, 1, false));
        for (WhittedMaterialBsdf bsdf : materials) {
            for (double cos : new double[] {1, 0.5, 0.05, -0.4}) {
                double[] wo = BsdfChiSquareTest.wo(cos);
                double sum = 0, sumSq = 0;
                int n = 50_000;
                for (int i = 0; i < n; i++) {
                    if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) continue;
                    double w = Math.max(s.f[0], Math.max(s.f[1], s.f[2])) * Math.abs(s.wiz) / s.pdf * s.eta * s.eta;
                    sum += w;
                    sumSq += w * w;
                }
                double mean = sum / n, sigma = Math.sqrt(Math.max(0, sumSq / n - mean * mean) / n);
                assertTrue(mean <= 1 + 4 * sigma + 1e-9, "cos " + cos + ": albedo " + mean);
            }
        }
    }

    @Test
    void degenerateInputsGiveNoNaN() {
        List<WhittedMaterialBsdf> materials = List.of(plastic(),
                WhittedMaterialBsdf.fromWhittedTerms(0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, false),
                WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 0.2, 0.2, 0, 0.2, 0.4, 1, 1, 1, 1, false),
                WhittedMaterialBsdf.fromWhittedTerms(1, 1, 1, 0.2, 0.2, 1e12, 0.2, 0.4, 1.5, 0, 0, 0, true));
        double[][] special = {{1, 0, 0}, {0, 0, 1}, {0, 0, -1}, {Math.sqrt(1 - 1e-20), 0, 1e-10}};
        BsdfSample s = new BsdfSample();
        double[] f = new double[3];
        SplittableRandom rng = new SplittableRandom(35);
        for (WhittedMaterialBsdf bsdf : materials) {
            for (double[] wo : special) {
                for (double[] wi : special) {
                    bsdf.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], f);
                    double pdf = bsdf.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]);
                    assertTrue(pdf >= 0 && Double.isFinite(pdf));
                    for (double v : f) assertTrue(v >= 0 && Double.isFinite(v));
                }
                for (int i = 0; i < 200; i++) {
                    boolean ok = bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s);
                    if (wo[2] == 0) assertFalse(ok);
                    if (!ok) continue;
                    assertTrue(s.pdf > 0 && Double.isFinite(s.pdf));
                    for (double v : s.f) assertTrue(v >= 0 && Double.isFinite(v));
                }
            }
        }
    }

    @Test
    void materialFactoryReadsTheMaterialsTerms() {
        Material m = Material.builder().color(new Color(0.8, 0.4, 0.2)).kd(0.6).ks(0.3).shininess(20).build();
        WhittedMaterialBsdf fromMaterial = WhittedMaterialBsdf.fromMaterial(m);
        WhittedMaterialBsdf fromTerms = plastic();
        assertEquals(fromTerms.glossyAlpha(), fromMaterial.glossyAlpha(), 0);
        double[] a = new double[3], b = new double[3];
        SplittableRandom rng = new SplittableRandom(36);
        for (int i = 0; i < 1000; i++) {
            double[] wo = BsdfChiSquareTest.wo(rng.nextDouble()), wi = BsdfChiSquareTest.wo(rng.nextDouble());
            fromMaterial.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], a);
            fromTerms.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], b);
            for (int c = 0; c < 3; c++) assertEquals(b[c], a[c], 0);
            assertEquals(fromTerms.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]),
                    fromMaterial.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]), 0);
        }
    }
}
