package lt.spindulys.sampling;

import java.util.Objects;

import lt.spindulys.camera.LensPattern;
import lt.spindulys.camera.PixelFilter;

/**
 * Stratified samples for one pixel: film position on a grid as square as the sample count
 * allows ({@link #grid}), jittered within each cell; lens and time samples are stratified too
 * and paired with the film strata through seeded shuffles, so all dimensions are drawn together
 * in one pass. Lens samples are points on the unit disk placed by a {@link LensPattern}: the
 * lens strata are the same grid mapped onto the disk, or the thesis's ring. Everything is seeded
 * from (global seed, pixel), so the image does not depend on the thread count. One instance per
 * thread; {@link #startPixel} resets it.
 *
 * <p><b>Pixel filter.</b> The film samples are drawn from the pixel's reconstruction filter
 * ({@link FilterSampler}): each stratum's jittered point in the unit square is mapped through the
 * filter's inverted distribution, per axis, to an offset from the pixel's centre, and the sample
 * carries the filter's {@link #weight}. With the box of width 1 (the default) the film samples
 * are exactly the jittered strata of the pixel, as always; with one sample, the box's sample is
 * the pixel centre, and another filter's is drawn from that filter like any other.
 *
 * <p><b>Progressive.</b> A pixel whose count is open (adaptive sampling) takes its samples by
 * {@link #startProgressive} instead: film, lens and time from {@link ProgressiveSequence}s at the
 * samples' indices in the pixel, so that those taken are stratified wherever the pixel stops.
 */
public final class PixelSampler {
    private final int n, cols, rows;
    private final LensPattern lens;
    private final FilterSampler filter;
    /** The box of width 1: the film samples are the pixel's strata themselves, bit for bit as before filters. */
    private final boolean unitBox;
    private final double[] filmX, filmY, lensU, lensV, time;
    /** The filter's weight of each sample; null when every weight is 1 (a non-negative filter), which spares its memory. */
    private final double[] weight;
    private final int[] perm;
    private final boolean times;
    private final Rng rng = new Rng();

    /** A sampler with the default {@link LensPattern#CONCENTRIC} lens samples. */
    public PixelSampler(int samplesPerPixel) {
        this(samplesPerPixel, LensPattern.CONCENTRIC);
    }

    /**
     * @param lens where lens samples go on the disk, or null for a camera without a lens: every
     *             lens sample is then the centre (0, 0), and the film and time samples are the
     *             same as with a pattern (the lens random numbers are drawn all the same)
     */
    public PixelSampler(int samplesPerPixel, LensPattern lens) {
        this(samplesPerPixel, lens, true);
    }

    /**
     * @param lens  as for {@link #PixelSampler(int, LensPattern)}
     * @param times false when nothing reads the time samples (nothing in the scene moves, or a
     *              time step fixes the time): they, and without a lens the lens samples drawn
     *              before them, are then not drawn, and every time is 0. The film samples, drawn
     *              first, and any lens samples stay exactly those drawn with times.
     */
    public PixelSampler(int samplesPerPixel, LensPattern lens, boolean times) {
        this(samplesPerPixel, lens, times, BOX);
    }

    /** The box filter of width 1: every sample of a pixel weighs the same. */
    private static final FilterSampler BOX = new FilterSampler(PixelFilter.BOX, 1);

    /**
     * @param lens   as for {@link #PixelSampler(int, LensPattern)}
     * @param times  as for {@link #PixelSampler(int, LensPattern, boolean)}
     * @param filter the pixel filter the film samples are drawn from
     */
    public PixelSampler(int samplesPerPixel, LensPattern lens, boolean times, FilterSampler filter) {
        this.filter = Objects.requireNonNull(filter, "filter");
        unitBox = filter.filter() == PixelFilter.BOX && filter.width() == 1;
        this.lens = lens;
        this.times = times;
        if (samplesPerPixel < 1) throw new IllegalArgumentException("samples per pixel must be positive, found " + samplesPerPixel);
        n = samplesPerPixel;
        int[] grid = grid(n);
        cols = grid[0];
        rows = grid[1];
        filmX = new double[n]; filmY = new double[n];
        lensU = new double[n]; lensV = new double[n];
        time = new double[n];
        weight = filter.hasNegativeWeights() ? new double[n] : null;
        perm = new int[cols * rows];
    }

    public int samplesPerPixel() { return n; }

    /**
     * The grid of strata for n samples, {cols, rows}: n = cols x rows as square as n allows, when
     * that is at most twice as wide as it is tall (or n is at most 4); otherwise the nearly
     * square grid of ceil(sqrt n) columns and as many rows as n needs, of which n cells are taken.
     * A prime count would else cut the square into strips one cell tall, stratified across but
     * not down: at 251 samples, edges running across the strips were measured twice as noisy as
     * at 256.
     *
     * @param n the samples, at least 1
     * @return columns and rows; their product is n, or a little more
     */
    public static int[] grid(int n) {
        int cols = gridColumns(n);
        return new int[] {cols, (n + cols - 1) / cols};
    }

    /**
     * The columns of {@link #grid}{@code (n)}, without allocating: its rows are
     * {@code ceil(n / columns)}.
     *
     * @param n the samples, at least 1
     * @return the columns
     */
    public static int gridColumns(int n) {
        int rows = (int) Math.floor(Math.sqrt(n));
        while (n % rows != 0) rows--;
        int cols = n / rows;
        if (n <= 4 || cols <= 2 * rows) return cols; // cols x rows = n: n / cols rows
        return (int) Math.ceil(Math.sqrt(n));
    }

    /**
     * Heap a sampler of {@code samplesPerPixel} samples holds with a non-negative filter: five
     * doubles and an int a sample (film, lens and time samples, the shuffle), and the object
     * itself; the filter's table is shared by all threads.
     *
     * @param samplesPerPixel the pixel samples, from the input
     * @return bytes
     */
    public static long bytes(int samplesPerPixel) {
        if (samplesPerPixel < 1) return 256;
        int[] g = grid(samplesPerPixel);
        return 256 + 44L * samplesPerPixel + 4L * ((long) g[0] * g[1] - samplesPerPixel); // a padded grid's spare cells in the shuffle
    }

    /**
     * {@link #bytes(int)}, and a double a sample more for a filter with negative weights.
     *
     * @param samplesPerPixel the pixel samples, from the input
     * @param filter          the pixel filter
     * @return bytes
     */
    public static long bytes(int samplesPerPixel, FilterSampler filter) {
        return bytes(samplesPerPixel) + (filter.hasNegativeWeights() ? 8L * Math.max(0, samplesPerPixel) : 0);
    }

    /** The lens pattern, or null when the lens samples are all the centre. */
    public LensPattern lensPattern() { return lens; }

    /** The pixel filter the film samples are drawn from. */
    public FilterSampler filter() { return filter; }

    /**
     * Draws all samples of pixel (px, py). With one sample and the box filter the film sample is
     * the pixel centre.
     */
    public void startPixel(long seed, int px, int py) {
        rng.seed(seed, px, py, 0);
        if (n == 1 && filter.filter() == PixelFilter.BOX) {
            filmX[0] = px + 0.5; filmY[0] = py + 0.5;
            if (!times && lens == null) return;
            double u = rng.nextDouble(), v = rng.nextDouble();
            lensSample(0, 0, u, v);
            time[0] = times ? rng.nextDouble() : 0;
            return;
        }
        boolean padded = cols * rows != n;
        if (padded) shuffle(); // n of the grid's cells, at random
        for (int i = 0; i < n; i++) {
            int cell = padded ? perm[i] : i;
            int cx = cell % cols, cy = cell / cols;
            filmSample(i, px, py, (cx + rng.nextDouble()) / cols, (cy + rng.nextDouble()) / rows);
        }
        if (!times && lens == null) return; // lens samples stay (0, 0), times 0
        // Lens: the same grid shape, assigned to film strata in a shuffled order. The ring pattern
        // uses the stratum index only, but the jitter is drawn anyway so that the time samples
        // below are the same whichever lens pattern is chosen.
        shuffle();
        for (int i = 0; i < n; i++) {
            int s = perm[i];
            double u = (s % cols + rng.nextDouble()) / cols;
            double v = (s / cols + rng.nextDouble()) / rows;
            lensSample(i, s, u, v);
        }
        if (!times) return;
        // Time: n one-dimensional strata, shuffled independently.
        shuffle(n);
        for (int i = 0; i < n; i++) time[i] = (perm[i] + rng.nextDouble()) / n;
    }

    /**
     * Film sample i of pixel (px, py) from its point (u, v) in the unit square: the pixel's own
     * square for the unit box, else mapped through the filter's inverted distribution, so that
     * strata of the square stay strata of the filter, with the filter's weight.
     */
    private void filmSample(int i, int px, int py, double u, double v) {
        if (unitBox) {
            filmX[i] = px + u;
            filmY[i] = py + v;
        } else {
            int bx = filter.bin(u), by = filter.bin(v);
            filmX[i] = px + 0.5 + filter.offset(bx, u);
            filmY[i] = py + 0.5 + filter.offset(by, v);
            if (weight != null) weight[i] = filter.weight(bx, by);
        }
    }

    /** Sequence numbers of the film, lens and time samples' {@link ProgressiveSequence}s. */
    private static final int FILM = 0, LENS = 1, TIME = 2;
    private final double[] point = new double[2];

    /**
     * Draws samples {@code first} to {@code first + count - 1} of pixel (px, py), whose count is
     * open (adaptive sampling), into slots 0 to count - 1: film, lens and time each from its own
     * {@link ProgressiveSequence} at the sample's index in the pixel, so that the samples taken
     * so far are stratified wherever the pixel stops (every power-of-two prefix is a (0,2)-net).
     * Filter and lens map them as they map strata; the ring lens places the count's samples
     * about its ring in order (the sequence's shuffle decorrelates them from the film).
     *
     * @param seed  the pass's seed
     * @param px    pixel column
     * @param py    pixel row
     * @param first the index in the pixel of the first sample
     * @param count how many, 1 to {@link #samplesPerPixel()}
     */
    public void startProgressive(long seed, int px, int py, int first, int count) {
        if (count < 1 || count > n) throw new IllegalArgumentException("count must be between 1 and " + n + ", found " + count);
        long film = ProgressiveSequence.key(seed, px, py, FILM), lensKey = ProgressiveSequence.key(seed, px, py, LENS);
        long timeKey = ProgressiveSequence.key(seed, px, py, TIME);
        for (int i = 0; i < count; i++) {
            ProgressiveSequence.get2D(first + i, film, point);
            filmSample(i, px, py, point[0], point[1]);
            if (lens != null) {
                ProgressiveSequence.get2D(first + i, lensKey, point);
                lensSample(i, i, point[0], point[1], count);
            } else {
                lensU[i] = 0; lensV[i] = 0;
            }
            time[i] = times ? ProgressiveSequence.get1D(first + i, timeKey) : 0;
        }
    }

    /** Lens sample i on the unit disk from lens stratum s and its jittered square sample (u, v). */
    private void lensSample(int i, int s, double u, double v) {
        lensSample(i, s, u, v, n);
    }

    /** As {@link #lensSample(int, int, double, double)}, of a set of {@code count} samples. */
    private void lensSample(int i, int s, double u, double v, int count) {
        if (lens == null) {
            // No lens: a pinhole ignores the samples, so the mapping's sine and cosine are spared.
            lensU[i] = 0; lensV[i] = 0;
            return;
        }
        if (lens == LensPattern.RING) {
            if (count == 1) {
                lensU[i] = 0; lensV[i] = 0;
                return;
            }
            double angle = 2 * Math.PI * s / count, r = (s & 1) == 0 ? 1 : 0.5;
            lensU[i] = r * Math.cos(angle); lensV[i] = r * Math.sin(angle);
            return;
        }
        // Shirley and Chiu's concentric map: squares about the centre go to circles, so the
        // strata stay equal in area and little distorted.
        double a = 2 * u - 1, b = 2 * v - 1, r, phi;
        if (a == 0 && b == 0) {
            lensU[i] = 0; lensV[i] = 0;
            return;
        }
        if (Math.abs(a) > Math.abs(b)) {
            r = a; phi = Math.PI / 4 * (b / a);
        } else {
            r = b; phi = Math.PI / 2 - Math.PI / 4 * (a / b);
        }
        lensU[i] = r * Math.cos(phi); lensV[i] = r * Math.sin(phi);
    }

    /** Shuffles the grid's cells (n of them, or a few more on a padded grid) into perm. */
    private void shuffle() { shuffle(perm.length); }

    /** Shuffles 0 .. cells - 1 into perm[0 .. cells - 1]. */
    private void shuffle(int cells) {
        for (int i = 0; i < cells; i++) perm[i] = i;
        for (int i = cells - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            int t = perm[i]; perm[i] = perm[j]; perm[j] = t;
        }
    }

    /** Film x in pixels (the pixel's left edge is px). */
    public double filmX(int i) { return filmX[i]; }
    public double filmY(int i) { return filmY[i]; }
    /** Lens sample on the unit disk: (0, 0) is the lens centre. */
    public double lensU(int i) { return lensU[i]; }
    public double lensV(int i) { return lensV[i]; }
    public double time(int i) { return time[i]; }
    /**
     * The filter's weight of sample i, f / pdf scaled to a mean of 1: exactly 1 unless the filter
     * has negative lobes.
     */
    public double weight(int i) { return weight != null ? weight[i] : 1; }
}
