package lt.spindulys.texture;

import lt.spindulys.math.Color;

/**
 * Perlin noise: the two colours mixed by {@code 0.5 + 0.5 * fbm(s p)}, where {@code fbm} sums
 * {@code octaves} octaves of {@link Perlin#noise} (each of double frequency and half amplitude)
 * and {@code s} is the scale; {@code p} is (u, v, 0) or, for the solid variant, the object-space
 * point. Immutable, thread-safe.
 */
public final class Noise extends Procedural {
    private final int octaves;

    /**
     * @param a       colour at noise -1 (and below)
     * @param b       colour at noise +1
     * @param scale   frequency: lattice cells per unit; positive
     * @param octaves 1 (plain noise) to 16
     * @param solid   evaluate over the object-space point instead of (u, v)
     */
    public Noise(Color a, Color b, double scale, int octaves, boolean solid) {
        super(a, b, scale, solid);
        this.octaves = checkOctaves(octaves);
    }

    /**
     * Number of octaves summed.
     *
     * @return the octave count
     */
    public int octaves() {
        return octaves;
    }

    @Override
    double pattern(double x, double y, double z) {
        return 0.5 + 0.5 * Perlin.fbm(x, y, z, octaves);
    }

    @Override
    public String toString() {
        return "Noise[" + colourA() + ", " + colourB() + ", scale " + scale + ", octaves " + octaves + (solid ? ", solid]" : "]");
    }
}
