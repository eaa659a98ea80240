package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Motion;
import lt.spindulys.material.Material;

/**
 * A single triangle, optionally with per-vertex normals and texture coordinates. Open (no inside).
 *
 * <p>The hit records prim 0 and the barycentrics (u, v) = (b1, b2) of vertices b and c, so the
 * point is a + b1 (b - a) + b2 (c - a). The geometric normal is (b - a) x (c - a) (counter-
 * clockwise winding faces out). Texture coordinates are (b1, b2), with dpdu = b - a and
 * dpdv = c - a, unless {@link #uvs} gives per-vertex ones, which are then interpolated.
 * With {@link #normals} the shading normal is the interpolated vertex normal, and the
 * geometric normal is turned to its side (vertex normals say which side is out).
 * A ray in the triangle's plane does not hit it.
 */
public final class Triangle extends GObject {
    private final Vec3 a, b, c;
    // a and the edges b - a, c - a, unpacked for the per-ray path.
    private final double ax, ay, az, e1x, e1y, e1z, e2x, e2y, e2z;
    /** Unit vertex normals (9 values) or null. */
    private double[] normals;
    /** Vertex texture coordinates u0, v0, u1, v1, u2, v2, or null. */
    private double[] uvs;

    /**
     * The triangle abc; counter-clockwise seen from the side its normal points to.
     *
     * @param a first vertex (object space)
     * @param b second vertex
     * @param c third vertex
     * @throws IllegalArgumentException if it has zero area or a coordinate is not finite and modest
     */
    public Triangle(Vec3 a, Vec3 b, Vec3 c) {
        if (!Ranges.isModest(a) || !Ranges.isModest(b) || !Ranges.isModest(c)) throw new IllegalArgumentException("triangle vertices must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude, found " + a + " " + b + " " + c);
        if (!(b.minus(a).cross(c.minus(a)).length() > 0)) throw new IllegalArgumentException("triangle " + a + " " + b + " " + c + " is degenerate (zero area)");
        this.a = a; this.b = b; this.c = c;
        ax = a.x(); ay = a.y(); az = a.z();
        e1x = b.x() - ax; e1y = b.y() - ay; e1z = b.z() - az;
        e2x = c.x() - ax; e2y = c.y() - ay; e2z = c.z() - az;
    }

    /**
     * First vertex (object space).
     *
     * @return the first vertex, as given
     */
    public Vec3 a() { return a; }
    /**
     * Second vertex (object space).
     *
     * @return the second vertex, as given
     */
    public Vec3 b() { return b; }
    /**
     * Third vertex (object space).
     *
     * @return the third vertex, as given
     */
    public Vec3 c() { return c; }

    /**
     * Sets per-vertex shading normals (normalised here); each must be finite and non-zero.
     *
     * @param na shading normal at a, any non-zero length
     * @param nb shading normal at b, any non-zero length
     * @param nc shading normal at c, any non-zero length
     * @return this triangle, for chaining
     */
    public Triangle normals(Vec3 na, Vec3 nb, Vec3 nc) {
        checkMutable();
        Vec3[] ns = {na, nb, nc};
        double[] out = new double[9];
        for (int i = 0; i < 3; i++) {
            Vec3 n = ns[i];
            if (n == null || !n.isFinite() || !(n.length() > 0)) {
                throw new IllegalArgumentException("triangle vertex normal " + i + " must be a non-zero finite vector, found " + n);
            }
            Vec3 u = n.normalized();
            out[3 * i] = u.x(); out[3 * i + 1] = u.y(); out[3 * i + 2] = u.z();
        }
        normals = out;
        return this;
    }

    /**
     * Sets per-vertex texture coordinates (u0, v0) at a, (u1, v1) at b, (u2, v2) at c; all finite.
     *
     * @param u0 u at a
     * @param v0 v at a
     * @param u1 u at b
     * @param v1 v at b
     * @param u2 u at c
     * @param v2 v at c
     * @return this triangle, for chaining
     */
    public Triangle uvs(double u0, double v0, double u1, double v1, double u2, double v2) {
        checkMutable();
        double[] out = {u0, v0, u1, v1, u2, v2};
        for (double x : out) {
            if (!Double.isFinite(x)) throw new IllegalArgumentException("triangle texture coordinates must be finite, found " + x);
        }
        uvs = out;
        return this;
    }

    /**
     * True if vertex normals were given.
     *
     * @return true if {@link #normals} was called
     */
    public boolean hasNormals() { return normals != null; }
    /**
     * True if vertex texture coordinates were given.
     *
     * @return true if {@link #uvs} was called
     */
    public boolean hasUvs() { return uvs != null; }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public Triangle transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public Triangle motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public Triangle material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public Triangle name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public Triangle source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public Triangle source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "triangle"; }
    @Override public Bounds localBounds() { return Bounds.of(a, b).union(c.x(), c.y(), c.z()); }
    @Override public boolean isClosed() { return false; }

    @Override public boolean flat() { return true; }

    /** Möller–Trumbore; every rejection is written so that a NaN rejects too. */
    /** The whole object is one cheap test: worth trying first as the thread's last occluder. */
    @Override int blockingPart(TraceContext ctx) { return 0; }

    @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        double dx = ray.dx, dy = ray.dy, dz = ray.dz;
        double px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        double det = e1x * px + e1y * py + e1z * pz;
        if (det == 0) return false;
        double inv = 1 / det;
        double tx = ray.ox - ax, ty = ray.oy - ay, tz = ray.oz - az;
        double b1 = (tx * px + ty * py + tz * pz) * inv;
        if (!(b1 >= 0 && b1 <= 1)) return false;
        double qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
        double b2 = (dx * qx + dy * qy + dz * qz) * inv;
        if (!(b2 >= 0 && b1 + b2 <= 1)) return false;
        double t = (e2x * qx + e2y * qy + e2z * qz) * inv;
        if (!(t > ray.tMin && t < ray.tMax)) return false;
        hit.t = t;
        hit.prim = 0;
        hit.u = b1;
        hit.v = b2;
        return true;
    }

    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        double b1 = hit.u, b2 = hit.v, b0 = 1 - b1 - b2;
        double gx = e1y * e2z - e1z * e2y, gy = e1z * e2x - e1x * e2z, gz = e1x * e2y - e1y * e2x;
        double gl = Math.sqrt(gx * gx + gy * gy + gz * gz);
        gx /= gl; gy /= gl; gz /= gl;
        double sx = gx, sy = gy, sz = gz;
        if (normals != null) {
            double[] n = normals;
            double ix = b0 * n[0] + b1 * n[3] + b2 * n[6];
            double iy = b0 * n[1] + b1 * n[4] + b2 * n[7];
            double iz = b0 * n[2] + b1 * n[5] + b2 * n[8];
            double il = Math.sqrt(ix * ix + iy * iy + iz * iz);
            if (il > 0) {
                // Opposing vertex normals can cancel; then the geometric normal stands in.
                sx = ix / il; sy = iy / il; sz = iz / il;
                if (gx * sx + gy * sy + gz * sz < 0) { gx = -gx; gy = -gy; gz = -gz; }
            }
        }
        sd.ng[0] = gx; sd.ng[1] = gy; sd.ng[2] = gz;
        sd.ns[0] = sx; sd.ns[1] = sy; sd.ns[2] = sz;

        if (uvs == null) {
            sd.u = b1;
            sd.v = b2;
            sd.setDerivatives(e1x, e1y, e1z, e2x, e2y, e2z);
            return;
        }
        double[] t = uvs;
        sd.u = b0 * t[0] + b1 * t[2] + b2 * t[4];
        sd.v = b0 * t[1] + b1 * t[3] + b2 * t[5];
        // Solve [e1 e2] = [dpdu dpdv] J, J the uv edge matrix.
        double du1 = t[2] - t[0], dv1 = t[3] - t[1], du2 = t[4] - t[0], dv2 = t[5] - t[1];
        double det = du1 * dv2 - du2 * dv1;
        if (!(Math.abs(det) > 1e-12 * (Math.abs(du1 * dv2) + Math.abs(du2 * dv1)))) {
            // Collinear uvs: no derivative exists; the edges still give a valid tangent frame.
            sd.setDerivatives(e1x, e1y, e1z, e2x, e2y, e2z);
            return;
        }
        double id = 1 / det;
        sd.setDerivatives((dv2 * e1x - dv1 * e2x) * id, (dv2 * e1y - dv1 * e2y) * id, (dv2 * e1z - dv1 * e2z) * id,
                (du1 * e2x - du2 * e1x) * id, (du1 * e2y - du2 * e1y) * id, (du1 * e2z - du2 * e1z) * id);
    }
}
