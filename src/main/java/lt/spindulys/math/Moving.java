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

    /**
     * The box around the corners of {@code b} transformed at steps + 1 evenly spaced times of
     * [from, to] (the last exactly {@code to}), widened by {@code pad} on every side: what both
     * sweeps take, each with the pad that covers the corners' paths between the steps.
     *
     * @param m scratch for a matrix, 12 long
     */
    default Bounds cornersAtSteps(Bounds b, double from, double to, int steps, double pad, double[] m) {
        double minX = Double.POSITIVE_INFINITY, minY = minX, minZ = minX, maxX = -minX, maxY = maxX, maxZ = maxX;
        double dt = (to - from) / steps;
        for (int k = 0; k <= steps; k++) {
            matrices(k == steps ? to : from + k * dt, m, null);
            for (int i = 0; i < 8; i++) {
                double x = (i & 1) == 0 ? b.minX() : b.maxX(), y = (i & 2) == 0 ? b.minY() : b.maxY(), z = (i & 4) == 0 ? b.minZ() : b.maxZ();
                double X = m[0] * x + m[1] * y + m[2] * z + m[3];
                double Y = m[4] * x + m[5] * y + m[6] * z + m[7];
                double Z = m[8] * x + m[9] * y + m[10] * z + m[11];
                minX = Math.min(minX, X); maxX = Math.max(maxX, X);
                minY = Math.min(minY, Y); maxY = Math.max(maxY, Y);
                minZ = Math.min(minZ, Z); maxZ = Math.max(maxZ, Z);
            }
        }
        return new Bounds(minX - pad, minY - pad, minZ - pad, maxX + pad, maxY + pad, maxZ + pad);
    }
}
