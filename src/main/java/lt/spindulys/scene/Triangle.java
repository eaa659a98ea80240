package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/** A single triangle, optionally with per-vertex normals and texture coordinates. Open (no inside). */
public final class Triangle extends GObject {
    private final Vec3 a, b, c;

    public Triangle(Vec3 a, Vec3 b, Vec3 c) {
        if (!a.isFinite() || !b.isFinite() || !c.isFinite()) throw new IllegalArgumentException("triangle vertices must be finite");
        if (!(b.minus(a).cross(c.minus(a)).length() > 0)) throw new IllegalArgumentException("triangle " + a + " " + b + " " + c + " is degenerate (zero area)");
        this.a = a; this.b = b; this.c = c;
    }

    @Override public String kind() { return "triangle"; }
    @Override public Bounds localBounds() { throw new UnsupportedOperationException("TODO"); }
    @Override public boolean isClosed() { throw new UnsupportedOperationException("TODO"); }
    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { throw new UnsupportedOperationException("TODO"); }
    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) { throw new UnsupportedOperationException("TODO"); }
}
