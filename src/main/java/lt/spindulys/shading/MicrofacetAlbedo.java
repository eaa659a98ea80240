package lt.spindulys.shading;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.util.zip.GZIPInputStream;

/**
 * Directional albedos of the single-scattering GGX dielectric lobes, tabulated offline
 * (MicrofacetAlbedoGenerator in the tests regenerates the resource) and interpolated
 * trilinearly: E(mu, roughness, n) of {@link DielectricBsdf} seen from the less dense side
 * (relative index n &gt;= 1), from the denser side (relative index 1/n), and of
 * {@link DielectricSpecularLobe} (index n). E is energy: the 1/eta'^2 radiance factor of
 * transmission is undone. Whatever the single-scattering model loses, E says how much, so a
 * lobe divided by E conserves energy, and a layer under a coat can take 1 - E.
 *
 * <p>Axes, chosen so that E varies smoothly along each:
 * <ul>
 * <li>roughness r = sqrt(alpha) from {@link #ROUGHNESS_MIN} (the smooth threshold) to 1, uniform;</li>
 * <li>mu through x = (u + sqrt(mu)) / 2 with u = mu / (mu + alpha sin) (Smith's a = cot / alpha
 *   mapped to a / (1 + a)), uniform: u resolves the grazing dip of E, which sits near a = 1, at
 *   ever smaller mu as alpha shrinks, and sqrt(mu) the Fresnel variation over the rest and the
 *   steep rise of E towards 1 at the very horizon;</li>
 * <li>the index through t = (n - 1) / (n + 1) (t^2 is the normal reflectance), up to n = 3,
 *   with nodes uniform in sqrt(t - t_min), denser where E changes fastest. The glass tables start
 *   at n = {@link #GLASS_INDEX_MIN}: nearer 1 a rough interface degenerates (E falls steeply at
 *   grazing as n tends to 1), and the clamp there under-compensates, never adds energy. The
 *   coat's starts at n = 1, where E = 0.</li>
 * </ul>
 * Immutable after class initialisation (a 100 KB read); the lookups allocate nothing.
 */
final class MicrofacetAlbedo {
    static final int MU = 40, ROUGHNESS = 32, INDEX = 16;
    static final double ROUGHNESS_MIN = Math.sqrt(MicrofacetDistribution.SMOOTH_ALPHA), INDEX_MAX = 3;
    static final double GLASS_INDEX_MIN = 1.05;
    /** The tables in the resource's order. */
    static final int GLASS_ENTERING = 0, GLASS_LEAVING = 1, COAT = 2, TABLES = 3;
    static final String RESOURCE = "microfacet-albedo.bin.gz";
    static final int MAGIC = 0x45414c42; // "EALB"

    /** E quantised to 16 bits, [table][index][roughness][mu]; read on the first lookup, so the grid is usable without it. */
    private static final class Table {
        static final char[] E = load();
        /** The coat's cosine-weighted hemispherical average 2 int E mu dmu at each (index, roughness) node. */
        static final double[] COAT_AVERAGE = coatAverages();
    }

    private MicrofacetAlbedo() {}

    /** {@return the roughness of node j} */
    static double roughnessNode(int j) {
        return ROUGHNESS_MIN + (1 - ROUGHNESS_MIN) * j / (ROUGHNESS - 1);
    }

    /** {@return the lowest index of a table's axis} */
    static double indexMin(int table) { return table == COAT ? 1 : GLASS_INDEX_MIN; }

    /** {@return the relative index of node k of a table} */
    static double indexNode(int table, int k) {
        double t0 = toT(indexMin(table)), t1 = toT(INDEX_MAX);
        double s = (double) k / (INDEX - 1), t = t0 + (t1 - t0) * s * s;
        return (1 + t) / (1 - t);
    }

    private static double toT(double n) { return (n - 1) / (n + 1); }

    /** {@return x(mu) in [0,1], the mu axis's variable, for GGX alpha} */
    static double muAxis(double mu, double alpha) {
        mu = Math.min(1, Math.abs(mu));
        double sin = Math.sqrt(Math.max(0, 1 - mu * mu));
        double u = mu / (mu + alpha * sin);
        return Double.isNaN(u) ? 0 : 0.5 * (u + Math.sqrt(mu));
    }

    /**
     * The continuous roughness coordinate of a GGX alpha, clamped to the table: j + fraction.
     * Computed once per configuration, so that per-direction lookups cost only the mu axis.
     */
    static double roughnessCoordinate(double alpha) {
        double r = Math.sqrt(alpha);
        double x = (r - ROUGHNESS_MIN) / (1 - ROUGHNESS_MIN) * (ROUGHNESS - 1);
        return Math.max(0, Math.min(ROUGHNESS - 1, x));
    }

    /** The continuous index coordinate of relative index n (&gt;= 1) in a table, clamped. */
    static double indexCoordinate(int table, double n) {
        double t0 = toT(indexMin(table)), t1 = toT(INDEX_MAX);
        double x = Math.sqrt(Math.max(0, (toT(n) - t0) / (t1 - t0))) * (INDEX - 1);
        return Math.max(0, Math.min(INDEX - 1, x));
    }

    /** {@return the continuous mu coordinate of cosine mu for GGX alpha}, in [0, MU - 1]. */
    static double muCoordinate(double mu, double alpha) {
        return muAxis(mu, alpha) * (MU - 1);
    }

    /**
     * {@return E at the continuous coordinates}, trilinear between the nodes.
     *
     * @param table {@link #GLASS_ENTERING}, {@link #GLASS_LEAVING} or {@link #COAT}
     * @param indexCoord from {@link #indexCoordinate}
     * @param roughnessCoord from {@link #roughnessCoordinate}
     * @param muCoord from {@link #muCoordinate}
     */
    static double lookup(int table, double indexCoord, double roughnessCoord, double muCoord) {
        int k = Math.min(INDEX - 2, (int) indexCoord), j = Math.min(ROUGHNESS - 2, (int) roughnessCoord), i = Math.min(MU - 2, (int) muCoord);
        double fk = indexCoord - k, fj = roughnessCoord - j, fi = muCoord - i;
        int base = ((table * INDEX + k) * ROUGHNESS + j) * MU + i;
        int nextIndex = ROUGHNESS * MU;
        double e00 = lerp(base, fi), e01 = lerp(base + MU, fi);
        double e10 = lerp(base + nextIndex, fi), e11 = lerp(base + nextIndex + MU, fi);
        double e0 = e00 + (e01 - e00) * fj, e1 = e10 + (e11 - e10) * fj;
        return (e0 + (e1 - e0) * fk) * (1.0 / 65535);
    }

    private static double lerp(int at, double f) {
        char[] e = Table.E;
        double a = e[at], b = e[at + 1];
        return a + (b - a) * f;
    }

    /**
     * {@return the coat's E_avg = 2 int_0^1 E(mu) mu dmu}, bilinear between the nodes' averages of
     * the interpolated E, so that it matches {@link #lookup} of the coat to the quadrature's accuracy.
     */
    static double coatAverage(double indexCoord, double roughnessCoord) {
        int k = Math.min(INDEX - 2, (int) indexCoord), j = Math.min(ROUGHNESS - 2, (int) roughnessCoord);
        double fk = indexCoord - k, fj = roughnessCoord - j;
        double[] a = Table.COAT_AVERAGE;
        int at = k * ROUGHNESS + j;
        double e0 = a[at] + (a[at + 1] - a[at]) * fj, e1 = a[at + ROUGHNESS] + (a[at + ROUGHNESS + 1] - a[at + ROUGHNESS]) * fj;
        return e0 + (e1 - e0) * fk;
    }

    private static double[] coatAverages() {
        double[] average = new double[INDEX * ROUGHNESS];
        final int panels = 64; // midpoint rule in s = sqrt(mu), where E is smooth: 2 int E mu dmu = 4 int E s^3 ds
        for (int k = 0; k < INDEX; k++) {
            for (int j = 0; j < ROUGHNESS; j++) {
                double r = roughnessNode(j), alpha = r * r, sum = 0;
                for (int p = 0; p < panels; p++) {
                    double s = (p + 0.5) / panels, mu = s * s;
                    sum += lookup(COAT, k, j, muCoordinate(mu, alpha)) * s * s * s;
                }
                average[k * ROUGHNESS + j] = 4 * sum / panels;
            }
        }
        return average;
    }

    /** {@return the number of 16-bit entries of the resource} */
    static int size() { return TABLES * INDEX * ROUGHNESS * MU; }

    private static char[] load() {
        byte[] bytes;
        try (InputStream raw = MicrofacetAlbedo.class.getResourceAsStream(RESOURCE)) {
            if (raw == null) throw new IllegalStateException("missing resource " + RESOURCE);
            bytes = new GZIPInputStream(raw, 1 << 16).readAllBytes();
        } catch (IOException ex) {
            throw new UncheckedIOException(ex);
        }
        ByteBuffer in = ByteBuffer.wrap(bytes); // big-endian, as DataOutputStream wrote it
        if (bytes.length != 20 + 2 * size() || in.getInt() != MAGIC || in.getInt() != MU || in.getInt() != ROUGHNESS
                || in.getInt() != INDEX || in.getInt() != TABLES)
            throw new IllegalStateException(RESOURCE + " does not match the table's layout: regenerate it");
        // Stored as differences along mu (modulo 2^16), which compress better than the values.
        char[] e = new char[size()];
        for (int n = 0; n < e.length; n++) e[n] = (char) (in.getChar() + (n % MU == 0 ? 0 : e[n - 1]));
        return e;
    }
}
