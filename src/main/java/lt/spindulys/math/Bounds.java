package lt.spindulys.math;

/**
 * Immutable axis-aligned box, used at setup time. An empty box has min > max; an unbounded one
 * (an infinite plane) has infinite extents. Acceleration structures copy bounds into flat arrays.
 */
public record Bounds(double minX, double minY, double minZ, double maxX, double maxY, double maxZ) {
    /** The box that holds nothing: min +infinity, max -infinity; the identity of {@link #union(Bounds)}. */
    public static final Bounds EMPTY = new Bounds(Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY);
    /** The box that holds everything, the bounds of an unbounded object (a plane). */
    public static final Bounds INFINITE = new Bounds(Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY,
            Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY);

    /**
     * The box spanned by two corners in any order.
     *
     * @param a one corner
     * @param b the opposite corner
     * @return the box
     */
    public static Bounds of(Vec3 a, Vec3 b) {
        return new Bounds(Math.min(a.x(), b.x()), Math.min(a.y(), b.y()), Math.min(a.z(), b.z()),
                Math.max(a.x(), b.x()), Math.max(a.y(), b.y()), Math.max(a.z(), b.z()));
    }

    /** {@return whether the box holds no point} */
    public boolean isEmpty() { return minX > maxX || minY > maxY || minZ > maxZ; }

    /** {@return whether every extent is finite} */
    public boolean isFinite() {
        return Double.isFinite(minX) && Double.isFinite(minY) && Double.isFinite(minZ)
                && Double.isFinite(maxX) && Double.isFinite(maxY) && Double.isFinite(maxZ);
    }

    /**
     * The smallest box holding both.
     *
     * @param o another box
     * @return the union
     */
    public Bounds union(Bounds o) {
        return new Bounds(Math.min(minX, o.minX), Math.min(minY, o.minY), Math.min(minZ, o.minZ),
                Math.max(maxX, o.maxX), Math.max(maxY, o.maxY), Math.max(maxZ, o.maxZ));
    }

    /**
     * The smallest box holding this one and a point.
     *
     * @param x the point's x
     * @param y the point's y
     * @param z the point's z
     * @return the union
     */
    public Bounds union(double x, double y, double z) {
        return new Bounds(Math.min(minX, x), Math.min(minY, y), Math.min(minZ, z),
                Math.max(maxX, x), Math.max(maxY, y), Math.max(maxZ, z));
    }

    /**
     * The common part of both boxes.
     *
     * @param o another box
     * @return the intersection (empty if they do not overlap)
     */
    public Bounds intersection(Bounds o) {
        return new Bounds(Math.max(minX, o.minX), Math.max(minY, o.minY), Math.max(minZ, o.minZ),
                Math.min(maxX, o.maxX), Math.min(maxY, o.maxY), Math.min(maxZ, o.maxZ));
    }

    /** {@return the low corner} */
    public Vec3 min() { return new Vec3(minX, minY, minZ); }
    /** {@return the high corner} */
    public Vec3 max() { return new Vec3(maxX, maxY, maxZ); }

    /**
     * Whether a point lies in the box, boundary included.
     *
     * @param x the point's x
     * @param y the point's y
     * @param z the point's z
     * @return whether it is inside
     */
    public boolean contains(double x, double y, double z) {
        return x >= minX && x <= maxX && y >= minY && y <= maxY && z >= minZ && z <= maxZ;
    }

    /**
     * Slab test: the parametric range of the ray inside the box, clipped to (tMin, tMax), or
     * false if the ray misses (always for an empty box). Infinite box extents work because IEEE
     * arithmetic gives +-inf; a ray parallel to a slab is inside it exactly when its origin is
     * (boundary included), whatever the sign of the zero direction component.
     *
     * @param r the ray
     * @param outRange receives the entry and exit t, {@code outRange[0..1]}
     * @return whether the ray passes through the box within its range
     */
    public boolean hitRange(Ray r, double[] outRange) {
        // An inverted slab would otherwise be reordered by the swap below and look non-empty.
        if (isEmpty()) return false;
        double t0 = r.tMin, t1 = r.tMax;
        for (int a = 0; a < 3; a++) {
            double o = a == 0 ? r.ox : a == 1 ? r.oy : r.oz;
            double d = a == 0 ? r.dx : a == 1 ? r.dy : r.dz;
            double lo = a == 0 ? minX : a == 1 ? minY : minZ;
            double hi = a == 0 ? maxX : a == 1 ? maxY : maxZ;
            if (d == 0) {
                // Parallel to this slab: inside it for every t or for none. Decided explicitly
                // because 1/d is -inf for d == -0.0, and (lo - o) * inv is NaN for o on a plane.
                if (o < lo || o > hi) return false;
                continue;
            }
            double inv = 1 / d;
            double tn = (lo - o) * inv, tf = (hi - o) * inv;
            if (tn > tf) { double s = tn; tn = tf; tf = s; }
            if (tn > t0) t0 = tn;
            if (tf < t1) t1 = tf;
            if (t0 > t1) return false;
        }
        if (outRange != null) { outRange[0] = t0; outRange[1] = t1; }
        return true;
    }

    /**
     * The bounds of this box after an affine transform (all eight corners transformed).
     *
     * @param m the transform
     * @return the bounds of the transformed box
     */
    public Bounds transformed(Transform m) {
        if (isEmpty()) return this;
        if (!isFinite()) return m.isIdentity() ? this : INFINITE;
        Bounds b = EMPTY;
        for (int i = 0; i < 8; i++) {
            Vec3 p = m.point(new Vec3((i & 1) == 0 ? minX : maxX, (i & 2) == 0 ? minY : maxY, (i & 4) == 0 ? minZ : maxZ));
            b = b.union(p.x(), p.y(), p.z());
        }
        return b;
    }
}
