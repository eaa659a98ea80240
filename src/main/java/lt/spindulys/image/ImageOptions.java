package lt.spindulys.image;

/**
 * How {@link ImageWriter} encodes an image.
 *
 * @param srgb        encode 8-bit formats (TGA, PNG, JPEG) with the sRGB transfer function; if
 *                    false they get linear values. PFM is always linear and ignores this.
 * @param jpegQuality JPEG compression quality in [0, 1] (1 = best); ignored by other formats
 */
public record ImageOptions(boolean srgb, double jpegQuality) {
    /** sRGB-encoded 8-bit output, JPEG quality 0.92. */
    public static final ImageOptions DEFAULT = new ImageOptions(true, 0.92);

    /**
     * Checks the quality.
     *
     * @param srgb whether 8-bit formats are sRGB-encoded
     * @param jpegQuality JPEG quality in [0, 1]
     * @throws IllegalArgumentException if the JPEG quality is not in [0, 1]
     */
    public ImageOptions {
        // The negated range test also rejects NaN.
        if (!(jpegQuality >= 0 && jpegQuality <= 1)) {
            throw new IllegalArgumentException("JPEG quality must be in [0, 1], got " + jpegQuality);
        }
    }

    /**
     * A copy with another encoding.
     *
     * @param srgb whether 8-bit formats are sRGB-encoded
     * @return the options
     */
    public ImageOptions withSrgb(boolean srgb) { return new ImageOptions(srgb, jpegQuality); }

    /**
     * A copy with another JPEG quality.
     *
     * @param quality in [0, 1], 1 the best
     * @return the options
     */
    public ImageOptions withJpegQuality(double quality) { return new ImageOptions(srgb, quality); }
}
