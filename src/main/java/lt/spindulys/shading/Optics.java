package lt.spindulys.shading;

/**
 * Reflection, refraction and Fresnel on plain doubles (no allocation): the formulas the
 * integrator uses, kept apart so they can be tested on their own.
 */
public final class Optics {
    private Optics() {}

    /**
     * Mirror direction of unit incident direction d about unit normal n (either side):
     * r = d - 2 (d.n) n, written to out[0..2].
     */
    public static void reflect(double dx, double dy, double dz, double nx, double ny, double nz, double[] out) {
        double k = 2 * (dx * nx + dy * ny + dz * nz);
        out[0] = dx - k * nx;
        out[1] = dy - k * ny;
        out[2] = dz - k * nz;
    }

    /**
     * Snell refraction of unit direction d through a surface with unit normal n facing the incoming
     * ray (d.n <= 0), going from index n1 to n2. Writes the unit transmitted direction to out and
     * returns true, or returns false on total internal reflection.
     */
    public static boolean refract(double dx, double dy, double dz, double nx, double ny, double nz,
                                  double n1, double n2, double[] out) {
        double eta = n1 / n2;
        double cosI = -(dx * nx + dy * ny + dz * nz);
        double sin2T = eta * eta * Math.max(0, 1 - cosI * cosI);
        if (sin2T > 1) return false;
        double cosT = Math.sqrt(1 - sin2T);
        double k = eta * cosI - cosT;
        double x = eta * dx + k * nx, y = eta * dy + k * ny, z = eta * dz + k * nz;
        double len = Math.sqrt(x * x + y * y + z * z);
        out[0] = x / len; out[1] = y / len; out[2] = z / len;
        return true;
    }

    /**
     * Schlick's approximation of the Fresnel reflectance for light arriving at cosine cosI
     * (against the facing normal) from index n1 into n2; 1 under total internal reflection.
     * Uses the transmitted angle when leaving the denser medium, so it is symmetric.
     */
    public static double schlick(double cosI, double n1, double n2) {
        double r0 = (n1 - n2) / (n1 + n2);
        r0 *= r0;
        double c = cosI;
        if (n1 > n2) {
            double eta = n1 / n2;
            double sin2T = eta * eta * Math.max(0, 1 - cosI * cosI);
            if (sin2T > 1) return 1;
            c = Math.sqrt(1 - sin2T);
        }
        double m = 1 - c, m2 = m * m;
        return r0 + (1 - r0) * m2 * m2 * m;
    }
}
