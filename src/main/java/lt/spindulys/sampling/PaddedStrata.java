package lt.spindulys.sampling;

/**
 * Stratified random numbers for the first dimensions of a pixel's paths ("padded" strata, as
 * pbrt's stratified sampler pads them): for each dimension, or pair of dimensions, the pixel's n
 * samples fall into n strata of the unit interval or square, one each, in an order shuffled
 * independently per pixel and dimension, and jittered within their stratum. Over a pixel's
 * samples each dimension is then evenly covered, which lowers the noise of the light a pixel sees
 * off its first surfaces (soft shadows, glossy reflections, one bounce) against independent
 * numbers, while the dimensions stay uncorrelated with one another.
 *
 * <p>The shuffles are Kensler's hashed permutations ("Correlated Multi-Jittered Sampling", Pixar
 * technical memo 13-01, 2013): a bijection of [0, n) computed from its index and a seed, so that
 * nothing is stored per pixel, and every number depends only on the seed, the pixel, the sample
 * index and the dimension: the same for any thread count and tile split. Not thread-safe: one per
 * render thread.
 *
 * <p><b>Progressive.</b> An adaptively sampled pixel does not know its count in advance:
 * {@link #startProgressive} draws each dimension (or pair) from its own
 * {@link ProgressiveSequence} instead, at the sample's index in the pixel, so that the samples
 * the pixel has taken are stratified wherever it stops.
 */
public final class PaddedStrata {
    private final Rng hash = new Rng();
    private long pixelHash;
    private int samples = 1, sample, cols = 1, rows = 1;
    /** Drawing from the progressive sequences ({@link #startProgressive}) rather than from strata. */
    private boolean progressive;
    /** The pixel's hash for its sequences' keys ({@link ProgressiveSequence#pixel}). */
    private long pixelKey;

    /**
     * Starts a pixel sample.
     *
     * @param seed    the pass's global seed
     * @param px      pixel column
     * @param py      pixel row
     * @param sample  the sample's index in the pixel, 0 .. samples - 1
     * @param samples the pixel's sample count, at least 1
     */
    public void start(long seed, int px, int py, int sample, int samples) {
        if (samples != this.samples) {
            this.samples = samples;
            // A count that changes (another pass, a pixel of one adaptive round) allocates nothing.
            cols = PixelSampler.gridColumns(samples);
            rows = (samples + cols - 1) / cols;
        }
        this.sample = sample;
        progressive = false;
        pixelHash = hash.seed(seed, px, py, 0x73747261).nextLong(); // "stra"
    }

    /**
     * Starts a pixel sample of a pixel whose count is open (adaptive sampling): every dimension
     * is then point {@code sample} of its own {@link ProgressiveSequence}, and the jitter
     * generators passed to {@link #get1D} and {@link #get2D} are not drawn from.
     *
     * @param seed   the pass's global seed
     * @param px     pixel column
     * @param py     pixel row
     * @param sample the sample's index in the pixel, from 0
     */
    public void startProgressive(long seed, int px, int py, int sample) {
        progressive = true;
        pixelKey = ProgressiveSequence.pixel(seed, px, py);
        this.sample = sample;
    }

    /**
     * A number in [0, 1) in this sample's stratum of dimension {@code dim}, jittered by {@code rng}.
     *
     * @param dim the dimension's number, distinct from every other dimension's
     * @param rng the jitter
     * @return the number
     */
    public double get1D(int dim, Rng rng) {
        if (progressive) return ProgressiveSequence.get1D(sample, ProgressiveSequence.key(pixelKey, dim));
        int s = permute(sample, samples, seed(dim));
        return Math.min((s + rng.nextDouble()) / samples, Math.nextDown(1.0));
    }

    /**
     * A point of the unit square in this sample's stratum of the pair of dimensions {@code dim},
     * written to out[0..1]: the square is cut into the pixel sampler's grid for the count
     * ({@link PixelSampler#grid}), as square as the count allows.
     *
     * @param dim the pair's number, distinct from every other dimension's
     * @param rng the jitter
     * @param out receives u and v in [0, 1)
     */
    public void get2D(int dim, Rng rng, double[] out) {
        if (progressive) {
            ProgressiveSequence.get2D(sample, ProgressiveSequence.key(pixelKey, dim), out);
            return;
        }
        // Distinct samples take distinct cells, also of a padded grid (a few cells left empty).
        int s = permute(sample, cols * rows, seed(dim));
        int row = s / cols, col = s - row * cols;
        out[0] = Math.min((col + rng.nextDouble()) / cols, Math.nextDown(1.0));
        out[1] = Math.min((row + rng.nextDouble()) / rows, Math.nextDown(1.0));
    }

    private int seed(int dim) {
        long h = pixelHash + (dim + 1) * 0x9E3779B97F4A7C15L;
        h = (h ^ (h >>> 33)) * 0xFF51AFD7ED558CCDL;
        return (int) (h ^ (h >>> 29));
    }

    /**
     * Kensler's permutation of [0, n) keyed by p: the image of i. A hash restricted to the next
     * power of two, walked until it lands below n, then rotated by p mod n.
     */
    static int permute(int i, int n, int p) {
        if (n == 1) return 0;
        int w = n - 1;
        w |= w >>> 1; w |= w >>> 2; w |= w >>> 4; w |= w >>> 8; w |= w >>> 16;
        do {
            i ^= p; i *= 0xe170893d; i ^= p >>> 16; i ^= (i & w) >>> 4;
            i ^= p >>> 8; i *= 0x0929eb3f; i ^= p >>> 23; i ^= (i & w) >>> 1;
            i *= 1 | p >>> 27; i *= 0x6935fa69; i ^= (i & w) >>> 11;
            i *= 0x74dcb303; i ^= (i & w) >>> 2; i *= 0x9e501cc3;
            i ^= (i & w) >>> 2; i *= 0xc860a3df; i &= w; i ^= i >>> 5;
        } while (Integer.compareUnsigned(i, n) >= 0);
        // The rotation by p mod n, not (i + p) mod n as in the memo: that sum can wrap past 2^32,
        // and 2^32 is not a multiple of n, so the memo's map is not one-to-one for every p.
        return (i + Integer.remainderUnsigned(p, n)) % n;
    }
}
