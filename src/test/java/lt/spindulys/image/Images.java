package lt.spindulys.image;

import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.FileImageInputStream;
import javax.imageio.stream.ImageInputStream;
import lt.spindulys.texture.TgaReader;

/**
 * Reads images back into {@link FrameBuffer}s, for tests and golden-image comparison. The format
 * is chosen by extension, as for {@link ImageWriter}:
 * <ul>
 *   <li>{@code .tga}: what the textures' {@link TgaReader} reads (true colour or greyscale,
 *       uncompressed or run-length encoded, any origin);</li>
 *   <li>{@code .png}, {@code .jpg}, {@code .jpeg}: whatever javax.imageio decodes (grey images are
 *       read from their raw samples, not through Java's linear-grey colour conversion);</li>
 *   <li>{@code .pfm}: "PF" (colour) and "Pf" (grey, copied to all channels), either byte
 *       order; values are returned as stored (the scale's magnitude is not applied).</li>
 * </ul>
 */
public final class Images {
    private Images() {}

    /** Reads an image whose 8-bit values are sRGB-encoded, as {@link ImageOptions#DEFAULT} writes them. */
    public static FrameBuffer read(Path path) throws IOException {
        return read(path, true);
    }

    /**
     * Reads an image into linear values; {@code srgb} says whether 8-bit files hold sRGB-encoded
     * values (decoded to linear) or linear ones (PFM files are always linear).
     */
    public static FrameBuffer read(Path path, boolean srgb) throws IOException {
        ImageFormat format = ImageFormat.of(path, "input");
        switch (format) {
            case TGA: return readTga(path, srgb);
            case PNG: case JPEG: return readImageIo(path, srgb);
            case PFM: return readPfm(path);
            default: throw new AssertionError(format);
        }
    }

    /** Through the renderer's one TGA decoder, the textures' (which also reads RLE and greyscale files). */
    private static FrameBuffer readTga(Path path, boolean srgb) throws IOException {
        TgaReader.Image im;
        try {
            im = TgaReader.read(path);
        } catch (IOException e) {
            throw bad(path, "TGA", e.getMessage());
        }
        return FrameBuffer.fromRgb8(im.width(), im.height(), im.rgb(), srgb);
    }

    private static FrameBuffer readImageIo(Path path, boolean srgb) throws IOException {
        BufferedImage img;
        try (ImageInputStream in = new FileImageInputStream(path.toFile())) {
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            if (!readers.hasNext()) throw bad(path, "image", "no decoder recognises its contents");
            ImageReader reader = readers.next();
            try {
                reader.setInput(in, true, true);
                img = reader.read(0);
            } finally {
                reader.dispose();
            }
        }
        int w = img.getWidth(), h = img.getHeight();
        int[] rgb;
        if (img.getColorModel().getColorSpace().getType() == ColorSpace.TYPE_GRAY) {
            // getRGB would treat Java's grey colour space as linear and re-encode it, changing
            // every value; the stored samples are what the file means.
            Raster raster = img.getRaster();
            int max = (1 << img.getColorModel().getComponentSize(0)) - 1;
            rgb = new int[w * h];
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int g = (int) Math.round(raster.getSample(x, y, 0) * 255.0 / max);
                    rgb[y * w + x] = g << 16 | g << 8 | g;
                }
            }
        } else {
            rgb = img.getRGB(0, 0, w, h, null, 0, w);
        }
        return FrameBuffer.fromRgb8(w, h, rgb, srgb);
    }

    private static FrameBuffer readPfm(Path path) throws IOException {
        byte[] b = Files.readAllBytes(path);
        int[] pos = {0};
        String magic = token(b, pos, path);
        int channels;
        if (magic.equals("PF")) channels = 3;
        else if (magic.equals("Pf")) channels = 1;
        else throw bad(path, "PFM", "magic '" + magic + "' (expected PF or Pf)");
        int w = parseInt(token(b, pos, path), path, "width");
        int h = parseInt(token(b, pos, path), path, "height");
        String scaleText = token(b, pos, path);
        double scale;
        try {
            scale = Double.parseDouble(scaleText);
        } catch (NumberFormatException e) {
            throw bad(path, "PFM", "scale '" + scaleText + "' is not a number");
        }
        if (!(scale != 0) || !Double.isFinite(scale)) throw bad(path, "PFM", "scale must be finite and non-zero");
        // Exactly one whitespace byte separates the header from the binary data.
        int start = pos[0] + 1;
        long need = (long) w * h * channels * 4;
        if (start + need > b.length) throw bad(path, "PFM", "truncated pixel data");

        FrameBuffer fb = new FrameBuffer(w, h);
        double[] d = fb.data();
        ByteBuffer buf = ByteBuffer.wrap(b, start, (int) need)
                .order(scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
        for (int y = h - 1; y >= 0; y--) {   // bottom row first
            for (int i = 3 * y * w, end = i + 3 * w; i < end; i += 3) {
                if (channels == 3) {
                    d[i] = buf.getFloat();
                    d[i + 1] = buf.getFloat();
                    d[i + 2] = buf.getFloat();
                } else {
                    d[i] = d[i + 1] = d[i + 2] = buf.getFloat();
                }
            }
        }
        return fb;
    }

    /** The next whitespace-delimited header token; {@code pos} is left on the byte after it. */
    private static String token(byte[] b, int[] pos, Path path) throws IOException {
        int p = pos[0];
        while (p < b.length && isSpace(b[p])) p++;
        int start = p;
        while (p < b.length && !isSpace(b[p])) {
            if (++p - start > 64) throw bad(path, "PFM", "no valid header");
        }
        if (p == start || p >= b.length) throw bad(path, "PFM", "truncated header");
        pos[0] = p;
        return new String(b, start, p - start, StandardCharsets.US_ASCII);
    }

    private static boolean isSpace(byte c) {
        return c == ' ' || c == '\n' || c == '\r' || c == '\t';
    }

    private static int parseInt(String s, Path path, String what) throws IOException {
        try {
            int v = Integer.parseInt(s);
            if (v >= 1) return v;
        } catch (NumberFormatException e) {
            // reported below
        }
        throw bad(path, "PFM", what + " '" + s + "' is not a positive integer");
    }

    private static IOException bad(Path path, String format, String why) {
        return new IOException("'" + path + "' is not a readable " + format + " file: " + why);
    }
}
