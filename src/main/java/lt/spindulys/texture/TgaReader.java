package lt.spindulys.texture;

import java.io.BufferedInputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Path;

import lt.spindulys.limits.InputFiles;

/**
 * Reads Truevision TGA images: types 2 and 10 (uncompressed and run-length encoded true colour,
 * 24 or 32 bits per pixel; alpha is ignored) and types 3 and 11 (uncompressed and RLE 8-bit
 * greyscale). Both vertical origins (descriptor bit 5: set = top-left, clear = bottom-left) and
 * both horizontal directions (bit 4) are honoured. Colour-mapped images are refused.
 *
 * <p>The header is checked against {@link TextureCache#MAX_PIXELS} and the heap (the pixels, the
 * texels and the mip chain the cache makes of them) before any pixel memory is allocated, and the
 * data are decoded as a stream, so a huge or lying header costs nothing.
 * Errors are {@link IOException}s whose message is a one-line reason (the caller names the file).
 */
public final class TgaReader {
    private TgaReader() {}

    /**
     * A decoded TGA image: 8-bit values packed {@code 0xRRGGBB} (grey images have R = G = B),
     * rows TOP-DOWN whatever the file's origin.
     *
     * @param grey whether the file was a greyscale image (type 3 or 11)
     */
    public record Image(int width, int height, boolean grey, int[] rgb) {}

    /**
     * Reads the TGA file at {@code file}.
     *
     * @param file the file
     * @return the image
     * @throws IOException if the file cannot be read or is not a TGA image this reader supports
     */
    public static Image read(Path file) throws IOException {
        try (InputStream in = InputFiles.open(file)) {
            return read(in);
        }
    }

    /**
     * Reads a TGA image from {@code in} (not closed).
     *
     * @param in the stream
     * @return the image
     * @throws IOException if the stream cannot be read or is not a TGA image this reader supports
     */
    public static Image read(InputStream in) throws IOException {
        InputStream s = in instanceof BufferedInputStream ? in : new BufferedInputStream(in, 1 << 16);
        byte[] h = s.readNBytes(18);
        if (h.length < 18) throw new IOException("not a TGA file: truncated header (" + h.length + " of 18 bytes)");
        int idLength = h[0] & 0xFF, colorMapType = h[1] & 0xFF, type = h[2] & 0xFF;
        int mapLength = u16(h, 5), mapEntryBits = h[7] & 0xFF;
        int w = u16(h, 12), ht = u16(h, 14), depth = h[16] & 0xFF, descriptor = h[17] & 0xFF;
        boolean grey = type == 3 || type == 11, rle = type == 10 || type == 11;
        if (type != 2 && type != 10 && !grey) {
            throw new IOException("unsupported TGA image type " + type
                    + " (expected 2 or 10: true colour, or 3 or 11: greyscale)");
        }
        if (grey ? depth != 8 : depth != 24 && depth != 32) {
            throw new IOException("unsupported TGA depth of " + depth + " bits per pixel for image type " + type
                    + (grey ? " (expected 8)" : " (expected 24 or 32)"));
        }
        if (colorMapType > 1) throw new IOException("corrupt TGA header: colour map type " + colorMapType);
        if (w == 0 || ht == 0) throw new IOException("empty TGA image " + w + "x" + ht);
        TextureCache.checkSize(w, ht);
        // The pixels below (an int each), then the texels and the mip chain the cache makes of them.
        TextureCache.checkHeap(w, ht, 4L * w * ht, grey ? 1 : 3);

        // A colour map may be present even in a true-colour file; it is unused, so skip it.
        long skip = idLength + (colorMapType == 1 ? (long) mapLength * ((mapEntryBits + 7) / 8) : 0);
        try {
            s.skipNBytes(skip);
        } catch (EOFException e) {
            throw new IOException("truncated TGA file (in the image ID or colour map)");
        }

        int bpp = depth / 8, n = w * ht;
        int[] pixels = new int[n];  // in file order
        byte[] px = new byte[bpp];
        try {
            if (!rle) {
                byte[] row = new byte[w * bpp];
                for (int r = 0, p = 0; r < ht; r++) {
                    readFully(s, row);
                    for (int c = 0; c < w; c++, p++) pixels[p] = pack(row, c * bpp, grey);
                }
            } else {
                int p = 0;
                while (p < n) {
                    int head = s.read();
                    if (head < 0) throw new EOFException();
                    int count = (head & 0x7F) + 1;
                    if (count > n - p) throw new IOException("corrupt TGA data: a run-length packet runs past the end of the image");
                    if ((head & 0x80) != 0) {
                        readFully(s, px);
                        int v = pack(px, 0, grey);
                        for (int k = 0; k < count; k++) pixels[p++] = v;
                    } else {
                        for (int k = 0; k < count; k++) {
                            readFully(s, px);
                            pixels[p++] = pack(px, 0, grey);
                        }
                    }
                }
            }
        } catch (EOFException e) {
            throw new IOException("truncated TGA file (pixel data ends early)");
        }

        // Reorder in place to top-down, left-to-right (a second array would cost 4 bytes a pixel).
        boolean topDown = (descriptor & 0x20) != 0, rightToLeft = (descriptor & 0x10) != 0;
        if (!topDown) {
            for (int a = 0, b = ht - 1; a < b; a++, b--) {
                for (int c = 0; c < w; c++) swap(pixels, a * w + c, b * w + c);
            }
        }
        if (rightToLeft) {
            for (int r = 0; r < ht; r++) {
                for (int a = r * w, b = a + w - 1; a < b; a++, b--) swap(pixels, a, b);
            }
        }
        return new Image(w, ht, grey, pixels);
    }

    private static void swap(int[] a, int i, int j) {
        int t = a[i];
        a[i] = a[j];
        a[j] = t;
    }

    /** TGA stores true colour as B, G, R(, A); greyscale as one byte. */
    private static int pack(byte[] b, int o, boolean grey) {
        if (grey) {
            int g = b[o] & 0xFF;
            return g << 16 | g << 8 | g;
        }
        return (b[o + 2] & 0xFF) << 16 | (b[o + 1] & 0xFF) << 8 | (b[o] & 0xFF);
    }

    private static void readFully(InputStream s, byte[] b) throws IOException {
        if (s.readNBytes(b, 0, b.length) != b.length) throw new EOFException();
    }

    private static int u16(byte[] b, int i) {
        return (b[i] & 0xFF) | (b[i + 1] & 0xFF) << 8;
    }
}
