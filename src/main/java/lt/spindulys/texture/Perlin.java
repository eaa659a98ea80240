package lt.spindulys.texture;

/**
 * Perlin gradient noise in three dimensions (Perlin's 2002 "improved" scheme: a quintic fade and
 * gradients towards the twelve edge midpoints of a cube), with turbulence and fractal sums.
 *
 * <p>The permutation is a fixed shuffle from a constant seed, so every run and every thread sees
 * the same noise. Noise is exactly 0 at integer lattice points, continuous with continuous first
 * and second derivatives, and lies in about [-1, 1]. Stateless and allocation-free.
 */
public final class Perlin {
    private Perlin() {}

    private static final int[] P = new int[512];
    /** Edge-midpoint gradients of the cube, (x, y, z) per row. */
    private static final double[] G = {
        1, 1, 0, -1, 1, 0, 1, -1, 0, -1, -1, 0,
        1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, -1,
        0, 1, 1, 0, -1, 1, 0, 1, -1, 0, -1, -1,
    };

    static {
        int[] perm = new int[256];
        for (int i = 0; i < 256; i++) perm[i] = i;
        // Fisher-Yates driven by SplitMix64 from a fixed seed: deterministic, well mixed.
        long state = 0x5350494E44554CL;  // "SPINDUL"
        for (int i = 255; i > 0; i--) {
            state += 0x9E3779B97F4A7C15L;
            long z = state;
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            z ^= z >>> 31;
            int j = (int) Long.remainderUnsigned(z, i + 1);
            int t = perm[i];
            perm[i] = perm[j];
            perm[j] = t;
        }
        for (int i = 0; i < 512; i++) P[i] = perm[i & 255];
    }

    /**
     * Noise at (x, y, z); 0 at every integer lattice point.
     *
     * @param x the point's x
     * @param y the point's y
     * @param z the point's z
     * @return the noise, in about [-1, 1]
     */
    public static double noise(double x, double y, double z) {
        double fx = Math.floor(x), fy = Math.floor(y), fz = Math.floor(z);
        int xi = (int) (long) fx & 255, yi = (int) (long) fy & 255, zi = (int) (long) fz & 255;
        x -= fx;
        y -= fy;
        z -= fz;
        double u = fade(x), v = fade(y), w = fade(z);
        int a = P[xi] + yi, aa = P[a] + zi, ab = P[a + 1] + zi;
        int b = P[xi + 1] + yi, ba = P[b] + zi, bb = P[b + 1] + zi;
        double x1 = x - 1, y1 = y - 1, z1 = z - 1;
        return lerp(w,
                lerp(v, lerp(u, grad(P[aa], x, y, z), grad(P[ba], x1, y, z)),
                        lerp(u, grad(P[ab], x, y1, z), grad(P[bb], x1, y1, z))),
                lerp(v, lerp(u, grad(P[aa + 1], x, y, z1), grad(P[ba + 1], x1, y, z1)),
                        lerp(u, grad(P[ab + 1], x, y1, z1), grad(P[bb + 1], x1, y1, z1))));
    }

    /**
     * Turbulence: {@code sum over k < octaves of |noise(2^k p)| / 2^k}; in [0, 2).
     *
     * @param x the point's x
     * @param y the point's y
     * @param z the point's z
     * @param octaves how many octaves, at least 1
     * @return the turbulence
     */
    public static double turbulence(double x, double y, double z, int octaves) {
        double sum = 0, f = 1;
        for (int k = 0; k < octaves; k++, f *= 2) sum += Math.abs(noise(x * f, y * f, z * f)) / f;
        return sum;
    }

    /**
     * Fractal sum: {@code sum over k < octaves of noise(2^k p) / 2^k}; in about (-2, 2).
     *
     * @param x the point's x
     * @param y the point's y
     * @param z the point's z
     * @param octaves how many octaves, at least 1
     * @return the sum
     */
    public static double fbm(double x, double y, double z, int octaves) {
        double sum = 0, f = 1;
        for (int k = 0; k < octaves; k++, f *= 2) sum += noise(x * f, y * f, z * f) / f;
        return sum;
    }

    private static double fade(double t) {
        return t * t * t * (t * (t * 6 - 15) + 10);
    }

    private static double lerp(double t, double a, double b) {
        return a + t * (b - a);
    }

    private static double grad(int hash, double x, double y, double z) {
        int g = (hash % 12) * 3;
        return G[g] * x + G[g + 1] * y + G[g + 2] * z;
    }
}
