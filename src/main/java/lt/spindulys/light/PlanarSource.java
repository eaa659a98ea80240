package lt.spindulys.light;

import lt.spindulys.scene.AreaLight;

/**
 * A flat area light, a rectangle or a disc: sampled uniformly by area (the unit square mapped onto
 * it), so the density in solid angle of a point at distance d seen at cosine cos from the light's
 * normal is d^2 / (|cos| area). It emits from both faces, or if one-sided only towards its normal.
 */
public abstract sealed class PlanarSource extends AreaSource permits RectangleSource, DiscSource {
    /** Unit normal, and the half extents (a rectangle's half width and height; a disc's radius along two axes). */
    final double nx, ny, nz, ux, uy, uz, vx, vy, vz;
    /** The squared lengths of the half extents. */
    final double uu, vv;
    final double area;
    final boolean oneSided;

    PlanarSource(AreaLight light) {
        super(light);
        nx = light.normal().x(); ny = light.normal().y(); nz = light.normal().z();
        ux = light.halfU().x(); uy = light.halfU().y(); uz = light.halfU().z();
        vx = light.halfV().x(); vy = light.halfV().y(); vz = light.halfV().z();
        uu = ux * ux + uy * uy + uz * uz;
        vv = vx * vx + vy * vy + vz * vz;
        area = light.area();
        oneSided = light.oneSided();
    }

    /** Whether the point c + a u + b v of the light's plane is on the light. */
    abstract boolean inside(double a, double b);

    /**
     * The sample at c + a u + b v, seen from p: its direction, distance and solid angle per
     * sample, |cos| area / d^2 (cos at the light).
     *
     * @return false at the light's back or on the light itself
     */
    final boolean sampleAt(double a, double b, double px, double py, double pz, LightSample out) {
        double x = cx + a * ux + b * vx, y = cy + a * uy + b * vy, z = cz + a * uz + b * vz;
        double lx = px - x, ly = py - y, lz = pz - z;
        double d2 = lx * lx + ly * ly + lz * lz;
        if (!(d2 > 0)) return false;
        double d = Math.sqrt(d2);
        double cos = (lx * nx + ly * ny + lz * nz) / d;
        if (oneSided ? cos <= 0 : cos == 0) return false;
        out.x = x; out.y = y; out.z = z;
        out.distance = d; // the same as from the point to the sample: (px - x)^2 = (x - px)^2 exactly
        out.wx = (x - px) / d; out.wy = (y - py) / d; out.wz = (z - pz) / d;
        out.shadowTMax = SURFACE_T_MAX;
        emit(Math.abs(cos) * area / d2, out);
        return true;
    }

    /** A shadow ray's end short of a sampled surface point (t = 1 there). */
    static final double SURFACE_T_MAX = 1 - 1e-7;

    @Override
    final double intersect(double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        double denom = nx * dx + ny * dy + nz * dz;
        if (denom == 0) return Double.NaN;
        double t = (nx * (cx - ox) + ny * (cy - oy) + nz * (cz - oz)) / denom;
        if (!(t > tMin && t < tMax)) return Double.NaN;
        double qx = ox + t * dx - cx, qy = oy + t * dy - cy, qz = oz + t * dz - cz;
        double a = (qx * ux + qy * uy + qz * uz) / uu;
        double b = (qx * vx + qy * vy + qz * vz) / vv;
        return inside(a, b) ? t : Double.NaN;
    }

    @Override
    public final void radiance(double dx, double dy, double dz, double[] out) {
        boolean front = nx * dx + ny * dy + nz * dz < 0 || !oneSided;
        out[0] = front ? radianceR : 0;
        out[1] = front ? radianceG : 0;
        out[2] = front ? radianceB : 0;
    }

    @Override
    public final double pdfLi(double px, double py, double pz, double wx, double wy, double wz) {
        double t = intersect(px, py, pz, wx, wy, wz, 0, Double.POSITIVE_INFINITY);
        if (t != t) return 0;
        double cos = -(nx * wx + ny * wy + nz * wz); // at the light, towards the point
        if (oneSided ? cos <= 0 : cos == 0) return 0;
        return t * t / (Math.abs(cos) * area);
    }
}
