package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;

/** The Radiance RGBE and PFM readers, on small files written here. */
class HdrPfmReaderTest {
    @TempDir
    Path dir;

    private static final int W = 20, H = 5;

    /** Values over several octaves, with runs of equal pixels (RLE runs) and a black pixel. */
    private static float[] image() {
        float[] f = new float[3 * W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int q = 3 * (y * W + x);
                if (x < 6) { f[q] = 0.25f; f[q + 1] = 0.5f; f[q + 2] = 3f; continue; }
                f[q] = (float) (0.01 * (x + 1) * (y + 1));
                f[q + 1] = (float) Math.pow(2, x - 13) * 1.3f;
                f[q + 2] = x == 12 ? 0 : (float) (y + 0.7 * x);
            }
        }
        int black = 3 * (2 * W + 15);
        f[black] = f[black + 1] = f[black + 2] = 0;
        return f;
    }

    private static byte[] hdr(float[] f, boolean rle) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        HdrWriter.write(out, W, H, f, rle);
        return out.toByteArray();
    }

    @Test
    void rgbeRoundTripsFlatAndRunLengthEncodedWithinHalfAQuantisationStep() throws IOException {
        float[] f = image();
        byte[] flat = hdr(f, false), rle = hdr(f, true);
        assertTrue(rle.length < flat.length, rle.length + " bytes RLE, " + flat.length + " flat");
        HdrReader.Image a = HdrReader.read(new ByteArrayInputStream(flat)), b = HdrReader.read(new ByteArrayInputStream(rle));
        assertEquals(W, a.width());
        assertEquals(H, a.height());
        assertArrayEquals(a.rgb(), b.rgb());
        for (int p = 0; p < W * H; p++) {
            double max = Math.max(f[3 * p], Math.max(f[3 * p + 1], f[3 * p + 2]));
            for (int c = 0; c < 3; c++) {
                // The largest component lies in [128, 256) steps; a step is at most max / 128.
                assertEquals(f[3 * p + c], a.rgb()[3 * p + c], max / 256 + 1e-12, "pixel " + p + " channel " + c);
            }
        }
        int black = 3 * (2 * W + 15);
        assertEquals(0f, a.rgb()[black]);
    }

    @Test
    void rgbeBytesDecodeAsRadianceDoes() throws IOException {
        // One flat pixel, then an 8-wide run-length row written by hand: each component a run of 5 and a literal of 3.
        byte[] flat = concat(header(1, 1), new byte[] {(byte) 128, 64, 0, (byte) 129});
        float[] v = HdrReader.read(new ByteArrayInputStream(flat)).rgb();
        assertArrayEquals(new float[] {128.5f / 128, 64.5f / 128, 0.5f / 128}, v);
        // Over the colour bound: clamped to it.
        float[] sun = HdrReader.read(new ByteArrayInputStream(concat(header(1, 1), new byte[] {(byte) 200, 0, 0, (byte) 143}))).rgb();
        assertArrayEquals(new float[] {100f, 64f, 64f}, sun);  // 200.5 * 2^7 and 0.5 * 2^7

        ByteArrayOutputStream row = new ByteArrayOutputStream();
        row.writeBytes(new byte[] {2, 2, 0, 8});
        int[][] comps = {{10, 1, 2, 3}, {20, 4, 5, 6}, {30, 7, 8, 9}, {130, 128, 127, 126}};
        for (int[] c : comps) {
            row.writeBytes(new byte[] {(byte) (128 + 5), (byte) c[0], 3, (byte) c[1], (byte) c[2], (byte) c[3]});
        }
        float[] r = HdrReader.read(new ByteArrayInputStream(concat(header(1, 8), row.toByteArray()))).rgb();
        for (int x = 0; x < 8; x++) {
            int e = x < 5 ? 130 : comps[3][x - 4];
            for (int c = 0; c < 3; c++) {
                int m = x < 5 ? comps[c][0] : comps[c][x - 4];
                assertEquals((float) ((m + 0.5) * Math.scalb(1.0, e - 136)), r[3 * x + c], "x " + x + " c " + c);
            }
        }
    }

    @Test
    void badRgbeFilesAreRefusedSayingWhere() {
        assertMessage("header line 1", () -> HdrReader.read(new ByteArrayInputStream("P6\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("orientation at line 4", () -> HdrReader.read(new ByteArrayInputStream(
                "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n+Y 2 +X 2\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("orientation at line 3", () -> HdrReader.read(new ByteArrayInputStream("#?RGBE\n\n+X 2 -Y 2\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("format at header line 2", () -> HdrReader.read(new ByteArrayInputStream(
                "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 2 +X 2\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("bad Radiance HDR width 'x'", () -> HdrReader.read(new ByteArrayInputStream("#?RADIANCE\n\n-Y 2 +X x\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("before the empty line", () -> HdrReader.read(new ByteArrayInputStream("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("pixel data end in row 1 of 2", () -> HdrReader.read(new ByteArrayInputStream(concat(header(2, 1), new byte[] {1, 2, 3, (byte) 130}))));
        // A run of 9 in an 8-wide row.
        assertMessage("row 0: a run passes the end", () -> HdrReader.read(new ByteArrayInputStream(
                concat(header(1, 8), new byte[] {2, 2, 0, 8, (byte) (128 + 9), 1}))));
        assertMessage("row 0: the run-length row says width 9", () -> HdrReader.read(new ByteArrayInputStream(
                concat(header(1, 8), new byte[] {2, 2, 0, 9}))));
        assertMessage("old-style run-length", () -> HdrReader.read(new ByteArrayInputStream(
                concat(header(1, 3), new byte[] {5, 5, 5, (byte) 130, 1, 1, 1, 2, 0, 0, 0, 0}))));
    }

    @Test
    void aLargeHeaderIsRefusedBeforeItsPixelsAreAllocated() {
        byte[] big = header(10_000, 5_000);  // 50 Mpixels, 600 MB as floats, and no data
        try (HeapBudget.Scope s = HeapBudget.cap(1 << 20)) {
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> HdrReader.read(new ByteArrayInputStream(big)));
            assertTrue(e.getMessage().contains("5000x10000"), e.getMessage());
        }
        assertMessage("more than the limit", () -> HdrReader.read(new ByteArrayInputStream(header(10_000, 10_000))));
    }

    /** A PFM file: rows given top-down are written bottom row first, in the byte order the scale's sign says. */
    private static byte[] pfm(String magic, int w, int h, float[] topDown, String scale, ByteOrder order) {
        int ch = magic.equals("PF") ? 3 : 1;
        ByteBuffer b = ByteBuffer.allocate(4 * topDown.length).order(order);
        for (int y = h - 1; y >= 0; y--) for (int i = 0; i < w * ch; i++) b.putFloat(topDown[y * w * ch + i]);
        return concat((magic + "\n" + w + " " + h + "\n" + scale + "\n").getBytes(StandardCharsets.US_ASCII), b.array());
    }

    @Test
    void pfmReadsBothByteOrdersColourAndGreyWithTheBottomRowFirst() throws IOException {
        float[] colour = {0.5f, 1.25f, 7f, 0, 2e-3f, 99f, 1, 2, 3, 4, 5, 6};  // 2x2, top row first
        for (ByteOrder order : new ByteOrder[] {ByteOrder.LITTLE_ENDIAN, ByteOrder.BIG_ENDIAN}) {
            String scale = order == ByteOrder.LITTLE_ENDIAN ? "-1.0" : "1.0";
            HdrReader.Image img = PfmReader.read(new ByteArrayInputStream(pfm("PF", 2, 2, colour, scale, order)));
            assertEquals(2, img.width());
            assertArrayEquals(colour, img.rgb(), order.toString());
            float[] grey = {0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f};  // 3x2
            HdrReader.Image g = PfmReader.read(new ByteArrayInputStream(pfm("Pf", 3, 2, grey, scale, order)));
            for (int i = 0; i < 6; i++) for (int c = 0; c < 3; c++) assertEquals(grey[i], g.rgb()[3 * i + c]);
        }
        // Values over the colour bound are clamped to it.
        HdrReader.Image bright = PfmReader.read(new ByteArrayInputStream(pfm("Pf", 1, 1, new float[] {5000}, "-1", ByteOrder.LITTLE_ENDIAN)));
        assertEquals(100f, bright.rgb()[0]);
    }

    @Test
    void badPfmFilesAreRefused() {
        ByteOrder le = ByteOrder.LITTLE_ENDIAN;
        assertMessage("expected PF (colour) or Pf (grey)", () -> PfmReader.read(new ByteArrayInputStream("P6\n1 1\n255\n".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("bad PFM width '0'", () -> PfmReader.read(new ByteArrayInputStream(pfm("PF", 0, 1, new float[0], "-1", le))));
        assertMessage("bad PFM scale '0'", () -> PfmReader.read(new ByteArrayInputStream(pfm("Pf", 1, 1, new float[1], "0", le))));
        assertMessage("truncated PFM header", () -> PfmReader.read(new ByteArrayInputStream("PF\n3".getBytes(StandardCharsets.US_ASCII))));
        assertMessage("pixel data end in row 0 (from the top) of 2", () -> PfmReader.read(new ByteArrayInputStream(
                java.util.Arrays.copyOf(pfm("Pf", 1, 2, new float[] {1, 2}, "-1", le), 14))));
        assertMessage("at pixel 1,0", () -> PfmReader.read(new ByteArrayInputStream(pfm("Pf", 2, 1, new float[] {1, Float.NaN}, "-1", le))));
        assertMessage("value -1.0 at pixel 0,0", () -> PfmReader.read(new ByteArrayInputStream(pfm("Pf", 1, 1, new float[] {-1}, "-1", le))));
    }

    @Test
    void theTextureCacheReadsBothAsLinearAndNamesTheFileInErrors() throws IOException {
        Path h = dir.resolve("sky.hdr"), p = dir.resolve("sky.pfm"), bad = dir.resolve("bad.hdr");
        float[] f = image();
        HdrWriter.write(h, W, H, f, true);
        Files.write(p, pfm("PF", W, H, f, "-1", ByteOrder.LITTLE_ENDIAN));
        Files.write(bad, "#?RADIANCE\n\n+Y 1 +X 1\n".getBytes(StandardCharsets.US_ASCII));
        TextureCache cache = new TextureCache();
        TextureImage hi = cache.load(h), pi = cache.load(p);
        HdrReader.Image direct = HdrReader.read(h);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(f[3 * (y * W + x) + c], pi.texel(0, x, y, c), 0.0);
                    assertEquals(direct.rgb()[3 * (y * W + x) + c], hi.texel(0, x, y, c), 0.0);
                }
            }
        }
        IOException e = assertThrows(IOException.class, () -> cache.load(bad));
        assertTrue(e.getMessage().startsWith(bad + ": unsupported Radiance HDR orientation at line 3"), e.getMessage());
        assertTrue(!e.getMessage().contains("\n"), e.getMessage());
    }

    private static byte[] header(int h, int w) {
        return ("#?RADIANCE\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=1.0\n\n-Y " + h + " +X " + w + "\n").getBytes(StandardCharsets.US_ASCII);
    }

    private static byte[] concat(byte[] a, byte[] b) {
        byte[] c = java.util.Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, c, a.length, b.length);
        return c;
    }

    private interface Io {
        void run() throws IOException;
    }

    private static void assertMessage(String part, Io io) {
        IOException e = assertThrows(IOException.class, io::run);
        assertTrue(e.getMessage().contains(part), "expected '" + part + "' in: " + e.getMessage());
    }
}
