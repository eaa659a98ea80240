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
 * A cylinder with flat caps, from the centre of its base cap to the centre of its top cap. Closed.
 *
 * <p>The cylinder is intersected in its own orthonormal frame (U, V, W) anchored at the base,
 * with W the unit axis towards the top, U = the most perpendicular coordinate axis projected
 * off W ({@link #axisU()}) and V = W x U. The frame is rigid, so the ray parameter t is the
 * same in it and {@link #transform()} stays exactly the placement the user gave.
 *
 * <p>The hit's prim is the part: {@link #SIDE}, {@link #BASE_CAP} or {@link #TOP_CAP}.
 * Texture coordinates, with (x, y, z) the point's coordinates in the frame:
 * <ul>
 * <li>side: u = phi / (2 pi), phi = atan2(y, x) in [0, 2 pi) the angle about the axis from U
 * towards V; v = z / height, 0 at the base and 1 at the top;</li>
 * <li>top cap: u = (x / r + 1) / 2, v = (y / r + 1) / 2, planar coordinates of the disk in [0, 1];</li>
 * <li>base cap: u = (x / r + 1) / 2, v = (1 - y / r) / 2 (mirrored so that dpdu x dpdv points out).</li>
 * </ul>
 * On every part dpdu x dpdv points out of the solid.
 */
public final class Cylinder extends GObject {
    /** Part index of the curved side. */
    public static final int SIDE = 0;
    /** Part index of the cap at the base point. */
    public static final int BASE_CAP = 1;
    /** Part index of the cap at the top point. */
    public static final int TOP_CAP = 2;

    private static final double TWO_PI = 2 * Math.PI;

    private final Vec3 base, top;
    private final double radius;
    private final Vec3 axisU, axisV, axisW;
    // Unpacked frame for the per-ray path.
    private final double bx, by, bz, ux, uy, uz, vx, vy, vz, wx, wy, wz, height, r2;

    /**
     * The cylinder from the centre of its base cap to the centre of its top cap.
     *
     * @param base centre of the base cap (object space)
     * @param top centre of the top cap; must differ from {@code base}
     * @param radius the radius, positive (object-space units)
     * @throws IllegalArgumentException if the ends coincide, the radius is not positive, or a number is not finite and modest
     */
    public Cylinder(Vec3 base, Vec3 top, double radius) {
        if (!Ranges.isModest(base) || !Ranges.isModest(top)) throw new IllegalArgumentException("cylinder end points must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude, found " + base + " and " + top);
        if (!(top.minus(base).length() > 0)) throw new IllegalArgumentException("cylinder base and top are the same point " + base);
        if (!(radius > 0) || !Ranges.isModest(radius)) throw new IllegalArgumentException("cylinder radius must be a positive number at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + radius);
        this.base = base;
        this.top = top;
        this.radius = radius;
        Vec3 axis = top.minus(base);
        this.height = axis.length();
        if (!Double.isFinite(height)) throw new IllegalArgumentException("cylinder is too long: " + base + " to " + top);
        axisW = axis.times(1 / height);
        double ax = Math.abs(axisW.x()), ay = Math.abs(axisW.y()), az = Math.abs(axisW.z());
        Vec3 helper = ax <= ay && ax <= az ? Vec3.X : ay <= az ? Vec3.Y : Vec3.Z;
        axisU = helper.minus(axisW.times(helper.dot(axisW))).normalized();
        axisV = axisW.cross(axisU);
        bx = base.x(); by = base.y(); bz = base.z();
        ux = axisU.x(); uy = axisU.y(); uz = axisU.z();
        vx = axisV.x(); vy = axisV.y(); vz = axisV.z();
        wx = axisW.x(); wy = axisW.y(); wz = axisW.z();
        r2 = radius * radius;
    }

    /**
     * Centre of the base cap (object space).
     *
     * @return the base cap's centre
     */
    public Vec3 base() { return base; }
    /**
     * Centre of the top cap (object space).
     *
     * @return the top cap's centre
     */
    public Vec3 top() { return top; }
    /**
     * Radius (object-space units).
     *
     * @return the radius, positive
     */
    public double radius() { return radius; }
    /**
     * Distance from base to top.
     *
     * @return the length of the axis, positive (object-space units)
     */
    public double height() { return height; }
    /**
     * Unit axis from base to top (W of the frame).
     *
     * @return the unit vector from base to top
     */
    public Vec3 axis() { return axisW; }
    /**
     * Direction of u = 0 on the side (U of the frame), perpendicular to the axis.
     *
     * @return a unit vector perpendicular to the axis
     */
    public Vec3 axisU() { return axisU; }
    /**
     * The third frame direction, V = W x U (u = 1/4 on the side).
     *
     * @return the unit vector completing the right-handed frame U, V, W
     */
    public Vec3 axisV() { return axisV; }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public Cylinder transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public Cylinder motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public Cylinder material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public Cylinder name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public Cylinder source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public Cylinder source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "cylinder"; }

    @Override public Bounds localBounds() {
        // Exact box of the two cap disks: a disk of radius r with normal W extends
        // r sqrt(1 - W_i^2) along coordinate axis i.
        double ex = radius * Math.sqrt(Math.max(0, 1 - wx * wx));
        double ey = radius * Math.sqrt(Math.max(0, 1 - wy * wy));
        double ez = radius * Math.sqrt(Math.max(0, 1 - wz * wz));
        return new Bounds(Math.min(bx, top.x()) - ex, Math.min(by, top.y()) - ey, Math.min(bz, top.z()) - ez,
                Math.max(bx, top.x()) + ex, Math.max(by, top.y()) + ey, Math.max(bz, top.z()) + ez);
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
     * The solid is convex, so the ray is inside it on one interval: the intersection of the
     * slab 0 <= z <= height with the infinite cylinder x^2 + y^2 <= r^2 (in the frame). With
     * {@code out == null} records the nearest hit in (tMin, tMax); otherwise appends the span
     * if it overlaps (tMin, tMax).
     */
    private boolean trace(Ray ray, Hit hit, SpanBuffer out) {
        double qx = ray.ox - bx, qy = ray.oy - by, qz = ray.oz - bz;
        double ox = qx * ux + qy * uy + qz * uz;
        double oy = qx * vx + qy * vy + qz * vz;
        double oz = qx * wx + qy * wy + qz * wz;
        double dx = ray.dx * ux + ray.dy * uy + ray.dz * uz;
        double dy = ray.dx * vx + ray.dy * vy + ray.dz * vz;
        double dz = ray.dx * wx + ray.dy * wy + ray.dz * wz;

        double tIn, tOut;
        int pIn, pOut;
        if (dz == 0) {
            // Perpendicular to the axis: between the cap planes for every t or for none.
            if (!(oz >= 0 && oz <= height)) return false;
            tIn = Double.NEGATIVE_INFINITY; tOut = Double.POSITIVE_INFINITY;
            pIn = pOut = -1;
        } else {
            double tb = -oz / dz, tt = (height - oz) / dz;
            if (dz > 0) { tIn = tb; pIn = BASE_CAP; tOut = tt; pOut = TOP_CAP; }
            else { tIn = tt; pIn = TOP_CAP; tOut = tb; pOut = BASE_CAP; }
        }

        double a = dx * dx + dy * dy;
        if (a == 0) {
            // Parallel to the axis: inside the infinite cylinder for every t or for none.
            if (!(ox * ox + oy * oy <= r2)) return false;
        } else {
            // Same stable quadratic as the sphere, in the plane perpendicular to the axis.
            double h = ox * dx + oy * dy;
            double k = h / a;
            double lx = ox - k * dx, ly = oy - k * dy;
            double disc = r2 - (lx * lx + ly * ly);
            if (!(disc >= 0)) return false;
            double c = ox * ox + oy * oy - r2;
            double q = -(h + Math.copySign(Math.sqrt(a * disc), h));
            double s0 = q / a;
            double s1 = q != 0 ? c / q : s0;
            if (s0 > s1) { double s = s0; s0 = s1; s1 = s; }
            if (s0 > tIn) { tIn = s0; pIn = SIDE; }
            if (s1 < tOut) { tOut = s1; pOut = SIDE; }
        }
        if (!(tIn <= tOut)) return false;
        if (out != null) {
            if (tOut > ray.tMin && tIn < ray.tMax) out.add(tIn, this, pIn, 0, 0, tOut, this, pOut, 0, 0);
            return false;
        }
        double t;
        int part;
        if (tIn > ray.tMin) { t = tIn; part = pIn; } else { t = tOut; part = pOut; }
        if (!(t > ray.tMin && t < ray.tMax)) return false;
        hit.t = t;
        hit.prim = part;
        hit.u = 0;
        hit.v = 0;
        return true;
    }

    @Override protected void shadeLocal(double px, double py, double pz, Hit hit, ShadingData sd) {
        double qx = px - bx, qy = py - by, qz = pz - bz;
        double x = qx * ux + qy * uy + qz * uz;
        double y = qx * vx + qy * vy + qz * vz;
        double z = qx * wx + qy * wy + qz * wz;
        double rho = Math.sqrt(x * x + y * y);
        int part = hit.prim;
        if (part < SIDE || part > TOP_CAP) {
            // No part recorded: take the surface nearest to the point.
            double dSide = Math.abs(rho - radius), dBase = Math.abs(z), dTop = Math.abs(z - height);
            part = dSide <= dBase && dSide <= dTop ? SIDE : dBase <= dTop ? BASE_CAP : TOP_CAP;
        }
        if (part == SIDE) {
            double phi = Math.atan2(y, x);
            if (phi < 0) phi += TWO_PI;
            double cosPhi = Math.cos(phi), sinPhi = Math.sin(phi);
            // Outward radial direction (cos phi U + sin phi V), exact even if the point drifted.
            double nX = cosPhi * ux + sinPhi * vx, nY = cosPhi * uy + sinPhi * vy, nZ = cosPhi * uz + sinPhi * vz;
            sd.setNormal(nX, nY, nZ);
            sd.u = phi / TWO_PI;
            sd.v = Math.max(0, Math.min(1, z / height));
            // p = B + r cos(2 pi u) U + r sin(2 pi u) V + v h W
            double s = TWO_PI * radius;
            sd.setDerivatives(s * (-sinPhi * ux + cosPhi * vx), s * (-sinPhi * uy + cosPhi * vy), s * (-sinPhi * uz + cosPhi * vz),
                    height * wx, height * wy, height * wz);
        } else {
            double sx = Math.max(-1, Math.min(1, x / radius)), sy = Math.max(-1, Math.min(1, y / radius));
            double d = 2 * radius;
            sd.u = (sx + 1) / 2;
            if (part == TOP_CAP) {
                sd.setNormal(wx, wy, wz);
                sd.v = (sy + 1) / 2;
                sd.setDerivatives(d * ux, d * uy, d * uz, d * vx, d * vy, d * vz);
            } else {
                sd.setNormal(-wx, -wy, -wz);
                sd.v = (1 - sy) / 2;
                sd.setDerivatives(d * ux, d * uy, d * uz, -d * vx, -d * vy, -d * vz);
            }
        }
    }
}
