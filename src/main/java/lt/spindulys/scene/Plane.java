package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/**
 * The infinite plane n.p = offset. As a solid it is the half-space n.p <= offset (the normal
 * points out), so it can take part in CSG.
 */
public final class Plane extends GObject {
    private final Vec3 normal;
    private final double offset;

    public Plane(Vec3 normal, double offset) {
        if (!normal.isFinite() || !(normal.length() > 0)) throw new IllegalArgumentException("plane normal must be a non-zero finite vector, found " + normal);
        if (!Double.isFinite(offset)) throw new IllegalArgumentException("plane offset must be finite, found " + offset);
        double len = normal.length();
        this.normal = normal.times(1 / len);
        this.offset = offset / len;
    }

    /** Unit normal. */
    public Vec3 normal() { return normal; }
    /** Signed distance of the plane from the origin along the unit normal. */
    public double offset() { return offset; }

    @Override public String kind() { return "plane"; }
    @Override public Bounds localBounds() { throw new UnsupportedOperationException("TODO"); }
    @Override public boolean isClosed() { throw new UnsupportedOperationException("TODO"); }
    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { throw new UnsupportedOperationException("TODO"); }
    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) { throw new UnsupportedOperationException("TODO"); }
}
