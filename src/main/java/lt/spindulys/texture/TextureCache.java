package lt.spindulys.texture;

import java.awt.color.ColorSpace;
import java.awt.image.BufferedImage;
import java.awt.image.DataBuffer;
import java.awt.image.MultiPixelPackedSampleModel;
import java.awt.image.Raster;
import java.awt.image.SampleModel;
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
import javax.imageio.ImageTypeSpecifier;
import javax.imageio.stream.ImageInputStream;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InputFiles;

/**
 * Loads texture images, each file once: one cache per scene parse maps the normalised absolute
 * path to its {@link TextureImage}, so every object naming the same file shares one instance
 * (and one mip chain).
 *
 * <p>Formats: {@code .tga} files are read by {@link TgaReader}, {@code .hdr} (Radiance RGBE) by
 * {@link HdrReader}, {@code .pfm} by {@link PfmReader} and {@code .exr} (OpenEXR) by
 * {@link ExrReader} (all high dynamic range, LINEAR, kept as three floats a texel); everything else by javax.imageio, which recognises PNG, JPEG, BMP and
 * GIF by their contents. Alpha is ignored;
 * 16-bit colour images are reduced to 8 bits per channel (16-bit greyscale keeps its precision).
 *
 * <p>Colour: 8-bit colour images are taken as sRGB-encoded and decoded to linear with the exact
 * sRGB transfer function ({@code c / 12.92} for {@code c <= 0.04045}, else
 * {@code ((c + 0.055) / 1.055)^2.4}); palette images count as colour. Greyscale images
 * (greyscale PNG/JPEG, TGA types 3 and 11) are taken as LINEAR data ({@code value / max}), since
 * they usually hold heights or masks for bump, transparency or specular channels, not colours.
 *
 * <p>Memory: a texel of an 8-bit image is kept as its bytes (3 for colour, 1 for greyscale; 2
 * for 16-bit greyscale), see {@link TextureImage}; the mip chain adds 4 bytes per texel (floats,
 * a third of the texel count). Before any pixel is decoded, the heap is asked for all of it:
 * what the decoder itself allocates (TGA: an int per pixel; javax.imageio: its BufferedImage, 1
 * to 8 bytes per pixel by the file's kind), the texels and the mip chain; an image that does
 * not fit is refused with how much it needs and how much is free. Images of more than
 * {@link #MAX_PIXELS} pixels are refused outright: at 7 bytes per colour texel with its chain,
 * the limit keeps one texture under half a GiB once loaded.
 *
 * <p>Errors are {@link IOException}s with a one-line message "FILE: reason"; the scene parser
 * adds the scene location. Loading is synchronised, so a cache may be shared between threads.
 */
public final class TextureCache {
    /** Largest accepted image, in pixels: 2^26 (e.g. 8192 x 8192 or 16384 x 4096). */
    public static final int MAX_PIXELS = 1 << 26;

    /** An empty cache; share one between the scenes that use the same image files. */
    public TextureCache() {}

    private static final double[] SRGB_TO_LINEAR = new double[256];
    /** The float each byte of an 8-bit image stands for: sRGB-decoded (colour) or divided by 255 (grey). */
    private static final float[] SRGB_TABLE = new float[256], LINEAR_TABLE = new float[256];
    static {
        for (int i = 0; i < 256; i++) {
            SRGB_TO_LINEAR[i] = srgbToLinear(i / 255.0);
            SRGB_TABLE[i] = (float) SRGB_TO_LINEAR[i];
            LINEAR_TABLE[i] = (float) (i / 255.0);
        }
    }

    /** The float of each 16-bit grey code ({@code code / 65535}); made on the first 16-bit image. */
    private static final class Grey16 {
        static final float[] TABLE = greyTable(16);
    }

    /** {@code (float) (code / (2^bits - 1))} for every code of {@code bits} bits, in a table of 256 or 65,536. */
    private static float[] greyTable(int bits) {
        double max = (1L << bits) - 1;
        float[] t = new float[bits <= 8 ? 256 : 65536];
        for (int i = 0; i <= max && i < t.length; i++) t[i] = (float) (i / max);
        return t;
    }

    private final Map<Path, TextureImage> images = new HashMap<>();

    /**
     * The image in {@code file}, loaded on the first request for its normalised absolute path and
     * shared afterwards.
     *
     * @param file the image file (TGA, HDR, PFM, PNG or JPEG)
     * @return the image
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

    /**
     * Number of distinct images loaded so far.
     *
     * @return the count
     */
    public synchronized int size() {
        return images.size();
    }

    /**
     * The exact sRGB decoding function, for {@code c} in [0, 1].
     *
     * @param c an encoded value
     * @return the linear value
     */
    public static double srgbToLinear(double c) {
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    /**
     * Asks the heap for a {@code w x h} image before it is decoded: {@code decodeBytes} that the
     * decoder allocates for its own image, {@code texelBytes} per texel kept, and the mip chain.
     *
     * @throws lt.spindulys.limits.InsufficientMemoryException if the heap cannot give it now
     */
    static void checkHeap(long w, long h, long decodeBytes, int texelBytes) {
        long texels = HeapBudget.product(w, h);
        long bytes = HeapBudget.sum(decodeBytes, HeapBudget.product(texels, texelBytes), TextureImage.mipBytes((int) w, (int) h));
        HeapBudget.require(bytes, "the " + w + "x" + h + " image");
    }

    /**
     * Bytes javax.imageio's decoder allocates for a {@code w x h} image of the first type
     * {@code reader} offers (the one {@code read} decodes into); 8 bytes a pixel if it says none.
     */
    private static long decodeBytes(ImageReader reader, int w, int h) {
        long bits = 64;
        try {
            Iterator<ImageTypeSpecifier> types = reader.getImageTypes(0);
            if (types != null && types.hasNext()) {
                SampleModel sm = types.next().getSampleModel();
                bits = sm instanceof MultiPixelPackedSampleModel mp ? mp.getPixelBitStride()
                        : (long) sm.getNumDataElements() * DataBuffer.getDataTypeSize(sm.getDataType());
            }
        } catch (IOException | RuntimeException e) {
            // Not known before decoding: the widest kind (four 16-bit samples) stands in.
        }
        return HeapBudget.product((HeapBudget.product(w, bits) + 7) / 8, h);
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
        if (name.endsWith(".hdr") || name.endsWith(".pfm") || name.endsWith(".exr")) {
            HdrReader.Image f = name.endsWith(".hdr") ? HdrReader.read(file)
                    : name.endsWith(".pfm") ? PfmReader.read(file) : ExrReader.read(file);
            return TextureImage.wrap(f.width(), f.height(), f.rgb());
        }
        try (ImageInputStream in = ImageIO.createImageInputStream(file.toFile())) {
            if (in == null) throw new IOException("cannot open the file");
            Iterator<ImageReader> readers = ImageIO.getImageReaders(in);
            if (!readers.hasNext()) {
                throw new IOException("not a PNG, JPEG, BMP, GIF or TGA image (no decoder recognises its contents; .hdr, .pfm and .exr files are read by their extension)");
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
                checkHeap(w, h, decodeBytes(reader, w, h), 3);
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
            int bits = img.getColorModel().getComponentSize(0);
            if (bits <= 8) {
                byte[] codes = new byte[w * h];
                for (int y = 0, q = 0; y < h; y++) for (int x = 0; x < w; x++) codes[q++] = (byte) raster.getSample(x, y, 0);
                return TextureImage.ofBytes(w, h, codes, 1, bits == 8 ? LINEAR_TABLE : greyTable(bits));
            }
            if (bits <= 16) {
                char[] codes = new char[w * h];
                for (int y = 0, q = 0; y < h; y++) for (int x = 0; x < w; x++) codes[q++] = (char) raster.getSample(x, y, 0);
                return TextureImage.ofChars(w, h, codes, bits == 16 ? Grey16.TABLE : greyTable(bits));
            }
            double max = (1L << bits) - 1;
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
        byte[] codes = new byte[w * h * 3];
        for (int y = 0, q = 0; y < h; y++) {
            img.getRGB(0, y, w, 1, row, 0, w);
            for (int x = 0; x < w; x++, q += 3) {
                int p = row[x];
                codes[q] = (byte) (p >> 16);
                codes[q + 1] = (byte) (p >> 8);
                codes[q + 2] = (byte) p;
            }
        }
        return TextureImage.ofBytes(w, h, codes, 3, SRGB_TABLE);
    }

    /** 8-bit packed RGB, rows top-down; sRGB-decoded if {@code srgb}, else divided by 255 (grey: R = G = B, one byte kept). */
    static TextureImage fromRgb8(int w, int h, int[] rgb, boolean srgb) {
        if (!srgb && isGrey(rgb)) {
            byte[] codes = new byte[rgb.length];
            for (int i = 0; i < rgb.length; i++) codes[i] = (byte) rgb[i];
            return TextureImage.ofBytes(w, h, codes, 1, LINEAR_TABLE);
        }
        byte[] codes = new byte[rgb.length * 3];
        for (int i = 0, q = 0; i < rgb.length; i++, q += 3) {
            int p = rgb[i];
            codes[q] = (byte) (p >> 16);
            codes[q + 1] = (byte) (p >> 8);
            codes[q + 2] = (byte) p;
        }
        return TextureImage.ofBytes(w, h, codes, 3, srgb ? SRGB_TABLE : LINEAR_TABLE);
    }

    private static boolean isGrey(int[] rgb) {
        for (int p : rgb) if ((p >> 16 & 0xFF) != (p & 0xFF) || (p >> 8 & 0xFF) != (p & 0xFF)) return false;
        return true;
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
