package lt.spindulys.sampling;

/**
 * A progressive sample sequence for one pixel and one dimension (or pair of dimensions): the
 * first two dimensions of Sobol's sequence, a (0,2)-sequence in base 2, Owen-scrambled and
 * shuffled by hashing as Burley describes ("Practical Hash-based Owen Scrambling", JCGT 9(4),
 * 2020). Every prefix of 2^k points, and every block of 2^k points that starts at a multiple of
 * 2^k, is a (0,k,2)-net: exactly one point in each elementary interval of area 2^-k (each
 * 2^a x 2^b grid with a + b = k). A pixel that stops after any such count has therefore taken
 * one stratified set, not a union of sets stratified each on its own; a count that is a
 * multiple of 2^m is stratified in the intervals of area 2^-m.
 *
 * <p>The index is shuffled by a nested uniform scramble of its bits taken from the low end: the
 * first 2^k shuffled indices are then one aligned block of 2^k Sobol indices (the bits from k up
 * depend only on the index's bits from k up, all zero), so the shuffle keeps the nets, and
 * different keys give pairs of dimensions that are not correlated with one another (padding).
 * Each coordinate is then Owen-scrambled with its own seed. Everything is a function of the
 * index and the key: nothing is stored, nothing allocated.
 */
public final class ProgressiveSequence {
    private ProgressiveSequence() {}

    /**
     * The key of a dimension (or pair) of a pixel's samples.
     *
     * @param seed the pass's seed
     * @param px   pixel column
     * @param py   pixel row
     * @param dim  the dimension's number, distinct from every other's of the pixel
     * @return the key
     */
    public static long key(long seed, int px, int py, int dim) {
        return key(pixel(seed, px, py), dim);
    }

    /**
     * The hash of a pixel that {@link #key(long, int)} makes its dimensions' keys from: computed
     * once for all the dimensions of a sample.
     *
     * @param seed the pass's seed
     * @param px   pixel column
     * @param py   pixel row
     * @return the pixel's hash
     */
    public static long pixel(long seed, int px, int py) {
        long h = mix(seed ^ 0x70726f67L); // "prog"
        h = mix(h ^ px * 0xC2B2AE3D27D4EB4FL);
        return mix(h ^ py * 0x165667B19E3779F9L);
    }

    /**
     * The key of a dimension (or pair) of a pixel's samples.
     *
     * @param pixel from {@link #pixel}
     * @param dim   the dimension's number, distinct from every other's of the pixel
     * @return the key, as {@link #key(long, int, int, int)}
     */
    public static long key(long pixel, int dim) {
        return mix(pixel ^ (dim + 1) * 0xD6E8FEB86659FD93L);
    }

    /**
     * Point {@code index} of the one-dimensional sequence of {@code key}: the first Sobol
     * dimension (van der Corput's sequence) of the shuffled index, scrambled.
     *
     * @param index the sample's index in the pixel, from 0
     * @param key   from {@link #key}
     * @return a number in [0, 1)
     */
    public static double get1D(int index, long key) {
        int i = scramble(index, (int) key);
        return unit(scramble(Integer.reverse(i), (int) (key >>> 32)));
    }

    /**
     * Point {@code index} of the two-dimensional sequence of {@code key}, written to out[0..1].
     *
     * @param index the sample's index in the pixel, from 0
     * @param key   from {@link #key}
     * @param out   receives the point, each coordinate in [0, 1)
     */
    public static void get2D(int index, long key, double[] out) {
        int i = scramble(index, (int) key);
        long k2 = mix(key);
        out[0] = unit(scramble(Integer.reverse(i), (int) (key >>> 32)));
        out[1] = unit(scramble(sobol1(i), (int) k2));
    }

    /** The second Sobol dimension of index i, as 32 bits of a fraction (Kollig and Keller's loop). */
    static int sobol1(int i) {
        int r = 0;
        for (int v = 1 << 31; i != 0; i >>>= 1, v ^= v >>> 1) if ((i & 1) != 0) r ^= v;
        return r;
    }

    /**
     * Owen's nested uniform scramble of 32 bits: each bit flipped by a hash of the bits above it.
     * Of a fraction, it is Owen's scramble; of an index, the shuffle (the first 2^k indices go to
     * one aligned block of 2^k, bits from k up being flipped by a hash of zeros alone).
     */
    static int scramble(int x, int seed) {
        return Integer.reverse(laineKarras(Integer.reverse(x), seed));
    }

    /**
     * A hash in which each bit depends only on itself and the bits below it (Laine and Karras's
     * form, with Vegdahl's constants): additions and multiplications carry only upwards.
     */
    private static int laineKarras(int x, int seed) {
        x ^= x * 0x3d20adea;
        x += seed;
        x *= (seed >>> 16) | 1;
        x ^= x * 0x05526c56;
        x ^= x * 0x53a22864;
        return x;
    }

    /** 32 bits of a fraction as a double in [0, 1). */
    private static double unit(int x) {
        return (x & 0xFFFFFFFFL) * 0x1p-32;
    }

    private static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
