package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Random;
import java.util.zip.GZIPInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.math.Ranges;
import lt.spindulys.scene.Environment;

/**
 * The OpenEXR reader on the small files of {@code src/test/resources/exr} (see the README there
 * for how each was made): every codec and layout reads back the same pixels as the uncompressed
 * scanline file, which itself matches the values it was written from.
 */
class ExrReaderTest {
    @TempDir
    Path dir;

    private static final int W = 40, H = 20;

    /** The values make_exr.py writes (before rounding to HALF), as read: clamped to {@link Ranges#MAX_COLOUR}. */
    private static double value(int x, int y, int c) {
        return Math.min(written(x, y, c), Ranges.MAX_COLOUR);
    }

    private static double written(int x, int y, int c) {
        if (x < 5) return new double[] {0.25, 0.5, 3.0}[c];
        if (x == 12 && c == 2) return 0;
        return switch (c) {
            case 0 -> 0.01 * (x + 1) * (y + 1);
            case 1 -> Math.pow(2, Math.floorDiv(x, 2) - 13) * 1.3;
            default -> y + 0.7 * x + (x == 37 ? 100 : 0);
        };
    }

    static byte[] bytes(String name) {
        try (InputStream in = ExrReaderTest.class.getResourceAsStream("/exr/" + name + ".exr.gz")) {
            if (in == null) throw new IllegalStateException("missing test file exr/" + name + ".exr.gz");
            return new GZIPInputStream(in).readAllBytes();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static HdrReader.Image read(String name) throws IOException {
        return ExrReader.read(bytes(name));
    }

    private static void assertSame(HdrReader.Image expected, HdrReader.Image actual, String what) {
        assertEquals(expected.width(), actual.width(), what);
        assertEquals(expected.height(), actual.height(), what);
        assertArrayEquals(expected.rgb(), actual.rgb(), 0f, what);
    }

    @Test
    void theUncompressedFileHoldsTheWrittenValuesToHalfPrecision() throws IOException {
        HdrReader.Image im = read("scan-none");
        assertEquals(W, im.width());
        assertEquals(H, im.height());
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    double v = value(x, y, c);
                    assertEquals(v, im.rgb()[3 * (y * W + x) + c], v * 1e-3 + 1e-7, x + "," + y + " channel " + c);
                }
            }
        }
    }

    @Test
    void everyLosslessCodecScanlineAndTiledReadsTheSamePixels() throws IOException {
        HdrReader.Image reference = read("scan-none");
        for (String name : new String[] {"scan-rle", "scan-zips", "scan-zip", "tiled-rle", "tiled-zip", "tiled-piz-stored", "mipmap-zip"}) {
            assertSame(reference, read(name), name);
        }
    }

    /** The quantised gradient of make_exr.py, which PIZ compresses. */
    private static double steps(int x, int y, int c) {
        return switch (c) {
            case 0 -> Math.floorDiv(x, 3) * 0.25;
            case 1 -> Math.floorDiv(y, 2) * 0.5 + 1;
            default -> Math.floorDiv(x + y, 5) * 0.125;
        };
    }

    @Test
    void pizTilesHalfFloatAndLuminanceReadTheWrittenValues() throws IOException {
        int w = 64, h = 32;
        HdrReader.Image half = read("tiled-steps-piz"), single = read("tiled-steps-float-piz");
        HdrReader.Image luminance = read("tiled-steps-luminance-piz");
        assertSame(read("steps-none"), half, "tiled-steps-piz");
        assertSame(read("steps-float-zip"), single, "tiled-steps-float-piz");
        assertSame(read("steps-luminance-none"), luminance, "tiled-steps-luminance-piz");
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int q = 3 * (y * w + x);
                for (int c = 0; c < 3; c++) {
                    // Every value is a multiple of 1/8 below 64: exact in HALF and FLOAT.
                    assertEquals(steps(x, y, c), half.rgb()[q + c], 0.0, x + "," + y);
                    assertEquals(steps(x, y, c), single.rgb()[q + c], 0.0, x + "," + y);
                    assertEquals(steps(x, y, 1) + 0.5 * steps(x, y, 2), luminance.rgb()[q + c], 0.0, x + "," + y);
                }
            }
        }
    }

    @Test
    void uintChannelsReadAsTheirIntegers() throws IOException {
        HdrReader.Image zip = read("steps-uint-zip");
        for (int y = 0; y < 32; y++) {
            for (int x = 0; x < 64; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(Math.min(8 * steps(x, y, c), Ranges.MAX_COLOUR), zip.rgb()[3 * (y * 64 + x) + c], 0.0, x + "," + y);
                }
            }
        }
        assertSame(zip, read("tiled-steps-uint-piz"), "tiled-steps-uint-piz");
    }

    @Test
    void pizWithMoreThan16384DistinctWordsUsesTheSixteenBitWaveletCorrectly() throws IOException {
        HdrReader.Image wide = read("tiled-wide-float-piz");
        assertEquals(128, wide.width());
        for (int i = 0; i < 128 * 128; i++) {
            assertEquals(Float.intBitsToFloat(0x3F800000 | (20000 + i)), wide.rgb()[3 * i], 0f, "pixel " + i);
            assertEquals(0f, wide.rgb()[3 * i + 1], 0f);
            assertEquals(0f, wide.rgb()[3 * i + 2], 0f);
        }
    }

    @Test
    void scanlinePizMatchesTheSameImageUncompressed() throws IOException {
        HdrReader.Image piz = read("scan-steps-piz");
        assertSame(read("scan-steps-piz-reference"), piz, "scan-steps-piz");
        // exr2aces converted the colours: the image must still be far from black.
        double sum = 0;
        for (float v : piz.rgb()) sum += v;
        assertTrue(sum > 1000, "sum " + sum);
    }

    @Test
    void floatChannelsReadExactlyThroughZip() throws IOException {
        HdrReader.Image zip = read("scan-float-zip");
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals((float) value(x, y, c), zip.rgb()[3 * (y * W + x) + c], 0f, x + "," + y);
                }
            }
        }
    }

    @Test
    void aLuminanceFileIsReadAsGrey() throws IOException {
        HdrReader.Image y = read("luminance-none");
        for (int p = 0; p < W * H; p++) {
            assertEquals(y.rgb()[3 * p], y.rgb()[3 * p + 1], 0f);
            assertEquals(y.rgb()[3 * p], y.rgb()[3 * p + 2], 0f);
            int px = p % W, py = p / W;
            double v = Math.min(written(px, py, 1) + 0.5 * written(px, py, 2), Ranges.MAX_COLOUR);
            assertEquals(v, y.rgb()[3 * p], v * 1e-3 + 1e-7);
        }
    }

    @Test
    void pixelsOutsideTheDataWindowAreBlack() throws IOException {
        HdrReader.Image inner = read("scan-none"), window = read("window-none");
        assertEquals(W + 4, window.width());
        assertEquals(H + 2, window.height());
        for (int y = 0; y < window.height(); y++) {
            for (int x = 0; x < window.width(); x++) {
                boolean inside = x >= 2 && x < 2 + W && y >= 1 && y < 1 + H;
                for (int c = 0; c < 3; c++) {
                    float expected = inside ? inner.rgb()[3 * ((y - 1) * W + x - 2) + c] : 0f;
                    assertEquals(expected, window.rgb()[3 * (y * window.width() + x) + c], 0f, x + "," + y);
                }
            }
        }
        assertSame(window, read("window-tiled-zip"), "window-tiled-zip");
    }

    @Test
    void lossyCodecsAreRefusedByName() {
        for (String codec : new String[] {"dwab", "pxr24"}) {
            IOException e = assertThrows(IOException.class, () -> read("tiled-" + codec));
            assertEquals(codec.toUpperCase() + " compression is not supported (a lossy codec); re-save it with ZIP or PIZ", e.getMessage());
        }
    }

    @Test
    void theTextureCacheReadsExrAndNamesTheFileInErrors() throws IOException {
        Path good = dir.resolve("sky.exr"), bad = dir.resolve("sky-dwab.exr");
        Files.write(good, bytes("tiled-zip"));
        Files.write(bad, bytes("tiled-dwab"));
        TextureCache cache = new TextureCache();
        TextureImage t = cache.load(good);
        HdrReader.Image reference = read("scan-none");
        assertEquals(W, t.width());
        assertEquals(reference.rgb()[3 * (7 * W + 30) + 2], t.texel(0, 30, 7, 2), 0.0);
        assertEquals(W, Environment.load(good, 0, 1).map().width());
        IOException e = assertThrows(IOException.class, () -> cache.load(bad));
        assertEquals(bad + ": DWAB compression is not supported (a lossy codec); re-save it with ZIP or PIZ", e.getMessage());
    }

    @Test
    void headerErrorsSayWhatWasFoundAndExpected() {
        byte[] b = bytes("scan-none");
        byte[] magic = b.clone();
        magic[0] = 'P';
        assertMessage(magic, "not an OpenEXR file: it starts with 50 2f 31 01, expected 76 2f 31 01");
        byte[] multi = b.clone();
        multi[5] |= 0x10;
        assertMessage(multi, "multi-part OpenEXR files are not supported");
        byte[] deep = b.clone();
        deep[5] |= 0x08;
        assertMessage(deep, "deep OpenEXR data are not supported");
        assertMessage(Arrays.copyOf(b, 5), "truncated OpenEXR file: 5 bytes");
        byte[] name = b.clone();
        int at = indexOf(name, "pixelAspectRatio".getBytes());
        name[at] = '\n';
        writeInt(name, at + "pixelAspectRatio\0float\0".length(), 1 << 30);
        assertMessage(name, "truncated OpenEXR header: attribute '\\x0aixelAspectRatio' says 1073741824 bytes");
        assertMessage(Arrays.copyOf(b, 100), "truncated OpenEXR header");
    }

    @Test
    void aHugeDeclaredSizeIsRefusedBeforeAllocating() {
        byte[] b = bytes("scan-none");
        int at = indexOf(b, "dataWindow".getBytes()) + "dataWindow\0box2i\0".length() + 4;
        byte[] huge = b.clone();
        writeInt(huge, at + 8, 1 << 20);   // xMax
        writeInt(huge, at + 12, 1 << 20);  // yMax
        assertMessage(huge, "more than the limit of");
    }

    @Test
    void truncatedAndCorruptedFilesGiveIoExceptionsOnly() {
        for (String name : new String[] {"scan-zip", "scan-rle", "tiled-steps-piz", "scan-steps-piz", "tiled-steps-float-piz"}) {
            byte[] b = bytes(name);
            for (int n = 0; n < b.length; n += Math.max(1, b.length / 300)) {
                byte[] cut = Arrays.copyOf(b, n);
                assertThrows(IOException.class, () -> ExrReader.read(cut), name + " cut to " + n);
            }
            Random random = new Random(name.hashCode());
            for (int k = 0; k < 300; k++) {
                byte[] bad = b.clone();
                for (int j = 0; j < 4; j++) bad[random.nextInt(bad.length)] = (byte) random.nextInt(256);
                try {
                    ExrReader.read(bad);
                } catch (IOException expected) {
                    assertTrue(!expected.getMessage().contains("\n"), expected.getMessage());
                } catch (RuntimeException | OutOfMemoryError e) {
                    fail(name + " corrupted (" + k + ") threw " + e, e);
                }
            }
        }
    }

    private static void assertMessage(byte[] file, String part) {
        IOException e = assertThrows(IOException.class, () -> ExrReader.read(file));
        assertTrue(e.getMessage().contains(part), "expected '" + part + "' in: " + e.getMessage());
    }

    private static int indexOf(byte[] b, byte[] what) {
        outer:
        for (int i = 0; i + what.length <= b.length; i++) {
            for (int j = 0; j < what.length; j++) if (b[i + j] != what[j]) continue outer;
            return i;
        }
        throw new IllegalStateException("not found");
    }

    private static void writeInt(byte[] b, int at, int v) {
        for (int k = 0; k < 4; k++) b[at + k] = (byte) (v >> 8 * k);
    }
}
