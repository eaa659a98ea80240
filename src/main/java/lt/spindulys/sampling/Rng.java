package lt.spindulys.sampling;

/**
 * A small, fast, reseedable random generator (SplitMix64). Reseeded from (global seed, pixel,
 * purpose) so that every random number depends only on where it is used, never on which thread
 * or in which order pixels are rendered.
 */
public final class Rng {
    private long state;

    public Rng seed(long seed) {
        state = seed;
        return this;
    }

    /** Reseeds from a global seed and up to three integers (pixel x, y, and a stream id). */
    public Rng seed(long global, int a, int b, int c) {
        long h = mix(global ^ 0x9E3779B97F4A7C15L);
        h = mix(h ^ (a * 0xC2B2AE3D27D4EB4FL));
        h = mix(h ^ (b * 0x165667B19E3779F9L));
        h = mix(h ^ (c * 0xD6E8FEB86659FD93L));
        state = h;
        return this;
    }

    public long nextLong() {
        state += 0x9E3779B97F4A7C15L;
        return mix(state);
    }

    /** Uniform in [0, 1). */
    public double nextDouble() {
        return (nextLong() >>> 11) * 0x1.0p-53;
    }

    /** Uniform in [0, bound). */
    public int nextInt(int bound) {
        return (int) (((nextLong() >>> 33) * bound) >>> 31);
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
