package lt.spindulys.scene;

import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.adaptive.CachedPatch;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;

/**
 * One piece of a {@link GridTessellation}: the triangles of part of a face's grid (a
 * {@link GridPiece}) or of a whole Loop face ({@link PatchTriangles}), with a small structure of
 * their own. Immutable once made, so any number of render threads may read one; the cache may
 * drop it while a thread still holds it.
 */
interface TessellationPiece extends CachedPatch {
    /** The nearest hit in (ray.tMin, ray.tMax): fills t, u, v and {@code sub} (the triangle), not {@code prim}. */
    boolean intersect(Ray ray, PrimitiveHit hit, TraceContext ctx);

    boolean occluded(Ray ray, TraceContext ctx);

    /** Adds every crossing of the whole line with the piece's triangles to the context's crossing list, as primitive {@code prim}. */
    void addCrossings(int prim, Ray ray, TraceContext ctx);

    /** Shading data of triangle {@code sub} at barycentrics (u, v). */
    void shade(boolean smooth, int sub, double u, double v, ShadingData sd);

    /** Widens {@code box} (min x, y, z, max x, y, z) to hold every vertex. */
    void include(double[] box);

    /** The triangles, zero-area ones included. */
    int triangleCount();
}
