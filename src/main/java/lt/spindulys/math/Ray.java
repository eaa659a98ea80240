package lt.spindulys.math;

/**
 * A mutable ray o + t d for t in (tMin, tMax), with a time in the shutter interval.
 * The direction need not be unit length: affine transforms map a ray to object space without
 * renormalising, so t is the same parameter in every space. Rays live in per-thread scratch and
 * are reused, never allocated per sample.
 */
public final class Ray {
    /** The origin. */
    public double ox, oy, oz;
    /** The direction (not necessarily unit length). */
    public double dx, dy, dz;
    /** The parametric range in which hits count: t in (tMin, tMax). */
    public double tMin, tMax;
    /** The time within the shutter interval that the ray samples. */
    public double time;

    /** A ray at the origin with no direction yet and an unbounded range; fill it with {@link #set}. */
    public Ray() { tMax = Double.POSITIVE_INFINITY; }

    /**
     * A ray from {@code origin} along {@code direction}, t in (0, infinity), at time 0.
     *
     * @param origin the origin
     * @param direction the direction (not normalised)
     */
    public Ray(Vec3 origin, Vec3 direction) {
        set(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z(), 0, Double.POSITIVE_INFINITY);
    }

    /**
     * Sets everything but the time.
     *
     * @param ox origin x
     * @param oy origin y
     * @param oz origin z
     * @param dx direction x
     * @param dy direction y
     * @param dz direction z
     * @param tMin start of the range
     * @param tMax end of the range
     * @return {@code this}
     */
    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        this.ox = ox; this.oy = oy; this.oz = oz;
        this.dx = dx; this.dy = dy; this.dz = dz;
        this.tMin = tMin; this.tMax = tMax;
        return this;
    }

    /**
     * Copies {@code r}, time included.
     *
     * @param r the ray to copy
     * @return {@code this}
     */
    public Ray set(Ray r) {
        set(r.ox, r.oy, r.oz, r.dx, r.dy, r.dz, r.tMin, r.tMax);
        time = r.time;
        return this;
    }

    /**
     * The x of the point at parameter t.
     *
     * @param t the parameter
     * @return ox + t dx
     */
    public double pointX(double t) { return ox + t * dx; }
    /**
     * The y of the point at parameter t.
     *
     * @param t the parameter
     * @return oy + t dy
     */
    public double pointY(double t) { return oy + t * dy; }
    /**
     * The z of the point at parameter t.
     *
     * @param t the parameter
     * @return oz + t dz
     */
    public double pointZ(double t) { return oz + t * dz; }

    @Override public String toString() {
        return "Ray[o=(" + ox + ", " + oy + ", " + oz + ") d=(" + dx + ", " + dy + ", " + dz + ") t=(" + tMin + ", " + tMax + ") time=" + time + "]";
    }
}
