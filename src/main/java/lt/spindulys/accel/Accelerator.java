package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/** A ray query structure over a {@link PrimitiveSet}. Immutable after construction; thread-safe. */
public interface Accelerator {
    /**
     * Finds the nearest hit in (ray.tMin, ray.tMax), recording it in {@code hit}. On return
     * ray.tMax is unchanged; hit.t holds the nearest distance if the result is true.
     */
    boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx);

    /** True if any primitive blocks the ray in (ray.tMin, ray.tMax); stops at the first one found. */
    boolean occluded(Ray ray, TraversalScratch ctx);

    /**
     * Calls {@code visitor} for every primitive the structure cannot rule out for the ray within
     * [ray.tMin, ray.tMax] (infinite limits allowed), in no particular order and possibly more than
     * once (a structure may reference a primitive from several cells). The visitor must not change
     * the ray. Used to collect all crossings of a line (mesh spans).
     */
    void visit(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor);

    /** Bytes held by the structure's own arrays (not the primitives it indexes). */
    long memoryBytes();

    /**
     * The surface-area-heuristic cost of the binary hierarchy this structure is (or was collapsed
     * from), as {@link Bvh#sahCost()} defines it, for reports of tree quality.
     *
     * @return the cost, or NaN for a structure that is not a bounding volume hierarchy
     */
    default double sahCost() { return Double.NaN; }
}
