package lt.spindulys.denoise;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.limits.HeapBudget;

/**
 * Removes Monte Carlo noise from a rendered frame, guided by its {@link FeatureFrame}: each
 * pixel's colour becomes the value at that pixel of a first-order (linear) regression of the
 * colours of a window around it on their features (albedo, normal, inverse depth), each
 * neighbour weighted by how alike the colours of the patches around the two pixels are, as far
 * as their noise tells (non-local means with the variance-cancelling distance of Rousselle et
 * al. 2012). The features are first smoothed themselves, each by non-local means on its own
 * variance, so that the chance coverage of an edge by a pixel's samples is not taken for detail.
 * This is Bitterli et al.'s NFOR (EGSR 2016) simplified: one bandwidth, the noise estimated from
 * the samples' spread instead of half buffers (measured better here: docs/performance.md), no
 * second pass.
 *
 * <p>What it keeps: edges and textures that the features show (an albedo edge, a checker, the
 * faces of a box), since the regression follows the features inside the window; detail that
 * changes the colour beyond its noise (a shadow's edge, a highlight) lowers the weights across
 * it; a pixel without noise (variance 0) gives weight only to identical patches, so noise-free
 * areas stay as they were. What it blurs: detail the features do not show and that is weak
 * against the noise, such as the soft edge of a faint shadow, the reflection in a mirror or what
 * is seen through glass (the features are those of the first surface), and noise that is
 * correlated over several pixels.
 *
 * <p>Deterministic: every output pixel is computed from the inputs alone, so the result is the
 * same for any thread count. Immutable and thread-safe.
 */
public final class Denoiser {
    /** Regression features: albedo 3, normal 3, inverse depth 1. */
    private static final int FEATURES = 7;
    /** Unknowns of the regression: the intercept and one slope per feature. */
    private static final int UNKNOWNS = FEATURES + 1;
    /** Weights below this are not worth a neighbour's work. */
    private static final double MIN_WEIGHT = 1e-4;

    /**
     * Ridge on the slopes, as a share of the weights' sum, so that a feature that barely varies
     * in the window (a flat wall's normal) gets no slope fitted to noise.
     */
    private static final double RIDGE = 1e-3;

    private final int radius, patch;
    private final double k;

    /** The denoiser with the window, patch and bandwidth measured best in docs/performance.md. */
    public Denoiser() {
        this(DEFAULT_RADIUS, DEFAULT_PATCH, DEFAULT_K);
    }

    /** Default half-width of the window of neighbours, pixels. */
    public static final int DEFAULT_RADIUS = 9;
    /** Default half-width of the patches compared, pixels. */
    public static final int DEFAULT_PATCH = 2;
    /** Default bandwidth of the colour weights, in units of the noise's standard deviation. */
    public static final double DEFAULT_K = 0.35;

    /**
     * A denoiser with its own window, patch and bandwidth.
     *
     * @param radius half-width of the window of neighbours, 1 to 32 pixels
     * @param patch half-width of the patches compared, 0 to 8 pixels
     * @param k bandwidth of the colour weights, in units of the noise's standard deviation: larger blurs more; above 0
     * @throws IllegalArgumentException if a value is out of range
     */
    public Denoiser(int radius, int patch, double k) {
        if (radius < 1 || radius > 32) throw new IllegalArgumentException("denoising radius must be 1 to 32 pixels, found " + radius);
        if (patch < 0 || patch > 8) throw new IllegalArgumentException("denoising patch radius must be 0 to 8 pixels, found " + patch);
        if (!(k > 0) || k > 100) throw new IllegalArgumentException("denoising bandwidth must be above 0 and at most 100, found " + k);
        this.radius = radius;
        this.patch = patch;
        this.k = k;
    }

    /**
     * Heap {@link #denoise} allocates for a frame of this size: the output, the smoothed
     * variance and the features it regresses on, before and after their prefilter.
     *
     * @param width pixels across
     * @param height pixels down
     * @return bytes, saturating
     */
    public static long bytes(int width, int height) {
        return HeapBudget.product(Math.max(0, width), Math.max(0, height), 8L * (3 + 3 + 2 * FEATURES));
    }

    /**
     * The denoised frame; {@code colour} and {@code features} are not changed.
     *
     * @param colour the noisy frame
     * @param features its features, of the same size
     * @param threads threads to use, at least 1; the result does not depend on it
     * @return a new frame of the same size
     * @throws IllegalArgumentException if the sizes differ or threads is below 1
     * @throws lt.spindulys.limits.InsufficientMemoryException if the heap cannot hold {@link #bytes}
     * @throws InterruptedException if the calling thread is interrupted (the workers are stopped)
     */
    public FrameBuffer denoise(FrameBuffer colour, FeatureFrame features, int threads) throws InterruptedException {
        int w = colour.width(), h = colour.height();
        if (features.width() != w || features.height() != h) {
            throw new IllegalArgumentException("features of " + features.width() + "x" + features.height() + " do not fit a "
                    + w + "x" + h + " frame");
        }
        if (threads < 1) throw new IllegalArgumentException("threads must be at least 1, found " + threads);
        int workers = Math.min(threads, (h + BAND - 1) / BAND);
        // Reserved, not only checked, so that two denoisers (or a render beside one) started at once
        // do not both count the same free heap; each part is released once it is allocated.
        try (HeapBudget.Reservation r = HeapBudget.reserve(HeapBudget.sum(bytes(w, h), HeapBudget.product(workers, Band.bytes(w, patch))),
                "denoising the " + w + "x" + h + " frame")) {
            FrameBuffer out = new FrameBuffer(w, h);
            double[] c = colour.data(), f = features.data(), variance = smoothedVariance(f, w, h), raw = regressionFeatures(f, w, h);
            double[] x = new double[raw.length], o = out.data();
            r.release(bytes(w, h)); // allocated: only the bands' scratch is still to come
            double depthScale = depthScale(f, w, h);
            int bands = (h + BAND - 1) / BAND;
            inParallel(bands, workers, () -> null, (b, unused) -> prefilterFeatures(b * BAND, Math.min(h, (b + 1) * BAND), w, h, raw, f, depthScale, x));
            inParallel(bands, workers, () -> new Band(w, patch), (b, band) -> band(b * BAND, Math.min(h, (b + 1) * BAND), w, h, c, variance, x, o, band));
            return out;
        }
    }

    /** One piece of work of {@link #inParallel}, with its thread's scratch. */
    @FunctionalInterface
    private interface Piece<S> {
        void run(int index, S scratch);
    }

    /**
     * Runs pieces 0 to count - 1 on {@code threads} threads, each with a scratch of its own;
     * every piece writes its own part of the output, so the order does not matter.
     */
    private static <S> void inParallel(int count, int threads, java.util.function.Supplier<S> scratch, Piece<S> piece)
            throws InterruptedException {
        AtomicInteger next = new AtomicInteger();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread[] pool = new Thread[Math.max(1, Math.min(threads, count))];
        for (int t = 0; t < pool.length; t++) {
            pool[t] = new Thread(() -> {
                try {
                    S own = scratch.get();
                    for (int i; failure.get() == null && !Thread.currentThread().isInterrupted() && (i = next.getAndIncrement()) < count; ) {
                        piece.run(i, own);
                    }
                } catch (Throwable e) {
                    failure.compareAndSet(null, e);
                }
            }, "spindulys-denoise-" + t);
            pool[t].start();
        }
        try {
            for (Thread t : pool) t.join();
        } catch (InterruptedException e) {
            for (Thread t : pool) t.interrupt();
            throw e;
        }
        Throwable e = failure.get();
        if (e instanceof RuntimeException re) throw re;
        if (e instanceof Error err) throw err;
        if (e != null) throw new IllegalStateException(e);
        if (Thread.currentThread().isInterrupted()) throw new InterruptedException("denoising interrupted");
    }

    /** Half-width of the window of the features' own prefilter, and of its patches, pixels. */
    private static final int FEATURE_RADIUS = 3, FEATURE_PATCH = 1;
    /** The features' feature groups: albedo, normal, inverse depth (first feature, count). */
    private static final int[][] GROUPS = {{0, 3}, {3, 3}, {6, 1}};

    /**
     * Rows y0 to y1 of the features, each group (albedo, normal, inverse depth) averaged over a
     * small window by non-local means on that group itself, with its own variance (NFOR's
     * feature prefilter): a pixel on an edge has features that carry the chance of its samples'
     * coverage, and the colour regressed on them would keep that noise as if it were detail;
     * where the features have no noise they are unchanged.
     */
    private static void prefilterFeatures(int y0, int y1, int w, int h, double[] x, double[] f, double depthScale, double[] out) {
        for (int py = y0; py < y1; py++) {
            for (int px = 0; px < w; px++) {
                int p = py * w + px;
                for (int g = 0; g < GROUPS.length; g++) {
                    int first = GROUPS[g][0], n = GROUPS[g][1];
                    double scale = g == 2 ? depthScale * depthScale : 1;
                    double total = 0;
                    double s0 = 0, s1 = 0, s2 = 0;
                    for (int qy = Math.max(0, py - FEATURE_RADIUS); qy <= Math.min(h - 1, py + FEATURE_RADIUS); qy++) {
                        for (int qx = Math.max(0, px - FEATURE_RADIUS); qx <= Math.min(w - 1, px + FEATURE_RADIUS); qx++) {
                            double sum = 0;
                            int count = 0;
                            for (int oy = -FEATURE_PATCH; oy <= FEATURE_PATCH; oy++) {
                                int ay = py + oy, by = qy + oy;
                                if (ay < 0 || by < 0 || ay >= h || by >= h) continue;
                                for (int ox = -FEATURE_PATCH; ox <= FEATURE_PATCH; ox++) {
                                    int ax = px + ox, bx = qx + ox;
                                    if (ax < 0 || bx < 0 || ax >= w || bx >= w) continue;
                                    int a = ay * w + ax, b = by * w + bx;
                                    double va = scale * f[FeatureFrame.VALUES * a + FeatureFrame.FEATURE_VARIANCE + g];
                                    double vb = scale * f[FeatureFrame.VALUES * b + FeatureFrame.FEATURE_VARIANCE + g];
                                    for (int i = first; i < first + n; i++) {
                                        double d = x[FEATURES * a + i] - x[FEATURES * b + i];
                                        sum += (d * d - (va + Math.min(va, vb))) / (1e-10 + va + vb);
                                    }
                                    count += n;
                                }
                            }
                            double weight = Math.exp(-Math.max(0, sum / count));
                            int q = qy * w + qx;
                            total += weight;
                            s0 += weight * x[FEATURES * q + first];
                            if (n == 3) {
                                s1 += weight * x[FEATURES * q + first + 1];
                                s2 += weight * x[FEATURES * q + first + 2];
                            }
                        }
                    }
                    out[FEATURES * p + first] = s0 / total;
                    if (n == 3) {
                        out[FEATURES * p + first + 1] = s1 / total;
                        out[FEATURES * p + first + 2] = s2 / total;
                    }
                }
            }
        }
    }

    /** Rows a thread denoises at a time: the regression sums of a band are held at once. */
    private static final int BAND = 4;
    /** Sums per pixel: the upper triangle of the normal matrix, then three right-hand sides. */
    private static final int SUMS = UNKNOWNS * (UNKNOWNS + 1) / 2 + 3 * UNKNOWNS;

    /** One thread's working space for a band of rows: the regression sums and the patch distance maps. */
    private static final class Band {
        final double[] sums, term, count, rowTerm, rowCount, d = new double[UNKNOWNS], a = new double[UNKNOWNS * UNKNOWNS],
                b = new double[3 * UNKNOWNS];

        Band(int w, int patch) {
            int rows = BAND + 2 * patch;
            sums = new double[SUMS * BAND * w];
            term = new double[rows * w];
            count = new double[rows * w];
            rowTerm = new double[rows * w];
            rowCount = new double[rows * w];
        }

        /** Heap of one band's space for frames {@code w} wide. */
        static long bytes(int w, int patch) {
            return HeapBudget.product(8L * Math.max(0, w), SUMS * BAND + 4L * (BAND + 2 * patch));
        }
    }

    /**
     * Denoises rows y0 to y1 (exclusive): for each offset of the window in a fixed order, the
     * patch distance of every pixel of the band to its neighbour at that offset (the per-pixel
     * terms, summed over the patch by a separable box filter), its weight, and its share of
     * the pixel's regression sums; then each pixel's regression is solved.
     */
    private void band(int y0, int y1, int w, int h, double[] c, double[] var, double[] x, double[] o, Band s) {
        double[] sums = s.sums;
        java.util.Arrays.fill(sums, 0, SUMS * (y1 - y0) * w, 0);
        double k2 = k * k;
        int ty0 = Math.max(0, y0 - patch), ty1 = Math.min(h, y1 + patch); // rows whose terms the band's patches reach
        double[] d = s.d;
        for (int dy = -radius; dy <= radius; dy++) {
            for (int dx = -radius; dx <= radius; dx++) {
                boolean centre = dx == 0 && dy == 0;
                if (!centre) patchDistances(dx, dy, y0, y1, ty0, ty1, w, h, c, var, k2, s);
                for (int py = y0; py < y1; py++) {
                    int qy = py + dy;
                    if (qy < 0 || qy >= h) continue;
                    for (int px = Math.max(0, -dx); px < Math.min(w, w - dx); px++) {
                        double weight = centre ? 1 : Math.exp(-s.term[(py - y0) * w + px]);
                        if (weight < MIN_WEIGHT) continue;
                        int p = py * w + px, q = p + dy * w + dx;
                        d[0] = 1;
                        for (int i = 0; i < FEATURES; i++) d[i + 1] = x[FEATURES * q + i] - x[FEATURES * p + i];
                        int at = SUMS * ((py - y0) * w + px);
                        double cr = c[3 * q], cg = c[3 * q + 1], cb = c[3 * q + 2];
                        for (int i = 0; i < UNKNOWNS; i++) {
                            double wd = weight * d[i];
                            for (int j = i; j < UNKNOWNS; j++) sums[at++] += wd * d[j];
                        }
                        for (int i = 0; i < UNKNOWNS; i++) {
                            double wd = weight * d[i];
                            sums[at++] += wd * cr; sums[at++] += wd * cg; sums[at++] += wd * cb;
                        }
                    }
                }
            }
        }
        double[] a = s.a, b = s.b;
        for (int py = y0; py < y1; py++) {
            for (int px = 0; px < w; px++) {
                int at = SUMS * ((py - y0) * w + px);
                for (int i = 0; i < UNKNOWNS; i++) for (int j = i; j < UNKNOWNS; j++) a[i * UNKNOWNS + j] = sums[at++];
                for (int i = 0; i < 3 * UNKNOWNS; i++) b[i] = sums[at++];
                double lambda = RIDGE * a[0];
                for (int i = 1; i < UNKNOWNS; i++) a[i * UNKNOWNS + i] += lambda;
                double r, g, bl;
                double a0 = a[0];
                if (solve(a, b)) { r = b[0]; g = b[1]; bl = b[2]; }
                else { r = sums[at - 3 * UNKNOWNS] / a0; g = sums[at - 3 * UNKNOWNS + 1] / a0; bl = sums[at - 3 * UNKNOWNS + 2] / a0; }
                int p = 3 * (py * w + px);
                o[p] = Math.max(0, r); o[p + 1] = Math.max(0, g); o[p + 2] = Math.max(0, bl);
            }
        }
    }

    /**
     * Into s.term (rows y0 to y1 of the band), the non-local-means distance of each pixel p's
     * patch to that of p + (dx, dy): per pixel pair of the patches and per channel the squared
     * difference less what their noise explains (Rousselle et al.), over the bandwidth's share
     * of their noise, averaged over the pairs inside the frame; at least 0.
     */
    private void patchDistances(int dx, int dy, int y0, int y1, int ty0, int ty1, int w, int h, double[] c, double[] var, double k2, Band s) {
        double[] term = s.term, count = s.count, rowTerm = s.rowTerm, rowCount = s.rowCount;
        // Per-pixel terms of rows ty0 to ty1 (stored from row 0 of the arrays).
        for (int y = ty0; y < ty1; y++) {
            int row = (y - ty0) * w, yq = y + dy;
            for (int xx = 0; xx < w; xx++) {
                int xq = xx + dx;
                if (yq < 0 || yq >= h || xq < 0 || xq >= w) { term[row + xx] = 0; count[row + xx] = 0; continue; }
                int i = 3 * (y * w + xx), j = 3 * (yq * w + xq);
                double t = 0;
                for (int ch = 0; ch < 3; ch++) {
                    double vi = var[i + ch], vj = var[j + ch], diff = c[i + ch] - c[j + ch];
                    t += (diff * diff - (vi + Math.min(vi, vj))) / (1e-10 + k2 * (vi + vj));
                }
                term[row + xx] = t;
                count[row + xx] = 3;
            }
        }
        // Box filter along rows, then along columns into the band's rows of term (reused: row r of the band).
        for (int y = ty0; y < ty1; y++) {
            int row = (y - ty0) * w;
            for (int xx = 0; xx < w; xx++) {
                double t = 0, n = 0;
                for (int ox = Math.max(0, xx - patch); ox <= Math.min(w - 1, xx + patch); ox++) { t += term[row + ox]; n += count[row + ox]; }
                rowTerm[row + xx] = t;
                rowCount[row + xx] = n;
            }
        }
        for (int y = y0; y < y1; y++) {
            int out = (y - y0) * w;
            for (int xx = 0; xx < w; xx++) {
                double t = 0, n = 0;
                for (int oy = Math.max(ty0, y - patch); oy <= Math.min(ty1 - 1, y + patch); oy++) {
                    t += rowTerm[(oy - ty0) * w + xx];
                    n += rowCount[(oy - ty0) * w + xx];
                }
                term[out + xx] = n > 0 ? Math.max(0, t / n) : 0;
            }
        }
    }

    /** Half-width of the neighbourhood a pixel's variance is averaged over (wider measured no better). */
    private static final int VARIANCE_RADIUS = 1;

    /** The variance of each pixel's mean, averaged over its 3x3 neighbourhood: an estimate from few samples is itself noisy. */
    private static double[] smoothedVariance(double[] f, int w, int h) {
        double[] out = new double[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                double r = 0, g = 0, b = 0;
                int n = 0;
                for (int yy = Math.max(0, y - VARIANCE_RADIUS); yy <= Math.min(h - 1, y + VARIANCE_RADIUS); yy++) {
                    for (int xx = Math.max(0, x - VARIANCE_RADIUS); xx <= Math.min(w - 1, x + VARIANCE_RADIUS); xx++) {
                        int o = FeatureFrame.VALUES * (yy * w + xx) + FeatureFrame.VARIANCE;
                        r += f[o]; g += f[o + 1]; b += f[o + 2];
                        n++;
                    }
                }
                int o = 3 * (y * w + x);
                out[o] = r / n; out[o + 1] = g / n; out[o + 2] = b / n;
            }
        }
        return out;
    }

    /** What scales the inverse depth to [0, 1]: one over the frame's largest (0 for a frame of sky). */
    private static double depthScale(double[] f, int w, int h) {
        double maxInverse = 0;
        for (int p = 0; p < w * h; p++) maxInverse = Math.max(maxInverse, f[FeatureFrame.VALUES * p + FeatureFrame.INVERSE_DEPTH]);
        return maxInverse > 0 ? 1 / maxInverse : 0;
    }

    /** The regression's features per pixel: albedo, normal, and inverse depth scaled to [0, 1] by the frame's largest. */
    private static double[] regressionFeatures(double[] f, int w, int h) {
        int n = w * h;
        double scale = depthScale(f, w, h);
        double[] x = new double[FEATURES * n];
        for (int p = 0; p < n; p++) {
            int i = FeatureFrame.VALUES * p;
            System.arraycopy(f, i, x, FEATURES * p, 6);
            x[FEATURES * p + 6] = f[i + FeatureFrame.INVERSE_DEPTH] * scale;
        }
        return x;
    }

    /**
     * Solves the symmetric positive definite system (upper triangle of a) for the three right-hand
     * sides in b by Cholesky decomposition, in place; false if a pivot is not positive.
     */
    private static boolean solve(double[] a, double[] b) {
        int n = UNKNOWNS;
        // a = L L^T, L stored in the lower triangle (read from the upper triangle as it goes).
        for (int j = 0; j < n; j++) {
            double sum = a[j * n + j];
            for (int m = 0; m < j; m++) sum -= a[j * n + m] * a[j * n + m];
            if (!(sum > 0)) return false;
            double l = Math.sqrt(sum);
            a[j * n + j] = l;
            for (int i = j + 1; i < n; i++) {
                double s = a[j * n + i];
                for (int m = 0; m < j; m++) s -= a[i * n + m] * a[j * n + m];
                a[i * n + j] = s / l;
            }
        }
        for (int ch = 0; ch < 3; ch++) {
            for (int i = 0; i < n; i++) {
                double s = b[3 * i + ch];
                for (int m = 0; m < i; m++) s -= a[i * n + m] * b[3 * m + ch];
                b[3 * i + ch] = s / a[i * n + i];
            }
            for (int i = n - 1; i >= 0; i--) {
                double s = b[3 * i + ch];
                for (int m = i + 1; m < n; m++) s -= a[m * n + i] * b[3 * m + ch];
                b[3 * i + ch] = s / a[i * n + i];
            }
        }
        return true;
    }
}
