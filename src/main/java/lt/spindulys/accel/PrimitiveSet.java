package lt.spindulys.accel;

import lt.spindulys.math.Ray;
import lt.spindulys.scene.Hit;
import lt.spindulys.scene.TraceContext;

/**
 * What an acceleration structure indexes: a fixed number of primitives with bounds and a
 * ray test each. A mesh's triangles and a scene's objects are both primitive sets.
 */
public interface PrimitiveSet {
    int size();

    /** Writes the bounds of primitive {@code i} as minX, minY, minZ, maxX, maxY, maxZ into {@code out[0..5]}. */
    void bounds(int i, double[] out);

    /** Nearest-hit test of primitive {@code i} for t in (ray.tMin, ray.tMax); records a hit and returns true if nearer. */
    boolean intersect(int i, Ray ray, Hit hit, TraceContext ctx);

    /** Any-hit test of primitive {@code i}. */
    default boolean occluded(int i, Ray ray, TraceContext ctx) {
        return intersect(i, ray, ctx.scratchHit.reset(ray.tMax), ctx);
    }
}
