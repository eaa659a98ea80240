package lt.spindulys.light;

import lt.spindulys.scene.AreaLight;

/** A rectangle light: the unit square stretched over it. */
public final class RectangleSource extends PlanarSource {
    RectangleSource(AreaLight light) { super(light); }

    @Override
    public boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out) {
        return sampleAt(2 * u - 1, 2 * v - 1, px, py, pz, out);
    }

    @Override
    boolean inside(double a, double b) { return Math.abs(a) <= 1 && Math.abs(b) <= 1; }

    @Override
    public String statement() { return "rectlight"; }
}
