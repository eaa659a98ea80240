package lt.spindulys.shading;

import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;
import java.util.stream.IntStream;
import java.util.zip.GZIPOutputStream;

/**
 * Computes the resource of {@link MicrofacetAlbedo}: the directional albedo of each
 * single-scattering lobe at every node, by stratified Monte Carlo of the uncompensated lobe's
 * own sampling (K x K strata of the visible-normal pair, the lobe choice Latin-hypercube over
 * them). With K = 256 the standard error is about 5e-4 (1.5e-3 where the glass is rough and seen from inside, E near 0.5).
 *
 * <p>Regenerate (about eight minutes on two cores) with
 * {@code mvn -o -q test -Dtest=MicrofacetAlbedoTest#regenerate -Dalbedo.regenerate=true},
 * then run MicrofacetAlbedoTest and the BSDF tests.
 */
final class MicrofacetAlbedoGenerator {
    static final int STRATA = 256;

    private MicrofacetAlbedoGenerator() {}

    /** {@return the uncompensated lobe of a table at relative index n and a roughness} */
    static Bsdf lobe(int table, double n, double roughness) {
        // The first roughness node is the smooth threshold itself; keep it on the rough side.
        while (roughness * roughness < MicrofacetDistribution.SMOOTH_ALPHA) roughness = Math.nextUp(roughness);
        switch (table) {
            case MicrofacetAlbedo.GLASS_ENTERING: return DielectricBsdf.uncompensated(n, roughness);
            case MicrofacetAlbedo.GLASS_LEAVING: return DielectricBsdf.uncompensated(1 / n, roughness);
            default: return new DielectricSpecularLobe(n, roughness);
        }
    }

    /**
     * {@return the directional albedo of bsdf for wo at cosine mu &gt; 0} (energy: transmission's
     * 1/eta'^2 undone), from strata x strata stratified samples.
     */
    static double albedo(Bsdf bsdf, double mu, int strata, SplittableRandom rng) {
        double wox = Math.sqrt(Math.max(0, 1 - mu * mu)), woz = mu;
        int n = strata * strata;
        int[] order = new int[n];
        for (int i = 0; i < n; i++) order[i] = i;
        for (int i = n - 1; i > 0; i--) { int j = rng.nextInt(i + 1), t = order[i]; order[i] = order[j]; order[j] = t; }
        BsdfSample s = new BsdfSample();
        double sum = 0;
        for (int a = 0; a < strata; a++) {
            for (int b = 0; b < strata; b++) {
                double uc = (order[a * strata + b] + rng.nextDouble()) / n;
                double u1 = (a + rng.nextDouble()) / strata, u2 = (b + rng.nextDouble()) / strata;
                if (!bsdf.sample(wox, 0, woz, uc, u1, u2, s)) continue;
                sum += s.f[1] * Math.abs(s.wiz) / s.pdf * s.eta * s.eta;
            }
        }
        return sum / n;
    }

    /**
     * {@return the cosine a table's mu node i stands for}, x(mu) inverted by bisection; node 0 is
     * grazing, estimated just above it.
     */
    static double muForNode(int i, double roughness) {
        double alpha = Math.max(MicrofacetDistribution.SMOOTH_ALPHA, roughness * roughness);
        double x = Math.max(1e-4, (double) i / (MicrofacetAlbedo.MU - 1));
        if (x >= 1) return 1;
        double lo = 0, hi = 1;
        for (int k = 0; k < 60; k++) {
            double mid = 0.5 * (lo + hi);
            if (MicrofacetAlbedo.muAxis(mid, alpha) < x) lo = mid; else hi = mid;
        }
        return 0.5 * (lo + hi);
    }

    /** {@return all tables, in the resource's order} */
    static double[] compute(int strata) {
        int mu = MicrofacetAlbedo.MU, rough = MicrofacetAlbedo.ROUGHNESS, index = MicrofacetAlbedo.INDEX;
        double[] e = new double[MicrofacetAlbedo.size()];
        int rows = MicrofacetAlbedo.TABLES * index * rough; // one row: all mu of one (table, index, roughness)
        IntStream.range(0, rows).parallel().forEach(row -> {
            int table = row / (index * rough), k = row / rough % index, j = row % rough;
            double n = MicrofacetAlbedo.indexNode(table, k), r = MicrofacetAlbedo.roughnessNode(j);
            Bsdf bsdf = lobe(table, n, r);
            SplittableRandom rng = new SplittableRandom(0x5EED_0000L + row);
            for (int i = 0; i < mu; i++) e[row * mu + i] = albedo(bsdf, muForNode(i, r), strata, rng);
        });
        return e;
    }

    /** Writes the tables as {@link MicrofacetAlbedo} reads them. */
    static void write(double[] e, Path file) throws IOException {
        Files.createDirectories(file.getParent());
        try (OutputStream raw = Files.newOutputStream(file);
                DataOutputStream out = new DataOutputStream(new GZIPOutputStream(raw, 1 << 14))) {
            out.writeInt(MicrofacetAlbedo.MAGIC);
            out.writeInt(MicrofacetAlbedo.MU);
            out.writeInt(MicrofacetAlbedo.ROUGHNESS);
            out.writeInt(MicrofacetAlbedo.INDEX);
            out.writeInt(MicrofacetAlbedo.TABLES);
            int previous = 0;
            for (int n = 0; n < e.length; n++) {
                int q = (int) Math.round(Math.max(0, Math.min(1, e[n])) * 65535);
                out.writeChar(n % MicrofacetAlbedo.MU == 0 ? q : q - previous); // differences along mu, modulo 2^16
                previous = q;
            }
        }
    }

    /** Computes and writes the resource into the source tree (run from the project's directory). */
    public static void main(String[] args) throws IOException {
        Path file = Path.of("src/main/resources/lt/spindulys/shading", MicrofacetAlbedo.RESOURCE);
        long start = System.nanoTime();
        write(compute(STRATA), file);
        System.out.printf("%s: %d bytes in %.1f s%n", file, Files.size(file), (System.nanoTime() - start) * 1e-9);
    }
}
