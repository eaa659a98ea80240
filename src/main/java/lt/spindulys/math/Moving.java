package lt.spindulys.math;

/**
 * A factor of a {@link Placement} that changes with time: a {@link Motion} or {@link Keyframes}.
 * Both write their transform at a time without allocating and bound a box carried along them.
 */
interface Moving {
    /**
     * Writes the row-major 3x4 matrix of the transform at {@code time} to {@code m} and, if
     * {@code inv} is not null, its inverse. No allocation.
     */
    void matrices(double time, double[] m, double[] inv);

    /** Bounds of {@code b} carried along this factor at every time of [open, close] (at least). */
    Bounds sweep(Bounds b, double open, double close);
}
