package lt.spindulys.math;

import java.util.Arrays;

/**
 * An object-to-world mapping that may change with time: static transforms and {@link Motion}s or
 * {@link Keyframes} in
 * the order they apply, S0, M0(t), S1, M1(t), ..., Sk. An object's is its own transform, then its
 * own motion, then its parent's placement, so a moving operand of a moving CSG node carries both
 * motions. It also carries the shutter interval, which fills in motions' open start and finish
 * times. Immutable; {@link #evaluate} writes the transform at a time into per-thread scratch
 * without allocating.
 */
public final class Placement {
    /** The default shutter interval. */
    public static final double OPEN = 0, CLOSE = 1;

    /** The identity with the default shutter. */
    public static final Placement IDENTITY = new Placement(new Transform[] {Transform.IDENTITY}, new Moving[0], OPEN, CLOSE);

    private final Transform[] statics; // statics.length == motions.length + 1
    private final Moving[] motions;
    private final double open, close;

    private Placement(Transform[] statics, Moving[] motions, double open, double close) {
        this.statics = statics;
        this.motions = motions;
        this.open = open;
        this.close = close;
    }

    /**
     * A static placement with the default shutter.
     *
     * @param t the transform
     * @return the placement
     */
    public static Placement of(Transform t) { return of(t, OPEN, CLOSE); }

    /**
     * A static placement within the shutter interval [open, close].
     *
     * @param t the transform
     * @param open the shutter's open time
     * @param close the shutter's close time, at least {@code open}
     * @return the placement
     * @throws IllegalArgumentException if the times are not finite or close is before open
     */
    public static Placement of(Transform t, double open, double close) {
        checkShutter(open, close);
        return new Placement(new Transform[] {t}, new Moving[0], open, close);
    }

    /**
     * Refuses a shutter interval that is not finite or closes before it opens.
     *
     * @param open the shutter's open time
     * @param close the shutter's close time
     */
    public static void checkShutter(double open, double close) {
        if (!Double.isFinite(open) || !Double.isFinite(close)) throw new IllegalArgumentException("shutter times must be finite, found " + open + " " + close);
        if (close < open) throw new IllegalArgumentException("shutter must close after it opens, found open " + open + " and close " + close);
    }

    /** {@return the time the shutter opens} */
    public double open() { return open; }
    /** {@return the time the shutter closes (equal to the open time: no motion blur)} */
    public double close() { return close; }

    /**
     * True if nothing in it moves: {@link #staticTransform()} is the whole placement.
     *
     * @return whether nothing moves
     */
    public boolean isStatic() { return motions.length == 0; }

    /**
     * The transform of a static placement.
     *
     * @return the one transform of a static placement
     */
    public Transform staticTransform() {
        if (!isStatic()) throw new IllegalStateException("a moving placement has no single transform");
        return statics[0];
    }

    /**
     * This placement followed by {@code t}.
     *
     * @param t the transform applied after this placement
     * @return the combined placement (this one is unchanged)
     */
    public Placement then(Transform t) {
        Transform[] s = statics.clone();
        s[s.length - 1] = s[s.length - 1].then(t);
        return new Placement(s, motions, open, close);
    }

    /**
     * This placement followed by {@code m}, its open times filled in from this shutter.
     *
     * @param m the motion applied after this placement
     * @return the combined placement (this one is unchanged)
     */
    public Placement then(Motion m) {
        Transform[] s = Arrays.copyOf(statics, statics.length + 1);
        s[s.length - 1] = Transform.IDENTITY;
        Moving[] ms = Arrays.copyOf(motions, motions.length + 1);
        ms[ms.length - 1] = m.resolve(open, close);
        return new Placement(s, ms, open, close);
    }

    /**
     * This placement followed by the keyframed transform {@code k}.
     *
     * @param k the keyframed transform applied after this placement
     * @return the combined placement (this one is unchanged)
     */
    public Placement then(Keyframes k) {
        Transform[] s = Arrays.copyOf(statics, statics.length + 1);
        s[s.length - 1] = Transform.IDENTITY;
        Moving[] ms = Arrays.copyOf(motions, motions.length + 1);
        ms[ms.length - 1] = k;
        return new Placement(s, ms, open, close);
    }

    /**
     * This placement followed by {@code next} (with next's shutter).
     *
     * @param next the placement applied after this one
     * @return the combined placement (this one is unchanged)
     */
    public Placement then(Placement next) {
        Transform[] s = new Transform[statics.length + next.statics.length - 1];
        System.arraycopy(statics, 0, s, 0, statics.length);
        s[statics.length - 1] = statics[statics.length - 1].then(next.statics[0]);
        System.arraycopy(next.statics, 1, s, statics.length, next.statics.length - 1);
        Moving[] ms = Arrays.copyOf(motions, motions.length + next.motions.length);
        System.arraycopy(next.motions, 0, ms, motions.length, next.motions.length);
        return new Placement(s, ms, next.open, next.close);
    }

    /**
     * Writes the transform at {@code time} and its inverse into {@code out}. The inverse is
     * composed from the factors' own (precomputed for static ones, analytic for motions), never
     * by a general inversion.
     *
     * @param time a time in the shutter interval
     * @param out receives the transform and its inverse
     */
    public void evaluate(double time, Affine out) {
        double[] m = out.m, inv = out.inv, f = out.factor, fi = out.factorInv, tmp = out.tmp;
        System.arraycopy(statics[0].matrix(), 0, m, 0, 12);
        System.arraycopy(statics[0].inverseMatrix(), 0, inv, 0, 12);
        for (int i = 0; i < motions.length; i++) {
            motions[i].matrices(time, f, fi);
            apply(f, fi, out);
            Transform s = statics[i + 1];
            if (!s.isIdentity()) apply(s.matrix(), s.inverseMatrix(), out);
        }
    }

    /** Appends the factor (f, its inverse fi): m = f m, inv = inv fi. */
    private static void apply(double[] f, double[] fi, Affine out) {
        Transform.compose(out.m, f, out.tmp);
        System.arraycopy(out.tmp, 0, out.m, 0, 12);
        Transform.compose(fi, out.inv, out.tmp);
        System.arraycopy(out.tmp, 0, out.inv, 0, 12);
    }

    /**
     * The transform at {@code time} (allocates; for tests and tools).
     *
     * @param time a time in the shutter interval
     * @return the transform at that time
     */
    public Transform at(double time) {
        Affine a = new Affine();
        evaluate(time, a);
        return a.toTransform();
    }

    /**
     * World bounds of an object with object-space bounds {@code local} over every time: each
     * motion's {@link Motion#sweep} of the box carried so far, static factors by their corners.
     * Rigorous (never misses the object at any time), slightly loose for nested motions. A static
     * placement gives exactly {@code local.transformed(staticTransform())}.
     *
     * @param local object-space bounds
     * @return world bounds over the whole shutter interval
     */
    public Bounds bounds(Bounds local) {
        Bounds b = local.transformed(statics[0]);
        for (int i = 0; i < motions.length; i++) {
            b = motions[i].sweep(b, open, close);
            if (!statics[i + 1].isIdentity()) b = b.transformed(statics[i + 1]);
        }
        return b;
    }

    @Override public String toString() {
        return "Placement[" + Arrays.toString(statics) + ", " + Arrays.toString(motions) + ", shutter " + open + " " + close + "]";
    }
}
