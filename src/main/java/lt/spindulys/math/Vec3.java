package lt.spindulys.math;

/**
 * Immutable 3D vector of doubles, for the API, scene setup and tests.
 * The per-ray inner loops work on plain doubles instead and never allocate these.
 */
public record Vec3(double x, double y, double z) {
    /** The zero vector. */
    public static final Vec3 ZERO = new Vec3(0, 0, 0);
    /** The unit x axis. */
    public static final Vec3 X = new Vec3(1, 0, 0);
    /** The unit y axis. */
    public static final Vec3 Y = new Vec3(0, 1, 0);
    /** The unit z axis. */
    public static final Vec3 Z = new Vec3(0, 0, 1);

    /**
     * The sum.
     *
     * @param o the other vector
     * @return this + o
     */
    public Vec3 plus(Vec3 o) { return new Vec3(x + o.x, y + o.y, z + o.z); }
    /**
     * The difference.
     *
     * @param o the other vector
     * @return this - o
     */
    public Vec3 minus(Vec3 o) { return new Vec3(x - o.x, y - o.y, z - o.z); }
    /**
     * The vector scaled.
     *
     * @param s the factor
     * @return this * s
     */
    public Vec3 times(double s) { return new Vec3(x * s, y * s, z * s); }
    /**
     * The dot product.
     *
     * @param o the other vector
     * @return this . o
     */
    public double dot(Vec3 o) { return x * o.x + y * o.y + z * o.z; }
    /**
     * The cross product (right-handed).
     *
     * @param o the other vector
     * @return this x o
     */
    public Vec3 cross(Vec3 o) { return new Vec3(y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x); }
    /** {@return the Euclidean length} */
    public double length() { return Math.sqrt(dot(this)); }

    /**
     * This vector scaled to unit length; throws if it has zero or non-finite length.
     *
     * @return a new vector of length 1
     */
    public Vec3 normalized() {
        double len = length();
        if (!(len > 0) || !Double.isFinite(len)) {
            throw new IllegalArgumentException("cannot normalise vector " + this);
        }
        return times(1 / len);
    }

    /** {@return whether every component is finite} */
    public boolean isFinite() {
        return Double.isFinite(x) && Double.isFinite(y) && Double.isFinite(z);
    }

    /**
     * One component by index.
     *
     * @param axis 0 x, 1 y, 2 z
     * @return the component
     */
    public double get(int axis) { return axis == 0 ? x : axis == 1 ? y : z; }

    @Override public String toString() { return "(" + x + ", " + y + ", " + z + ")"; }
}
