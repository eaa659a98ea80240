package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The per-thread reusable BSDF: re-set in any order it answers bit for bit as a freshly built
 * material BSDF with the same terms, and setting and querying it allocates nothing.
 */
class SurfaceBsdfTest {
    /** One parameter set of either model; the test's own record, so allocation here is fine. */
    private record Params(boolean principled, double[] v, boolean fresnel) {
        void apply(SurfaceBsdf s) {
            if (principled) s.setPrincipled(v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
            else s.setWhitted(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], fresnel);
        }

        Bsdf fresh() {
            return principled
                    ? new PrincipledBsdf(v[0], v[1], v[2], v[3], v[4], v[5], v[6])
                    : WhittedMaterialBsdf.fromWhittedTerms(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], fresnel);
        }

        @Override
        public String toString() {
            return (principled ? "principled " : "whitted fresnel=" + fresnel + " ") + java.util.Arrays.toString(v);
        }
    }

    /** Picks one of the edge values half of the time, otherwise a uniform in [lo, hi). */
    private static double pick(SplittableRandom rng, double lo, double hi, double... edges) {
        if (edges.length > 0 && rng.nextBoolean()) return edges[rng.nextInt(edges.length)];
        return lo + (hi - lo) * rng.nextDouble();
    }

    private static double ior(SplittableRandom rng) {
        return pick(rng, 0.5, 2.6, 1, 1.5, 1 / 1.33, 1.33, 2.4, 1 + 1e-12);
    }

    private static List<Params> parameterSets(long seed, int n) {
        SplittableRandom rng = new SplittableRandom(seed);
        List<Params> all = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            if (rng.nextBoolean()) {
                all.add(new Params(true, new double[] {
                    pick(rng, 0, 1, 0, 1), pick(rng, 0, 1, 0, 1), pick(rng, 0, 1, 0, 1),
                    pick(rng, 0, 1, 0, 1, 0.5), pick(rng, 0, 1, 0, 0.01, 0.03, 0.0316, 0.04, 1),
                    ior(rng), pick(rng, 0, 1, 0, 1)}, false));
            } else {
                // Coefficients past 1 and below 0 (sums above 1, clamping), shininess from rough to mirror.
                all.add(new Params(false, new double[] {
                    pick(rng, -0.2, 1.2, 0, 1), pick(rng, 0, 1, 0, 1), pick(rng, 0, 1, 0, 1),
                    pick(rng, -0.1, 1.5, 0, 1), pick(rng, 0, 1.5, 0, 1), pick(rng, 0, 2000, 0, -3, 1e7, 1e12),
                    pick(rng, 0, 1.5, 0, 1), pick(rng, 0, 1.5, 0, 1), ior(rng),
                    pick(rng, -0.2, 1.2, 0, 1), pick(rng, 0, 1, 0, 1), pick(rng, 0, 1, 0, 1)}, rng.nextBoolean()));
            }
        }
        return all;
    }

    /** A direction uniform on the sphere, or now and then a special one (normal, grazing, in the surface). */
    private static double[] direction(SplittableRandom rng) {
        switch (rng.nextInt(12)) {
            case 0: return new double[] {0, 0, 1};
            case 1: return new double[] {0, 0, -1};
            case 2: return new double[] {1, 0, 0};
            case 3: { double z = 1e-9, s = Math.sqrt(1 - z * z); return new double[] {s, 0, z}; }
            default: {
                double z = 2 * rng.nextDouble() - 1, phi = 2 * Math.PI * rng.nextDouble(), s = Math.sqrt(Math.max(0, 1 - z * z));
                return new double[] {s * Math.cos(phi), s * Math.sin(phi), z};
            }
        }
    }

    @Test
    void resetInRandomOrderMatchesFreshConstructionBitForBit() {
        List<Params> sets = parameterSets(0x5EEDL, 400);
        SplittableRandom rng = new SplittableRandom(42);
        SurfaceBsdf reused = new SurfaceBsdf();
        double[] expectedRgb = new double[3], actualRgb = new double[3];
        BsdfSample expectedSample = new BsdfSample(), actualSample = new BsdfSample();
        for (int step = 0; step < 3000; step++) {
            Params p = sets.get(rng.nextInt(sets.size()));
            p.apply(reused);
            Bsdf fresh = p.fresh();
            assertEquals(fresh.isSpecular(), reused.isSpecular(), p::toString);
            for (int q = 0; q < 8; q++) {
                double[] wo = direction(rng), wi = direction(rng);
                if (q == 0) wi = new double[] {-wo[0], -wo[1], wo[2]}; // the mirror direction
                double uc = rng.nextDouble(), u1 = rng.nextDouble(), u2 = rng.nextDouble();
                String where = p + " wo " + java.util.Arrays.toString(wo) + " wi " + java.util.Arrays.toString(wi)
                        + " u " + uc + " " + u1 + " " + u2;
                fresh.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], expectedRgb);
                reused.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], actualRgb);
                for (int c = 0; c < 3; c++) assertEquals(expectedRgb[c], actualRgb[c], where);
                assertEquals(fresh.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]),
                        reused.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]), where);
                boolean expectedOk = fresh.sample(wo[0], wo[1], wo[2], uc, u1, u2, expectedSample);
                boolean actualOk = reused.sample(wo[0], wo[1], wo[2], uc, u1, u2, actualSample);
                assertSameSample(expectedOk, expectedSample, actualOk, actualSample, where);
                if (expectedOk) {
                    // And at the sampled direction, where the rough lobes are not zero.
                    fresh.eval(wo[0], wo[1], wo[2], expectedSample.wix, expectedSample.wiy, expectedSample.wiz, expectedRgb);
                    reused.eval(wo[0], wo[1], wo[2], expectedSample.wix, expectedSample.wiy, expectedSample.wiz, actualRgb);
                    for (int c = 0; c < 3; c++) assertEquals(expectedRgb[c], actualRgb[c], where);
                    assertEquals(fresh.pdf(wo[0], wo[1], wo[2], expectedSample.wix, expectedSample.wiy, expectedSample.wiz),
                            reused.pdf(wo[0], wo[1], wo[2], expectedSample.wix, expectedSample.wiy, expectedSample.wiz), where);
                }
            }
        }
    }

    private static void assertSameSample(boolean expectedOk, BsdfSample e, boolean actualOk, BsdfSample a, String where) {
        assertEquals(expectedOk, actualOk, where);
        assertEquals(e.wix, a.wix, where);
        assertEquals(e.wiy, a.wiy, where);
        assertEquals(e.wiz, a.wiz, where);
        for (int c = 0; c < 3; c++) assertEquals(e.f[c], a.f[c], where);
        assertEquals(e.pdf, a.pdf, where);
        assertEquals(e.specular, a.specular, where);
        assertEquals(e.eta, a.eta, where);
    }

    @Test
    void theParameterSetsReachTheDegenerateCases() {
        // Guards the generator: the comparison above is only as good as the cases it meets.
        List<Params> sets = parameterSets(0x5EEDL, 400);
        assertTrue(sets.stream().anyMatch(p -> p.principled() && p.v()[4] == 0 && p.v()[3] == 1));
        assertTrue(sets.stream().anyMatch(p -> p.principled() && p.v()[5] == 1));
        assertTrue(sets.stream().anyMatch(p -> p.principled() && p.v()[6] == 1 && p.v()[3] == 0));
        assertTrue(sets.stream().anyMatch(p -> !p.principled() && p.v()[7] == 1 && p.fresnel()));
        assertTrue(sets.stream().anyMatch(p -> !p.principled() && p.v()[7] == 1 && !p.fresnel()));
        assertTrue(sets.stream().anyMatch(p -> !p.principled() && p.v()[3] + p.v()[4] + p.v()[6] + p.v()[7] > 1));
        assertTrue(sets.stream().anyMatch(p -> !p.principled() && p.v()[8] == 1));
    }

    @Test
    void aRejectedSetKeepsThePreviousConfiguration() {
        SurfaceBsdf s = new SurfaceBsdf();
        s.setPrincipled(0.8, 0.5, 0.2, 0.3, 0.4, 1.5, 0.2);
        Bsdf fresh = new PrincipledBsdf(0.8, 0.5, 0.2, 0.3, 0.4, 1.5, 0.2);
        assertThrows(IllegalArgumentException.class, () -> s.setPrincipled(0.8, 0.5, 0.2, 0.3, 1.5, 1.33, 0.2));
        assertThrows(IllegalArgumentException.class, () -> s.setPrincipled(0.1, 0.1, 0.1, 0, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> s.setWhitted(1, 1, 1, 0.5, 0, 0, 0, 0.5, -1, 1, 1, 1, false));
        assertThrows(IllegalArgumentException.class, () -> s.setWhitted(1, 1, 1, 0.5, 0, 0, 0, 0.5, Double.POSITIVE_INFINITY, 1, 1, 1, true));
        double[] wo = {0.3, 0.2, Math.sqrt(1 - 0.13)}, wi = {-0.5, 0.1, Math.sqrt(1 - 0.26)};
        double[] e = new double[3], a = new double[3];
        fresh.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], e);
        s.eval(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2], a);
        for (int c = 0; c < 3; c++) assertEquals(e[c], a[c]);
        assertEquals(fresh.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]), s.pdf(wo[0], wo[1], wo[2], wi[0], wi[1], wi[2]));
    }

    @Test
    void scattersNothingBeforeTheFirstSet() {
        SurfaceBsdf s = new SurfaceBsdf();
        double[] rgb = {7, 7, 7};
        s.eval(0, 0, 1, 0, 0, 1, rgb);
        assertEquals(0, rgb[0] + rgb[1] + rgb[2]);
        assertEquals(0, s.pdf(0, 0, 1, 0, 0, 1));
        assertFalse(s.sample(0, 0, 1, 0.5, 0.5, 0.5, new BsdfSample()));
    }

    @Test
    void settingAndQueryingAllocatesNothing() {
        assumeTrue(ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean,
                "needs HotSpot's per-thread allocation counter");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(mx.isThreadAllocatedMemorySupported() && mx.isThreadAllocatedMemoryEnabled());
        SurfaceBsdf s = new SurfaceBsdf();
        BsdfSample sample = new BsdfSample();
        double[] rgb = new double[3];
        long tid = Thread.currentThread().getId();
        double sink = run(s, sample, rgb, 20_000); // warm up (class loading, compilation)
        long before = mx.getThreadAllocatedBytes(tid);
        sink += run(s, sample, rgb, 100_000);
        long used = mx.getThreadAllocatedBytes(tid) - before;
        // 100,000 x 4 calls: even one small object per call would be megabytes; the slack is TextureAllocationTest's.
        assertTrue(used < 64 * 1024, "allocated " + used + " bytes (sink " + sink + ")");
    }

    /** Alternates the two models with parameters varying per iteration, as textures would, and queries each. */
    private static double run(SurfaceBsdf s, BsdfSample sample, double[] rgb, int n) {
        double sum = 0;
        for (int i = 0; i < n; i++) {
            double t = (i * 0.6180339887498949) % 1, u = (i * 0.7548776662466927) % 1, v = (i * 0.5698402909980532) % 1;
            if ((i & 1) == 0) {
                // Indices from a handful of materials, and now and then one never seen (a cache miss).
                double ior = i % 97 == 0 ? 1.2 + t : i % 4 == 0 ? 1.5 : i % 4 == 2 ? 1.33 : 1 / 1.33;
                s.setPrincipled(t, u, v, (i % 5) / 4.0, (i % 11) / 10.0, ior, (i % 3) / 2.0);
            } else {
                s.setWhitted(t, u, v, 0.6 * u, 0.4 * v, 100 * t, (i % 3) * 0.2, (i % 7) / 6.0, 1.5, v, t, u, i % 6 == 1);
            }
            double woz = 2 * t - 1, wor = Math.sqrt(1 - woz * woz);
            double wox = wor * Math.cos(7 * u), woy = wor * Math.sin(7 * u);
            if (s.sample(wox, woy, woz, u, v, t, sample)) sum += sample.f[0] + sample.pdf;
            s.eval(wox, woy, woz, -woy, wox, woz, rgb);
            sum += rgb[1];
            sum += s.pdf(wox, woy, woz, -wox, -woy, woz);
        }
        return sum;
    }
}
