package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * What an acceleration structure indexes: a fixed number of primitives with bounds and a
 * ray test each. A mesh's triangles and a scene's objects are both primitive sets.
 */
public interface PrimitiveSet {
    /** {@return the number of primitives} */
    int size();

    /**
     * Writes the bounds of primitive {@code i} as minX, minY, minZ, maxX, maxY, maxZ into {@code out[0..5]}.
     *
     * @param i the primitive, 0 to size() - 1
     * @param out receives six doubles
     */
    void bounds(int i, double[] out);

    /**
     * Nearest-hit test of primitive {@code i} for t in (ray.tMin, ray.tMax); records a hit and returns true if nearer.
     *
     * @param i the primitive
     * @param ray the ray, in this set's space
     * @param hit receives the hit when it is nearer than the one it holds
     * @param ctx the thread's traversal scratch
     * @return whether a nearer hit was found
     */
    boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx);

    /**
     * Any-hit test of primitive {@code i}.
     *
     * @param i the primitive
     * @param ray the ray, in this set's space
     * @param ctx the thread's traversal scratch
     * @return whether the primitive blocks the ray within its range
     */
    default boolean occluded(int i, Ray ray, TraversalScratch ctx) {
        PrimitiveHit h = ctx.anyHit;
        h.t = ray.tMax;
        h.prim = -1;
        return intersect(i, ray, h, ctx);
    }

    /**
     * Offers to renumber the primitives so that new primitive k is old primitive
     * {@code order[k]} (a permutation of all of them), putting those a structure's leaves hold
     * together next to each other in memory. Returns true if the set did; a structure then
     * passes a null {@code prims} to the range tests below, meaning primitive k itself.
     *
     * @param order the new order, a permutation of 0 to size() - 1
     * @return whether the set was reordered
     */
    default boolean reorder(int[] order) { return false; }

    /**
     * Nearest-hit test of the primitives {@code prims[from..to)} (a structure's leaf; with
     * {@code prims} null, the primitives from..to themselves), shrinking
     * ray.tMax to each hit found; true if any was. A set overrides this to hoist its per-ray
     * work out of the loop.
     *
     * @param prims primitive indices, or null
     * @param from first position, inclusive
     * @param to last position, exclusive
     * @param ray the ray; its tMax shrinks to each hit
     * @param hit receives the nearest hit
     * @param ctx the thread's traversal scratch
     * @return whether any hit was found
     */
    default boolean intersectRange(int[] prims, int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        boolean any = false;
        for (int k = from; k < to; k++) {
            if (intersect(prims == null ? k : prims[k], ray, hit, ctx)) {
                any = true;
                ray.tMax = hit.t;
            }
        }
        return any;
    }

    /**
     * Any-hit test of the primitives {@code prims[from..to)} (from..to with prims null); stops at the first one found.
     *
     * @param prims primitive indices, or null
     * @param from first position, inclusive
     * @param to last position, exclusive
     * @param ray the ray
     * @param ctx the thread's traversal scratch
     * @return whether any primitive blocks the ray
     */
    default boolean occludedRange(int[] prims, int from, int to, Ray ray, TraversalScratch ctx) {
        for (int k = from; k < to; k++) if (occluded(prims == null ? k : prims[k], ray, ctx)) return true;
        return false;
    }
}
