package lt.spindulys.light;

import lt.spindulys.scene.AreaLight;

/**
 * A sphere light, emitting outwards: sampled uniformly within the cone of directions it fills
 * seen from the shaded point, so the density in solid angle is 1 / (2 pi (1 - cos theta_max))
 * inside the cone and 0 outside; a point inside the sphere gets no sample.
 */
public final class SphereSource extends AreaSource {
    private final double r, r2;

    SphereSource(AreaLight light) {
        super(light);
        r = light.radius();
        r2 = r * r;
    }

    @Override
    public boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out) {
        double wx = cx - px, wy = cy - py, wz = cz - pz;
        double d2 = wx * wx + wy * wy + wz * wz;
        if (!(d2 > r2)) return false;
        double d = Math.sqrt(d2);
        wx /= d; wy /= d; wz /= d;
        double oneMinusCosMax = oneMinusCosMax(d2);
        double cos = 1 - u * oneMinusCosMax, sin = Math.sqrt(Math.max(0, 1 - cos * cos));
        double phi = 2 * Math.PI * v;
        // A frame about the direction to the centre.
        double ax = Math.abs(wx) < 0.9 ? 1 : 0, ay = ax == 1 ? 0 : 1;
        double tx = ay * wz, ty = -ax * wz, tz = ax * wy - ay * wx; // (a x w)
        double tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
        tx /= tl; ty /= tl; tz /= tl;
        double bx = wy * tz - wz * ty, by = wz * tx - wx * tz, bz = wx * ty - wy * tx;
        double cp = Math.cos(phi) * sin, sp = Math.sin(phi) * sin;
        double dx = wx * cos + tx * cp + bx * sp, dy = wy * cos + ty * cp + by * sp, dz = wz * cos + tz * cp + bz * sp;
        // The nearer crossing of the sphere along that direction.
        double t = d * cos - Math.sqrt(Math.max(0, r2 - d2 * sin * sin));
        double x = px + t * dx, y = py + t * dy, z = pz + t * dz;
        double lx = x - px, ly = y - py, lz = z - pz;
        double dist = Math.sqrt(lx * lx + ly * ly + lz * lz);
        if (!(dist > 0)) return false;
        out.x = x; out.y = y; out.z = z;
        out.distance = dist;
        out.wx = lx / dist; out.wy = ly / dist; out.wz = lz / dist;
        out.shadowTMax = PlanarSource.SURFACE_T_MAX;
        emit(2 * Math.PI * oneMinusCosMax, out);
        return true;
    }

    /** 1 - cos of the cone's half angle seen from squared distance d2 > r^2: 1 - sqrt(1 - x) without cancellation. */
    private double oneMinusCosMax(double d2) {
        double x = r2 / d2;
        return x / (1 + Math.sqrt(1 - x));
    }

    @Override
    double intersect(double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax) {
        double x = cx - ox, y = cy - oy, z = cz - oz;
        double a = dx * dx + dy * dy + dz * dz, hb = dx * x + dy * y + dz * z;
        double disc = hb * hb - a * (x * x + y * y + z * z - r2);
        if (disc < 0) return Double.NaN;
        double sq = Math.sqrt(disc);
        double t = (hb - sq) / a;
        if (!(t > tMin)) t = (hb + sq) / a;
        return t > tMin && t < tMax ? t : Double.NaN;
    }

    @Override
    public void radiance(double dx, double dy, double dz, double[] out) {
        out[0] = radianceR; out[1] = radianceG; out[2] = radianceB;
    }

    @Override
    public double pdfLi(double px, double py, double pz, double wx, double wy, double wz) {
        double x = cx - px, y = cy - py, z = cz - pz;
        double d2 = x * x + y * y + z * z;
        if (!(d2 > r2)) return 0;
        double oneMinusCosMax = oneMinusCosMax(d2);
        double cos = (wx * x + wy * y + wz * z) / Math.sqrt(d2);
        return 1 - cos <= oneMinusCosMax ? 1 / (2 * Math.PI * oneMinusCosMax) : 0;
    }

    @Override
    public String statement() { return "spherelight"; }
}
