package lt.spindulys.light;

import lt.spindulys.scene.AreaLight;

/**
 * A disc light: the unit square mapped onto it by Shirley and Chiu's concentric map, as lens
 * samples are, so strata stay equal in area and compact.
 */
public final class DiscSource extends PlanarSource {
    DiscSource(AreaLight light) { super(light); }

    @Override
    public boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out) {
        double a = 2 * u - 1, b = 2 * v - 1;
        double r, phi;
        if (a == 0 && b == 0) { r = 0; phi = 0; }
        else if (Math.abs(a) > Math.abs(b)) { r = a; phi = Math.PI / 4 * (b / a); }
        else { r = b; phi = Math.PI / 2 - Math.PI / 4 * (a / b); }
        return sampleAt(r * Math.cos(phi), r * Math.sin(phi), px, py, pz, out);
    }

    @Override
    boolean inside(double a, double b) { return a * a + b * b <= 1; }

    @Override
    public String statement() { return "disclight"; }
}
