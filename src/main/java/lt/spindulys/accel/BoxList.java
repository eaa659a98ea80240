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

    /**
     * Stores box {@code i} (minX, minY, minZ, maxX, maxY, maxZ in {@code bounds}) into
     * {@code boxes} as six float bits rounded outward, the form {@link #crosses(int[], int, Ray, TraversalScratch)}
     * reads. Each int is one plain write: a reader racing with a store that only shrinks a box
     * sees, coordinate by coordinate, the old or the new value, a box that still contains the new one.
     *
     * @param boxes six ints per box
     * @param i the box
     * @param bounds six doubles
     */
    public static void store(int[] boxes, int i, double[] bounds) {
        for (int k = 0; k < 3; k++) {
            boxes[6 * i + k] = Float.floatToRawIntBits(Bvh.down(bounds[k]));
            boxes[6 * i + 3 + k] = Float.floatToRawIntBits(Bvh.up(bounds[k + 3]));
        }
    }

    /**
     * Whether the ray crosses box {@code i} of {@code boxes} (stored by {@link #store}) within
     * [tMin, tMax], by the padded slab test of a {@link Bvh} node: never false for a box whose
     * contents the watertight triangle test could hit.
     *
     * @param boxes six ints per box
     * @param i the box
     * @param ray the ray
     * @param ctx the thread's scratch (its per-direction constants)
     * @return whether the ray may meet what the box holds
     */
    public static boolean crosses(int[] boxes, int i, Ray ray, TraversalScratch ctx) {
        ctx.direction(ray);
        double ix = ctx.invX, iy = ctx.invY, iz = ctx.invZ;
        return !Double.isNaN(Bvh.slabEntry(boxes, 6 * i, ray.ox, ray.oy, ray.oz, ix, iy, iz,
                ix < 0 ? 3 : 0, iy < 0 ? 3 : 0, iz < 0 ? 3 : 0, ray.tMin, ray.tMax));
    }
}
