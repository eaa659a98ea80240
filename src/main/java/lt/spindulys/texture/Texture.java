package lt.spindulys.texture;

/**
 * A colour (linear RGB) over surface coordinates or space. Implementations are immutable after
 * construction and thread-safe, and do not allocate in {@link #evaluate}.
 */
public interface Texture {
    /**
     * Writes the linear RGB colour at {@code p} into {@code rgb[0..2]}.
     *
     * @param p where to evaluate
     * @param rgb receives the colour
     */
    void evaluate(TexturePoint p, double[] rgb);

    /**
     * The mean of the three channels at {@code p} (e.g. a bump height); {@code scratch3} is overwritten.
     *
     * @param p where to evaluate
     * @param scratch3 three doubles of scratch
     * @return the mean
     */
    default double scalar(TexturePoint p, double[] scratch3) {
        evaluate(p, scratch3);
        return (scratch3[0] + scratch3[1] + scratch3[2]) / 3;
    }
}
