package lt.spindulys.light;

import lt.spindulys.math.Color;
import lt.spindulys.scene.PointLight;

/**
 * A {@link PointLight}: one sample, its position, whatever the unit-square point; what arrives is
 * its colour times intensity, divided by the squared distance when it falls off (never by less
 * than the scene's smallest squared distance, see {@link Lights}).
 */
public final class PointSource extends Light {
    private final double x, y, z;
    private final Color color;
    private final double intensity;
    private final boolean inverseSquare;
    /** Smallest squared distance the falloff divides by. */
    private final double minDistance2;

    PointSource(PointLight light, double minDistance2) {
        super(1, true);
        x = light.position().x();
        y = light.position().y();
        z = light.position().z();
        color = light.color();
        intensity = light.intensity();
        inverseSquare = light.falloff() == PointLight.Falloff.INVERSE_SQUARE;
        this.minDistance2 = minDistance2;
    }

    @Override
    public boolean sampleLi(double px, double py, double pz, double u, double v, LightSample out) {
        double lx = x - px, ly = y - py, lz = z - pz;
        double dist2 = lx * lx + ly * ly + lz * lz, dist = Math.sqrt(dist2);
        if (!(dist > 0)) return false;
        out.wx = lx / dist; out.wy = ly / dist; out.wz = lz / dist;
        out.distance = dist;
        out.x = x; out.y = y; out.z = z;
        out.shadowTMax = 1;
        double scale = intensity;
        if (inverseSquare) scale /= Math.max(dist2, minDistance2);
        out.r = color.r() * scale; out.g = color.g() * scale; out.b = color.b() * scale;
        out.pdf = 1;
        out.delta = true;
        out.weightedR = out.r; out.weightedG = out.g; out.weightedB = out.b;
        return true;
    }

    @Override
    public double pdfLi(double px, double py, double pz, double wx, double wy, double wz) { return 0; }

    @Override
    public String statement() { return "light"; }
}
