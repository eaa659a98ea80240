package lt.spindulys.texture;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;

/**
 * Shared part of the procedural textures: two colours mixed by a pattern value {@code t} in
 * [0, 1] computed either over the surface coordinates (u, v) or, for a solid texture, over the
 * object-space point (x, y, z), both multiplied by {@code scale} first.
 */
abstract class Procedural implements Texture {
    static final int MAX_OCTAVES = 16;

    private final double ar, ag, ab, br, bg, bb;
    final double scale;
    final boolean solid;

    Procedural(Color a, Color b, double scale, boolean solid) {
        if (a == null || b == null) throw new NullPointerException("both colours are required");
        // Negative values are allowed (heights for bump maps); the bound keeps pixels finite (see Ranges).
        if (!modest(a) || !modest(b)) {
            throw new IllegalArgumentException((modest(a) ? "color2" : "color1") + " must have components between -" + Ranges.show(Ranges.MAX_COLOUR)
                    + " and " + Ranges.show(Ranges.MAX_COLOUR) + ", found " + (modest(a) ? b : a));
        }
        if (!(scale > 0) || !Double.isFinite(scale)) throw new IllegalArgumentException("scale must be positive and finite, got " + scale);
        ar = a.r();
        ag = a.g();
        ab = a.b();
        br = b.r();
        bg = b.g();
        bb = b.b();
        this.scale = scale;
        this.solid = solid;
    }

    private static boolean modest(Color c) {
        double m = Ranges.MAX_COLOUR;
        return Math.abs(c.r()) <= m && Math.abs(c.g()) <= m && Math.abs(c.b()) <= m;
    }

    static int checkOctaves(int octaves) {
        if (octaves < 1 || octaves > MAX_OCTAVES) throw new IllegalArgumentException("octaves must be 1.." + MAX_OCTAVES + ", got " + octaves);
        return octaves;
    }

    static double checkTurbulence(double t) {
        if (!(t >= 0) || !Double.isFinite(t)) throw new IllegalArgumentException("turbulence must be non-negative and finite, got " + t);
        return t;
    }

    /** The pattern value at the scaled point (x, y, z) (z = 0 for a surface texture); clamped to [0, 1] by the caller. */
    abstract double pattern(double x, double y, double z);

    @Override
    public final void evaluate(TexturePoint p, double[] rgb) {
        double t = solid ? pattern(p.x * scale, p.y * scale, p.z * scale) : pattern(p.u * scale, p.v * scale, 0);
        t = t > 0 ? (t < 1 ? t : 1) : 0;  // also maps NaN to the first colour
        rgb[0] = ar + t * (br - ar);
        rgb[1] = ag + t * (bg - ag);
        rgb[2] = ab + t * (bb - ab);
    }

    /**
     * The first colour (pattern value 0).
     *
     * @return the colour, linear RGB
     */
    public final Color colourA() {
        return new Color(ar, ag, ab);
    }

    /**
     * The second colour (pattern value 1).
     *
     * @return the colour, linear RGB
     */
    public final Color colourB() {
        return new Color(br, bg, bb);
    }

    /**
     * The scale applied to the coordinates.
     *
     * @return the scale: pattern units per object or (u, v) unit
     */
    public final double scale() {
        return scale;
    }

    /**
     * Whether this is a solid (3D, object-space) texture rather than a surface (u, v) one.
     *
     * @return whether it is solid
     */
    public final boolean solid() {
        return solid;
    }
}
