package lt.spindulys.texture;

import lt.spindulys.math.Color;

/**
 * Marble: veins from a sine of one coordinate perturbed by turbulence,
 * {@code t = 0.5 + 0.5 sin(2 pi (s x + k turbulence(s p)))} with scale {@code s} and strength
 * {@code k}; {@code x} is u (surface variant) or object-space x (solid variant). With
 * {@code k = 0} it is plain parallel stripes, {@code s} of them per unit. Immutable, thread-safe.
 */
public final class Marble extends Procedural {
    private final double turbulence;
    private final int octaves;

    /**
     * @param a          colour at the sine's trough
     * @param b          colour at its crest (the veins)
     * @param scale      stripes per unit; positive
     * @param turbulence strength of the perturbation, in stripe periods; non-negative
     * @param octaves    octaves of turbulence, 1 to 16
     * @param solid      evaluate over the object-space point instead of (u, v)
     */
    public Marble(Color a, Color b, double scale, double turbulence, int octaves, boolean solid) {
        super(a, b, scale, solid);
        this.turbulence = checkTurbulence(turbulence);
        this.octaves = checkOctaves(octaves);
    }

    /**
     * Strength of the turbulence.
     *
     * @return the turbulence's weight
     */
    public double turbulence() {
        return turbulence;
    }

    /**
     * Octaves of turbulence.
     *
     * @return the octave count
     */
    public int octaves() {
        return octaves;
    }

    @Override
    double pattern(double x, double y, double z) {
        double f = x + (turbulence == 0 ? 0 : turbulence * Perlin.turbulence(x, y, z, octaves));
        return 0.5 + 0.5 * Math.sin(2 * Math.PI * f);
    }

    @Override
    public String toString() {
        return "Marble[" + colourA() + ", " + colourB() + ", scale " + scale + ", turbulence " + turbulence
                + ", octaves " + octaves + (solid ? ", solid]" : "]");
    }
}
