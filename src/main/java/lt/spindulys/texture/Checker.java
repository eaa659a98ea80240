package lt.spindulys.texture;

import lt.spindulys.math.Color;

/**
 * A checkerboard: colour {@code a} where {@code floor(s u) + floor(s v)} is even, {@code b} where
 * it is odd ({@code s} = scale, so one square is {@code 1/s} wide); the solid variant uses
 * {@code floor(s x) + floor(s y) + floor(s z)}, a 3D checker of cubes. Immutable, thread-safe.
 */
public final class Checker extends Procedural {
    /**
     * @param a     colour of the even squares (e.g. the square from (0, 0) to (1/s, 1/s))
     * @param b     colour of the odd squares
     * @param scale squares per unit of u, v (or of object space when {@code solid}); positive
     * @param solid evaluate over the object-space point instead of (u, v)
     */
    public Checker(Color a, Color b, double scale, boolean solid) {
        super(a, b, scale, solid);
    }

    @Override
    double pattern(double x, double y, double z) {
        long n = (long) Math.floor(x) + (long) Math.floor(y) + (long) Math.floor(z);
        return (n & 1) == 0 ? 0 : 1;
    }

    @Override
    public String toString() {
        return "Checker[" + colourA() + ", " + colourB() + ", scale " + scale + (solid ? ", solid]" : "]");
    }
}
