package lt.spindulys.sampling;

import java.util.Arrays;

/**
 * The order in which an adaptively sampled pixel takes its samples: in rounds, after each of
 * which (from the minimum on) its error is checked. The samples are one progressive sequence over
 * the pixel ({@link ProgressiveSequence}, drawn by {@link PixelSampler#startProgressive} and the
 * integrators' progressive strata), and each round is an aligned block of it whose size is a
 * power of two: the samples a pixel has taken when it stops are then stratified as one set (a
 * multiple of 2^m samples is stratified in the elementary intervals of area 2^-m), and each
 * round is itself a stratified set, whose mean {@link NoiseEstimate} compares with the others'.
 * (Rounds drawn each as its own stratified set, as before, lost that: their union is not
 * stratified, which cost 19 % in relMSE on the Cornell box with no pixel stopping early.)
 *
 * <p>The first rounds have q samples, the power of two at most {@code minSamples / 4} (at least
 * 4, at most 16, Cycles' interval between checks), as many as reach the minimum and at least
 * two; the error is first checked after them. After that each round takes the largest power of
 * two up to half the samples so far that divides them (at least q), and the error is checked
 * after each: with the default minimum of 64 the checks come at 64, 96, 128, 192, 256, 384, ...,
 * each a power of two or 1.5 times one. Rounds that grow keep their number, and the cost of the
 * checks, small. The last round takes the remainder too, so that no round has a single sample.
 *
 * <p>Without adaptive sampling there is one round of all the samples, seeded with the pass's seed
 * itself and drawn as one stratified set: exactly the samples of a render before rounds existed.
 * Immutable.
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
        int size = Integer.highestOneBit(Math.max(MIN_ROUND, Math.min(MAX_ROUND, minSamples / 4)));
        int roundsToMin = Math.max(2, (minSamples + size - 1) / size);
        int[] sizes = new int[16];
        int k = 0;
        for (int taken = 0; taken < samples; k++) {
            int next = size;
            if (k >= roundsToMin) {
                // The largest power of two up to half the samples taken that divides them: the round is an aligned block of the sequence.
                next = Integer.highestOneBit(Math.max(size, taken / 2));
                while (taken % next != 0) next >>= 1;
            }
            // The last round takes the remainder too: a round of one sample would compare nothing.
            if (samples - taken - next < size) next = samples - taken;
            if (k == sizes.length) sizes = Arrays.copyOf(sizes, 2 * k);
            sizes[k] = next;
            taken += next;
        }
        return new SampleRounds(samples, Arrays.copyOf(sizes, k), Math.min(roundsToMin, k) - 1);
    }

    /** {@return the most samples a pixel takes} */
    public int samples() { return samples; }

    /** {@return the samples of the largest round} */
    public int largest() {
        int m = 0;
        for (int size : sizes) m = Math.max(m, size);
        return m;
    }

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
}
