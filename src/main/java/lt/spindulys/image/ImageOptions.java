package lt.spindulys.image;

/**
 * How {@link ImageWriter} encodes an image.
 *
 * @param srgb        encode 8-bit formats (TGA, PNG, JPEG) with the sRGB transfer function; if
 *                    false they get linear values. PFM is always linear and ignores this.
 * @param jpegQuality JPEG compression quality in [0, 1] (1 = best); ignored by other formats
 * @param exrPrecision how an OpenEXR output stores colour and normals; ignored by other formats
 * @param exrCompression how an OpenEXR output compresses its blocks; ignored by other formats
 */
public record ImageOptions(boolean srgb, double jpegQuality, ExrPrecision exrPrecision, ExrCompression exrCompression) {
    /** sRGB-encoded 8-bit output, JPEG quality 0.92, OpenEXR in halves with ZIP compression. */
    public static final ImageOptions DEFAULT = new ImageOptions(true, 0.92);

    /**
     * Checks the quality.
     *
     * @param srgb whether 8-bit formats are sRGB-encoded
     * @param jpegQuality JPEG quality in [0, 1]
     * @param exrPrecision OpenEXR channel precision
     * @param exrCompression OpenEXR compression
     * @throws IllegalArgumentException if the JPEG quality is not in [0, 1]
     */
    public ImageOptions {
        java.util.Objects.requireNonNull(exrPrecision, "exrPrecision");
        java.util.Objects.requireNonNull(exrCompression, "exrCompression");
        // The negated range test also rejects NaN.
        if (!(jpegQuality >= 0 && jpegQuality <= 1)) {
            throw new IllegalArgumentException("JPEG quality must be in [0, 1], got " + jpegQuality);
        }
    }

    /**
     * Options with OpenEXR's defaults: half precision, ZIP compression.
     *
     * @param srgb whether 8-bit formats are sRGB-encoded
     * @param jpegQuality JPEG quality in [0, 1]
     * @throws IllegalArgumentException if the JPEG quality is not in [0, 1]
     */
    public ImageOptions(boolean srgb, double jpegQuality) {
        this(srgb, jpegQuality, ExrPrecision.HALF, ExrCompression.ZIP);
    }

    /**
     * A copy with another encoding.
     *
     * @param srgb whether 8-bit formats are sRGB-encoded
     * @return the options
     */
    public ImageOptions withSrgb(boolean srgb) { return new ImageOptions(srgb, jpegQuality, exrPrecision, exrCompression); }

    /**
     * A copy with another JPEG quality.
     *
     * @param quality in [0, 1], 1 the best
     * @return the options
     */
    public ImageOptions withJpegQuality(double quality) { return new ImageOptions(srgb, quality, exrPrecision, exrCompression); }

    /**
     * A copy with another OpenEXR precision and compression.
     *
     * @param precision how colour and normals are stored
     * @param compression how blocks are compressed
     * @return the options
     */
    public ImageOptions withExr(ExrPrecision precision, ExrCompression compression) {
        return new ImageOptions(srgb, jpegQuality, precision, compression);
    }
}
