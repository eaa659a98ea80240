package lt.spindulys.texture;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Writes Radiance {@code .hdr} (RGBE) images, {@code -Y height +X width} (rows top-down), as
 * {@link HdrReader} reads them: flat scanlines, or new-style run-length encoded ones (runs of at
 * least three equal bytes become runs, the rest literals; rows narrower than 8 or wider than 32767
 * pixels are written flat, as the format requires). Encoding follows Ward's: the largest component
 * {@code m = f * 2^e} with f in [0.5, 1) gives the exponent {@code e + 128} and each component
 * {@code c} the byte {@code floor(c * f * 256 / m)}; values below 1e-32 are black.
 */
final class HdrWriter {
    private HdrWriter() {}

    /**
     * Writes {@code rgb} (three linear values a pixel, rows top-down, non-negative and finite).
     *
     * @param file the file
     * @param w    width
     * @param h    height
     * @param rgb  3 * w * h values
     * @param rle  whether to run-length encode the rows
     * @throws IOException if the file cannot be written
     */
    static void write(Path file, int w, int h, float[] rgb, boolean rle) throws IOException {
        try (OutputStream out = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16)) {
            write(out, w, h, rgb, rle);
        }
    }

    /**
     * Writes to {@code out} (not closed); see {@link #write(Path, int, int, float[], boolean)}.
     *
     * @param out the stream
     * @param w    width
     * @param h    height
     * @param rgb  3 * w * h values
     * @param rle  whether to run-length encode the rows
     * @throws IOException if the stream cannot be written
     */
    static void write(OutputStream out, int w, int h, float[] rgb, boolean rle) throws IOException {
        if (w <= 0 || h <= 0 || rgb.length != 3L * w * h) throw new IllegalArgumentException("expected " + 3L * w * h + " values for " + w + "x" + h);
        out.write(("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + h + " +X " + w + "\n").getBytes(StandardCharsets.US_ASCII));
        byte[] row = new byte[4 * w];
        boolean runs = rle && w >= 8 && w < 32768;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int q = 3 * (y * w + x);
                encode(rgb[q], rgb[q + 1], rgb[q + 2], row, runs ? x : 4 * x, runs ? w : 1);
            }
            if (!runs) {
                out.write(row);
                continue;
            }
            out.write(2);
            out.write(2);
            out.write(w >> 8);
            out.write(w & 0xFF);
            for (int c = 0; c < 4; c++) writeComponent(out, row, c * w, w);
        }
    }

    /** The RGBE bytes of one pixel, at {@code at}, {@code at + stride}, ... */
    private static void encode(double r, double g, double b, byte[] dst, int at, int stride) {
        if (!(r >= 0 && g >= 0 && b >= 0) || !Double.isFinite(r + g + b)) throw new IllegalArgumentException("value not finite and non-negative: " + r + " " + g + " " + b);
        double m = Math.max(r, Math.max(g, b));
        if (m < 1e-32) {
            dst[at] = dst[at + stride] = dst[at + 2 * stride] = dst[at + 3 * stride] = 0;
            return;
        }
        int e = Math.getExponent(m) + 1;       // m = f * 2^e with f in [0.5, 1)
        double scale = Math.scalb(1.0, 8 - e); // f * 256 / m
        dst[at] = (byte) Math.min(255, (int) (r * scale));
        dst[at + stride] = (byte) Math.min(255, (int) (g * scale));
        dst[at + 2 * stride] = (byte) Math.min(255, (int) (b * scale));
        dst[at + 3 * stride] = (byte) (e + 128);
    }

    /** One component of a row as runs (3 to 127 equal bytes) and literals (up to 128 bytes). */
    private static void writeComponent(OutputStream out, byte[] row, int at, int w) throws IOException {
        int x = 0;
        while (x < w) {
            // The next run of at least 3 equal bytes, starting at or after x.
            int runStart = x, runLen = 0;
            while (runStart < w) {
                runLen = 1;
                while (runStart + runLen < w && runLen < 127 && row[at + runStart + runLen] == row[at + runStart]) runLen++;
                if (runLen >= 3) break;
                runStart += runLen;
                runLen = 0;
            }
            while (x < runStart) { // literals before the run
                int n = Math.min(128, runStart - x);
                out.write(n);
                out.write(row, at + x, n);
                x += n;
            }
            if (runLen >= 3) {
                out.write(128 + runLen);
                out.write(row[at + x]);
                x += runLen;
            }
        }
    }
}
