package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/** An axis-aligned box between two corners in its own space (rotate it with a transform). Closed. */
public final class Box extends GObject {
    private final Vec3 min, max;

    public Box(Vec3 corner1, Vec3 corner2) {
        if (!corner1.isFinite() || !corner2.isFinite()) throw new IllegalArgumentException("box corners must be finite");
        Vec3 lo = new Vec3(Math.min(corner1.x(), corner2.x()), Math.min(corner1.y(), corner2.y()), Math.min(corner1.z(), corner2.z()));
        Vec3 hi = new Vec3(Math.max(corner1.x(), corner2.x()), Math.max(corner1.y(), corner2.y()), Math.max(corner1.z(), corner2.z()));
        if (!(hi.x() > lo.x() && hi.y() > lo.y() && hi.z() > lo.z())) {
            throw new IllegalArgumentException("box has zero thickness: corners " + corner1 + " and " + corner2);
        }
        this.min = lo;
        this.max = hi;
    }

    public Vec3 min() { return min; }
    public Vec3 max() { return max; }

    @Override public String kind() { return "box"; }
    @Override public Bounds localBounds() { throw new UnsupportedOperationException("TODO"); }
    @Override public boolean isClosed() { throw new UnsupportedOperationException("TODO"); }
    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { throw new UnsupportedOperationException("TODO"); }
    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) { throw new UnsupportedOperationException("TODO"); }
}
