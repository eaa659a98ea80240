package lt.spindulys.light;

import lt.spindulys.scene.Environment;
import lt.spindulys.scene.EnvironmentLight;

/**
 * The environment as a light ({@link EnvironmentLight}): directions drawn in proportion to the
 * map's brightness, infinitely far; u of the unit square picks the azimuth and v the polar band,
 * as u and v run across and down the lat-long map.
 */
public final class EnvironmentSource extends Light {
    private final EnvironmentLight light;
    private final Environment environment;

    EnvironmentSource(EnvironmentLight light) {
        super(light.environment().samples(), false);
        this.light = light;
        this.environment = light.environment();
    }

    @Override
    public boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out) {
        double[] drawn = out.drawn;
        light.sample(v, u, drawn);
        out.wx = drawn[0]; out.wy = drawn[1]; out.wz = drawn[2];
        out.distance = Double.POSITIVE_INFINITY;
        out.shadowTMax = Double.POSITIVE_INFINITY;
        out.r = drawn[4]; out.g = drawn[5]; out.b = drawn[6];
        double solidAngle = drawn[3];
        out.pdf = 1 / solidAngle;
        out.delta = false;
        double weight = solidAngle / samples();
        out.weightedR = out.r * weight; out.weightedG = out.g * weight; out.weightedB = out.b * weight;
        return true;
    }

    @Override
    public double pdfLi(double px, double py, double pz, double wx, double wy, double wz) {
        return light.pdf(wx, wy, wz);
    }

    /**
     * The radiance seen along the unit direction w, written to out[0..2]: what a ray that leaves
     * the scene sees.
     *
     * @param wx  unit direction x
     * @param wy  unit direction y
     * @param wz  unit direction z
     * @param out receives r, g, b
     */
    public void radiance(double wx, double wy, double wz, double[] out) { environment.lookup(wx, wy, wz, out); }

    @Override
    public String statement() { return "environment"; }
}
