package lt.spindulys.texture;

import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.Raster;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Iterator;
import java.util.Locale;
import java.util.Map;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;

import lt.spindulys.limits.InputFiles;

/**
 * Loads texture images, each file once: one cache per scene parse maps the normalised absolute
 * path to its {@link TextureImage}, so every object naming the same file shares one instance
 * (and one mip chain).
 *
 * <p>Formats: {@code .tga} files are read by {@link TgaReader}; everything else by
 * javax.imageio, which recognises PNG, JPEG, BMP and GIF by their contents. Alpha is ignored;
 * 16-bit colour images are reduced to 8 bits per channel (16-bit greyscale keeps its precision).
 *
 * <p>Colour: 8-bit colour images are taken as sRGB-encoded and decoded to linear with the exact
 * sRGB transfer function ({@code c / 12.92} for {@code c <= 0.04045}, else
 * {@code ((c + 0.055) / 1.055)^2.4}); palette images count as colour. Greyscale images
 * (greyscale PNG/JPEG, TGA types 3 and 11) are taken as LINEAR data ({@code value / max}), since
 * they usually hold heights or masks for bump, transparency or specular channels, not colours.
 *
 * <p>Limit: images of more than {@link #MAX_PIXELS} pixels are refused (before their pixels are
 * decoded): a texel costs 12 bytes plus a third for the mip chain, so the limit keeps one texture
 * near 1 GiB.
 *
 * <p>Errors are {@link IOException}s with a one-line message "FILE: reason"; the scene parser
 * adds the scene location. Loading is synchronised, so a cache may be shared between threads.
 */
public final class TextureCache {
    /** Largest accepted image, in pixels: 2^26 (e.g. 8192 x 8192 or 16384 x 4096). */
    public static final int MAX_PIXELS = 1 << 26;

    private static final double[] SRGB_TO_LINEAR = new double[256];
    static {
        for (int i = 0; i < 256; i++) SRGB_TO_LINEAR[i] = srgbToLinear(i / 255.0);
    }

    private final Map<Path, TextureImage> images = new HashMap<>();

    /**
     * The image in {@code file}, loaded on the first request for its normalised absolute path and
     * shared afterwards.
     *
     * @throws IOException "FILE: reason" if the file is missing, unreadable, corrupt, of an
     *         unsupported kind, or larger than {@link #MAX_PIXELS}
     */
    public synchronized TextureImage load(Path file) throws IOException {
        Path key = file.toAbsolutePath().normalize();
        TextureImage img = images.get(key);
        if (img == null) {
            try {
                img = decode(key);
            } catch (NoSuchFileException e) {
                throw new IOException(file + ": file not found", e);
            } catch (IOException | RuntimeException e) {
                throw new IOException(file + ": " + oneLine(e), e);
            }
            images.put(key, img);
        }
        return img;
    }

    /** Number of distinct images loaded so far. */
    public synchronized int size() {
        return images.size();
    }

    /** The exact sRGB decoding function, for {@code c} in [0, 1]. */
    public static double srgbToLinear(double c) {
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /** Refuses sizes above {@link #MAX_PIXELS}; the message states the size and the limit. */
    static void checkSize(long w, long h) throws IOException {
        if (w * h > MAX_PIXELS) {
            throw new IOException("image is " + w + "x" + h + " pixels, more than the limit of " + MAX_PIXELS
                    + " pixels (e.g. 8192x8192)");
        }
    }

    private static TextureImage decode(Path file) throws IOException {
        // A pipe would block the decoder and a device never end: only regular files are opened.
        String problem = InputFiles.problem(file);
        if (problem != null) throw problem.equals("not found") ? new NoSuchFileException(file.toString()) : new IOException(problem);
        if (!Files.isReadable(file)) throw new IOException("file is not readable");
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".tga")) {
            TgaReader.Image t = TgaReader.read(file);
            return fromRgb8(t.width(), t.height(), t.rgb(), !t.grey());
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            if (in == null) throw new IOException("cannot open the file");
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            if (!readers.hasNext()) {
                throw new IOException("not a PNG, JPEG, BMP, GIF or TGA image (no decoder recognises its contents)");
            }
            ImageReader reader = readers.next();
            try {
                reader.setInput(in, true, true);
                String format = reader.getFormatName().toUpperCase(Locale.ROOT);
                int w, h;
                try {
                    w = reader.getWidth(0);
                    h = reader.getHeight(0);
                } catch (IOException e) {
                    throw corrupt(format, e);
                }
                checkSize(w, h);  // before the pixels are decoded
                BufferedImage img;
                try {
                    img = reader.read(0);
                } catch (IOException e) {
                    throw corrupt(format, e);
                }
                return fromBufferedImage(img);
            } finally {
                reader.dispose();
            }
        }
    }

    private static TextureImage fromBufferedImage(BufferedImage img) {
        int w = img.getWidth(), h = img.getHeight();
        if (img.getColorModel().getColorSpace().getType() == ColorSpace.TYPE_GRAY
                && img.getColorModel().getNumColorComponents() == 1) {
            // getRGB would push Java's linear grey colour space through an sRGB conversion; the
            // stored samples are what the file means (linear data, see the class comment).
            Raster raster = img.getRaster();
            double max = (1L << img.getColorModel().getComponentSize(0)) - 1;
            float[] f = new float[w * h * 3];
            for (int y = 0, q = 0; y < h; y++) {
                for (int x = 0; x < w; x++, q += 3) {
                    float g = (float) (raster.getSample(x, y, 0) / max);
                    f[q] = g;
                    f[q + 1] = g;
                    f[q + 2] = g;
                }
            }
            return TextureImage.wrap(w, h, f);
        }
        int[] row = new int[w];
        float[] f = new float[w * h * 3];
        for (int y = 0, q = 0; y < h; y++) {
            img.getRGB(0, y, w, 1, row, 0, w);
            for (int x = 0; x < w; x++, q += 3) {
                int p = row[x];
                f[q] = (float) SRGB_TO_LINEAR[p >> 16 & 0xFF];
                f[q + 1] = (float) SRGB_TO_LINEAR[p >> 8 & 0xFF];
                f[q + 2] = (float) SRGB_TO_LINEAR[p & 0xFF];
            }
        }
        return TextureImage.wrap(w, h, f);
    }

    /** 8-bit packed RGB, rows top-down; sRGB-decoded if {@code srgb}, else divided by 255. */
    static TextureImage fromRgb8(int w, int h, int[] rgb, boolean srgb) {
        float[] f = new float[w * h * 3];
        for (int i = 0, q = 0; i < rgb.length; i++, q += 3) {
            int p = rgb[i];
            for (int c = 0; c < 3; c++) {
                int b = p >> (16 - 8 * c) & 0xFF;
                f[q + c] = (float) (srgb ? SRGB_TO_LINEAR[b] : b / 255.0);
            }
        }
        return TextureImage.wrap(w, h, f);
    }

    private static IOException corrupt(String format, IOException e) {
        return new IOException("corrupt " + format + " image (" + oneLine(e) + ")", e);
    }

    private static String oneLine(Exception e) {
        String m = e.getMessage();
        if (m == null || m.isBlank()) m = e.getClass().getSimpleName();
        return m.replaceAll("\\s*[\\r\\n]+\\s*", " ").trim();
    }
}
