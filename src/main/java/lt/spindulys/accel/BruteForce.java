package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/** Tests every primitive: the reference the real structures are checked against, and fine for a handful. */
public final class BruteForce implements Accelerator {
    private final PrimitiveSet set;

    public BruteForce(PrimitiveSet set) { this.set = set; }

    // One range call, so a set with a batched test (a mesh's triangles) reads its per-ray constants once.
    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        double saved = ray.tMax;
        boolean any = set.intersectRange(null, 0, set.size(), ray, hit, ctx);
        ray.tMax = saved;
        return any;
    }

    @Override
    public boolean occluded(Ray ray, TraversalScratch ctx) {
        return set.occludedRange(null, 0, set.size(), ray, ctx);
    }

    @Override
    public void visit(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor) {
        for (int i = 0, n = set.size(); i < n; i++) visitor.visit(i, ray, ctx);
    }

    /** Holds no arrays of its own. */
    @Override
    public long memoryBytes() { return 0; }
}
