package lt.spindulys.sampling;

/**
 * Stratified samples for one pixel: film position on a grid as square as the sample count
 * allows (n = cols x rows), jittered within each cell; lens and time samples are stratified too
 * and paired with the film strata through seeded shuffles, so all dimensions are drawn together
 * in one pass. Everything is seeded from (global seed, pixel), so the image does not depend on
 * the thread count. One instance per thread; {@link #startPixel} resets it.
 */
public final class PixelSampler {
    private final int n, cols, rows;
    private final double[] filmX, filmY, lensU, lensV, time;
    private final int[] perm;
    private final Rng rng = new Rng();

    public PixelSampler(int samplesPerPixel) {
        if (samplesPerPixel < 1) throw new IllegalArgumentException("samples per pixel must be positive, found " + samplesPerPixel);
        n = samplesPerPixel;
        int c = (int) Math.floor(Math.sqrt(n));
        while (n % c != 0) c--;
        rows = c;
        cols = n / c;
        filmX = new double[n]; filmY = new double[n];
        lensU = new double[n]; lensV = new double[n];
        time = new double[n];
        perm = new int[n];
    }

    public int samplesPerPixel() { return n; }

    /** Draws all samples of pixel (px, py). With one sample the film sample is the pixel centre. */
    public void startPixel(long seed, int px, int py) {
        rng.seed(seed, px, py, 0);
        if (n == 1) {
            filmX[0] = px + 0.5; filmY[0] = py + 0.5;
            lensU[0] = rng.nextDouble(); lensV[0] = rng.nextDouble(); time[0] = rng.nextDouble();
            return;
        }
        for (int i = 0; i < n; i++) {
            int cx = i % cols, cy = i / cols;
            filmX[i] = px + (cx + rng.nextDouble()) / cols;
            filmY[i] = py + (cy + rng.nextDouble()) / rows;
        }
        // Lens: the same grid shape, assigned to film strata in a shuffled order.
        shuffle();
        for (int i = 0; i < n; i++) {
            int s = perm[i];
            lensU[i] = (s % cols + rng.nextDouble()) / cols;
            lensV[i] = (s / cols + rng.nextDouble()) / rows;
        }
        // Time: n one-dimensional strata, shuffled independently.
        shuffle();
        for (int i = 0; i < n; i++) time[i] = (perm[i] + rng.nextDouble()) / n;
    }

    private void shuffle() {
        for (int i = 0; i < n; i++) perm[i] = i;
        for (int i = n - 1; i > 0; i--) {
            int j = rng.nextInt(i + 1);
            int t = perm[i]; perm[i] = perm[j]; perm[j] = t;
        }
    }

    /** Film x in pixels (the pixel's left edge is px). */
    public double filmX(int i) { return filmX[i]; }
    public double filmY(int i) { return filmY[i]; }
    public double lensU(int i) { return lensU[i]; }
    public double lensV(int i) { return lensV[i]; }
    public double time(int i) { return time[i]; }
}
