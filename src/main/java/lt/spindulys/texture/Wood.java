package lt.spindulys.texture;

import lt.spindulys.math.Color;

/**
 * Wood: concentric rings of the distance {@code r} from an axis, perturbed by turbulence,
 * {@code t = 0.5 - 0.5 cos(2 pi (s r + k turbulence(s p)))} with scale {@code s} (rings per unit)
 * and strength {@code k}. The solid variant measures {@code r} from the object's z axis (the
 * trunk runs along z); the surface variant from the centre (0.5, 0.5) of the (u, v) square, like
 * the end grain of a board. Immutable, thread-safe.
 */
public final class Wood extends Procedural {
    private final double turbulence;
    private final int octaves;

    /**
     * @param a          colour between the rings (early wood)
     * @param b          colour of the rings (late wood)
     * @param scale      rings per unit of distance; positive
     * @param turbulence strength of the perturbation, in ring periods; non-negative
     * @param octaves    octaves of turbulence, 1 to 16
     * @param solid      evaluate over the object-space point instead of (u, v)
     */
    public Wood(Color a, Color b, double scale, double turbulence, int octaves, boolean solid) {
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
        // The coordinates arrive scaled, so the surface variant's centre is (0.5 s, 0.5 s).
        double c = solid ? 0 : 0.5 * scale;
        double r = Math.sqrt((x - c) * (x - c) + (y - c) * (y - c));
        double f = r + (turbulence == 0 ? 0 : turbulence * Perlin.turbulence(x, y, z, octaves));
        return 0.5 - 0.5 * Math.cos(2 * Math.PI * f);
    }

    @Override
    public String toString() {
        return "Wood[" + colourA() + ", " + colourB() + ", scale " + scale + ", turbulence " + turbulence
                + ", octaves " + octaves + (solid ? ", solid]" : "]");
    }
}
