package lt.spindulys.texture;

/**
 * How texel indices outside the image are folded back into it. Applied per texel index (not to
 * the coordinate), so bilinear filtering blends across the u = 0/1 seam under {@link #REPEAT}.
 */
public enum Wrap {
    /** Tile: index modulo the size. */
    REPEAT,
    /** Clamp to the edge texel. */
    CLAMP,
    /** Tile with every other copy mirrored, so edges meet themselves without a jump. */
    MIRROR;

    /** Folds texel index {@code i} into {@code [0, n)}. */
    int apply(int i, int n) {
        switch (this) {
            case REPEAT:
                return Math.floorMod(i, n);
            case CLAMP:
                return i < 0 ? 0 : i >= n ? n - 1 : i;
            case MIRROR: {
                int m = Math.floorMod(i, 2 * n);
                return m < n ? m : 2 * n - 1 - m;
            }
            default:
                throw new AssertionError(this);
        }
    }
}
