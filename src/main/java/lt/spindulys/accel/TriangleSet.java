package lt.spindulys.accel;

/**
 * A {@link PrimitiveSet} whose primitives are triangles tested by {@link WatertightTriangles}
 * through {@link #intersectRange} and {@link #occludedRange}. A wide tree over such a set copies
 * the corners into its leaves ({@link TriangleBlocks}) for a float test that only drops
 * triangles, and has every hit it keeps confirmed by the set's own exact test.
 */
public interface TriangleSet extends PrimitiveSet {
    /**
     * Writes the corners of triangle {@code i} to {@code out[0..8]}: x, y, z of the first
     * corner, then of the second and the third, exactly as the set's ray test sees them.
     */
    void corners(int i, double[] out);

    /** {@return the largest absolute coordinate of any corner} (it bounds the float copies' rounding) */
    double maxAbsCoordinate();
}
