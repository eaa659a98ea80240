package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The albedo table of the single-scattering lobes: its interpolation against fresh Monte Carlo, and its regeneration. */
class MicrofacetAlbedoTest {
    /** Rewrites the resource; only with -Dalbedo.regenerate=true (see {@link MicrofacetAlbedoGenerator}). */
    @Test
    void regenerate() throws Exception {
        assumeTrue(Boolean.getBoolean("albedo.regenerate"), "set -Dalbedo.regenerate=true to rewrite the table");
        MicrofacetAlbedoGenerator.main(new String[0]);
    }

    private static double tabulated(int table, double n, double roughness, double mu) {
        double alpha = roughness * roughness;
        return MicrofacetAlbedo.lookup(table, MicrofacetAlbedo.indexCoordinate(table, n),
                MicrofacetAlbedo.roughnessCoordinate(alpha), MicrofacetAlbedo.muCoordinate(mu, alpha));
    }

    /**
     * Between the nodes (random indices, roughnesses and cosines, none on the grid) the table
     * agrees with fresh stratified Monte Carlo of the lobe within 5e-3: relative for the glass,
     * whose E divides the lobe, absolute for the coat, whose 1 - E the base takes. Indices of real
     * materials, 1.2 to 2.4, cosines from 0.02. Typically the error is below 1e-3 (the table's own
     * noise is about 5e-4); it reaches 2e-3 to 5e-3 where E bends sharply, for very rough glass
     * near normal incidence and at grazing, and 1e-2 for glass of index 1.07 seen from inside at grazing.
     */
    @Test
    void interpolationMatchesFreshMonteCarlo() {
        SplittableRandom rng = new SplittableRandom(11);
        for (int trial = 0; trial < 120; trial++) {
            int table = trial % MicrofacetAlbedo.TABLES;
            double n = 1.2 + 1.2 * rng.nextDouble();
            double r = MicrofacetAlbedo.ROUGHNESS_MIN + 1e-3 + (1 - MicrofacetAlbedo.ROUGHNESS_MIN - 1e-3) * rng.nextDouble();
            double mu = 0.02 + 0.98 * rng.nextDouble();
            double mc = MicrofacetAlbedoGenerator.albedo(MicrofacetAlbedoGenerator.lobe(table, n, r), mu, 160, rng);
            double e = tabulated(table, n, r, mu);
            double error = table == MicrofacetAlbedo.COAT ? Math.abs(e - mc) : Math.abs(e / mc - 1);
            assertTrue(error <= 5e-3, String.format("table %d n %.4f roughness %.4f mu %.4f: %.5f, Monte Carlo %.5f", table, n, r, mu, e, mc));
        }
    }

    /** At the nodes the table is the generator's estimate, to its Monte Carlo noise (about 7e-4) and a finer estimate's. */
    @Test
    void nodesHoldTheGeneratorsEstimates() {
        SplittableRandom rng = new SplittableRandom(12);
        for (int table = 0; table < MicrofacetAlbedo.TABLES; table++) {
            for (int k : new int[] {0, 5, MicrofacetAlbedo.INDEX - 1}) {
                for (int j : new int[] {0, 9, MicrofacetAlbedo.ROUGHNESS - 1}) {
                    for (int i : new int[] {3, 17, MicrofacetAlbedo.MU - 1}) {
                        double n = MicrofacetAlbedo.indexNode(table, k), r = MicrofacetAlbedo.roughnessNode(j);
                        double mu = MicrofacetAlbedoGenerator.muForNode(i, r);
                        double e = MicrofacetAlbedo.lookup(table, k, j, i);
                        double mc = MicrofacetAlbedoGenerator.albedo(MicrofacetAlbedoGenerator.lobe(table, n, r), mu, 256, rng);
                        assertEquals(mc, e, 2.5e-3, "table " + table + " node " + k + "," + j + "," + i);
                    }
                }
            }
        }
    }

    /** The coat's hemispherical average is the smooth Fresnel average where the coat is nearly smooth, and 0 at index 1. */
    @Test
    void coatAverageAgreesWithFresnelWhenNearlySmooth() {
        for (double n : new double[] {1.2, 1.5, 2.4}) {
            double e = MicrofacetAlbedo.coatAverage(MicrofacetAlbedo.indexCoordinate(MicrofacetAlbedo.COAT, n), 0);
            assertEquals(FresnelDiffuseLobe.averageFresnel(n), e, 3e-3, "index " + n);
        }
        assertEquals(0, MicrofacetAlbedo.coatAverage(0, 10), 1e-4);
    }
}
