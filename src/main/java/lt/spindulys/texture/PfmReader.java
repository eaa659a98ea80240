package lt.spindulys.texture;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Path;

import lt.spindulys.limits.InputFiles;
import lt.spindulys.math.Ranges;

/**
 * Reads portable float maps ({@code .pfm}): {@code PF} (colour, three floats a pixel) and
 * {@code Pf} (grey, one float copied to r, g and b), then the width and height, then the scale,
 * whose sign gives the byte order (negative: little-endian, positive: big-endian; its magnitude
 * is ignored, as most writers set it to 1), each followed by whitespace, then the 32-bit floats
 * with the BOTTOM row first (rows are returned top-down). Values are linear.
 *
 * <p>A value that is not finite or is negative is refused (with its pixel); values above
 * {@link Ranges#MAX_COLOUR} are clamped to it, as {@link HdrReader} does. The size is checked
 * against {@link TextureCache#MAX_PIXELS} and the heap before anything is allocated. Errors are
 * {@link IOException}s with a one-line reason; the caller names the file.
 */
final class PfmReader {
    private PfmReader() {}

    /**
     * Reads the file.
     *
     * @param file the file
     * @return the image (linear RGB, rows top-down)
     * @throws IOException if it cannot be read or is not a PFM image
     */
    static HdrReader.Image read(Path file) throws IOException {
        try (InputStream in = InputFiles.open(file)) {
            return read(in);
        }
    }

    /**
     * Reads an image from {@code in} (not closed).
     *
     * @param in the stream
     * @return the image (linear RGB, rows top-down)
     * @throws IOException if it cannot be read or is not a PFM image
     */
    static HdrReader.Image read(InputStream in) throws IOException {
        InputStream s = in instanceof BufferedInputStream ? in : new BufferedInputStream(in, 1 << 16);
        String magic = token(s, "type");
        int channels = switch (magic) {
            case "PF" -> 3;
            case "Pf" -> 1;
            default -> throw new IOException("not a PFM file: it starts with '" + cut(magic) + "', expected PF (colour) or Pf (grey)");
        };
        int w = size(token(s, "width"), "width"), h = size(token(s, "height"), "height");
        String scaleText = token(s, "scale");
        double scale;
        try {
            scale = Double.parseDouble(scaleText);
        } catch (NumberFormatException e) {
            scale = Double.NaN;
        }
        if (!Double.isFinite(scale) || scale == 0) {
            throw new IOException("bad PFM scale '" + cut(scaleText) + "' (expected a non-zero number: negative for little-endian, positive for big-endian)");
        }
        TextureCache.checkSize(w, h);
        TextureCache.checkHeap(w, h, 0, 12);
        ByteOrder order = scale < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
        float[] rgb = new float[3 * w * h];
        byte[] rowBytes = new byte[4 * channels * w];
        ByteBuffer row = ByteBuffer.wrap(rowBytes).order(order);
        for (int fileRow = 0; fileRow < h; fileRow++) {
            int y = h - 1 - fileRow;  // the file's first row is the bottom one
            if (s.readNBytes(rowBytes, 0, rowBytes.length) < rowBytes.length) {
                throw new IOException("truncated PFM file: pixel data end in row " + y + " (from the top) of " + h);
            }
            for (int x = 0, q = 3 * y * w; x < w; x++, q += 3) {
                for (int c = 0; c < 3; c++) {
                    float v = row.getFloat(4 * (channels == 1 ? x : 3 * x + c));
                    if (!(v >= 0) || v == Float.POSITIVE_INFINITY) {
                        throw new IOException("PFM value " + v + " at pixel " + x + "," + y + " (from the top left) is not a finite non-negative number");
                    }
                    rgb[q + c] = (float) Math.min(v, Ranges.MAX_COLOUR);
                }
            }
        }
        return new HdrReader.Image(w, h, rgb);
    }

    /** A header token: non-whitespace bytes after optional whitespace, ended by one whitespace byte. */
    private static String token(InputStream s, String what) throws IOException {
        StringBuilder b = new StringBuilder();
        int c;
        do {
            c = s.read();
        } while (c == ' ' || c == '\t' || c == '\n' || c == '\r');
        while (c >= 0 && !(c == ' ' || c == '\t' || c == '\n' || c == '\r')) {
            if (b.length() >= 64) throw new IOException("bad PFM header: the " + what + " is longer than 64 characters");
            b.append((char) c);
            c = s.read();
        }
        if (c < 0) throw new IOException("truncated PFM header: it ends in or before the " + what);
        return b.toString();
    }

    private static int size(String v, String what) throws IOException {
        try {
            int n = Integer.parseInt(v);
            if (n > 0) return n;
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IOException("bad PFM " + what + " '" + cut(v) + "' (expected a positive integer)");
    }

    /** Header text as shown in messages: printable, at most 20 characters. */
    private static String cut(String t) {
        StringBuilder b = new StringBuilder();
        for (char c : t.toCharArray()) {
            if (b.length() >= 20) return b + "...";
            b.append(c >= 32 && c < 127 ? String.valueOf(c) : String.format("\\x%02x", (int) c));
        }
        return b.toString();
    }
}
