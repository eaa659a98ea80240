package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;

/** The GGX distribution: normalisation, masking, and visible-normal sampling against its density. */
class MicrofacetDistributionTest {

    @ParameterizedTest
    @ValueSource(doubles = {0.01, 0.05, 0.1, 0.3, 0.7, 1.0})
    void projectedAreaOfTheNormalsIsOne(double alpha) {
        // Integral of D(wm) cos(theta_m) over the hemisphere = 2 pi * integral over mu = cos theta of D mu dmu.
        MicrofacetDistribution ggx = new MicrofacetDistribution(alpha);
        int n = 2_000_000;
        double h = 1.0 / n, sum = 0;
        for (int i = 0; i <= n; i++) {
            double mu = i * h;
            double weight = i == 0 || i == n ? 1 : (i % 2 == 1 ? 4 : 2);
            sum += weight * ggx.d(Math.sqrt(1 - mu * mu), 0, mu) * mu;
        }
        assertEquals(1, 2 * Math.PI * sum * h / 3, 1e-6);
    }

    @ParameterizedTest
    @CsvSource({"0.1, 1", "0.1, 0.5", "0.3, 0.9", "0.3, 0.1", "0.7, 0.5", "0.7, -0.3", "1.0, 0.05"})
    void visibleNormalDensityIntegratesToOne(double alpha, double cosWo) {
        MicrofacetDistribution ggx = new MicrofacetDistribution(alpha);
        double sinWo = Math.sqrt(1 - cosWo * cosWo);
        double wx = sinWo * Math.cos(0.3), wy = sinWo * Math.sin(0.3);
        int nMu = 4000, nPhi = 400; // Simpson in mu = cos theta_m and phi_m
        double hMu = 1.0 / nMu, hPhi = 2 * Math.PI / nPhi, sum = 0;
        for (int i = 0; i <= nMu; i++) {
            double mu = i * hMu, s = Math.sqrt(1 - mu * mu);
            double wi = i == 0 || i == nMu ? 1 : (i % 2 == 1 ? 4 : 2);
            for (int j = 0; j <= nPhi; j++) {
                double phi = j * hPhi;
                double wj = j == 0 || j == nPhi ? 1 : (j % 2 == 1 ? 4 : 2);
                sum += wi * wj * ggx.visibleNormalPdf(wx, wy, cosWo, s * Math.cos(phi), s * Math.sin(phi), mu);
            }
        }
        assertEquals(1, sum * hMu * hPhi / 9, 2e-4);
    }

    @ParameterizedTest
    @CsvSource({"0.3, 0.5", "0.5, 0.9", "0.7, 0.1", "0.3, -0.6"})
    void visibleNormalSamplesFollowTheirDensity(double alpha, double cosWo) {
        MicrofacetDistribution ggx = new MicrofacetDistribution(alpha);
        double[] w = BsdfChiSquareTest.wo(cosWo);
        SphereChiSquare.Result r = SphereChiSquare.run(
                (rng, out) -> {
                    ggx.sampleVisibleNormal(w[0], w[1], w[2], rng.nextDouble(), rng.nextDouble(), out);
                    return true;
                },
                (x, y, z) -> ggx.visibleNormalPdf(w[0], w[1], w[2], x, y, z), 300_000, 42);
        assertEquals(0, r.unexpectedSamples(), r.toString());
        assertTrue(r.pValue() > SphereChiSquare.sidakThreshold(0.01, 4), r.toString());
    }

    @Test
    void sampledNormalsAreUnitAndAboveTheHorizon() {
        SplittableRandom rng = new SplittableRandom(3);
        double[] wm = new double[3];
        for (double alpha : new double[] {1e-4, 0.01, 0.5, 1}) {
            MicrofacetDistribution ggx = new MicrofacetDistribution(alpha);
            for (int i = 0; i < 10_000; i++) {
                double z = 2 * rng.nextDouble() - 1, phi = 2 * Math.PI * rng.nextDouble(), s = Math.sqrt(1 - z * z);
                ggx.sampleVisibleNormal(s * Math.cos(phi), s * Math.sin(phi), z, rng.nextDouble(), rng.nextDouble(), wm);
                assertTrue(wm[2] > 0);
                assertEquals(1, wm[0] * wm[0] + wm[1] * wm[1] + wm[2] * wm[2], 1e-12);
            }
        }
    }

    @Test
    void maskingTerms() {
        MicrofacetDistribution ggx = MicrofacetDistribution.fromRoughness(0.5);
        assertEquals(0.25, ggx.alpha(), 0);
        assertEquals(0, ggx.lambda(0, 0, 1), 0);
        assertEquals(1, ggx.g1(0, 0, 1), 0);
        assertEquals(0, ggx.g1(1, 0, 0), 0); // grazing: fully masked, not NaN
        assertEquals(0, ggx.g(1, 0, 0, 0, 0, 1), 0);
        SplittableRandom rng = new SplittableRandom(5);
        for (int i = 0; i < 1000; i++) {
            double zo = rng.nextDouble(), zi = rng.nextDouble();
            double so = Math.sqrt(1 - zo * zo), si = Math.sqrt(1 - zi * zi);
            double g = ggx.g(so, 0, zo, 0, si, zi);
            // Height correlation: never more shadowing-free than either direction alone, and at least their product.
            assertTrue(g <= Math.min(ggx.g1(so, 0, zo), ggx.g1(0, si, zi)) + 1e-15);
            assertTrue(g >= ggx.g1(so, 0, zo) * ggx.g1(0, si, zi) - 1e-15);
        }
    }

    @Test
    void alphaIsClampedAndSmoothnessFlagged() {
        assertEquals(MicrofacetDistribution.MIN_ALPHA, new MicrofacetDistribution(0).alpha(), 0);
        assertTrue(MicrofacetDistribution.fromRoughness(0.03).isEffectivelySmooth()); // alpha 9e-4
        assertFalse(MicrofacetDistribution.fromRoughness(0.04).isEffectivelySmooth()); // alpha 1.6e-3
        MicrofacetDistribution tiny = new MicrofacetDistribution(0);
        assertTrue(Double.isFinite(tiny.d(0, 0, 1)));
        assertEquals(0, tiny.d(1, 0, 0), 0);
        assertEquals(0, tiny.d(0, 0, -1), 0);
    }
}
