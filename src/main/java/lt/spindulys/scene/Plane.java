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
 * The infinite plane n.p = offset. As a solid it is the half-space n.p &lt;= offset (the normal
 * points out), so it can take part in CSG; its bounds are infinite.
 *
 * <p>Texture coordinates are distances (object-space units) along two fixed orthonormal
 * tangents: u = p.{@link #tangentU()}, v = p.{@link #tangentV()}. tangentU is +x projected onto
 * the plane (+y instead when the normal is within about 25 degrees of the x axis), and
 * tangentV = n x tangentU, so dpdu x dpdv = n points out. For the floor plane (n = +y) u runs
 * along +x and v along -z; for n = +z, u along +x and v along +y.
 *
 * <p>A ray parallel to the plane never hits it; for spans it lies either wholly inside
 * (-inf, +inf) or wholly outside. Infinite span endpoints carry prim -1 (no surface there).
 */
public final class Plane extends GObject {
    private final Vec3 normal;
    private final double offset;
    private final Vec3 tangentU, tangentV;
    private final double nx, ny, nz;

    /**
     * The plane of points p with normal.p = offset (normal and offset scaled together to a unit normal).
     *
     * @param normal the normal, of any non-zero length
     * @param offset the value of normal.p on the plane, in the scale of the given normal
     * @throws IllegalArgumentException if the normal is zero or a number is not finite and modest
     */
    public Plane(Vec3 normal, double offset) {
        if (!Ranges.isModest(normal) || !(normal.length() > 0)) throw new IllegalArgumentException("plane normal must be a non-zero vector with components at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude, found " + normal);
        Ranges.modest("plane offset", offset);
        double len = normal.length();
        this.normal = normal.times(1 / len);
        this.offset = offset / len;
        nx = this.normal.x();
        ny = this.normal.y();
        nz = this.normal.z();
        Vec3 helper = Math.abs(nx) > 0.9 ? Vec3.Y : Vec3.X;
        tangentU = helper.minus(this.normal.times(helper.dot(this.normal))).normalized();
        tangentV = this.normal.cross(tangentU);
    }

    /**
     * Unit normal.
     *
     * @return the given normal scaled to unit length
     */
    public Vec3 normal() { return normal; }
    /**
     * Signed distance of the plane from the origin along the unit normal.
     *
     * @return the offset scaled to the unit normal (negative if the origin is on the normal's side)
     */
    public double offset() { return offset; }
    /**
     * Unit direction of increasing u (dpdu).
     *
     * @return the unit tangent along which u grows, perpendicular to the normal
     */
    public Vec3 tangentU() { return tangentU; }
    /**
     * Unit direction of increasing v (dpdv); normal() = tangentU() x tangentV().
     *
     * @return the unit tangent along which v grows
     */
    public Vec3 tangentV() { return tangentV; }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public Plane transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public Plane motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public Plane material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public Plane name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public Plane source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public Plane source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "plane"; }
    @Override public Bounds localBounds() { return Bounds.INFINITE; }
    @Override public boolean isClosed() { return true; }

    @Override public boolean flat() { return true; }

    /** The whole object is one cheap test: worth trying first as the thread's last occluder. */
    @Override int blockingPart(TraceContext ctx) { return 0; }

    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        double denom = nx * ray.dx + ny * ray.dy + nz * ray.dz;
        if (denom == 0) return false;
        double t = (offset - (nx * ray.ox + ny * ray.oy + nz * ray.oz)) / denom;
        if (!(t > ray.tMin && t < ray.tMax)) return false;
        hit.t = t;
        hit.prim = 0;
        hit.u = 0;
        hit.v = 0;
        return true;
    }

    @Override protected void spansLocal(Ray ray, SpanBuffer out, TraceContext ctx) {
        double denom = nx * ray.dx + ny * ray.dy + nz * ray.dz;
        double dist = nx * ray.ox + ny * ray.oy + nz * ray.oz - offset; // > 0 outside
        if (denom == 0) {
            if (dist <= 0) out.add(Double.NEGATIVE_INFINITY, this, -1, 0, 0, Double.POSITIVE_INFINITY, this, -1, 0, 0);
            return;
        }
        double t = -dist / denom;
        if (denom > 0) {
            // Heading out: inside before the crossing.
            if (t > ray.tMin) out.add(Double.NEGATIVE_INFINITY, this, -1, 0, 0, t, this, 0, 0, 0);
        } else if (denom < 0) {
            if (t < ray.tMax) out.add(t, this, 0, 0, 0, Double.POSITIVE_INFINITY, this, -1, 0, 0);
        }
    }

    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        sd.setNormal(nx, ny, nz);
        sd.u = x * tangentU.x() + y * tangentU.y() + z * tangentU.z();
        sd.v = x * tangentV.x() + y * tangentV.y() + z * tangentV.z();
        sd.setDerivatives(tangentU.x(), tangentU.y(), tangentU.z(), tangentV.x(), tangentV.y(), tangentV.z());
    }
}
