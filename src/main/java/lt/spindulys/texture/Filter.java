package lt.spindulys.texture;

/** How an {@link ImageTexture} reconstructs a colour between texels. */
public enum Filter {
    /** The texel containing the point. */
    NEAREST,
    /** Weighted mix of the four nearest texel centres (the default). */
    BILINEAR,
    /** Mip-mapped: bilinear in the two mip levels bracketing the footprint, blended linearly. */
    TRILINEAR
}
