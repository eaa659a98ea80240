package lt.spindulys.math;

import java.util.Locale;

/**
 * A transform that changes with time through keys: at each key time a pose (a per-axis scale, then
 * rotations about x, then y, then z, then a translation), and between keys each of the nine
 * numbers interpolated on its own, so a rotation of 0 to 720 degrees turns twice. Before the first
 * key the first pose holds, after the last the last. The poses act in the space of a fixed
 * {@link #basis()} B (the identity, a pivot's translation, or a turntable's axis frame):
 * <pre>  K(t) = B E(t) B^-1,   E(t) = translate(t) rotateZ(t) rotateY(t) rotateX(t) scale(t)</pre>
 *
 * <p>Interpolation ({@link Interpolation}): {@code linear}, exact at keys with a constant rate
 * between them; {@code ease}, each span eased in and out by smoothstep (3u^2 - 2u^3), so motion
 * stops at every key; {@code smooth}, a Catmull-Rom spline through the keys (a cubic Hermite whose
 * tangent at a key is the difference of its neighbours over their time apart, one-sided at the
 * first and last key), which keeps the rate continuous across keys. A smooth scale is interpolated
 * as its logarithm, so it stays positive where the spline overshoots.
 *
 * <p>Times are the scene's (an animation's frame N is at N / fps). Immutable; evaluating
 * allocates nothing.
 */
public final class Keyframes implements Moving {
    /** How values between keys are made. */
    public enum Interpolation {
        /** Straight between keys. */
        LINEAR("linear"),
        /** Smoothstep within each span: zero rate at every key. */
        EASE("ease"),
        /** Catmull-Rom through the keys: continuous rate. */
        SMOOTH("smooth");

        private final String keyword;

        Interpolation(String keyword) { this.keyword = keyword; }

        /** {@return the word the scene language uses} */
        public String keyword() { return keyword; }

        /**
         * The interpolation a word names.
         *
         * @param word linear, ease or smooth
         * @return the interpolation
         * @throws IllegalArgumentException for any other word
         */
        public static Interpolation fromKeyword(String word) {
            for (Interpolation i : values()) if (i.keyword.equals(word)) return i;
            throw new IllegalArgumentException("interpolation must be linear, ease or smooth, found '" + word + "'");
        }
    }

    /**
     * One key's pose: applied as scale, then rotations about x, y and z by the given degrees in
     * that order, then translate.
     *
     * @param translate the translation
     * @param rotate degrees about x, y and z, applied in that order
     * @param scale per-axis scale factors, each positive
     */
    public record Pose(Vec3 translate, Vec3 rotate, Vec3 scale) {
        /** The identity pose. */
        public static final Pose IDENTITY = new Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(1, 1, 1));

        /**
         * Checks the values.
         *
         * @throws IllegalArgumentException if a value is not finite, above 10^15 in magnitude, or a
         *         scale is not positive or outside [10^-15, 10^15]
         */
        public Pose {
            if (!Ranges.isModest(translate)) throw new IllegalArgumentException("key translate must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + translate);
            if (!Ranges.isModest(rotate)) throw new IllegalArgumentException("key rotate must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + " degrees, found " + rotate);
            for (double s : new double[] {scale.x(), scale.y(), scale.z()}) {
                // Interpolating to a zero or negative scale would pass through a singular transform.
                if (!(s >= 1 / Ranges.MAX_SCALE && s <= Ranges.MAX_SCALE)) {
                    throw new IllegalArgumentException("key scale must be positive, between 1e-15 and " + Ranges.show(Ranges.MAX_SCALE) + ", found " + scale);
                }
            }
        }

        /** {@return true if this pose scales (some factor is not 1)} */
        public boolean scales() { return scale.x() != 1 || scale.y() != 1 || scale.z() != 1; }
    }

    /** Most keys a track may have: a key per frame of a long shot, and bounded for the input. */
    public static final int MAX_KEYS = 100_000;

    /** Time samples of a {@link #sweep}; the padding is the path of a shutter interval over twice this. */
    static final int SWEEP_STEPS = 256;

    private static final int CHANNELS = 9; // tx ty tz, rx ry rz (radians), sx sy sz (log for smooth)
    private final double[] times;
    private final double[][] values; // [channel][key]
    private final double[][] slopes; // [channel][key], per unit of time; smooth only
    private final Interpolation interpolation;
    private final Transform basis;
    private final boolean scales;

    private Keyframes(double[] times, Pose[] poses, Interpolation interpolation, Transform basis) {
        int n = times.length;
        if (n == 0) throw new IllegalArgumentException("keys need at least one key");
        if (n > MAX_KEYS) throw new IllegalArgumentException("at most " + MAX_KEYS + " keys, found " + n);
        if (poses.length != n) throw new IllegalArgumentException(n + " key times but " + poses.length + " poses");
        for (int i = 0; i < n; i++) {
            if (!Double.isFinite(times[i]) || !Ranges.isModest(times[i])) throw new IllegalArgumentException("key time must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + times[i]);
            if (i > 0 && !(times[i] > times[i - 1])) {
                throw new IllegalArgumentException("key " + (i + 1) + " at time " + fmt(times[i]) + " is not after key " + i + " at time " + fmt(times[i - 1]) + ": keys must be in increasing time, without repeats");
            }
        }
        this.times = times.clone();
        this.interpolation = interpolation;
        this.basis = basis;
        values = new double[CHANNELS][n];
        boolean sc = false;
        for (int i = 0; i < n; i++) {
            Pose p = poses[i];
            values[0][i] = p.translate.x(); values[1][i] = p.translate.y(); values[2][i] = p.translate.z();
            values[3][i] = Math.toRadians(p.rotate.x()); values[4][i] = Math.toRadians(p.rotate.y()); values[5][i] = Math.toRadians(p.rotate.z());
            boolean log = interpolation == Interpolation.SMOOTH;
            values[6][i] = log ? Math.log(p.scale.x()) : p.scale.x();
            values[7][i] = log ? Math.log(p.scale.y()) : p.scale.y();
            values[8][i] = log ? Math.log(p.scale.z()) : p.scale.z();
            sc |= p.scales();
        }
        scales = sc;
        slopes = new double[CHANNELS][];
        if (interpolation == Interpolation.SMOOTH) {
            for (int c = 0; c < CHANNELS; c++) {
                double[] v = values[c], m = new double[n];
                for (int i = 0; i < n && n > 1; i++) {
                    int a = Math.max(0, i - 1), b = Math.min(n - 1, i + 1);
                    m[i] = (v[b] - v[a]) / (times[b] - times[a]);
                }
                slopes[c] = m;
            }
        }
    }

    /**
     * A track of keys in the identity basis.
     *
     * @param times key times, strictly increasing, at most {@link #MAX_KEYS}
     * @param poses the pose at each time
     * @param interpolation how to go between keys
     * @return the track
     * @throws IllegalArgumentException if there are no keys, too many, or the times do not increase
     */
    public static Keyframes of(double[] times, Pose[] poses, Interpolation interpolation) {
        return of(times, poses, interpolation, Transform.IDENTITY);
    }

    /**
     * A track of keys whose poses act in the space of {@code basis} (for a pivot p,
     * {@code Transform.translate(p)}: rotations and scales about p).
     *
     * @param times key times, strictly increasing, at most {@link #MAX_KEYS}
     * @param poses the pose at each time
     * @param interpolation how to go between keys
     * @param basis the frame the poses act in
     * @return the track
     * @throws IllegalArgumentException if there are no keys, too many, or the times do not increase
     */
    public static Keyframes of(double[] times, Pose[] poses, Interpolation interpolation, Transform basis) {
        return new Keyframes(times, poses.clone(), java.util.Objects.requireNonNull(interpolation), java.util.Objects.requireNonNull(basis));
    }

    /**
     * A turntable: {@code turns} whole turns about {@code axis} through {@code center}, at a
     * constant rate from {@code start} to {@code finish} (positive turns are counter-clockwise
     * looking from the axis' tip, as rotations are), no turn at {@code start} and all of them at
     * {@code finish}. For an animation of frames A to B, start at frame A's time and finish at
     * frame B + 1's, so that frame B + 1 would repeat frame A and the frames loop. The turn goes on
     * at the same rate for one more span before the start and after the finish (a shutter open
     * around the first or the last frame sees it turning), and stops beyond those.
     *
     * @param axis the axis of the turn (any length but zero)
     * @param center a point on the axis
     * @param turns how many turns (negative: the other way)
     * @param start time of the first pose
     * @param finish time the turns are done, after {@code start}
     * @return the track
     * @throws IllegalArgumentException if the axis is zero, a value not finite, or finish not after start
     */
    public static Keyframes turntable(Vec3 axis, Vec3 center, double turns, double start, double finish) {
        if (!Ranges.isModest(axis) || !(axis.length() > 0)) throw new IllegalArgumentException("turntable axis must be non-zero and finite, found " + axis);
        if (!Ranges.isModest(center)) throw new IllegalArgumentException("turntable center must be finite, found " + center);
        if (!Double.isFinite(turns) || Math.abs(turns) > 1e6) throw new IllegalArgumentException("turntable turns must be finite and at most 1000000, found " + turns);
        Vec3 a = axis.normalized();
        // The basis takes y to the axis, so the turn is a rotation about the basis' y.
        Vec3 c = Vec3.Y.cross(a);
        Transform toAxis;
        if (c.length() > 1e-12) toAxis = Transform.rotate(c, Math.toDegrees(Math.atan2(c.length(), Vec3.Y.dot(a))));
        else toAxis = a.y() > 0 ? Transform.IDENTITY : Transform.rotate(Vec3.X, 180);
        Transform basis = toAxis.then(Transform.translate(center));
        if (!(finish > start) || !Double.isFinite(start) || !Double.isFinite(finish)) throw new IllegalArgumentException("turntable must finish after it starts, found " + start + " and " + finish);
        // Keys one whole span before and after, at the same rate, so that a shutter open a little
        // before the start or after the finish sees the turn going on rather than held.
        double d = finish - start;
        Pose before = new Pose(Vec3.ZERO, new Vec3(0, -360 * turns, 0), new Vec3(1, 1, 1));
        Pose after = new Pose(Vec3.ZERO, new Vec3(0, 720 * turns, 0), new Vec3(1, 1, 1));
        return of(new double[] {start - d, finish + d}, new Pose[] {before, after}, Interpolation.LINEAR, basis);
    }

    /** {@return the number of keys} */
    public int size() { return times.length; }
    /**
     * The time of a key.
     *
     * @param i the key, from 0
     * @return its time
     */
    public double time(int i) { return times[i]; }
    /** {@return how values between keys are made} */
    public Interpolation interpolation() { return interpolation; }
    /** {@return the frame the poses act in} */
    public Transform basis() { return basis; }
    /** {@return true if some key scales} */
    public boolean scales() { return scales; }

    /**
     * The transform at {@code time} (allocates; for building and tests, not the per-ray path).
     *
     * @param time a time
     * @return the transform
     */
    public Transform at(double time) {
        double[] m = new double[12];
        matrices(time, m, null);
        return Transform.ofMatrix(m);
    }

    /**
     * The value of one of the nine numbers at {@code time}: 0-2 translation, 3-5 rotation in
     * degrees, 6-8 scale (for tests and tools).
     *
     * @param channel 0 to 8
     * @param time a time
     * @return the interpolated value
     */
    public double value(int channel, double time) {
        int seg = segment(time);
        double v = channel(channel, seg, time);
        if (channel >= 3 && channel < 6) return Math.toDegrees(v);
        if (channel >= 6 && interpolation == Interpolation.SMOOTH) return Math.exp(v);
        return v;
    }

    /** The span index i with times[i] &lt;= time &lt; times[i + 1]; -1 before the first key, n - 1 from the last on. */
    private int segment(double time) {
        int n = times.length;
        if (!(time >= times[0])) return -1;
        if (time >= times[n - 1]) return n - 1;
        int lo = 0, hi = n - 1; // times[lo] <= time < times[hi]
        while (hi - lo > 1) {
            int mid = (lo + hi) >>> 1;
            if (times[mid] <= time) lo = mid;
            else hi = mid;
        }
        return lo;
    }

    /** Channel c at time, in its stored form (radians, log scale for smooth), in span seg. */
    private double channel(int c, int seg, double time) {
        double[] v = values[c];
        if (seg < 0) return v[0];
        if (seg >= v.length - 1) return v[v.length - 1];
        double t0 = times[seg], h = times[seg + 1] - t0, u = (time - t0) / h;
        double a = v[seg], b = v[seg + 1];
        switch (interpolation) {
            case LINEAR: return a + u * (b - a);
            case EASE: return a + u * u * (3 - 2 * u) * (b - a);
            default: {
                double u2 = u * u, u3 = u2 * u;
                double[] m = slopes[c];
                return (2 * u3 - 3 * u2 + 1) * a + (u3 - 2 * u2 + u) * h * m[seg] + (-2 * u3 + 3 * u2) * b + (u3 - u2) * h * m[seg + 1];
            }
        }
    }

    private double scaleValue(int c, int seg, double time) {
        double v = channel(c, seg, time);
        return interpolation == Interpolation.SMOOTH ? Math.exp(v) : v;
    }

    @Override
    public void matrices(double time, double[] m, double[] inv) {
        int seg = segment(time);
        double tx = channel(0, seg, time), ty = channel(1, seg, time), tz = channel(2, seg, time);
        double ax = channel(3, seg, time), ay = channel(4, seg, time), az = channel(5, seg, time);
        double sx = scaleValue(6, seg, time), sy = scaleValue(7, seg, time), sz = scaleValue(8, seg, time);
        double cx = Math.cos(ax), snx = Math.sin(ax), cy = Math.cos(ay), sny = Math.sin(ay), cz = Math.cos(az), snz = Math.sin(az);
        // R = Rz Ry Rx.
        double r00 = cz * cy, r01 = cz * sny * snx - snz * cx, r02 = cz * sny * cx + snz * snx;
        double r10 = snz * cy, r11 = snz * sny * snx + cz * cx, r12 = snz * sny * cx - cz * snx;
        double r20 = -sny, r21 = cy * snx, r22 = cy * cx;
        m[0] = r00 * sx; m[1] = r01 * sy; m[2] = r02 * sz; m[3] = tx;
        m[4] = r10 * sx; m[5] = r11 * sy; m[6] = r12 * sz; m[7] = ty;
        m[8] = r20 * sx; m[9] = r21 * sy; m[10] = r22 * sz; m[11] = tz;
        if (!basis.isIdentity()) sandwich(basis.matrix(), m, basis.inverseMatrix());
        if (inv == null) return;
        // E^-1 = [S^-1 R^T | -S^-1 R^T t], analytically rather than by a general inversion.
        inv[0] = r00 / sx; inv[1] = r10 / sx; inv[2] = r20 / sx;
        inv[4] = r01 / sy; inv[5] = r11 / sy; inv[6] = r21 / sy;
        inv[8] = r02 / sz; inv[9] = r12 / sz; inv[10] = r22 / sz;
        inv[3] = -(inv[0] * tx + inv[1] * ty + inv[2] * tz);
        inv[7] = -(inv[4] * tx + inv[5] * ty + inv[6] * tz);
        inv[11] = -(inv[8] * tx + inv[9] * ty + inv[10] * tz);
        if (!basis.isIdentity()) sandwich(basis.matrix(), inv, basis.inverseMatrix());
    }

    /** e = b e c in place (3x4 affine matrices, row-major), without scratch arrays. */
    private static void sandwich(double[] b, double[] e, double[] c) {
        // e c, one row at a time: row i of the product needs only row i of e.
        for (int i = 0; i < 3; i++) {
            int r = 4 * i;
            double e0 = e[r], e1 = e[r + 1], e2 = e[r + 2], e3 = e[r + 3];
            for (int j = 0; j < 4; j++) {
                double s = e0 * c[j] + e1 * c[4 + j] + e2 * c[8 + j];
                e[r + j] = j == 3 ? s + e3 : s;
            }
        }
        // b (e c), one column at a time: column j of the product needs only column j.
        for (int j = 0; j < 4; j++) {
            double p0 = e[j], p1 = e[4 + j], p2 = e[8 + j];
            for (int i = 0; i < 3; i++) {
                int r = 4 * i;
                double s = b[r] * p0 + b[r + 1] * p1 + b[r + 2] * p2;
                e[r + j] = j == 3 ? s + b[r + 3] : s;
            }
        }
    }

    /**
     * Moves a ray by the transform at {@code time}: its origin as a point, its direction as a
     * vector, renormalised. For a camera carried by the keys; allocates nothing.
     *
     * @param time a time
     * @param ray the ray, changed in place (its time is not read)
     */
    public void moveRay(double time, Ray ray) {
        int seg = segment(time);
        double tx = channel(0, seg, time), ty = channel(1, seg, time), tz = channel(2, seg, time);
        double ax = channel(3, seg, time), ay = channel(4, seg, time), az = channel(5, seg, time);
        double sx = scaleValue(6, seg, time), sy = scaleValue(7, seg, time), sz = scaleValue(8, seg, time);
        double[] bi = basis.inverseMatrix(), b = basis.matrix();
        boolean id = basis.isIdentity();
        double ox = ray.ox, oy = ray.oy, oz = ray.oz, dx = ray.dx, dy = ray.dy, dz = ray.dz;
        if (!id) {
            double x = ox, y = oy, z = oz;
            ox = bi[0] * x + bi[1] * y + bi[2] * z + bi[3];
            oy = bi[4] * x + bi[5] * y + bi[6] * z + bi[7];
            oz = bi[8] * x + bi[9] * y + bi[10] * z + bi[11];
            x = dx; y = dy; z = dz;
            dx = bi[0] * x + bi[1] * y + bi[2] * z;
            dy = bi[4] * x + bi[5] * y + bi[6] * z;
            dz = bi[8] * x + bi[9] * y + bi[10] * z;
        }
        ox *= sx; oy *= sy; oz *= sz; dx *= sx; dy *= sy; dz *= sz;
        double c = Math.cos(ax), s = Math.sin(ax), y, z, x;
        y = c * oy - s * oz; z = s * oy + c * oz; oy = y; oz = z;
        y = c * dy - s * dz; z = s * dy + c * dz; dy = y; dz = z;
        c = Math.cos(ay); s = Math.sin(ay);
        x = c * ox + s * oz; z = -s * ox + c * oz; ox = x; oz = z;
        x = c * dx + s * dz; z = -s * dx + c * dz; dx = x; dz = z;
        c = Math.cos(az); s = Math.sin(az);
        x = c * ox - s * oy; y = s * ox + c * oy; ox = x; oy = y;
        x = c * dx - s * dy; y = s * dx + c * dy; dx = x; dy = y;
        ox += tx; oy += ty; oz += tz;
        if (!id) {
            x = ox; y = oy; z = oz;
            ox = b[0] * x + b[1] * y + b[2] * z + b[3];
            oy = b[4] * x + b[5] * y + b[6] * z + b[7];
            oz = b[8] * x + b[9] * y + b[10] * z + b[11];
            x = dx; y = dy; z = dz;
            dx = b[0] * x + b[1] * y + b[2] * z;
            dy = b[4] * x + b[5] * y + b[6] * z;
            dz = b[8] * x + b[9] * y + b[10] * z;
        }
        double len = 1 / Math.sqrt(dx * dx + dy * dy + dz * dz);
        ray.ox = ox; ray.oy = oy; ray.oz = oz;
        ray.dx = dx * len; ray.dy = dy * len; ray.dz = dz * len;
    }

    /**
     * True if the keys hold one pose all through [open, close] (a shutter of no length, or one
     * open before the first key, after the last, or between two equal poses): an object can then
     * take {@link #at the transform at open} and be placed as a still one.
     *
     * @param open the shutter's open time
     * @param close the shutter's close time
     * @return whether nothing changes in the interval
     */
    public boolean isStill(double open, double close) {
        if (!(close > open)) return true;
        double[] most = new double[CHANNELS], rate = new double[CHANNELS];
        for (int c = 0; c < CHANNELS; c++) {
            channelBounds(c, open, close, most, rate);
            if (rate[c] != 0) return false;
        }
        return true;
    }

    /**
     * Bounds of {@code b} carried along the keys at every time of [open, close]. The eight
     * corners are moved to {@link #SWEEP_STEPS} + 1 times spread over the interval and unioned;
     * the union is padded by half a step times a bound on how fast a corner moves (from bounds on
     * each number's rate over the spans the interval touches: the rate of a linear span, 1.5 times
     * it for an eased one, and for a smooth one the Bezier hull of the cubic's derivative), so no
     * time in between escapes it. A box contains the moved box at each time because the transform
     * is affine.
     */
    @Override
    public Bounds sweep(Bounds b, double open, double close) {
        if (b.isEmpty()) return b;
        if (!b.isFinite()) return Bounds.INFINITE;
        double[] m = new double[12];
        if (!(close > open)) {
            matrices(open, m, null);
            return b.transformed(Transform.ofMatrix(m));
        }
        // Per channel: largest magnitude of the value (for scales) and of the rate over [open, close].
        double[] most = new double[CHANNELS], rate = new double[CHANNELS];
        for (int c = 0; c < CHANNELS; c++) channelBounds(c, open, close, most, rate);
        double move = Math.sqrt(rate[0] * rate[0] + rate[1] * rate[1] + rate[2] * rate[2]);
        double turn = rate[3] + rate[4] + rate[5];
        double[] bi = basis.inverseMatrix(), bm = basis.matrix();
        double norm = 0;
        for (int i = 0; i < 3; i++) for (int j = 0; j < 3; j++) norm += bm[4 * i + j] * bm[4 * i + j];
        norm = Math.sqrt(norm);
        double speed = 0, size = 0;
        for (int i = 0; i < 8; i++) {
            double x = (i & 1) == 0 ? b.minX() : b.maxX(), y = (i & 2) == 0 ? b.minY() : b.maxY(), z = (i & 4) == 0 ? b.minZ() : b.maxZ();
            double qx = bi[0] * x + bi[1] * y + bi[2] * z + bi[3];
            double qy = bi[4] * x + bi[5] * y + bi[6] * z + bi[7];
            double qz = bi[8] * x + bi[9] * y + bi[10] * z + bi[11];
            double scaled = Math.sqrt(sq(most[6] * qx) + sq(most[7] * qy) + sq(most[8] * qz));
            double growing = Math.sqrt(sq(rate[6] * qx) + sq(rate[7] * qy) + sq(rate[8] * qz));
            speed = Math.max(speed, norm * (move + turn * scaled + growing));
            size = Math.max(size, Math.abs(x) + Math.abs(y) + Math.abs(z) + scaled + most[0] + most[1] + most[2]);
        }
        double dt = (close - open) / SWEEP_STEPS;
        // Half a step at the corner's top speed, and a little for the rounding of the per-ray transform.
        double pad = dt / 2 * speed + 1e-12 * norm * size;
        return cornersAtSteps(b, open, close, SWEEP_STEPS, pad, m);
    }

    /**
     * Widens most[c] to the largest |value| and rate[c] to the largest |rate| (per unit of time)
     * of channel c over [open, close], in natural units (a smooth scale's exp taken).
     */
    private void channelBounds(int c, double open, double close, double[] most, double[] rate) {
        double[] v = values[c];
        int n = v.length;
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY, r = 0;
        int first = Math.max(0, segment(open)), last = Math.min(n - 2, segment(close));
        if (!(open >= times[0])) { lo = Math.min(lo, v[0]); hi = Math.max(hi, v[0]); }
        if (close >= times[n - 1]) { lo = Math.min(lo, v[n - 1]); hi = Math.max(hi, v[n - 1]); }
        for (int i = first; i <= last; i++) {
            double a = v[i], b = v[i + 1], h = times[i + 1] - times[i];
            double p1 = a, p2 = b;
            if (interpolation == Interpolation.SMOOTH) {
                p1 = a + h * slopes[c][i] / 3;
                p2 = b - h * slopes[c][i + 1] / 3;
            }
            lo = Math.min(lo, Math.min(Math.min(a, b), Math.min(p1, p2)));
            hi = Math.max(hi, Math.max(Math.max(a, b), Math.max(p1, p2)));
            double d = switch (interpolation) {
                case LINEAR -> Math.abs(b - a) / h;
                case EASE -> 1.5 * Math.abs(b - a) / h;
                case SMOOTH -> 3 * Math.max(Math.abs(p1 - a), Math.max(Math.abs(p2 - p1), Math.abs(b - p2))) / h;
            };
            r = Math.max(r, d);
        }
        if (c >= 6 && interpolation == Interpolation.SMOOTH) {
            // s = exp(L): |s| <= exp(max L), |s'| = s |L'|.
            most[c] = Math.exp(hi);
            rate[c] = Math.exp(hi) * r;
        } else {
            most[c] = Math.max(Math.abs(lo), Math.abs(hi));
            rate[c] = r;
        }
    }

    private static double sq(double x) { return x * x; }

    private static String fmt(double t) { return String.format(Locale.ROOT, "%s", t); }

    @Override public String toString() {
        return "Keyframes[" + times.length + " keys, " + interpolation.keyword() + ", " + fmt(times[0]) + " to " + fmt(times[times.length - 1]) + "]";
    }
}
