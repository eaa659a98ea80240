package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/** A cylinder with flat caps, from the centre of its base cap to the centre of its top cap. Closed. */
public final class Cylinder extends GObject {
    private final Vec3 base, top;
    private final double radius;

    public Cylinder(Vec3 base, Vec3 top, double radius) {
        if (!base.isFinite() || !top.isFinite()) throw new IllegalArgumentException("cylinder end points must be finite");
        if (!(top.minus(base).length() > 0)) throw new IllegalArgumentException("cylinder base and top are the same point " + base);
        if (!(radius > 0) || !Double.isFinite(radius)) throw new IllegalArgumentException("cylinder radius must be a positive number, found " + radius);
        this.base = base;
        this.top = top;
        this.radius = radius;
    }

    public Vec3 base() { return base; }
    public Vec3 top() { return top; }
    public double radius() { return radius; }

    @Override public String kind() { return "cylinder"; }
    @Override public Bounds localBounds() { throw new UnsupportedOperationException("TODO"); }
    @Override public boolean isClosed() { throw new UnsupportedOperationException("TODO"); }
    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { throw new UnsupportedOperationException("TODO"); }
    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) { throw new UnsupportedOperationException("TODO"); }
}
