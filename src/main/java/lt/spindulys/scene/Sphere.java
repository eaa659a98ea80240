package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Motion;
import lt.spindulys.material.Material;

/**
 * A sphere given by centre and radius. Closed: its inside is the solid ball.
 *
 * <p>Surface parametrisation (object space), with (x, y, z) relative to the centre:
 * u = phi / (2 pi), phi = atan2(z, x) in [0, 2 pi) the azimuth about the centre's y axis;
 * v = theta / pi, theta the polar angle from +y (v = 0 at the top pole, 1 at the bottom).
 * Then p(u, v) = c + r (sin theta cos phi, cos theta, sin theta sin phi), and dpdu x dpdv points
 * outwards. dpdu vanishes at the poles, where the parametrisation is singular.
 *
 * <p>The hit records prim 0 and u = v = 0; shading derives everything from the hit point.
 */
public final class Sphere extends GObject {
    private static final double TWO_PI = 2 * Math.PI;

    private final Vec3 center;
    private final double radius;
    // Unpacked for the per-ray path.
    private final double cx, cy, cz, r2;

    /**
     * The sphere of {@code radius} about {@code center} (object space).
     *
     * @param center the centre (object space)
     * @param radius the radius, positive (object-space units)
     * @throws IllegalArgumentException if the radius is not positive or a number is not finite and modest
     */
    public Sphere(Vec3 center, double radius) {
        Ranges.modest("sphere center", center);
        if (!(radius > 0) || !Ranges.isModest(radius)) throw new IllegalArgumentException("sphere radius must be a positive number at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + radius);
        this.center = center;
        this.radius = radius;
        this.cx = center.x();
        this.cy = center.y();
        this.cz = center.z();
        this.r2 = radius * radius;
    }

    /**
     * Centre (object space).
     *
     * @return the centre, as given
     */
    public Vec3 center() { return center; }
    /**
     * Radius (object-space units).
     *
     * @return the radius, positive
     */
    public double radius() { return radius; }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public Sphere transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public Sphere motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public Sphere material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public Sphere name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public Sphere source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public Sphere source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "sphere"; }

    @Override public Bounds localBounds() {
        return new Bounds(cx - radius, cy - radius, cz - radius, cx + radius, cy + radius, cz + radius);
    }

    @Override public boolean isClosed() { return true; }

    /** The whole object is one cheap test: worth trying first as the thread's last occluder. */
    @Override int blockingPart(TraceContext ctx) { return 0; }

    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        return trace(ray, hit, null);
    }

    @Override protected void spansLocal(Ray ray, SpanBuffer out, TraceContext ctx) {
        trace(ray, null, out);
    }

    /**
     * One root finder for both queries so that the nearest hit is always the first span
     * endpoint after tMin. With {@code out == null} records the nearest hit in (tMin, tMax);
     * otherwise appends the span [t0, t1] if it overlaps (tMin, tMax).
     */
    private boolean trace(Ray ray, Hit hit, SpanBuffer out) {
        double ox = ray.ox - cx, oy = ray.oy - cy, oz = ray.oz - cz;
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        double a = dx * dx + dy * dy + dz * dz;
        if (!(a > 0)) return false;
        // a t^2 + 2 h t + c = 0. The discriminant h^2 - a c equals a (r^2 - |l|^2), l being the
        // offset from the centre to the ray's closest point; computed that way it does not
        // cancel catastrophically for distant origins and near-tangent rays.
        double h = ox * dx + oy * dy + oz * dz;
        double k = h / a;
        double lx = ox - k * dx, ly = oy - k * dy, lz = oz - k * dz;
        double disc = r2 - (lx * lx + ly * ly + lz * lz);
        if (!(disc >= 0)) return false;
        double c = ox * ox + oy * oy + oz * oz - r2;
        // Stable form: q has the magnitude of the larger root's numerator, so neither root
        // is a difference of nearly equal numbers.
        double q = -(h + Math.copySign(Math.sqrt(a * disc), h));
        double t0 = q / a;
        double t1 = q != 0 ? c / q : t0; // q == 0: origin on the surface, tangent there: double root 0
        if (t0 > t1) { double s = t0; t0 = t1; t1 = s; }
        if (out != null) {
            if (t1 > ray.tMin && t0 < ray.tMax) out.add(t0, this, 0, 0, 0, t1, this, 0, 0, 0);
            return false;
        }
        double t = t0 > ray.tMin ? t0 : t1;
        if (!(t > ray.tMin && t < ray.tMax)) return false;
        hit.t = t;
        hit.prim = 0;
        hit.u = 0;
        hit.v = 0;
        return true;
    }

    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        double px = x - cx, py = y - cy, pz = z - cz;
        double len = Math.sqrt(px * px + py * py + pz * pz);
        if (len > 0) {
            // Project onto the surface: the point came back through a transform and drifted.
            double s = radius / len;
            px *= s; py *= s; pz *= s;
        } else {
            py = radius; // the centre itself: cannot happen for a real hit; pick the top pole
        }
        sd.setNormal(px, py, pz);
        double phi = Math.atan2(pz, px);
        if (phi < 0) phi += TWO_PI;
        double cosTheta = Math.max(-1, Math.min(1, py / radius));
        sd.u = phi / TWO_PI;
        sd.v = Math.acos(cosTheta) / Math.PI;
        // d/dphi = (-z, 0, x); d/dtheta = (y cos phi, -r sin theta, y sin phi).
        double rho = Math.sqrt(px * px + pz * pz);
        double cosPhi = Math.cos(phi), sinPhi = Math.sin(phi);
        sd.setDerivatives(-TWO_PI * pz, 0, TWO_PI * px,
                Math.PI * py * cosPhi, -Math.PI * rho, Math.PI * py * sinPhi);
    }
}
