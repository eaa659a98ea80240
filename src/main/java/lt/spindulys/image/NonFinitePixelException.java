package lt.spindulys.image;

/**
 * A pixel about to be written is infinite or NaN (or too large for a 32-bit float). The ranges of
 * the scene's numbers make this unreachable (see lt.spindulys.math.Ranges), so it is an internal
 * error, refused by {@link ImageWriter} before anything is written rather than written silently.
 */
public final class NonFinitePixelException extends IllegalStateException {
    /** The pixel's column and row. */
    private final int x, y;

    /**
     * The pixel at column x, row y.
     *
     * @param x column, from the left
     * @param y row, from the top
     */
    public NonFinitePixelException(int x, int y) {
        super("non-finite pixel at " + x + "," + y);
        this.x = x;
        this.y = y;
    }

    /**
     * Column of the pixel, from the left.
     *
     * @return the column
     */
    public int x() { return x; }

    /**
     * Row of the pixel, from the top.
     *
     * @return the row
     */
    public int y() { return y; }
}
