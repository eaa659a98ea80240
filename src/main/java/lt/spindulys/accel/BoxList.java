package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * A handful of primitives, each behind its own box: a ray tests every box (the same widened
 * slab test as {@link Bvh}'s nodes) and enters only the primitives whose box it crosses before
 * the nearest hit found so far. For a scene's few objects, where a primitive is itself a
 * structure that costs more to enter than a box test, and a tree over them would add its own
 * entry, stack and root box. Immutable; thread-safe.
 */
public final class BoxList implements Accelerator {
    private final PrimitiveSet set;
    /** Per primitive the bits of six floats, min x, y, z then max x, y, z, rounded outward. */
    private final int[] box;
    private final int count;

    public BoxList(PrimitiveSet set) {
        this.set = set;
        this.count = set.size();
        this.box = new int[6 * count];
        double[] b = new double[6];
        for (int i = 0; i < count; i++) {
            set.bounds(i, b);
            for (int k = 0; k < 3; k++) {
                box[6 * i + k] = Float.floatToRawIntBits(Bvh.down(b[k]));
                box[6 * i + 3 + k] = Float.floatToRawIntBits(Bvh.up(b[k + 3]));
            }
        }
    }

    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        ctx.direction(ray);
        // Read once: an object entered below may leave its own (transformed) ray's constants in ctx.
        final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        final int xn = ix < 0 ? 3 : 0, yn = iy < 0 ? 3 : 0, zn = iz < 0 ? 3 : 0;
        final double saved = ray.tMax;
        boolean any = false;
        for (int i = 0; i < count; i++) {
            if (crosses(i, ray, ix, iy, iz, xn, yn, zn) && set.intersect(i, ray, hit, ctx)) {
                any = true;
                ray.tMax = hit.t;
            }
        }
        ray.tMax = saved;
        return any;
    }

    @Override
    public boolean occluded(Ray ray, TraversalScratch ctx) {
        ctx.direction(ray);
        final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        final int xn = ix < 0 ? 3 : 0, yn = iy < 0 ? 3 : 0, zn = iz < 0 ? 3 : 0;
        for (int i = 0; i < count; i++) if (crosses(i, ray, ix, iy, iz, xn, yn, zn) && set.occluded(i, ray, ctx)) return true;
        return false;
    }

    @Override
    public void visit(Ray ray, TraversalScratch ctx, PrimitiveVisitor visitor) {
        ctx.direction(ray);
        final double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        final int xn = ix < 0 ? 3 : 0, yn = iy < 0 ? 3 : 0, zn = iz < 0 ? 3 : 0;
        for (int i = 0; i < count; i++) if (crosses(i, ray, ix, iy, iz, xn, yn, zn)) visitor.visit(i, ray, ctx);
    }

    /**
     * Whether the ray, with inverse direction (ix, iy, iz) and near planes xn, yn, zn (3 where
     * that component is negative: the box's max is met first), crosses box i within [tMin, tMax].
     */
    private boolean crosses(int i, Ray ray, double ix, double iy, double iz, int xn, int yn, int zn) {
        return !Double.isNaN(Bvh.slabEntry(box, 6 * i, ray.ox, ray.oy, ray.oz, ix, iy, iz, xn, yn, zn, ray.tMin, ray.tMax));
    }

    @Override
    public long memoryBytes() { return 4L * box.length; }
}
