package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** The principled BSDF: its one-sample mixture draws what its pdf claims, and it stays consistent, energy-conserving, reciprocal and finite. */
class PrincipledBsdfTest {
    private static final int ATTEMPTS = 300_000;
    private static final double FAMILY_LEVEL = 0.01;

    private static PrincipledBsdf principled(double metallic, double roughness, double ior, double transmission) {
        return new PrincipledBsdf(0.8, 0.5, 0.2, metallic, roughness, ior, transmission);
    }

    /** Parameter sets with a density (possibly beside delta lobes), each with the wo cosines to test. */
    static List<Arguments> cases() {
        List<Arguments> cases = new ArrayList<>();
        for (double cos : new double[] {0.9, 0.3}) {
            cases.add(Arguments.of("pure diffuse", principled(0, 0.5, 1, 0), cos));
            cases.add(Arguments.of("metallic 1 rough 0.4", principled(1, 0.4, 1.5, 0), cos));
            cases.add(Arguments.of("transmission 1 rough 0.5 outside", principled(0, 0.5, 1.5, 1), cos));
            cases.add(Arguments.of("transmission 1 rough 0.5 inside", principled(0, 0.5, 1.5, 1), -cos));
            cases.add(Arguments.of("half metal, half glass, rough 0.5", principled(0.5, 0.5, 1.5, 0.5), cos));
            cases.add(Arguments.of("half metal, half glass, rough 0.5, inside", principled(0.5, 0.5, 1.5, 0.5), -cos));
            cases.add(Arguments.of("plastic rough 0.3", principled(0, 0.3, 1.5, 0), cos));
            cases.add(Arguments.of("smooth plastic: diffuse beside a delta coat", principled(0, 0, 1.5, 0), cos));
        }
        cases.add(Arguments.of("half metal, half glass, rough 0.5, grazing", principled(0.5, 0.5, 1.5, 0.5), 0.05));
        return cases;
    }

    private static final int CASE_COUNT = cases().size();

    static Stream<Arguments> caseStream() { return cases().stream(); }

    @ParameterizedTest(name = "{0}, cos wo {2}")
    @MethodSource("caseStream")
    void samplerMatchesMixturePdf(String name, Bsdf bsdf, double cosWo) {
        double[] wo = BsdfChiSquareTest.wo(cosWo);
        SphereChiSquare.Result r = SphereChiSquare.run(BsdfChiSquareTest.sampler(bsdf, wo),
                (x, y, z) -> bsdf.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 0xB5DFL + name.hashCode() + Double.hashCode(cosWo));
        r.assertFits(name + " cos " + cosWo, FAMILY_LEVEL, CASE_COUNT);
    }

    @Test
    void rejectsAMixturePdfWithWrongSelectionProbabilities() {
        // Plastic mixed half and half instead of by the per-wo estimates: the test must see the wrong selection probabilities.
        PrincipledBsdf plastic = principled(0, 0.3, 1.5, 0);
        DielectricSpecularLobe coat = new DielectricSpecularLobe(1.5, 0.3);
        double[] wo = BsdfChiSquareTest.wo(0.6);
        SphereChiSquare.Result r = SphereChiSquare.run(BsdfChiSquareTest.sampler(plastic, wo),
                (x, y, z) -> new LambertBsdf(1, 1, 1).pdf(wo[0], wo[1], wo[2], x, y, z) * 0.5
                        + 0.5 * coat.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 17);
        assertTrue(r.pValue() < 1e-12, r.toString());
    }

    private static List<PrincipledBsdf> roughSets() {
        return List.of(principled(0, 0.5, 1, 0), principled(1, 0.4, 1.5, 0), principled(0, 0.5, 1.5, 1),
                principled(0.5, 0.5, 1.5, 0.5), principled(0, 0.3, 1.5, 0), principled(0.3, 0.8, 1 / 1.33, 0.4),
                principled(0, 0, 1.5, 0));
    }

    @Test
    void nonDeltaSamplesReportTheWholeMixturesFAndPdf() {
        SplittableRandom rng = new SplittableRandom(21);
        BsdfSample s = new BsdfSample();
        double[] f = new double[3];
        for (PrincipledBsdf bsdf : roughSets()) {
            int produced = 0;
            for (int i = 0; i < 20_000; i++) {
                double[] wo = SphereChiSquare.uniformDirection(rng);
                if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) {
                    assertEquals(0, s.pdf, 0);
                    continue;
                }
                assertTrue(s.pdf > 0 && Double.isFinite(s.pdf), bsdf + " pdf " + s.pdf);
                assertEquals(1, s.wix * s.wix + s.wiy * s.wiy + s.wiz * s.wiz, 1e-9);
                if (s.specular) continue;
                produced++;
                SphereChiSquare.assertRelative(bsdf.pdf(wo[0], wo[1], wo[2], s.wix, s.wiy, s.wiz), s.pdf, 1e-9, bsdf + " pdf");
                bsdf.eval(wo[0], wo[1], wo[2], s.wix, s.wiy, s.wiz, f);
                for (int c = 0; c < 3; c++) {
                    assertTrue(s.f[c] >= 0 && Double.isFinite(s.f[c]));
                    SphereChiSquare.assertRelative(f[c], s.f[c], 1e-9, bsdf + " f");
                }
                if (wo[2] * s.wiz < 0) assertTrue(s.eta != 1 && s.eta > 0);
                else assertEquals(1, s.eta, 0);
            }
            assertTrue(produced > 5_000, bsdf + " produced " + produced);
        }
    }

    /** Mean of f |cos wi| / pdf (transmission's 1/eta'^2 undone) and its standard error. */
    private static double[] albedo(Bsdf bsdf, double cos, int n, SplittableRandom rng) {
        double[] wo = BsdfChiSquareTest.wo(cos);
        BsdfSample s = new BsdfSample();
        double sum = 0, sumSq = 0;
        for (int i = 0; i < n; i++) {
            if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) continue;
            double w = s.f[1] * Math.abs(s.wiz) / s.pdf * s.eta * s.eta;
            sum += w;
            sumSq += w * w;
        }
        double mean = sum / n;
        return new double[] {mean, Math.sqrt(Math.max(0, sumSq / n - mean * mean) / n)};
    }

    @Test
    void whiteAlbedoIsAtMostOneIncludingGrazing() {
        SplittableRandom rng = new SplittableRandom(22);
        for (double roughness : new double[] {0, 0.2, 0.5, 1}) {
            for (double ior : new double[] {1.1, 1.5, 2.4, 0.7}) {
                List<PrincipledBsdf> sets = List.of(new PrincipledBsdf(1, 1, 1, 0, roughness, ior, 0),
                        new PrincipledBsdf(1, 1, 1, 1, roughness, ior, 0), new PrincipledBsdf(1, 1, 1, 0, roughness, ior, 1),
                        new PrincipledBsdf(1, 1, 1, 0.3, roughness, ior, 0.5));
                for (PrincipledBsdf bsdf : sets) {
                    for (double cos : new double[] {1, 0.7, 0.3, 0.1, 0.02, 1e-3, -0.5}) {
                        double[] a = albedo(bsdf, cos, 20_000, rng);
                        // Rough glass and a rough coat's base follow a tabulated albedo: 1 to its accuracy,
                        // 3e-3, at the very horizon 1e-2 (0.75 % at cosine 1e-3, index 1.1, roughness 1).
                        double tableError = Math.abs(cos) < 0.01 ? 1e-2 : 3e-3;
                        assertTrue(a[0] <= 1 + 4 * a[1] + tableError, bsdf + " cos " + cos + ": albedo " + a[0] + " +- " + a[1]);
                    }
                }
            }
        }
    }

    @Test
    void smoothWhitePlasticReflectsEverything() {
        // A smooth coat reflects F(cos wo) and the base exactly 1 - F(cos wo) of white: nothing lost, nothing made.
        SplittableRandom rng = new SplittableRandom(23);
        PrincipledBsdf plastic = new PrincipledBsdf(1, 1, 1, 0, 0, 1.5, 0);
        for (double cos : new double[] {1, 0.5, 0.1}) {
            double[] a = albedo(plastic, cos, 200_000, rng);
            assertEquals(1, a[0], 4 * a[1] + 1e-3, "cos " + cos);
        }
    }

    @Test
    void diffuseBaseHasAlbedoOneMinusFresnelOfWo() {
        SplittableRandom rng = new SplittableRandom(24);
        FresnelDiffuseLobe base = new FresnelDiffuseLobe(1, 1, 1, 1.5);
        for (double cos : new double[] {1, 0.6, 0.2, 0.05}) {
            double[] a = albedo(base, cos, 200_000, rng);
            assertEquals(1 - DielectricBsdf.fresnel(cos, 1.5), a[0], 4 * a[1] + 1e-4, "cos " + cos);
        }
        // The hemispherical average of Fresnel for n = 1.5, about 0.092 (the textbook internal/external diffuse reflectance).
        assertEquals(0.0918, FresnelDiffuseLobe.averageFresnel(1.5), 1e-3);
        assertEquals(0, FresnelDiffuseLobe.averageFresnel(1), 1e-15);
    }

    @Test
    void reflectionIsReciprocal() {
        SplittableRandom rng = new SplittableRandom(25);
        double[] a = new double[3], b = new double[3];
        for (PrincipledBsdf bsdf : roughSets()) {
            // Rough glass is divided by its albedo from wo, which gives up exact reciprocity (as in Cycles).
            if (bsdf.transmission() > 0) continue;
            for (int i = 0; i < 20_000; i++) {
                double[] wo = SphereChiSquare.uniformDirection(rng), wi = SphereChiSquare.uniformDirection(rng);
                if (wo[2] * wi[2] < 0) wi[2] = -wi[2];
                bsdf.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], a);
                bsdf.eval(wi[0], wi[1], wi[2], wo[0], wo[1], wo[2], b);
                for (int c = 0; c < 3; c++) {
                    assertTrue(a[c] >= 0 && Double.isFinite(a[c]));
                    SphereChiSquare.assertRelative(a[c], b[c], 1e-9, bsdf + " reciprocity");
                }
            }
        }
    }

    @Test
    void smoothLobesAreDeltaWithTheirWeightOverTheirProbability() {
        PrincipledBsdf mirror = new PrincipledBsdf(1, 1, 1, 1, 0, 1.5, 0);
        assertTrue(mirror.isSpecular());
        BsdfSample s = new BsdfSample();
        double[] wo = BsdfChiSquareTest.wo(0.4);
        assertTrue(mirror.sample(wo[0], wo[1], wo[2], 0.3, 0.2, 0.1, s));
        assertTrue(s.specular);
        assertEquals(1, s.f[0] * s.wiz / s.pdf, 1e-12);
        assertEquals(-wo[0], s.wix, 0);
        assertEquals(0, mirror.pdf(wo[0], wo[1], wo[2], -wo[0], -wo[1], wo[2]), 0);

        // Smooth glass and metal half and half: over many samples the delta weights add up to the lobes' albedos.
        PrincipledBsdf mix = new PrincipledBsdf(1, 1, 1, 0.5, 0, 1.5, 1);
        assertTrue(mix.isSpecular());
        double[] a = albedo(mix, 0.6, 100_000, new SplittableRandom(26));
        double metal = 1; // white Schlick metal reflects everything
        double glass = 1; // Fresnel R + T with a white tint
        assertEquals(0.5 * metal + 0.5 * glass, a[0], 4 * a[1] + 1e-9);
        assertFalse(new PrincipledBsdf(1, 1, 1, 0, 0, 1.5, 0).isSpecular()); // the diffuse base has a density
    }

    @Test
    void degenerateInputsGiveNoNaNOrNegative() {
        List<PrincipledBsdf> all = new ArrayList<>(roughSets());
        all.add(new PrincipledBsdf(1, 1, 1, 1, 0, 1.5, 0));
        all.add(new PrincipledBsdf(1, 1, 1, 0, 0, 1, 1));
        all.add(new PrincipledBsdf(1, 1, 1, 0, 0.5, 1, 0));
        all.add(new PrincipledBsdf(0, 0, 0, 0, 0.5, 1, 0)); // nothing to scatter at all
        all.add(new PrincipledBsdf(0, 0, 0, 1, 1e-9, 1, 0));
        all.add(new PrincipledBsdf(1, 0, 0, 0.5, 1, 1e-3, 0.5));
        double[][] special = {{1, 0, 0}, {0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {Math.sqrt(1 - 1e-20), 0, 1e-10}, {Math.sqrt(1 - 1e-20), 0, -1e-10}};
        SplittableRandom rng = new SplittableRandom(27);
        BsdfSample s = new BsdfSample();
        double[] f = new double[3];
        for (PrincipledBsdf bsdf : all) {
            for (double[] wo : special) {
                for (double[] wi : special) {
                    bsdf.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], f);
                    double pdf = bsdf.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]);
                    assertTrue(pdf >= 0 && Double.isFinite(pdf), bsdf + " pdf " + pdf);
                    for (double v : f) assertTrue(v >= 0 && Double.isFinite(v), bsdf + " f " + v);
                }
                for (int i = 0; i < 300; i++) {
                    boolean ok = bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s);
                    if (wo[2] == 0) assertFalse(ok, bsdf + " sampled from the horizon");
                    if (!ok) { assertEquals(0, s.pdf, 0); continue; }
                    assertTrue(s.pdf > 0 && Double.isFinite(s.pdf) && Double.isFinite(s.wiz), bsdf + " pdf " + s.pdf);
                    for (double v : s.f) assertTrue(v >= 0 && Double.isFinite(v), bsdf + " f " + v);
                }
            }
        }
        assertThrows(IllegalArgumentException.class, () -> new PrincipledBsdf(1, 1, 1, 1.5, 0, 1.5, 0));
        assertThrows(IllegalArgumentException.class, () -> new PrincipledBsdf(1, 1, 1, 0, 0, 0, 0));
    }
}
