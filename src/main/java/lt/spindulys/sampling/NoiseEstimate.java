package lt.spindulys.sampling;

/**
 * The estimated relative error of a pixel's value, for adaptive sampling: the standard error of
 * the pixel's mean, estimated from how the means of groups of its samples (the
 * rounds of {@link SampleRounds}, or single samples when there is one round) scatter about it,
 * made relative as Cycles makes its error relative
 * ({@code film_adaptive_sampling_convergence_check}).
 *
 * <p>Cycles compares the mean I of all samples with the mean A of every other sample: |I - A| is
 * of the order of I's standard error, but it is one random number (one degree of freedom), and a
 * pixel checked again and again stops early whenever it happens to be small. The scatter of G group means
 * has G - 1 degrees of freedom (3 at the first check of the default schedule, more at each
 * further check). Each group is a stratified set by itself (an aligned block of the pixel's
 * progressive sequence), so the scatter of the group means measures the error of stratified
 * sampling, not the larger spread of single samples; the groups together are one better
 * stratified set, so the estimate errs towards more samples.
 *
 * <p>For group means m_g of s_g samples, n in all and I = sum s_g m_g / n, the variance of I is
 * estimated as {@code sum s_g (m_g - I)^2 / ((G - 1) n)}, per channel: exact in expectation for
 * groups whose means vary as 1 / s_g. A larger stratified round does better than that where
 * stratification pays, so with rounds of growing size the estimate errs towards more samples.
 * With one round (the noise pass without a threshold) the groups are single samples, and the
 * estimate is that of independent samples, above the true error of a stratified set. The error is the sum of
 * the channels' standard errors divided by the sum of I's channels where that is at least 1, and
 * by its square root below (plus 1e-4), as Cycles divides, so that dark pixels, whose absolute
 * noise is small but relative noise large, are not sampled without end. Only the pixel's own
 * samples enter it: the stopping rule does not depend on neighbours, threads or tiles.
 * Per render thread; {@link #reset} for each pixel.
 */
public final class NoiseEstimate {
    private int groups, samples;
    /** Per channel: sum of s_g m_g, and of s_g m_g^2. */
    private double sr, sg, sb, qr, qg, qb;

    /** Forgets the groups: a new pixel. */
    public void reset() {
        groups = samples = 0;
        sr = sg = sb = qr = qg = qb = 0;
    }

    /**
     * Adds a group of samples.
     *
     * @param size the group's samples, at least 1
     * @param r    the group's mean, red
     * @param g    green
     * @param b    blue
     */
    public void add(int size, double r, double g, double b) {
        groups++;
        samples += size;
        sr += size * r; sg += size * g; sb += size * b;
        qr += size * r * r; qg += size * g * g; qb += size * b * b;
    }

    /** {@return the samples added} */
    public int samples() { return samples; }

    /**
     * The estimated relative error of the mean of the groups added.
     *
     * @return at least 0; 0 with fewer than two groups (nothing to compare)
     */
    public double error() {
        if (groups < 2) return 0;
        double n = samples, r = sr / n, g = sg / n, b = sb / n;
        double scale = (groups - 1) * n;
        double se = Math.sqrt(Math.max(0, qr - n * r * r) / scale) + Math.sqrt(Math.max(0, qg - n * g * g) / scale)
                + Math.sqrt(Math.max(0, qb - n * b * b) / scale);
        return relative(se, r + g + b);
    }

    /**
     * An absolute error made relative to a pixel's level as Cycles makes it.
     *
     * @param error the absolute error (summed over the channels)
     * @param level the sum of the pixel's channels
     * @return the relative error
     */
    static double relative(double error, double level) {
        // A filter with negative lobes may leave the level below 0: it is never taken below 0.
        double l = Math.max(0, level);
        return error / (l < 1 ? 1e-4 + Math.sqrt(l) : l);
    }
}
