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
 * An axis-aligned box between two corners in its own space (rotate it with a transform). Closed.
 *
 * <p>The hit's prim is the face: 2 * axis + (0 for the min face, 1 for the max face), so
 * 0 = -x, 1 = +x, 2 = -y, 3 = +y, 4 = -z, 5 = +z. Each face has uv in [0, 1]^2: with
 * a1 = (axis + 1) % 3 and a2 = (axis + 2) % 3 and s1, s2 the point's fractions along them,
 * the max face has (u, v) = (s1, s2) and the min face (u, v) = (s2, s1), so that on every face
 * dpdu x dpdv points out. dpdu and dpdv are the box edges along those axes.
 *
 * <p>The faces are closed: a ray lying in a face plane counts as touching the box, and where
 * a ray enters through an edge or corner the face of the lowest axis is reported.
 */
public final class Box extends GObject {
    private final Vec3 min, max;
    private final double[] lo, hi;

    /**
     * The box between two opposite corners, in either order.
     *
     * @param corner1 one corner (object space)
     * @param corner2 the opposite corner; it must differ from {@code corner1} in every coordinate
     * @throws IllegalArgumentException if a coordinate is not finite and modest
     */
    public Box(Vec3 corner1, Vec3 corner2) {
        if (!Ranges.isModest(corner1) || !Ranges.isModest(corner2)) throw new IllegalArgumentException("box corners must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude, found " + corner1 + " and " + corner2);
        Vec3 lo = new Vec3(Math.min(corner1.x(), corner2.x()), Math.min(corner1.y(), corner2.y()), Math.min(corner1.z(), corner2.z()));
        Vec3 hi = new Vec3(Math.max(corner1.x(), corner2.x()), Math.max(corner1.y(), corner2.y()), Math.max(corner1.z(), corner2.z()));
        if (!(hi.x() > lo.x() && hi.y() > lo.y() && hi.z() > lo.z())) {
            throw new IllegalArgumentException("box has zero thickness: corners " + corner1 + " and " + corner2);
        }
        this.min = lo;
        this.max = hi;
        this.lo = new double[] {lo.x(), lo.y(), lo.z()};
        this.hi = new double[] {hi.x(), hi.y(), hi.z()};
    }

    /**
     * The corner with the smallest coordinates (object space).
     *
     * @return the lower corner: the smaller of the given corners' coordinates on each axis
     */
    public Vec3 min() { return min; }
    /**
     * The corner with the largest coordinates (object space).
     *
     * @return the upper corner: the larger of the given corners' coordinates on each axis
     */
    public Vec3 max() { return max; }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public Box transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public Box motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public Box material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public Box name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public Box source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public Box source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "box"; }
    @Override public Bounds localBounds() { return Bounds.of(min, max); }
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
     * Slab test shared by both queries, tracking which face bounds the entry and the exit.
     * With {@code out == null} records the nearest hit in (tMin, tMax); otherwise appends
     * the span if it overlaps (tMin, tMax).
     */
    private boolean trace(Ray ray, Hit hit, SpanBuffer out) {
        double t0 = Double.NEGATIVE_INFINITY, t1 = Double.POSITIVE_INFINITY;
        int f0 = -1, f1 = -1;
        for (int a = 0; a < 3; a++) {
            double o = a == 0 ? ray.ox : a == 1 ? ray.oy : ray.oz;
            double d = a == 0 ? ray.dx : a == 1 ? ray.dy : ray.dz;
            if (d == 0) {
                // Parallel to this slab (either zero sign): no crossing, and no 0 * inf NaN.
                if (!(o >= lo[a] && o <= hi[a])) return false;
                continue;
            }
            double tn = (lo[a] - o) / d, tf = (hi[a] - o) / d;
            int fn = 2 * a, ff = 2 * a + 1;
            if (d < 0) {
                double s = tn; tn = tf; tf = s;
                fn = 2 * a + 1; ff = 2 * a;
            }
            if (tn > t0) { t0 = tn; f0 = fn; }
            if (tf < t1) { t1 = tf; f1 = ff; }
        }
        if (!(t0 <= t1)) return false;
        if (out != null) {
            if (t1 > ray.tMin && t0 < ray.tMax) out.add(t0, this, f0, 0, 0, t1, this, f1, 0, 0);
            return false;
        }
        double t;
        int face;
        if (t0 > ray.tMin) { t = t0; face = f0; } else { t = t1; face = f1; }
        if (!(t > ray.tMin && t < ray.tMax)) return false;
        hit.t = t;
        hit.prim = face;
        hit.u = 0;
        hit.v = 0;
        return true;
    }

    @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        int face = hit.prim;
        if (face < 0 || face > 5) face = nearestFace(x, y, z);
        int axis = face >> 1;
        boolean maxFace = (face & 1) == 1;
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        double p1 = a1 == 0 ? x : a1 == 1 ? y : z;
        double p2 = a2 == 0 ? x : a2 == 1 ? y : z;
        double e1 = hi[a1] - lo[a1], e2 = hi[a2] - lo[a2];
        double s1 = clamp01((p1 - lo[a1]) / e1), s2 = clamp01((p2 - lo[a2]) / e2);
        double sign = maxFace ? 1 : -1;
        sd.setNormal(axis == 0 ? sign : 0, axis == 1 ? sign : 0, axis == 2 ? sign : 0);
        double[] du = sd.dpdu, dv = sd.dpdv;
        du[0] = du[1] = du[2] = 0;
        dv[0] = dv[1] = dv[2] = 0;
        if (maxFace) {
            sd.u = s1; sd.v = s2;
            du[a1] = e1; dv[a2] = e2;
        } else {
            sd.u = s2; sd.v = s1;
            du[a2] = e2; dv[a1] = e1;
        }
    }

    /** The face whose plane is closest to an object-space point (for a hit without a face). */
    private int nearestFace(double x, double y, double z) {
        int best = 0;
        double bestDist = Double.POSITIVE_INFINITY;
        for (int f = 0; f < 6; f++) {
            int a = f >> 1;
            double p = a == 0 ? x : a == 1 ? y : z;
            double dist = Math.abs(p - ((f & 1) == 1 ? hi[a] : lo[a]));
            if (dist < bestDist) { bestDist = dist; best = f; }
        }
        return best;
    }

    private static double clamp01(double s) { return s < 0 ? 0 : s > 1 ? 1 : s; }
}
