package lt.spindulys.texture;

/**
 * How texel indices outside the image are folded back into it. Applied per texel index (not to
 * the coordinate), so bilinear filtering blends across the u = 0/1 seam under {@link #REPEAT}.
 * Repeat and mirror are exact for any finite coordinate: far out, the coordinate is first moved
 * by whole periods (exactly) next to the image ({@link #fold}), so the image keeps tiling at
 * 2^31 or 2^60 texels as it does at 0.
 */
public enum Wrap {
    /** Tile: index modulo the size. */
    REPEAT,
    /** Clamp to the edge texel. */
    CLAMP,
    /** Tile with every other copy mirrored, so edges meet themselves without a jump. */
    MIRROR;

    /** Folds texel index {@code i} into {@code [0, n)}; exact for any long index. */
    int apply(long i, int n) {
        switch (this) {
            case REPEAT:
                return (int) Math.floorMod(i, (long) n);
            case CLAMP:
                return i < 0 ? 0 : i >= n ? n - 1 : (int) i;
            case MIRROR: {
                long m = Math.floorMod(i, 2L * n);
                return (int) (m < n ? m : 2L * n - 1 - m);
            }
            default:
                throw new AssertionError(this);
        }
    }

    /**
     * A coordinate (in image units: 1 is the image's size) moved by whole periods of this mode
     * into one period when it is far out: {@code u - floor(u)} for REPEAT, {@code u mod 2} for
     * MIRROR, both exact in floating point; CLAMP and coordinates near the image are returned as
     * they are. Far out, {@code u * size} would round away the fraction that places the sample
     * between texels (all of it beyond 2^53), so it is folded first; near the image the
     * coordinate is used unchanged, which keeps every sample there as it always was.
     */
    double fold(double u) {
        if (!(Math.abs(u) >= FOLD_FROM)) return u;
        switch (this) {
            case REPEAT:
                return u - Math.floor(u);
            case MIRROR:
                return u - 2 * Math.floor(u / 2);
            default:
                return u;
        }
    }

    /** Coordinates at least this far out are folded ({@link #fold}). */
    static final double FOLD_FROM = 1 << 16;
}
