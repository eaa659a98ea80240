package lt.spindulys.image;

import java.util.Locale;

/** The compression of an OpenEXR output's line blocks: lossless, zlib or none. */
public enum ExrCompression {
    /** Raw pixels, one scanline a block (OpenEXR NO_COMPRESSION, 0). */
    NONE(0, 1),
    /** zlib, one scanline a block (OpenEXR ZIPS_COMPRESSION, 2). */
    ZIPS(2, 1),
    /** zlib over blocks of 16 scanlines (OpenEXR ZIP_COMPRESSION, 3): the usual choice. */
    ZIP(3, 16);

    private final int code, linesPerBlock;

    ExrCompression(int code, int linesPerBlock) {
        this.code = code;
        this.linesPerBlock = linesPerBlock;
    }

    /** {@return the value of the file's compression attribute} */
    int code() { return code; }

    /** {@return the scanlines in one block of the file} */
    int linesPerBlock() { return linesPerBlock; }

    /**
     * The compression named on the command line.
     *
     * @param keyword {@code none}, {@code zip} or {@code zips}
     * @return the compression
     * @throws IllegalArgumentException for any other word
     */
    public static ExrCompression fromKeyword(String keyword) {
        for (ExrCompression c : values()) if (c.keyword().equals(keyword)) return c;
        throw new IllegalArgumentException("unknown OpenEXR compression '" + keyword + "' (expected none, zip or zips)");
    }

    /** {@return the name on the command line: none, zips or zip} */
    public String keyword() { return name().toLowerCase(Locale.ROOT); }
}
