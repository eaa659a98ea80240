package lt.spindulys.image;

import java.nio.file.Path;
import java.util.Locale;

/** The image file formats Spindulys reads and writes, chosen by file-name extension. */
public enum ImageFormat {
    /** Truevision TGA, uncompressed 24-bit true colour. */
    TGA,
    /** PNG, 8 bits per channel, through javax.imageio. */
    PNG,
    /** JPEG (baseline, lossy), through javax.imageio. */
    JPEG,
    /** Portable float map: 32-bit floats, linear, unclamped. */
    PFM,
    /** OpenEXR, scanline, half or float channels, written only ({@link ExrWriter}). */
    EXR;

    static final String EXPECTED = "(expected .tga, .png, .jpg, .jpeg, .pfm or .exr)";
    /** What may be read: OpenEXR is written only. */
    static final String EXPECTED_INPUT = "(expected .tga, .png, .jpg, .jpeg or .pfm)";

    /**
     * The format named by the extension of {@code path}, ignoring case.
     *
     * @param role "output" or "input", for the message
     * @throws IllegalArgumentException naming the extension and the supported ones
     */
    static ImageFormat of(Path path, String role) {
        Path name = path.getFileName();
        String file = name == null ? "" : name.toString();
        int dot = file.lastIndexOf('.');
        boolean output = role.equals("output");
        if (output && lt.spindulys.files.FileNames.isOnlyExtension(path)) {
            throw new IllegalArgumentException(lt.spindulys.files.FileNames.onlyExtensionMessage(path));
        }
        String expected = output ? EXPECTED : EXPECTED_INPUT;
        if (dot < 0) {
            throw new IllegalArgumentException("unsupported " + role + " format: '" + file
                    + "' has no extension " + expected);
        }
        String ext = file.substring(dot);
        switch (ext.toLowerCase(Locale.ROOT)) {
            case ".tga": return TGA;
            case ".png": return PNG;
            case ".jpg": case ".jpeg": return JPEG;
            case ".pfm": return PFM;
            case ".exr":
                if (output) return EXR;
                break; // written only: not an input
            default:
                break;
        }
        throw new IllegalArgumentException("unsupported " + role + " format '" + ext + "' " + expected);
    }
}
