package lt.spindulys.sampling;

import java.util.Arrays;

/**
 * The order in which an adaptively sampled pixel takes its samples: in rounds, each a stratified
 * set of its own with its own seed, so that the samples are well spread wherever the pixel stops.
 * (One stratified set of n samples covers the pixel, and each padded dimension of its paths, only
 * once all n are taken; a pixel's count is not known in advance.)
 *
 * <p>The first rounds have q = {@code minSamples / 4} samples (at least 4, a 2 x 2 grid, and at
 * most 16, Cycles' interval between checks), as many as reach the minimum and at least two; the
 * error is first checked after them, with at least two round means to compare
 * ({@link NoiseEstimate}). After that each round takes half as many samples as the pixel has
 * (rounded down to a multiple of q, at least q), and the error is checked after each: the checks
 * come at 64, 96, 144, 208, ... samples with the default minimum of 64. Rounds that grow keep
 * their number small: a mean of R independently stratified rounds has about sqrt(R) times the
 * error of one stratified set of as many samples where stratification pays (smooth light, soft
 * shadows): on the soft shadow of AdaptiveSamplingRenderTest (at 256 samples, threshold 0.01)
 * fixed rounds of 16 lost about a fifth of the gain over uniform sampling that these rounds keep. The last round takes the remainder too, so that no round has a single sample (which
 * {@link PixelSampler} puts at the pixel's centre).
 *
 * <p>Without adaptive sampling there is one round of all the samples, seeded with the pass's seed
 * itself: exactly the samples of a render before rounds existed. Round k's seed depends on the
 * pass's seed and k only, so every sample is still seeded from (seed, pixel, round, index), the
 * same for any thread count and tile split. Immutable.
 */
public final class SampleRounds {
    /** Most samples in a round: Cycles checks every 16 samples. */
    public static final int MAX_ROUND = 16;
    /** Fewest samples in a round: a 2 x 2 grid of strata. */
    public static final int MIN_ROUND = 4;

    /** The sizes of the rounds, in order; they add up to the samples per pixel. */
    private final int[] sizes;
    private final int samples;
    /** The first round after which the error is checked. */
    private final int firstCheck;

    private SampleRounds(int samples, int[] sizes, int firstCheck) {
        this.samples = samples;
        this.sizes = sizes;
        this.firstCheck = firstCheck;
    }

    /**
     * One round of all the samples, never checked: a pixel takes them all.
     *
     * @param samples the samples per pixel, at least 1
     * @return the schedule
     */
    public static SampleRounds uniform(int samples) {
        if (samples < 1) throw new IllegalArgumentException("samples per pixel must be positive, found " + samples);
        return new SampleRounds(samples, new int[] {samples}, Integer.MAX_VALUE);
    }

    /**
     * Rounds for adaptive sampling, as the class describes.
     *
     * @param samples    the most samples a pixel takes, at least 1
     * @param minSamples the samples before the first check, 1 to samples
     * @return the schedule
     */
    public static SampleRounds adaptive(int samples, int minSamples) {
        if (minSamples < 1 || minSamples > samples) {
            throw new IllegalArgumentException("minimum samples must be between 1 and " + samples + ", found " + minSamples);
        }
        int size = Math.max(MIN_ROUND, Math.min(MAX_ROUND, minSamples / 4));
        int roundsToMin = Math.max(2, (minSamples + size - 1) / size);
        int[] sizes = new int[16];
        int k = 0;
        for (int taken = 0; taken < samples; k++) {
            int next = k < roundsToMin ? size : Math.max(size, taken / 2 / size * size);
            // The last round takes the remainder too: a round of one sample would be the pixel's centre (PixelSampler).
            if (samples - taken - next < size) next = samples - taken;
            if (k == sizes.length) sizes = Arrays.copyOf(sizes, 2 * k);
            sizes[k] = next;
            taken += next;
        }
        return new SampleRounds(samples, Arrays.copyOf(sizes, k), Math.min(roundsToMin, k) - 1);
    }

    /** {@return the most samples a pixel takes} */
    public int samples() { return samples; }

    /** {@return the number of rounds a pixel that never converges takes} */
    public int rounds() { return sizes.length; }

    /**
     * The samples of round k.
     *
     * @param k the round, 0 to rounds - 1
     * @return its size
     */
    public int size(int k) { return sizes[k]; }

    /**
     * Whether the pixel's error is checked after round k (and the pixel may stop there).
     *
     * @param k the round just finished
     * @return true from the round that reaches the minimum on, except after the last
     */
    public boolean checkAfter(int k) { return k >= firstCheck && k < sizes.length - 1; }

    /**
     * The seed of round k's samples: the pass's own for round 0, a well-mixed other for the rest.
     *
     * @param seed the pass's seed
     * @param k    the round
     * @return the round's seed
     */
    public static long seed(long seed, int k) {
        if (k == 0) return seed;
        // SplitMix64's finaliser of the seed moved along by the round: no allocation per pixel.
        long z = seed + (k + 1) * 0x9E3779B97F4A7C15L ^ 0x726f756e64L; // "round"
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
