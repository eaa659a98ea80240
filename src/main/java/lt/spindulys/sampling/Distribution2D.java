package lt.spindulys.sampling;

/**
 * A piecewise-constant distribution over a grid of w x h cells covering the unit square (after
 * pbrt's PiecewiseConstant2D): a cell is drawn with probability proportional to its weight, by
 * inverting first the marginal distribution of the rows, then the conditional distribution of
 * the columns within the drawn row, and the point within the cell is where the two uniform
 * numbers fall within their intervals. Continuous inversion keeps stratified inputs stratified.
 *
 * <p>Flat arrays: the marginal CDF over rows (h + 1 values) and one conditional CDF per row
 * (w + 1 values each), built once; sampling is two binary searches and allocates nothing.
 * Immutable and thread-safe.
 */
public final class Distribution2D {
    /** Supplies one row's cell weights. */
    @FunctionalInterface
    public interface Rows {
        /**
         * Writes row {@code row}'s w weights, each finite and at least 0, into {@code into}.
         *
         * @param row  0..h-1
         * @param into w values to fill
         */
        void row(int row, double[] into);
    }

    private final int w, h;
    /** marginal[j] = probability of rows before j; marginal[h] = 1. */
    private final double[] marginal;
    /** conditional[j * (w + 1) + i] = probability of row j's columns before i; the row's last entry is 1. */
    private final double[] conditional;
    private final double total;

    /**
     * The heap the tables of a w x h grid take.
     *
     * @param w columns
     * @param h rows
     * @return bytes, saturating at Long.MAX_VALUE
     */
    public static long bytes(long w, long h) {
        if (w + 1 > Long.MAX_VALUE / 8 / Math.max(1, h + 1)) return Long.MAX_VALUE;
        return 8 * ((w + 1) * h + h + 1);
    }

    /**
     * Builds the tables. The caller checks {@link #bytes} against the heap first.
     *
     * @param w    columns, at least 1
     * @param h    rows, at least 1
     * @param rows the weights, asked for once per row in order
     * @throws IllegalArgumentException if a weight is negative or not finite, or the grid is too large for one array
     */
    public Distribution2D(int w, int h, Rows rows) {
        if (w < 1 || h < 1 || (long) (w + 1) * h > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("a " + w + "x" + h + " distribution is out of range");
        }
        this.w = w;
        this.h = h;
        marginal = new double[h + 1];
        conditional = new double[(w + 1) * h];
        double[] buf = new double[w];
        double sum = 0;
        for (int j = 0; j < h; j++) {
            rows.row(j, buf);
            int base = j * (w + 1);
            double rowSum = 0;
            for (int i = 0; i < w; i++) {
                double f = buf[i];
                if (!(f >= 0 && f < Double.POSITIVE_INFINITY)) throw new IllegalArgumentException("cell weight must be finite and at least 0, found " + f + " at " + i + ", " + j);
                conditional[base + i] = rowSum;
                rowSum += f;
            }
            // Normalise the row; a row of zeros is never drawn, but keeps a valid CDF.
            for (int i = 0; i < w; i++) conditional[base + i] = rowSum > 0 ? conditional[base + i] / rowSum : (double) i / w;
            conditional[base + w] = 1;
            marginal[j] = sum;
            sum += rowSum;
        }
        for (int j = 0; j < h; j++) marginal[j] = sum > 0 ? marginal[j] / sum : (double) j / h;
        marginal[h] = 1;
        total = sum;
    }

    /** Columns. @return w */
    public int width() { return w; }

    /** Rows. @return h */
    public int height() { return h; }

    /**
     * The sum of all weights; 0 means there is nothing to draw ({@link #sample} must not be called).
     *
     * @return the total weight
     */
    public double total() { return total; }

    /**
     * The point of the unit square that (u1, u2) in [0, 1)^2 maps to: u1 draws the row, u2 the
     * column within it. Writes the column's and row's index to out[0] and out[1] (as doubles)
     * and the position within the cell, each in [0, 1), to out[2] (across) and out[3] (down).
     *
     * @param u1  uniform number for the row
     * @param u2  uniform number for the column
     * @param out receives column, row, offset across, offset down
     */
    public void sample(double u1, double u2, double[] out) {
        int j = find(marginal, 0, h, u1);
        int base = j * (w + 1);
        int i = find(conditional, base, w, u2) - base;
        double m0 = marginal[j], m1 = marginal[j + 1];
        double c0 = conditional[base + i], c1 = conditional[base + i + 1];
        out[0] = i;
        out[1] = j;
        out[2] = Math.min((u2 - c0) / (c1 - c0), Math.nextDown(1.0));
        out[3] = Math.min((u1 - m0) / (m1 - m0), Math.nextDown(1.0));
    }

    /**
     * The probability that {@link #sample} draws cell (i, j): its weight over the total.
     *
     * @param i column
     * @param j row
     * @return the probability, 0 if the total is 0
     */
    public double probability(int i, int j) {
        int base = j * (w + 1);
        return (marginal[j + 1] - marginal[j]) * (conditional[base + i + 1] - conditional[base + i]);
    }

    /**
     * The largest k in [from, from + n) with cdf[k] <= u: the interval [cdf[k], cdf[k+1]) holds u
     * and is not empty (cdf[from] = 0 <= u < 1 = cdf[from + n]).
     */
    private static int find(double[] cdf, int from, int n, double u) {
        // Halving a length instead of moving two bounds: the loop runs a fixed log2(n) times
        // whatever the data, and the step is a conditional move, not a branch to mispredict.
        int lo = from, len = n; // cdf[lo] <= u < cdf[lo + len]
        while (len > 1) {
            int half = len >>> 1;
            lo = cdf[lo + half] <= u ? lo + half : lo;
            len -= half;
        }
        return lo;
    }
}
