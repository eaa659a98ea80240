package lt.spindulys.math;

import java.util.Locale;

/**
 * The ranges of the numbers a scene is made of, chosen so that no render can produce an infinite
 * or NaN pixel, with a wide margin; docs/scene-format.md ("Ranges of numbers") gives the argument
 * in full. In short:
 * <ul>
 *   <li>Geometry: every scene and mesh number is at most {@link #MAX_NUMBER} in magnitude and a
 *       transform scales by at most {@link #MAX_SCALE} either way, so coordinates stay below
 *       about 1e30 in world space and 1e46 in any object's space, and the squares and products
 *       of intersection tests (at most about 1e100) stay far below Double.MAX_VALUE (1.8e308).</li>
 *   <li>Light: one shaded point gives at most ka A C T + (kd C T + ks T) E + M + T_emission,
 *       where colours (C, A, light colours, a material's emission M, texture colours T) are at
 *       most {@link #MAX_COLOUR}, ka, kd and ks at most {@link #MAX_COEFFICIENT} (a principled
 *       material's derived terms are held to the same ranges), and E, the light arriving, at most
 *       {@link #MAX_IRRADIANCE} from inverse-square lights (the integrator keeps lights from
 *       getting closer than that allows) plus {@link #MAX_TOTAL_LIGHT} from constant ones:
 *       about 1e32. Reflection and refraction weights at a surface add up to at most 1 (kr + kt
 *       at most 1, filter at most 1, textures of kr and kt used as fractions in [0, 1]), so a
 *       path of at most 65 surfaces gives at most 65 times that: under 1e34, against
 *       Float.MAX_VALUE (3.4e38) of a .pfm pixel, a margin of more than 10^4.</li>
 * </ul>
 * The builders (Material, PointLight, RenderSettings, the shapes, textures) refuse values
 * outside these ranges with IllegalArgumentException; the scene and mesh readers refuse them at
 * the number that gave them.
 */
public final class Ranges {
    private Ranges() {}

    /** Largest magnitude of a number in a scene or mesh file, and of a coordinate or size. */
    public static final double MAX_NUMBER = 1e15;
    /** Largest factor by which a transform (or its inverse) may scale: |matrix entry| at most this. */
    public static final double MAX_SCALE = 1e15;
    /** Largest translation of a composed transform (a placement of placements). */
    public static final double MAX_TRANSLATION = 1e30;
    /** Largest colour component: material, light, ambient, background and texture colours. */
    public static final double MAX_COLOUR = 100;
    /** Largest ka, kd and ks. */
    public static final double MAX_COEFFICIENT = 10;
    /** Largest Blinn-Phong exponent. */
    public static final double MAX_SHININESS = 1e6;
    /** Largest intensity of one light. */
    public static final double MAX_INTENSITY = 1e15;
    /** Largest sum over a scene's lights of intensity times the largest colour component. */
    public static final double MAX_TOTAL_LIGHT = 1e20;
    /**
     * Largest light that inverse-square lights together may deliver to a point: the integrator
     * treats a point closer to them than that allows as if it were at that distance.
     */
    public static final double MAX_IRRADIANCE = 1e27;

    /**
     * True if {@code v} is a number (not NaN) of magnitude at most {@link #MAX_NUMBER}.
     *
     * @param v the value
     * @return whether it is a number of modest magnitude
     */
    public static boolean isModest(double v) { return Math.abs(v) <= MAX_NUMBER; }

    /**
     * True if every component is {@link #isModest}.
     *
     * @param v the vector
     * @return whether every component is modest
     */
    public static boolean isModest(Vec3 v) { return isModest(v.x()) && isModest(v.y()) && isModest(v.z()); }

    /**
     * "1e15": a bound for a message.
     *
     * @param bound a limit
     * @return its short text, as messages show it
     */
    public static String show(double bound) {
        if (bound >= 1e4) return String.format(Locale.ROOT, "%.0e", bound).replace("e+", "e").replace("e0", "e");
        return bound == Math.rint(bound) ? Long.toString((long) bound) : Double.toString(bound);
    }

    /**
     * "1e20", "1.5e16", "-3e-7", "250": a magnitude for a message, to three significant digits.
     *
     * @param v a value
     * @return its text with three significant digits
     */
    public static String approx(double v) {
        if (v == Math.rint(v) && Math.abs(v) < 1e6) return Long.toString((long) v);
        String s = String.format(Locale.ROOT, "%.3g", v);
        int e = s.indexOf('e');
        if (e < 0) return s.contains(".") ? s.replaceAll("0+$", "").replaceAll("\\.$", "") : s;
        String mantissa = s.substring(0, e), exponent = s.substring(e + 1);
        if (mantissa.contains(".")) mantissa = mantissa.replaceAll("0+$", "").replaceAll("\\.$", "");
        exponent = exponent.replace("+", "").replaceFirst("^(-?)0+(?=\\d)", "$1");
        return mantissa + "e" + exponent;
    }

    /**
     * {@code v}, if it is in [0, max]; else "WHAT must be between 0 and MAX, found V".
     *
     * @param what what the value is, for the message
     * @param v the value
     * @param max the largest value accepted
     * @return {@code v}
     */
    public static double inRange(String what, double v, double max) {
        if (!(v >= 0 && v <= max)) throw new IllegalArgumentException(what + " must be between 0 and " + show(max) + ", found " + v);
        return v;
    }

    /**
     * {@code c}, if every component is in [0, max]; else "WHAT must have components between 0 and MAX, found C".
     *
     * @param what what the colour is, for the message
     * @param c the colour
     * @param max the largest component accepted
     * @return {@code c}
     */
    public static Color colour(String what, Color c, double max) {
        if (c == null) throw new IllegalArgumentException(what + " is missing");
        if (!(c.r() >= 0 && c.r() <= max && c.g() >= 0 && c.g() <= max && c.b() >= 0 && c.b() <= max)) {
            throw new IllegalArgumentException(what + " must have components between 0 and " + show(max) + ", found " + c);
        }
        return c;
    }

    /**
     * {@code v} if {@link #isModest}; else "WHAT must be finite and at most 1e15 in magnitude, found V".
     *
     * @param what what the value is, for the message
     * @param v the value
     * @return {@code v}
     */
    public static double modest(String what, double v) {
        if (!isModest(v)) throw new IllegalArgumentException(what + " must be finite and at most " + show(MAX_NUMBER) + " in magnitude, found " + v);
        return v;
    }

    /**
     * {@code v} if every component {@link #isModest}; else as {@link #modest(String, double)}.
     *
     * @param what what the vector is, for the message
     * @param v the vector
     * @return {@code v}
     */
    public static Vec3 modest(String what, Vec3 v) {
        if (v == null || !isModest(v)) throw new IllegalArgumentException(what + " must be finite and at most " + show(MAX_NUMBER) + " in magnitude, found " + v);
        return v;
    }
}
