package lt.spindulys.math;

/**
 * A mutable ray o + t d for t in (tMin, tMax), with a time in the shutter interval.
 * The direction need not be unit length: affine transforms map a ray to object space without
 * renormalising, so t is the same parameter in every space. Rays live in per-thread scratch and
 * are reused, never allocated per sample.
 */
public final class Ray {
    public double ox, oy, oz;
    public double dx, dy, dz;
    public double tMin, tMax;
    public double time;

    public Ray() { tMax = Double.POSITIVE_INFINITY; }

    public Ray(Vec3 origin, Vec3 direction) {
        set(origin.x(), origin.y(), origin.z(), direction.x(), direction.y(), direction.z(), 0, Double.POSITIVE_INFINITY);
    }

    public Ray set(double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        this.ox = ox; this.oy = oy; this.oz = oz;
        this.dx = dx; this.dy = dy; this.dz = dz;
        this.tMin = tMin; this.tMax = tMax;
        return this;
    }

    public Ray set(Ray r) {
        set(r.ox, r.oy, r.oz, r.dx, r.dy, r.dz, r.tMin, r.tMax);
        time = r.time;
        return this;
    }

    public double pointX(double t) { return ox + t * dx; }
    public double pointY(double t) { return oy + t * dy; }
    public double pointZ(double t) { return oz + t * dz; }

    @Override public String toString() {
        return "Ray[o=(" + ox + ", " + oy + ", " + oz + ") d=(" + dx + ", " + dy + ", " + dz + ") t=(" + tMin + ", " + tMax + ") time=" + time + "]";
    }
}
