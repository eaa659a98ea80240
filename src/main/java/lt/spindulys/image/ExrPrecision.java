package lt.spindulys.image;

import java.util.Locale;

/**
 * How the colour and normal channels of an OpenEXR output are stored. Depth and object id are
 * always 32-bit floats: a half would clamp depths above 65504 and lose ids above 2048.
 */
public enum ExrPrecision {
    /** 16-bit half floats (OpenEXR pixel type 1), as compositors expect for colour. */
    HALF,
    /** 32-bit IEEE floats (OpenEXR pixel type 2): the render's values as PFM keeps them. */
    FLOAT;

    /**
     * The precision named on the command line.
     *
     * @param keyword {@code half} or {@code float}
     * @return the precision
     * @throws IllegalArgumentException for any other word
     */
    public static ExrPrecision fromKeyword(String keyword) {
        for (ExrPrecision p : values()) if (p.keyword().equals(keyword)) return p;
        throw new IllegalArgumentException("unknown OpenEXR precision '" + keyword + "' (expected half or float)");
    }

    /** {@return the name on the command line: half or float} */
    public String keyword() { return name().toLowerCase(Locale.ROOT); }
}
