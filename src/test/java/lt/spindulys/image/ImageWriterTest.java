package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import lt.spindulys.files.AtomicFile;

class ImageWriterTest {
    @TempDir Path dir;

    private static int[] randomRgb(int n, long seed) {
        Random rnd = new Random(seed);
        int[] rgb = new int[n];
        for (int i = 0; i < n; i++) rgb[i] = rnd.nextInt(1 << 24);
        // Make sure the extremes are present.
        rgb[0] = 0x000000;
        rgb[1] = 0xFFFFFF;
        return rgb;
    }

    private List<String> listing() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList());
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"round.tga", "round.png", "ROUND.TGA", "Round.Png"})
    void eightBitFormatsRoundTripExactly(String name) throws IOException {
        int w = 37, h = 23;   // odd sizes catch row-stride and orientation mistakes
        int[] rgb = randomRgb(w * h, name.hashCode());
        for (boolean srgb : new boolean[] {true, false}) {
            Path out = dir.resolve(name);
            ImageWriter.write(FrameBuffer.fromRgb8(w, h, rgb, srgb), out, ImageOptions.DEFAULT.withSrgb(srgb));
            FrameBuffer back = Images.read(out, srgb);
            assertEquals(w, back.width());
            assertEquals(h, back.height());
            assertArrayEquals(rgb, back.toRgb8(srgb), name + " srgb=" + srgb);
        }
        assertEquals(List.of(name), listing());
    }

    @Test
    void tgaIsTopDownTrueColourWithTheOriginBitSet() throws IOException {
        FrameBuffer fb = FrameBuffer.fromRgb8(300, 2, new int[600], false);
        fb.set(0, 0, 1, 0.5, 0);       // top-left: red + half green
        fb.set(299, 1, 0, 0, 1);       // bottom-right: blue
        Path out = dir.resolve("h.tga");
        ImageWriter.write(fb, out, ImageOptions.DEFAULT.withSrgb(false));
        byte[] b = Files.readAllBytes(out);
        assertEquals(18 + 300 * 2 * 3 + 26, b.length);
        assertEquals(0, b[0], "no image ID");
        assertEquals(0, b[1], "no colour map");
        assertEquals(2, b[2], "uncompressed true colour");
        assertEquals(300, (b[12] & 0xFF) | (b[13] & 0xFF) << 8);
        assertEquals(2, (b[14] & 0xFF) | (b[15] & 0xFF) << 8);
        assertEquals(24, b[16]);
        assertEquals(0x20, b[17], "top-left origin, no alpha bits");
        // First stored pixel is the top-left one, in B, G, R order.
        assertEquals(0, b[18] & 0xFF);
        assertEquals(128, b[19] & 0xFF);
        assertEquals(255, b[20] & 0xFF);
        int last = 18 + 300 * 2 * 3 - 3;
        assertEquals(255, b[last] & 0xFF);
        assertEquals("TRUEVISION-XFILE.\0",
                new String(b, b.length - 18, 18, StandardCharsets.US_ASCII));
    }

    @Test
    void tgaRejectsImagesWiderThanItsSizeField() {
        Path out = dir.resolve("wide.tga");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ImageWriter.write(new FrameBuffer(65536, 1), out, ImageOptions.DEFAULT));
        assertTrue(e.getMessage().contains("65536x1"), e.getMessage());
        assertFalse(Files.exists(out));
    }

    @Test
    void pngHasThePngSignatureEvenWithUpperCaseExtension() throws IOException {
        Path out = dir.resolve("x.PNG");
        ImageWriter.write(new FrameBuffer(3, 3), out, ImageOptions.DEFAULT);
        byte[] b = Files.readAllBytes(out);
        assertArrayEquals(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'}, Arrays.copyOf(b, 8));
    }

    @Test
    void pfmRoundTripsExactFloatsIncludingOutOfRangeValues() throws IOException {
        int w = 5, h = 4;
        Random rnd = new Random(7);
        FrameBuffer fb = new FrameBuffer(w, h);
        double[] d = fb.data();
        for (int i = 0; i < d.length; i++) d[i] = (float) ((rnd.nextDouble() - 0.3) * Math.pow(10, rnd.nextInt(9) - 4));
        d[0] = Float.MAX_VALUE;
        d[1] = -Float.MAX_VALUE;
        d[2] = -0.0f;
        d[3] = Float.MIN_VALUE;
        d[4] = 1e30f;
        Path out = dir.resolve("hdr.pfm");
        ImageWriter.write(fb, out, ImageOptions.DEFAULT);   // srgb must not affect PFM
        FrameBuffer back = Images.read(out);
        assertEquals(w, back.width());
        assertEquals(h, back.height());
        for (int i = 0; i < d.length; i++) {
            assertEquals(0, Double.compare(d[i], back.data()[i]), "value " + i + ": " + d[i] + " vs " + back.data()[i]);
        }
    }

    /** The last line of defence: a pixel that is not a finite float is an internal error, and nothing is written. */
    @Test
    void nonFinitePixelsAreNeverWritten() throws IOException {
        for (double bad : new double[] {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN, 1e39}) {
            for (String name : new String[] {"x.pfm", "x.png", "x.tga", "x.jpg"}) {
                FrameBuffer fb = new FrameBuffer(4, 3);
                fb.set(2, 1, 0.5, bad, 0.5);
                Path out = dir.resolve(name);
                NonFinitePixelException e = assertThrows(NonFinitePixelException.class, () -> ImageWriter.write(fb, out, ImageOptions.DEFAULT));
                assertEquals("non-finite pixel at 2,1", e.getMessage());
                assertFalse(Files.exists(out), name);
            }
        }
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "no temporary file is left");
        }
    }

    @Test
    void pfmHeaderIsLittleEndianAndRowsGoBottomUp() throws IOException {
        FrameBuffer fb = new FrameBuffer(3, 2);
        fb.set(0, 1, 1.5, -2, 3e5);     // bottom-left: first in the file
        fb.set(0, 0, 9, 8, 7);          // top-left: first of the second stored row
        Path out = dir.resolve("o.pfm");
        ImageWriter.write(fb, out, ImageOptions.DEFAULT);
        byte[] b = Files.readAllBytes(out);
        String header = "PF\n3 2\n-1.0\n";
        assertEquals(header, new String(b, 0, header.length(), StandardCharsets.US_ASCII));
        assertEquals(header.length() + 3 * 2 * 3 * 4, b.length);
        ByteBuffer buf = ByteBuffer.wrap(b, header.length(), b.length - header.length()).order(ByteOrder.LITTLE_ENDIAN);
        assertEquals(1.5f, buf.getFloat());
        assertEquals(-2f, buf.getFloat());
        assertEquals(3e5f, buf.getFloat());
        buf.position(header.length() + 3 * 3 * 4);
        assertEquals(9f, buf.getFloat());
    }

    /** A smooth test image, the kind of content JPEG is meant for. */
    private static FrameBuffer gradient(int w, int h) {
        FrameBuffer fb = new FrameBuffer(w, h);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                fb.set(x, y, x / (w - 1.0), y / (h - 1.0), 0.5 + 0.4 * Math.sin(x * 0.1 + y * 0.07));
            }
        }
        return fb;
    }

    @ParameterizedTest
    @ValueSource(strings = {"g.jpg", "g.jpeg", "G.JPEG"})
    void jpegIsReadableWithSmallError(String name) throws IOException {
        FrameBuffer fb = gradient(64, 48);
        Path out = dir.resolve(name);
        ImageWriter.write(fb, out, ImageOptions.DEFAULT);
        byte[] b = Files.readAllBytes(out);
        assertEquals(0xFF, b[0] & 0xFF);
        assertEquals(0xD8, b[1] & 0xFF, "JPEG start-of-image marker");
        FrameBuffer back = Images.read(out);
        assertEquals(64, back.width());
        assertEquals(48, back.height());
        // Chroma subsampling costs up to ~20 levels at saturated corners; on average it is far less.
        ImageDiff.Result diff = ImageDiff.compare(fb, back, 28);
        assertTrue(diff.withinThreshold() && diff.rmse() < 4, diff.toString());
    }

    @Test
    void jpegQualityControlsTheTradeOff() throws IOException {
        FrameBuffer fb = gradient(96, 96);
        Random rnd = new Random(3);
        for (int i = 0; i < fb.data().length; i++) fb.data()[i] += 0.1 * rnd.nextDouble();   // detail to compress
        Path lo = dir.resolve("lo.jpg"), hi = dir.resolve("hi.jpg");
        ImageWriter.write(fb, lo, ImageOptions.DEFAULT.withJpegQuality(0.1));
        ImageWriter.write(fb, hi, ImageOptions.DEFAULT.withJpegQuality(0.98));
        assertTrue(Files.size(lo) < Files.size(hi) / 2, Files.size(lo) + " vs " + Files.size(hi));
        assertTrue(ImageDiff.compare(fb, Images.read(lo), 0).rmse() > ImageDiff.compare(fb, Images.read(hi), 0).rmse());
    }

    @Test
    void optionsValidateTheJpegQuality() {
        assertEquals(new ImageOptions(true, 0.92), ImageOptions.DEFAULT);
        new ImageOptions(false, 0);
        new ImageOptions(false, 1);
        for (double q : new double[] {-0.01, 1.01, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ImageOptions(true, q));
            assertTrue(e.getMessage().contains("JPEG quality"), e.getMessage());
        }
    }

    @Test
    void unsupportedExtensionFailsFastWithTheExpectedMessage() throws IOException {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ImageWriter.checkFormat(Path.of("out.bmp")));
        assertEquals("unsupported output format '.bmp' (expected .tga, .png, .jpg, .jpeg, .pfm or .exr)", e.getMessage());
        e = assertThrows(IllegalArgumentException.class,
                () -> ImageWriter.write(new FrameBuffer(1, 1), dir.resolve("x.bmp"), ImageOptions.DEFAULT));
        assertEquals("unsupported output format '.bmp' (expected .tga, .png, .jpg, .jpeg, .pfm or .exr)", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> ImageWriter.checkFormat(Path.of("render")));
        assertTrue(e.getMessage().contains("'render' has no extension"), e.getMessage());
        assertEquals(List.of(), listing());
        assertEquals(ImageFormat.JPEG, ImageWriter.checkFormat(Path.of("a/b.JpEg")));
        assertEquals(ImageFormat.PFM, ImageWriter.checkFormat(Path.of("a.b.pfm")));
    }

    @Test
    void missingDirectoryIsNamedInTheMessage() {
        Path out = dir.resolve("no-such-dir").resolve("img.png");
        IOException e = assertThrows(IOException.class, () -> ImageWriter.write(new FrameBuffer(1, 1), out,
                ImageOptions.DEFAULT));
        assertTrue(e.getMessage().contains("directory '" + out.getParent() + "' does not exist"), e.getMessage());
        e = assertThrows(IOException.class, () -> ImageWriter.checkOutput(out));
        assertTrue(e.getMessage().contains("'" + out.getParent() + "'"), e.getMessage());
        assertFalse(Files.exists(out.getParent()));
    }

    @Test
    void refusesToReplaceADirectoryOrWriteBelowAFile() throws IOException {
        Path sub = Files.createDirectory(dir.resolve("sub.png"));
        IOException e = assertThrows(IOException.class, () -> ImageWriter.write(new FrameBuffer(1, 1), sub,
                ImageOptions.DEFAULT));
        assertTrue(e.getMessage().contains("is a directory"), e.getMessage());
        assertTrue(Files.isDirectory(sub));
        Path file = Files.writeString(dir.resolve("plain"), "x");
        e = assertThrows(IOException.class, () -> ImageWriter.checkOutput(file.resolve("a.png")));
        assertTrue(e.getMessage().contains("is not a directory"), e.getMessage());
    }

    @Test
    void atomicWriteGoesThroughAHiddenTempFileInTheSameDirectory() throws IOException {
        Path out = Files.writeString(dir.resolve("scene.obj"), "old");
        ImageWriter.writeAtomically(out, os -> {
            os.write("new content".getBytes(StandardCharsets.UTF_8));
            os.flush();
            List<String> during = listing();
            assertEquals(2, during.size(), during.toString());
            String tmp = during.get(0);
            assertTrue(AtomicFile.isTemporaryName(tmp) && tmp.startsWith(".spindulys-") && tmp.endsWith(".tmp"), tmp);
            assertEquals("old", Files.readString(out), "target untouched until the rename");
            os.close();   // closing the handed stream must not break the commit
        });
        assertEquals("new content", Files.readString(out));
        assertEquals(List.of("scene.obj"), listing());
    }

    @Test
    void failingBodyLeavesTheExistingTargetAndNoTempFile() throws IOException {
        Path out = Files.writeString(dir.resolve("keep.png"), "precious");
        IOException boom = new IOException("disk on fire");
        IOException e = assertThrows(IOException.class, () -> ImageWriter.writeAtomically(out, os -> {
            os.write(new byte[100_000]);   // more than the buffer, so bytes really reach the temp file
            throw boom;
        }));
        assertSame(boom, e);
        UncheckedIOException unchecked = new UncheckedIOException(boom);
        assertSame(unchecked, assertThrows(UncheckedIOException.class, () -> ImageWriter.writeAtomically(out, os -> {
            os.write(1);
            throw unchecked;
        })));
        assertEquals("precious", Files.readString(out));
        assertEquals(List.of("keep.png"), listing());
    }

    @Test
    void failingEncoderLeavesTheExistingTargetAndNoTempFile() throws IOException {
        Path out = Files.writeString(dir.resolve("keep.jpg"), "precious");
        // Baseline JPEG cannot encode more than 65500 pixels per side, so the encoder fails mid-write.
        assertThrows(IOException.class, () -> ImageWriter.write(new FrameBuffer(65_501, 1), out, ImageOptions.DEFAULT));
        assertEquals("precious", Files.readString(out));
        assertEquals(List.of("keep.jpg"), listing());
    }

    @Test
    void newFileCreatedWhenNoTargetExistsAndReplacementKeepsPermissions() throws IOException {
        Path out = dir.resolve("fresh.tga");
        ImageWriter.write(new FrameBuffer(2, 2), out, ImageOptions.DEFAULT);
        assertTrue(Files.isRegularFile(out));
        Assumptions.assumeTrue(FileSystems.getDefault().supportedFileAttributeViews().contains("posix"));
        Set<PosixFilePermission> perms = PosixFilePermissions.fromString("rw-r-----");
        Files.setPosixFilePermissions(out, perms);
        ImageWriter.write(new FrameBuffer(3, 3), out, ImageOptions.DEFAULT);
        assertEquals(3, Images.read(out).width());
        assertEquals(perms, Files.getPosixFilePermissions(out));
    }
}
