package lt.spindulys.texture;

import lt.spindulys.math.Color;

/**
 * One colour everywhere: for a channel that only a texture drives, such as
 * {@link Channel#EMISSION}, when the colour is the same over the whole surface (a .mtl file's
 * {@code Ke}).
 */
public final class Uniform implements Texture {
    private final double r, g, b;

    /**
     * The colour everywhere.
     *
     * @param c the colour, linear RGB
     */
    public Uniform(Color c) {
        r = c.r();
        g = c.g();
        b = c.b();
    }

    @Override
    public void evaluate(TexturePoint p, double[] rgb) {
        rgb[0] = r;
        rgb[1] = g;
        rgb[2] = b;
    }
}
