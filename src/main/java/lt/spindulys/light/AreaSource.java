package lt.spindulys.light;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.AreaLight;

/**
 * An {@link AreaLight}: a surface emitting one radiance (colour times intensity) from every
 * point, that rays can also reach ({@link #intersect}) and then see ({@link #radiance}). It is
 * not scene geometry: it casts no shadow.
 */
public abstract sealed class AreaSource extends Light permits PlanarSource, SphereSource {
    final double cx, cy, cz;
    /** The emitted radiance: colour times intensity. */
    final double radianceR, radianceG, radianceB;
    /** The radiance over the light's samples per pixel sample: one sample's share before its solid angle. */
    final double shareR, shareG, shareB;

    AreaSource(AreaLight light) {
        super(light.samples(), false);
        cx = light.center().x();
        cy = light.center().y();
        cz = light.center().z();
        Color c = light.color();
        double i = light.intensity(), scale = i / light.samples();
        radianceR = c.r() * i; radianceG = c.g() * i; radianceB = c.b() * i;
        shareR = c.r() * scale; shareG = c.g() * scale; shareB = c.b() * scale;
    }

    /**
     * Where the line o + t d first crosses the light with t in (tMin, tMax) (the sphere's far side
     * when its near one is not in range).
     *
     * @return the crossing's t, or NaN if there is none
     */
    abstract double intersect(double ox, double oy, double oz, double dx, double dy, double dz, double tMin, double tMax);

    /**
     * Where {@code ray} first reaches the light within (ray.tMin, tMax).
     *
     * @param ray  the ray; its own tMax is not consulted
     * @param tMax the far end of the range
     * @return the ray parameter of the crossing, or NaN if there is none
     */
    public final double intersect(Ray ray, double tMax) {
        return intersect(ray.ox, ray.oy, ray.oz, ray.dx, ray.dy, ray.dz, ray.tMin, tMax);
    }

    /**
     * The radiance a ray of direction d sees where it reaches the light (black from a one-sided
     * light's back), written to out[0..2].
     *
     * @param dx  direction x, any length
     * @param dy  direction y
     * @param dz  direction z
     * @param out receives r, g, b
     */
    public abstract void radiance(double dx, double dy, double dz, double[] out);

    /** Writes the sample's radiance and its weighted share, radiance over the samples times the solid angle it stands for (1 / pdf). */
    final void emit(double solidAngle, LightSample out) {
        out.r = radianceR; out.g = radianceG; out.b = radianceB;
        out.pdf = 1 / solidAngle;
        out.delta = false;
        out.weightedR = shareR * solidAngle; out.weightedG = shareG * solidAngle; out.weightedB = shareB * solidAngle;
    }
}
