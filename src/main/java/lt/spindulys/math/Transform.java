package lt.spindulys.math;

/**
 * Immutable affine transform (a 3x4 matrix) with its inverse precomputed.
 * {@code a.then(b)} applies a first, then b, so a scene file's transform lines compose in the
 * order they are written. The in-place methods serve the per-ray paths without allocation.
 */
public final class Transform implements ObjectMapping {
    /** The transform that changes nothing. */
    public static final Transform IDENTITY = new Transform(new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0});

    /** Row-major 3x4: m[0..3] is the first row (x' = m0 x + m1 y + m2 z + m3). */
    private final double[] m;
    private final double[] inv;
    private final boolean identity;

    private Transform(double[] m) {
        this.m = m;
        this.inv = invert(m);
        boolean id = true;
        double[] ref = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
        for (int i = 0; i < 12; i++) id &= m[i] == ref[i];
        this.identity = id;
    }

    /**
     * A transform from a row-major 3x4 matrix; throws if it is singular or not finite.
     *
     * @param rowMajor3x4 12 numbers: three rows of four, the last column the translation
     * @return the transform
     */
    public static Transform ofMatrix(double... rowMajor3x4) {
        if (rowMajor3x4.length != 12) throw new IllegalArgumentException("expected 12 matrix entries, found " + rowMajor3x4.length);
        return new Transform(rowMajor3x4.clone());
    }

    /**
     * A translation.
     *
     * @param x distance along x
     * @param y distance along y
     * @param z distance along z
     * @return the transform
     */
    public static Transform translate(double x, double y, double z) {
        return new Transform(new double[] {1, 0, 0, x, 0, 1, 0, y, 0, 0, 1, z});
    }

    /**
     * A translation by {@code v}.
     *
     * @param v the offset
     * @return the transform
     */
    public static Transform translate(Vec3 v) { return translate(v.x(), v.y(), v.z()); }

    /**
     * A scale about the origin; a negative factor mirrors.
     *
     * @param x factor on x
     * @param y factor on y
     * @param z factor on z
     * @return the transform
     */
    public static Transform scale(double x, double y, double z) {
        return new Transform(new double[] {x, 0, 0, 0, 0, y, 0, 0, 0, 0, z, 0});
    }

    /**
     * Rotation by {@code degrees} about {@code axis} (right-handed, counter-clockwise looking down the axis).
     *
     * @param axis the axis (any length but zero)
     * @param degrees the angle, degrees
     * @return the transform
     */
    public static Transform rotate(Vec3 axis, double degrees) {
        Vec3 a = axis.normalized();
        double rad = Math.toRadians(degrees), c = Math.cos(rad), s = Math.sin(rad), t = 1 - c;
        double x = a.x(), y = a.y(), z = a.z();
        return new Transform(new double[] {
                t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0,
                t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0,
                t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0});
    }

    /**
     * Rotation about the x axis.
     *
     * @param degrees the angle, degrees
     * @return the transform
     */
    public static Transform rotateX(double degrees) { return rotate(Vec3.X, degrees); }
    /**
     * Rotation about the y axis.
     *
     * @param degrees the angle, degrees
     * @return the transform
     */
    public static Transform rotateY(double degrees) { return rotate(Vec3.Y, degrees); }
    /**
     * Rotation about the z axis.
     *
     * @param degrees the angle, degrees
     * @return the transform
     */
    public static Transform rotateZ(double degrees) { return rotate(Vec3.Z, degrees); }

    /**
     * This transform followed by {@code next}.
     *
     * @param next the transform applied after this one
     * @return the combined transform
     */
    public Transform then(Transform next) {
        if (identity) return next;
        if (next.identity) return this;
        double[] r = new double[12];
        compose(m, next.m, r);
        return new Transform(r);
    }

    /** {@return the inverse transform} */
    public Transform inverse() { return new Transform(inv.clone()); }
    @Override public boolean isIdentity() { return identity; }

    /**
     * Maps a point (translation applied).
     *
     * @param p a point in object space
     * @return the point in world space
     */
    public Vec3 point(Vec3 p) {
        return new Vec3(m[0] * p.x() + m[1] * p.y() + m[2] * p.z() + m[3],
                m[4] * p.x() + m[5] * p.y() + m[6] * p.z() + m[7],
                m[8] * p.x() + m[9] * p.y() + m[10] * p.z() + m[11]);
    }

    /**
     * Maps a direction (translation ignored, not normalised).
     *
     * @param v a vector in object space
     * @return the vector in world space
     */
    public Vec3 vector(Vec3 v) {
        return new Vec3(m[0] * v.x() + m[1] * v.y() + m[2] * v.z(),
                m[4] * v.x() + m[5] * v.y() + m[6] * v.z(),
                m[8] * v.x() + m[9] * v.y() + m[10] * v.z());
    }

    /**
     * A surface normal mapped by the inverse transpose (not normalised).
     *
     * @param n a normal in object space
     * @return the normal in world space
     */
    public Vec3 normal(Vec3 n) {
        return new Vec3(inv[0] * n.x() + inv[4] * n.y() + inv[8] * n.z(),
                inv[1] * n.x() + inv[5] * n.y() + inv[9] * n.z(),
                inv[2] * n.x() + inv[6] * n.y() + inv[10] * n.z());
    }

    /**
     * Writes {@code world} mapped into this transform's object space (the inverse) into {@code local}.
     *
     * @param world a ray in world space
     * @param local receives the ray in object space (same t parameter)
     */
    public void toLocal(Ray world, Ray local) { toLocal(inv, world, local); }

    /** Writes the point {@code world[0..2]} mapped into object space (the inverse) to {@code local[0..2]}. */
    @Override public void toLocalPoint(double[] world, double[] local) {
        if (identity) System.arraycopy(world, 0, local, 0, 3); // the point itself, without twelve products
        else toLocalPoint(inv, world, local);
    }

    /** Maps the vector {@code v[off..off+2]} in place from object to world space. */
    @Override public void vectorInPlace(double[] v, int off) { vectorInPlace(m, v, off); }

    /** Maps the vector {@code v[off..off+2]} in place from world to object space. */
    @Override public void vectorToLocalInPlace(double[] v, int off) { if (!identity) vectorInPlace(inv, v, off); }

    /** Maps the normal {@code n[off..off+2]} in place from object to world space and normalises it. */
    @Override public void normalInPlace(double[] n, int off) { normalInPlace(inv, identity, n, off); }

    /** The row-major 3x4 matrix itself, not a copy: for {@link Placement} only, which never writes it. */
    double[] matrix() { return m; }

    /** The inverse's row-major 3x4 matrix itself, not a copy (see {@link #matrix()}). */
    double[] inverseMatrix() { return inv; }

    // The per-ray arithmetic, shared with Affine (a moving object's transform at one time) so that
    // both compute exactly alike.

    static void toLocal(double[] inv, Ray world, Ray local) {
        double x = world.ox, y = world.oy, z = world.oz;
        local.ox = inv[0] * x + inv[1] * y + inv[2] * z + inv[3];
        local.oy = inv[4] * x + inv[5] * y + inv[6] * z + inv[7];
        local.oz = inv[8] * x + inv[9] * y + inv[10] * z + inv[11];
        x = world.dx; y = world.dy; z = world.dz;
        local.dx = inv[0] * x + inv[1] * y + inv[2] * z;
        local.dy = inv[4] * x + inv[5] * y + inv[6] * z;
        local.dz = inv[8] * x + inv[9] * y + inv[10] * z;
        local.tMin = world.tMin;
        local.tMax = world.tMax;
        local.time = world.time;
    }

    static void toLocalPoint(double[] inv, double[] world, double[] local) {
        double x = world[0], y = world[1], z = world[2];
        local[0] = inv[0] * x + inv[1] * y + inv[2] * z + inv[3];
        local[1] = inv[4] * x + inv[5] * y + inv[6] * z + inv[7];
        local[2] = inv[8] * x + inv[9] * y + inv[10] * z + inv[11];
    }

    static void vectorInPlace(double[] m, double[] v, int off) {
        double x = v[off], y = v[off + 1], z = v[off + 2];
        v[off] = m[0] * x + m[1] * y + m[2] * z;
        v[off + 1] = m[4] * x + m[5] * y + m[6] * z;
        v[off + 2] = m[8] * x + m[9] * y + m[10] * z;
    }

    static void normalInPlace(double[] inv, boolean identity, double[] n, int off) {
        double x = n[off], y = n[off + 1], z = n[off + 2];
        double nx = x, ny = y, nz = z;
        if (!identity) {
            nx = inv[0] * x + inv[4] * y + inv[8] * z;
            ny = inv[1] * x + inv[5] * y + inv[9] * z;
            nz = inv[2] * x + inv[6] * y + inv[10] * z;
        }
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (len > 0) { nx /= len; ny /= len; nz /= len; }
        n[off] = nx; n[off + 1] = ny; n[off + 2] = nz;
    }

    /** Writes a then b (b applied after a, as matrices b * a) to {@code out}, which may be neither. */
    static void compose(double[] a, double[] b, double[] out) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 4; j++) {
                double s = b[i * 4] * a[j] + b[i * 4 + 1] * a[4 + j] + b[i * 4 + 2] * a[8 + j];
                if (j == 3) s += b[i * 4 + 3];
                out[i * 4 + j] = s;
            }
        }
    }

    private static double[] invert(double[] m) {
        for (double v : m) if (!Double.isFinite(v)) throw new IllegalArgumentException("transform has a non-finite entry");
        checkRanges(m, null);
        double a = m[0], b = m[1], c = m[2], d = m[4], e = m[5], f = m[6], g = m[8], h = m[9], k = m[10];
        double A = e * k - f * h, B = -(d * k - f * g), C = d * h - e * g;
        double det = a * A + b * B + c * C;
        double scale = Math.max(Math.abs(a), Math.max(Math.abs(e), Math.abs(k)));
        if (!(Math.abs(det) > 1e-300) || Math.abs(det) < 1e-18 * scale * scale * scale) {
            throw new IllegalArgumentException("transform is singular (a scale of zero?)");
        }
        double id = 1 / det;
        double[] r = new double[12];
        r[0] = A * id; r[1] = -(b * k - c * h) * id; r[2] = (b * f - c * e) * id;
        r[4] = B * id; r[5] = (a * k - c * g) * id; r[6] = -(a * f - c * d) * id;
        r[8] = C * id; r[9] = -(a * h - b * g) * id; r[10] = (a * e - b * d) * id;
        for (int i = 0; i < 3; i++) {
            r[i * 4 + 3] = -(r[i * 4] * m[3] + r[i * 4 + 1] * m[7] + r[i * 4 + 2] * m[11]);
        }
        checkRanges(m, r);
        return r;
    }

    /**
     * Bounded scale both ways and bounded translation ({@link Ranges}): with coordinates of at
     * most 1e15, points then stay far from where squares and products overflow.
     */
    private static void checkRanges(double[] m, double[] inv) {
        for (int i = 0; i < 12; i++) {
            boolean translation = i % 4 == 3;
            if (inv == null) {
                // The matrix alone, before it is inverted: a huge scale reads as such, not as "singular".
                if (!translation && !(Math.abs(m[i]) <= Ranges.MAX_SCALE)) {
                    throw new IllegalArgumentException("transform scales by more than " + Ranges.show(Ranges.MAX_SCALE) + " (a matrix entry is " + Ranges.approx(m[i]) + ")");
                }
                continue;
            }
            if (!translation && !(Math.abs(m[i]) <= Ranges.MAX_SCALE)) {
                throw new IllegalArgumentException("transform scales by more than " + Ranges.show(Ranges.MAX_SCALE) + " (a matrix entry is " + Ranges.approx(m[i]) + ")");
            }
            if (!translation && !(Math.abs(inv[i]) <= Ranges.MAX_SCALE)) {
                throw new IllegalArgumentException("transform shrinks by more than a factor of " + Ranges.show(Ranges.MAX_SCALE) + " (an entry of its inverse is " + Ranges.approx(inv[i]) + ")");
            }
            if (translation && !(Math.abs(m[i]) <= Ranges.MAX_TRANSLATION)) {
                throw new IllegalArgumentException("transform translates by more than " + Ranges.show(Ranges.MAX_TRANSLATION) + " (by " + Ranges.approx(m[i]) + ")");
            }
        }
    }

    @Override public boolean equals(Object o) {
        return o instanceof Transform t && java.util.Arrays.equals(m, t.m);
    }

    @Override public int hashCode() { return java.util.Arrays.hashCode(m); }

    @Override public String toString() { return "Transform" + java.util.Arrays.toString(m); }
}
