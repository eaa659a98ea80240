package lt.spindulys.texture;

import java.io.BufferedInputStream;
import java.io.ByteArrayOutputStream;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import lt.spindulys.limits.InputFiles;
import lt.spindulys.math.Ranges;

/**
 * Reads Radiance {@code .hdr} (RGBE) images: the header ({@code #?RADIANCE} or {@code #?RGBE},
 * {@code FORMAT=32-bit_rle_rgbe} if a format is named; other variables such as EXPOSURE are
 * ignored), the resolution line {@code -Y height +X width} (rows top-down, the orientation every
 * writer uses; the seven others are refused), and scanlines either flat (four bytes a pixel) or in
 * the new-style run-length encoding (a {@code 2 2 hi lo} marker, then each of the four components
 * of the row as runs and literals). Old-style run-length encoding (the repeat pixel
 * {@code 1 1 1 n}) is refused.
 *
 * <p>A pixel {@code (r, g, b, e)} decodes as Radiance does: 0 if {@code e} is 0, else
 * {@code (c + 0.5) * 2^(e - 136)} per component. Values above {@link Ranges#MAX_COLOUR} (the bound
 * on every colour, which keeps pixels finite) are clamped to it: a sun in a sky map saturates
 * there, which the display would do anyway.
 *
 * <p>The size is checked against {@link TextureCache#MAX_PIXELS} and the heap (twelve bytes a
 * texel) before anything is allocated; the data are decoded a row at a time. Errors are
 * {@link IOException}s with a one-line reason saying where (header line, row); the caller names the file.
 */
final class HdrReader {
    private HdrReader() {}

    /** Longest header line read before the file is refused as not a header. */
    private static final int MAX_LINE = 4096;
    /** Most header lines. */
    private static final int MAX_LINES = 1000;

    /**
     * A decoded image: linear RGB, three floats a texel, rows top-down.
     *
     * @param width  width in texels
     * @param height height in texels
     * @param rgb    the values
     */
    record Image(int width, int height, float[] rgb) {}

    /**
     * Reads the file.
     *
     * @param file the file
     * @return the image
     * @throws IOException if it cannot be read or is not an RGBE image this reader supports
     */
    static Image read(Path file) throws IOException {
        try (InputStream in = InputFiles.open(file)) {
            return read(in);
        }
    }

    /**
     * Reads an image from {@code in} (not closed).
     *
     * @param in the stream
     * @return the image
     * @throws IOException if it cannot be read or is not an RGBE image this reader supports
     */
    static Image read(InputStream in) throws IOException {
        InputStream s = in instanceof BufferedInputStream ? in : new BufferedInputStream(in, 1 << 16);
        String magic = line(s, 1);
        if (magic == null || !(magic.equals("#?RADIANCE") || magic.equals("#?RGBE"))) {
            throw new IOException("not a Radiance HDR file: header line 1 is " + show(magic) + ", expected #?RADIANCE or #?RGBE");
        }
        int lineNo = 1;
        while (true) {
            lineNo++;
            if (lineNo > MAX_LINES) throw new IOException("Radiance HDR header has more than " + MAX_LINES + " lines (no empty line ends it)");
            String l = line(s, lineNo);
            if (l == null) throw new IOException("truncated Radiance HDR header: the file ends at header line " + lineNo + " before the empty line that ends the header");
            if (l.isEmpty()) break;
            if (l.startsWith("FORMAT=") && !l.equals("FORMAT=32-bit_rle_rgbe")) {
                throw new IOException("unsupported Radiance HDR format at header line " + lineNo + ": " + show(l) + " (expected FORMAT=32-bit_rle_rgbe)");
            }
        }
        lineNo++;
        String res = line(s, lineNo);
        if (res == null) throw new IOException("truncated Radiance HDR file: no resolution line (line " + lineNo + ")");
        String[] f = res.trim().split("\\s+");
        if (f.length != 4 || !isAxis(f[0]) || !isAxis(f[2])) {
            throw new IOException("bad Radiance HDR resolution line " + lineNo + ": " + show(res) + " (expected -Y height +X width)");
        }
        if (!f[0].equals("-Y") || !f[2].equals("+X")) {
            throw new IOException("unsupported Radiance HDR orientation at line " + lineNo + ": " + show(res)
                    + " (only -Y height +X width, rows top-down, is read)");
        }
        int h = size(f[1], "height", lineNo, res), w = size(f[3], "width", lineNo, res);
        TextureCache.checkSize(w, h);
        TextureCache.checkHeap(w, h, 0, 12);

        float[] rgb = new float[3 * w * h];
        byte[] row = new byte[4 * w];  // component-planar for RLE rows, pixel-interleaved for flat ones
        byte[] first = new byte[4];
        for (int y = 0; y < h; y++) {
            try {
                readFully(s, first);
                boolean rle = w >= 8 && w < 32768 && first[0] == 2 && first[1] == 2 && (first[2] & 0x80) == 0;
                if (rle) {
                    int n = (first[2] & 0xFF) << 8 | first[3] & 0xFF;
                    if (n != w) throw new IOException("corrupt Radiance HDR data in row " + y + ": the run-length row says width " + n + ", the header " + w);
                    for (int c = 0; c < 4; c++) rleComponent(s, row, c * w, w, y);
                    for (int x = 0, q = 3 * y * w; x < w; x++, q += 3) {
                        decode(row[x], row[w + x], row[2 * w + x], row[3 * w + x], rgb, q);
                    }
                } else {
                    if (first[0] == 1 && first[1] == 1 && first[2] == 1) {
                        throw new IOException("unsupported old-style run-length encoding in Radiance HDR row " + y);
                    }
                    System.arraycopy(first, 0, row, 0, 4);
                    readFully(s, row, 4, 4 * w - 4);
                    for (int x = 0, q = 3 * y * w; x < w; x++, q += 3) {
                        if (x > 0 && row[4 * x] == 1 && row[4 * x + 1] == 1 && row[4 * x + 2] == 1) {
                            throw new IOException("unsupported old-style run-length encoding in Radiance HDR row " + y);
                        }
                        decode(row[4 * x], row[4 * x + 1], row[4 * x + 2], row[4 * x + 3], rgb, q);
                    }
                }
            } catch (EOFException e) {
                throw new IOException("truncated Radiance HDR file: pixel data end in row " + y + " of " + h);
            }
        }
        return new Image(w, h, rgb);
    }

    /** One component of a run-length row into {@code dst[at .. at + w)}. */
    private static void rleComponent(InputStream s, byte[] dst, int at, int w, int y) throws IOException {
        int x = 0;
        while (x < w) {
            int count = s.read();
            if (count < 0) throw new EOFException();
            if (count > 128) {
                count -= 128;
                if (count > w - x) throw new IOException("corrupt Radiance HDR data in row " + y + ": a run passes the end of the row");
                int v = s.read();
                if (v < 0) throw new EOFException();
                java.util.Arrays.fill(dst, at + x, at + x + count, (byte) v);
            } else {
                if (count == 0) throw new IOException("corrupt Radiance HDR data in row " + y + ": a literal of length 0");
                if (count > w - x) throw new IOException("corrupt Radiance HDR data in row " + y + ": a literal passes the end of the row");
                readFully(s, dst, at + x, count);
            }
            x += count;
        }
    }

    private static void decode(byte r, byte g, byte b, byte e, float[] out, int q) {
        int ex = e & 0xFF;
        if (ex == 0) {
            out[q] = out[q + 1] = out[q + 2] = 0;
            return;
        }
        double f = Math.scalb(1.0, ex - 136);
        out[q] = clamp(((r & 0xFF) + 0.5) * f);
        out[q + 1] = clamp(((g & 0xFF) + 0.5) * f);
        out[q + 2] = clamp(((b & 0xFF) + 0.5) * f);
    }

    private static float clamp(double v) {
        return (float) Math.min(v, Ranges.MAX_COLOUR);
    }

    private static boolean isAxis(String a) {
        return a.length() == 2 && (a.charAt(0) == '-' || a.charAt(0) == '+') && (a.charAt(1) == 'X' || a.charAt(1) == 'Y');
    }

    private static int size(String v, String what, int lineNo, String res) throws IOException {
        try {
            int n = Integer.parseInt(v);
            if (n > 0) return n;
        } catch (NumberFormatException e) {
            // reported below
        }
        throw new IOException("bad Radiance HDR " + what + " " + show(v) + " at line " + lineNo + " (expected a positive integer in " + show(res) + ")");
    }

    /** A header line without its newline, or null at the end of the file. */
    private static String line(InputStream s, int lineNo) throws IOException {
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        while (true) {
            int c = s.read();
            if (c < 0) return b.size() == 0 ? null : b.toString(StandardCharsets.ISO_8859_1);
            if (c == '\n') return b.toString(StandardCharsets.ISO_8859_1);
            if (b.size() >= MAX_LINE) throw new IOException("Radiance HDR header line " + lineNo + " is longer than " + MAX_LINE + " bytes");
            b.write(c);
        }
    }

    private static String show(String s) {
        if (s == null) return "missing";
        String t = s.length() > 60 ? s.substring(0, 60) + "..." : s;
        StringBuilder b = new StringBuilder("'");
        for (char c : t.toCharArray()) b.append(c >= 32 && c < 127 ? String.valueOf(c) : String.format("\\x%02x", (int) c));
        return b.append('\'').toString();
    }

    private static void readFully(InputStream s, byte[] b) throws IOException {
        readFully(s, b, 0, b.length);
    }

    private static void readFully(InputStream s, byte[] b, int off, int len) throws IOException {
        if (s.readNBytes(b, off, len) < len) throw new EOFException();
    }
}
