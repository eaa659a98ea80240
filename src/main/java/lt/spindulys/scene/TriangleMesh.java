package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/**
 * A triangle mesh held in flat arrays (no object per triangle) with its own acceleration
 * structure. Polygons are triangulated as fans. Closed when every edge has exactly two faces.
 */
public final class TriangleMesh extends GObject {
    private final MeshData data;

    /** Interpolate vertex normals (true) or shade each triangle with its face normal (false). */
    private boolean smooth;

    public TriangleMesh(MeshData data) { this.data = data; }

    /** Chooses smooth (interpolated vertex normals) or flat shading; the scene file's 'shading' key. */
    public TriangleMesh smooth(boolean s) {
        checkMutable();
        smooth = s;
        return this;
    }

    @Override public String kind() { return "mesh"; }
    @Override public Bounds localBounds() { throw new UnsupportedOperationException("TODO"); }
    @Override public boolean isClosed() { throw new UnsupportedOperationException("TODO"); }
    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { throw new UnsupportedOperationException("TODO"); }
    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) { throw new UnsupportedOperationException("TODO"); }
}
