package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * Receives the triangles {@link GridPatch#visitTriangles} finds along a ray: one call per triangle of every leaf
 * whose box the ray's interval crosses, for a caller that decides the crossings itself (CSG wants every crossing of
 * a whole line, not only the nearest). Called on the tracing thread; it must leave the ray as it found it.
 */
@FunctionalInterface
public interface GridTriangleVisitor {
    /**
     * One triangle of {@code grid}.
     *
     * @param grid the grid being traversed
     * @param sub the triangle ({@link GridPatch#triangleVertex}, {@link GridPatch#cornerCoordinate})
     * @param ray the ray traced, whose direction {@code ctx}'s per-direction constants describe
     * @param ctx the caller's scratch; traversals of the visitor's own use its stack above the grid's
     */
    void triangle(GridPatch grid, int sub, Ray ray, TraversalScratch ctx);
}
