package lt.spindulys.texture;

/**
 * What a texture is evaluated at. The caller (shading) fills one per thread and reuses it for
 * every shading point, so textures never allocate to receive their arguments.
 *
 * <p>Surface coordinates follow the OBJ {@code vt} convention: {@code v = 0} is the BOTTOM row
 * of an image, {@code v = 1} its top; {@code u = 0} is the left column.
 */
public final class TexturePoint {
    /** Surface coordinates after the mapping; any range, the texture's wrap mode applies. */
    public double u, v;
    /** Object-space point, for solid (3D) textures. */
    public double x, y, z;
    /** Width of the pixel's footprint in (u, v) units; 0 means sharpest (no pre-filtering). */
    public double footprint;

    /** A point at the origin with (u, v) = (0, 0) and footprint 0; the caller fills it per shading point. */
    public TexturePoint() {}

    /**
     * Sets the surface coordinates and footprint; returns {@code this} for chaining in setup code and tests.
     *
     * @param u surface coordinate u
     * @param v surface coordinate v
     * @param footprint the footprint in (u, v) units
     * @return {@code this}
     */
    public TexturePoint uv(double u, double v, double footprint) {
        this.u = u;
        this.v = v;
        this.footprint = footprint;
        return this;
    }

    /**
     * Sets the object-space point; returns {@code this}.
     *
     * @param x object-space x
     * @param y object-space y
     * @param z object-space z
     * @return {@code this}
     */
    public TexturePoint xyz(double x, double y, double z) {
        this.x = x;
        this.y = y;
        this.z = z;
        return this;
    }
}
