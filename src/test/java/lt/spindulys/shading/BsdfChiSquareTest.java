package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.junit.jupiter.api.Test;

/** Each BSDF's sampler draws directions with exactly the density its pdf claims (chi-square test over the sphere). */
class BsdfChiSquareTest {
    private static final int ATTEMPTS = 300_000;
    private static final double[] WO_COSINES = {0.95, 0.5, 0.1};
    private static final double FAMILY_LEVEL = 0.01;

    static List<Arguments> cases() {
        List<Arguments> cases = new ArrayList<>();
        for (double cos : WO_COSINES) cases.add(Arguments.of("Lambert", new LambertBsdf(0.8, 0.5, 0.2), cos));
        cases.add(Arguments.of("Lambert, wo below", new LambertBsdf(0.8, 0.5, 0.2), -0.5));
        for (double roughness : new double[] {0.3, 0.7}) {
            for (double cos : WO_COSINES) {
                cases.add(Arguments.of("conductor r=" + roughness, new ConductorBsdf(0.9, 0.6, 0.3, roughness), cos));
            }
        }
        for (double roughness : new double[] {0.3, 0.7}) {
            for (double cos : WO_COSINES) {
                DielectricBsdf glass = new DielectricBsdf(1.5, roughness, 1, 1, 1);
                cases.add(Arguments.of("dielectric 1.5 r=" + roughness + " outside", glass, cos));
                cases.add(Arguments.of("dielectric 1.5 r=" + roughness + " inside", glass, -cos));
            }
        }
        return cases;
    }

    private static final int CASE_COUNT = cases().size();

    static Stream<Arguments> caseStream() { return cases().stream(); }

    /** wo at the given cosine, at an azimuth off the bin edges. */
    static double[] wo(double cos) {
        double sin = Math.sqrt(1 - cos * cos), phi = 0.7;
        return new double[] {sin * Math.cos(phi), sin * Math.sin(phi), cos};
    }

    static SphereChiSquare.Sampler sampler(Bsdf bsdf, double[] wo) {
        BsdfSample s = new BsdfSample();
        return (rng, out) -> {
            if (!bsdf.sample(wo[0], wo[1], wo[2], rng.nextDouble(), rng.nextDouble(), rng.nextDouble(), s)) return false;
            if (s.specular) return false;
            out[0] = s.wix; out[1] = s.wiy; out[2] = s.wiz;
            return true;
        };
    }

    @ParameterizedTest(name = "{0}, cos wo {2}")
    @MethodSource("caseStream")
    void samplerMatchesPdf(String name, Bsdf bsdf, double cosWo) {
        double[] wo = wo(cosWo);
        SphereChiSquare.Result r = SphereChiSquare.run(sampler(bsdf, wo),
                (x, y, z) -> bsdf.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 0x5EEDL + Double.hashCode(cosWo));
        r.assertFits(name + " cos " + cosWo, FAMILY_LEVEL, CASE_COUNT);
    }

    @Test
    void rejectsAPdfScaledUp() {
        Bsdf conductor = new ConductorBsdf(1, 1, 1, 0.5);
        double[] wo = wo(0.6);
        SphereChiSquare.Result r = SphereChiSquare.run(sampler(conductor, wo),
                (x, y, z) -> 1.2 * conductor.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 7);
        assertTrue(r.pValue() < 1e-12, r.toString());
    }

    @Test
    void rejectsALambertPdfForTheGgxSampler() {
        Bsdf conductor = new ConductorBsdf(1, 1, 1, 0.7);
        Bsdf lambert = new LambertBsdf(1, 1, 1);
        double[] wo = wo(0.6);
        SphereChiSquare.Result r = SphereChiSquare.run(sampler(conductor, wo),
                (x, y, z) -> lambert.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 11);
        assertTrue(r.pValue() < 1e-12, r.toString());
    }

    @Test
    void rejectsATransmissionPdfTenPercentTooHigh() {
        Bsdf glass = new DielectricBsdf(1.5, 0.5, 1, 1, 1);
        double[] wo = wo(0.6);
        SphereChiSquare.Result r = SphereChiSquare.run(sampler(glass, wo),
                (x, y, z) -> (z < 0 ? 1.1 : 1) * glass.pdf(wo[0], wo[1], wo[2], x, y, z), ATTEMPTS, 13);
        assertTrue(r.pValue() < 1e-12, r.toString());
    }

    @Test
    void survivalFunctionMatchesKnownValues() {
        // Two degrees of freedom: exactly exp(-x/2).
        for (double x : new double[] {0.1, 1, 5, 30}) {
            assertEquals(Math.exp(-x / 2), SphereChiSquare.chiSquareSurvival(x, 2), 1e-12);
        }
        // Table critical values at the 5% level.
        assertEquals(0.05, SphereChiSquare.chiSquareSurvival(3.841459, 1), 1e-6);
        assertEquals(0.05, SphereChiSquare.chiSquareSurvival(18.307038, 10), 1e-6);
        assertEquals(0.05, SphereChiSquare.chiSquareSurvival(124.342113, 100), 1e-6);
        assertEquals(0.01, SphereChiSquare.chiSquareSurvival(1106.969, 1000), 1e-4);
        assertEquals(Math.log(24), SphereChiSquare.logGamma(5), 1e-12);
        assertEquals(0.5 * Math.log(Math.PI), SphereChiSquare.logGamma(0.5), 1e-12);
    }
}
