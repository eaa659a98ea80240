package lt.spindulys.texture;

/**
 * An opacity texture turned into a transparency: 1 − d × the inner texture's value, per channel.
 * A .mtl file's dissolve map ({@code map_d}) gives the opacity d × map, where this renderer's
 * transparency channel multiplies {@code kt} (see {@link Channel#TRANSPARENCY}); bound with
 * {@code kt} 1, this texture gives the transparency 1 − d × map that the file means.
 */
public final class Dissolve implements Texture {
    private final Texture opacity;
    private final double d;

    /**
     * The transparency of an opacity map scaled by d.
     *
     * @param opacity the opacity map (values 0 transparent to 1 opaque)
     * @param d the dissolve the map is multiplied by, 0..1
     */
    public Dissolve(Texture opacity, double d) {
        if (opacity == null) throw new IllegalArgumentException("opacity texture must be given");
        if (!(d >= 0 && d <= 1)) throw new IllegalArgumentException("dissolve must be between 0 and 1, found " + d);
        this.opacity = opacity;
        this.d = d;
    }

    @Override
    public void evaluate(TexturePoint p, double[] rgb) {
        opacity.evaluate(p, rgb);
        rgb[0] = 1 - d * rgb[0];
        rgb[1] = 1 - d * rgb[1];
        rgb[2] = 1 - d * rgb[2];
    }
}
