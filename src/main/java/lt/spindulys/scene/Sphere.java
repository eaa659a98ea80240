package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/** A sphere given by centre and radius. Closed. */
public final class Sphere extends GObject {
    private final Vec3 center;
    private final double radius;

    public Sphere(Vec3 center, double radius) {
        if (!center.isFinite()) throw new IllegalArgumentException("sphere center must be finite, found " + center);
        if (!(radius > 0) || !Double.isFinite(radius)) throw new IllegalArgumentException("sphere radius must be a positive number, found " + radius);
        this.center = center;
        this.radius = radius;
    }

    public Vec3 center() { return center; }
    public double radius() { return radius; }

    @Override public String kind() { return "sphere"; }
    @Override public Bounds localBounds() { throw new UnsupportedOperationException("TODO"); }
    @Override public boolean isClosed() { throw new UnsupportedOperationException("TODO"); }
    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { throw new UnsupportedOperationException("TODO"); }
    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) { throw new UnsupportedOperationException("TODO"); }
}
