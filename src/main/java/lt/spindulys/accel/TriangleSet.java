package lt.spindulys.accel;

/**
 * A {@link PrimitiveSet} whose primitives are indexed triangles tested by
 * {@link WatertightTriangles}: primitive i has the corners {@code positions()[3 t], ...} for
 * t = {@code corners()[3 i .. 3 i + 2]}. A wide tree over such a set may copy the corners into its
 * leaves ({@link TriangleBlocks}) and needs the arrays to confirm a hit exactly.
 */
public interface TriangleSet extends PrimitiveSet {
    /** Three position indices per triangle; shared, not copied. */
    int[] corners();

    /** Three coordinates per position; shared, not copied. */
    double[] positions();
}
