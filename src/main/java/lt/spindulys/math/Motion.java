package lt.spindulys.math;

/**
 * How an object moves during the shutter: from the identity at its start time to an end
 * transform at its finish time, and clamped outside [start, finish] (an object may start or stop
 * moving inside the shutter). The end transform is a per-axis scale, then a rotation about one
 * fixed axis, both about a pivot point, then a translation; at time t the scale and translation
 * are interpolated linearly, and so is the rotation angle (the axis stays fixed):
 * <pre>  p(t) = pivot + R(f angle) (s(f) * (p - pivot)) + f translation,   s(f) = 1 + f (scale - 1)</pre>
 * with f = (t - start) / (finish - start) clamped to [0, 1].
 *
 * <p>The thesis's linear motion (a direction, a speed, a start and a finish time) is the
 * translation-only case, {@link #linear}. Start and finish may be left open ({@link Double#NaN}):
 * they are then the scene's shutter open and close times, filled in by {@link #resolve} when the
 * scene is built, and a linear motion's distance follows from them. Immutable.
 */
public final class Motion implements Moving {
    private final double sx, sy, sz;
    private final double ax, ay, az, radians;
    private final double tx, ty, tz;
    private final double px, py, pz;
    private final double start, finish;
    /** For a linear motion whose distance depends on unresolved times: the unit direction times speed; else null. */
    private final Vec3 velocity;

    private Motion(Vec3 scale, Vec3 axis, double degrees, Vec3 translation, Vec3 pivot, double start, double finish, Vec3 velocity) {
        check(scale, "motion scale");
        if (!(scale.x() > 0 && scale.y() > 0 && scale.z() > 0)) {
            // Interpolating to a zero or negative scale would pass through a singular transform.
            throw new IllegalArgumentException("motion scale must be positive, found " + fmt(scale));
        }
        check(axis, "motion rotation axis");
        if (!Double.isFinite(degrees)) throw new IllegalArgumentException("motion rotation angle must be finite, found " + degrees);
        if (degrees != 0 && !(axis.length() > 0)) throw new IllegalArgumentException("motion rotation axis has zero length");
        check(translation, "motion translation");
        check(pivot, "motion pivot");
        if (!Double.isNaN(start) && !Double.isFinite(start)) throw new IllegalArgumentException("motion start must be finite, found " + start);
        if (!Double.isNaN(finish) && !Double.isFinite(finish)) throw new IllegalArgumentException("motion finish must be finite, found " + finish);
        sx = scale.x(); sy = scale.y(); sz = scale.z();
        Vec3 a = degrees != 0 ? axis.normalized() : Vec3.Y;
        ax = a.x(); ay = a.y(); az = a.z();
        radians = Math.toRadians(degrees);
        tx = translation.x(); ty = translation.y(); tz = translation.z();
        px = pivot.x(); py = pivot.y(); pz = pivot.z();
        this.start = start;
        this.finish = finish;
        this.velocity = velocity;
    }

    /**
     * A general motion to the end transform (scale, then rotation by {@code degrees} about
     * {@code axis}, both about {@code pivot}, then {@code translation}) between {@code start} and
     * {@code finish} (NaN: the shutter's open or close time).
     *
     * @param scale end scale factors on x, y and z (1 1 1: none)
     * @param axis rotation axis (any length but zero)
     * @param degrees end rotation angle, degrees
     * @param translation end translation
     * @param pivot centre of the scale and the rotation
     * @param start time the motion starts; NaN: the shutter's open time
     * @param finish time the motion ends; NaN: the shutter's close time
     * @return the motion
     * @throws IllegalArgumentException if a value is not finite, a scale is not positive, the
     *         axis of a non-zero rotation is zero, or finish is not after start
     */
    public static Motion of(Vec3 scale, Vec3 axis, double degrees, Vec3 translation, Vec3 pivot, double start, double finish) {
        checkOrder(start, finish);
        return new Motion(scale, axis, degrees, translation, pivot, start, finish, null);
    }

    /**
     * A translation by {@code translation} between {@code start} and {@code finish} (NaN: the shutter's).
     *
     * @param translation end translation
     * @param start time the motion starts; NaN: the shutter's open time
     * @param finish time the motion ends; NaN: the shutter's close time
     * @return the motion
     */
    public static Motion translation(Vec3 translation, double start, double finish) {
        return of(new Vec3(1, 1, 1), Vec3.Y, 0, translation, Vec3.ZERO, start, finish);
    }

    /**
     * The thesis's linear motion: along {@code direction} at {@code speed} units per unit of time
     * from {@code start} to {@code finish} (NaN: the shutter's), so it travels
     * speed * (finish - start).
     *
     * @param direction direction of travel (normalised here)
     * @param speed distance per unit of time
     * @param start time the motion starts; NaN: the shutter's open time
     * @param finish time the motion ends; NaN: the shutter's close time
     * @return the motion
     * @throws IllegalArgumentException if the direction is zero or a value is not finite
     */
    public static Motion linear(Vec3 direction, double speed, double start, double finish) {
        check(direction, "motion direction");
        if (!(direction.length() > 0)) throw new IllegalArgumentException("motion direction has zero length");
        if (!Double.isFinite(speed)) throw new IllegalArgumentException("motion speed must be finite, found " + speed);
        checkOrder(start, finish);
        Vec3 v = direction.normalized().times(speed);
        boolean resolved = !Double.isNaN(start) && !Double.isNaN(finish);
        Vec3 move = resolved ? v.times(finish - start) : Vec3.ZERO;
        return new Motion(new Vec3(1, 1, 1), Vec3.Y, 0, move, Vec3.ZERO, start, finish, resolved ? null : v);
    }

    /**
     * This motion with an open start or finish replaced by the shutter's {@code open} or
     * {@code close}; itself when both are given.
     *
     * A shutter of no length (open == close) may make them equal: the object is then where it
     * starts at that instant, and the motion never shows.
     *
     * @param open the shutter's open time
     * @param close the shutter's close time
     * @return the resolved motion
     * @throws IllegalArgumentException if the resulting finish is not after the start
     */
    public Motion resolve(double open, double close) {
        if (isResolved()) return this;
        double s = Double.isNaN(start) ? open : start, f = Double.isNaN(finish) ? close : finish;
        if (!(f > s || f == s && open == close)) {
            throw new IllegalArgumentException("motion finish must be after its start, found start " + s + " and finish " + f
                    + (Double.isNaN(start) ? " (start is the shutter open time)" : "") + (Double.isNaN(finish) ? " (finish is the shutter close time)" : ""));
        }
        Vec3 move = velocity != null ? velocity.times(f - s) : new Vec3(tx, ty, tz);
        return new Motion(new Vec3(sx, sy, sz), new Vec3(ax, ay, az), Math.toDegrees(radians), move, new Vec3(px, py, pz), s, f, null);
    }

    /**
     * True when start and finish are known (not left to the shutter).
     *
     * @return whether both times are set
     */
    public boolean isResolved() { return !Double.isNaN(start) && !Double.isNaN(finish); }

    /** {@return the time the motion starts; NaN until resolved against a shutter} */
    public double start() { return start; }
    /** {@return the time the motion ends; NaN until resolved against a shutter} */
    public double finish() { return finish; }
    /** {@return the end scale factors on x, y and z} */
    public Vec3 scale() { return new Vec3(sx, sy, sz); }
    /** {@return the rotation axis, unit length} */
    public Vec3 axis() { return new Vec3(ax, ay, az); }
    /** {@return the end rotation angle in degrees} */
    public double degrees() { return Math.toDegrees(radians); }
    /**
     * The end translation (zero for an unresolved linear motion, whose distance is not known yet).
     *
     * @return the translation at the finish
     */
    public Vec3 translation() { return new Vec3(tx, ty, tz); }
    /** {@return the centre of the scale and the rotation} */
    public Vec3 pivot() { return new Vec3(px, py, pz); }

    /**
     * The fraction of the motion done at {@code time}: 0 before the start, 1 after the finish.
     *
     * @param time a time in the shutter's units
     * @return the fraction done, in [0, 1]
     */
    public double fraction(double time) {
        requireResolved();
        if (!(time > start)) return 0;
        if (time >= finish) return 1;
        return (time - start) / (finish - start);
    }

    /**
     * The transform at {@code time} (allocates; for building and tests, not the per-ray path).
     *
     * @param time a time in the shutter's units
     * @return the transform at that time
     */
    public Transform at(double time) {
        double[] m = new double[12];
        matrices(time, m, null);
        return Transform.ofMatrix(m);
    }

    /**
     * Writes the row-major 3x4 matrix of the transform at {@code time} to {@code m} and, if
     * {@code inv} is not null, its inverse, computed analytically (transposed rotation, reciprocal
     * scale) rather than by a general inversion. No allocation.
     *
     * @param time a time in the shutter's units
     * @param m receives 12 doubles
     * @param inv receives 12 doubles, or null to skip the inverse
     */
    @Override
    public void matrices(double time, double[] m, double[] inv) {
        double f = fraction(time);
        double ux = 1 + f * (sx - 1), uy = 1 + f * (sy - 1), uz = 1 + f * (sz - 1);
        double th = f * radians, c = Math.cos(th), s = Math.sin(th), k = 1 - c;
        double r00 = k * ax * ax + c, r01 = k * ax * ay - s * az, r02 = k * ax * az + s * ay;
        double r10 = k * ax * ay + s * az, r11 = k * ay * ay + c, r12 = k * ay * az - s * ax;
        double r20 = k * ax * az - s * ay, r21 = k * ay * az + s * ax, r22 = k * az * az + c;
        if (radians == 0) { r00 = r11 = r22 = 1; r01 = r02 = r10 = r12 = r20 = r21 = 0; }
        // Linear part R diag(u); translation pivot + f t - R diag(u) pivot.
        m[0] = r00 * ux; m[1] = r01 * uy; m[2] = r02 * uz;
        m[4] = r10 * ux; m[5] = r11 * uy; m[6] = r12 * uz;
        m[8] = r20 * ux; m[9] = r21 * uy; m[10] = r22 * uz;
        double ox = px + f * tx, oy = py + f * ty, oz = pz + f * tz;
        m[3] = ox - (m[0] * px + m[1] * py + m[2] * pz);
        m[7] = oy - (m[4] * px + m[5] * py + m[6] * pz);
        m[11] = oz - (m[8] * px + m[9] * py + m[10] * pz);
        if (inv == null) return;
        // Inverse linear part diag(1/u) R^T; it maps pivot + f t back to the pivot.
        inv[0] = r00 / ux; inv[1] = r10 / ux; inv[2] = r20 / ux;
        inv[4] = r01 / uy; inv[5] = r11 / uy; inv[6] = r21 / uy;
        inv[8] = r02 / uz; inv[9] = r12 / uz; inv[10] = r22 / uz;
        inv[3] = px - (inv[0] * ox + inv[1] * oy + inv[2] * oz);
        inv[7] = py - (inv[4] * ox + inv[5] * oy + inv[6] * oz);
        inv[11] = pz - (inv[8] * ox + inv[9] * oy + inv[10] * oz);
    }

    /**
     * Time samples of {@link #sweep}: at least this many, and one per {@link #SWEEP_DEGREES} of
     * rotation, so that the padding stays a small fraction of the path (about 0.1% of the distance
     * from the pivot for a fast turn).
     */
    static final int SWEEP_STEPS = 32;
    static final double SWEEP_DEGREES = 5;

    /**
     * Bounds of {@code b} carried along this motion over all times: contains the box moved to
     * every time t, not only at the samples. The eight corners are moved to N + 1 times in
     * [start, finish] (N from {@link #SWEEP_STEPS} and {@link #SWEEP_DEGREES}; outside that
     * interval the motion is clamped) and unioned; between two samples dt apart a corner's path p(t) leaves the chord by at most dt^2 / 8 max |p''|, and
     * with q(t) = s(t) * (corner - pivot), which is linear in t, w the rotation rate and
     * p = R q + ..., |p''| &lt;= w^2 |q| + 2 w |q'|, so the union is padded by that much. A box
     * contains the moved box at t because the transform at t is affine: the image of the box is
     * the hull of its moved corners.
     *
     * @param b object-space bounds
     * @return bounds that hold {@code b} at every time of the motion
     */
    public Bounds sweep(Bounds b) {
        return sweep(b, start, finish);
    }

    /** {@inheritDoc} A motion is swept over its whole [start, finish], which holds every shutter time it is asked at. */
    @Override
    public Bounds sweep(Bounds b, double open, double close) {
        requireResolved();
        if (b.isEmpty()) return b;
        if (!b.isFinite()) return Bounds.INFINITE;
        double[] m = new double[12];
        if (finish == start) {
            // A jump (zero-length shutter): only the two ends are ever taken.
            matrices(start, m, null);
            Bounds a = b.transformed(Transform.ofMatrix(m));
            matrices(Math.nextUp(finish), m, null);
            return a.union(b.transformed(Transform.ofMatrix(m)));
        }
        int steps = (int) Math.min(1 << 16, Math.max(SWEEP_STEPS, Math.ceil(Math.abs(Math.toDegrees(radians)) / SWEEP_DEGREES)));
        double w = Math.abs(radians) / (finish - start), dt = (finish - start) / steps;
        double pad = 0, size = 0;
        for (int i = 0; i < 8; i++) {
            double x = (i & 1) == 0 ? b.minX() : b.maxX(), y = (i & 2) == 0 ? b.minY() : b.maxY(), z = (i & 4) == 0 ? b.minZ() : b.maxZ();
            double qx = x - px, qy = y - py, qz = z - pz;
            double q0 = Math.sqrt(qx * qx + qy * qy + qz * qz);
            double q1 = Math.sqrt(sq(qx * sx) + sq(qy * sy) + sq(qz * sz));
            double dq = Math.sqrt(sq(qx * (sx - 1)) + sq(qy * (sy - 1)) + sq(qz * (sz - 1))) / (finish - start);
            pad = Math.max(pad, dt * dt / 8 * (w * w * Math.max(q0, q1) + 2 * w * dq));
            size = Math.max(size, Math.max(q0, q1) + Math.abs(px) + Math.abs(py) + Math.abs(pz) + Math.abs(tx) + Math.abs(ty) + Math.abs(tz));
        }
        // And a little for the rounding of the transform evaluated per ray.
        pad += 1e-12 * size;
        return cornersAtSteps(b, start, finish, steps, pad, m);
    }

    private static void checkOrder(double start, double finish) {
        if (!Double.isNaN(start) && !Double.isNaN(finish) && !(finish > start)) {
            throw new IllegalArgumentException("motion finish must be after its start, found start " + start + " and finish " + finish);
        }
    }

    private static double sq(double v) { return v * v; }

    private void requireResolved() {
        if (!isResolved()) throw new IllegalStateException("motion start or finish is not set yet (the shutter fills it in when the scene is built)");
    }

    private static void check(Vec3 v, String what) {
        if (v == null) throw new IllegalArgumentException(what + " is missing");
        if (!v.isFinite()) throw new IllegalArgumentException(what + " must be finite, found " + fmt(v));
    }

    private static String fmt(Vec3 v) { return v.x() + " " + v.y() + " " + v.z(); }

    @Override public String toString() {
        return "Motion[scale " + fmt(scale()) + ", rotate " + fmt(axis()) + " " + degrees() + ", translate " + fmt(translation())
                + ", pivot " + fmt(pivot()) + ", from " + start + " to " + finish + (velocity != null ? ", velocity " + fmt(velocity) : "") + "]";
    }
}
