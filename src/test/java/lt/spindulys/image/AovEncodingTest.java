package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.stream.Stream;
import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The files of the render passes, decoded byte by byte, and their all-or-nothing writing. */
class AovEncodingTest {
    @TempDir Path dir;

    /** A 3x2 frame: hits in the top row, background at (1, 1), and distinct values everywhere. */
    private static AovFrame frame() {
        AovFrame f = new AovFrame(3, 2, EnumSet.allOf(Aov.class));
        f.setHit(0, 0, 1.5, 0, 0, -1, 0);
        f.setHit(1, 0, 2.25, 0.6, 0.8, 0, 1);
        f.setHit(2, 0, 1e6, -1, 0, 0, 0x123455);
        f.setHit(0, 1, 0.125, 0, 1, 0, 254);
        f.setBackground(1, 1);
        f.setHit(2, 1, 3, 0, -1, 0, 255);
        return f;
    }

    /** The header lines and the little-endian floats after them, rows bottom first as stored. */
    private static float[] pfm(Path p, String magic, int w, int h) throws IOException {
        byte[] b = Files.readAllBytes(p);
        byte[] header = (magic + "\n" + w + " " + h + "\n-1.0\n").getBytes(StandardCharsets.US_ASCII);
        int channels = magic.equals("PF") ? 3 : 1;
        assertEquals(header.length + 4 * channels * w * h, b.length, "size of " + p.getFileName());
        for (int i = 0; i < header.length; i++) assertEquals(header[i], b[i], "header byte " + i);
        ByteBuffer buf = ByteBuffer.wrap(b, header.length, b.length - header.length).order(ByteOrder.LITTLE_ENDIAN);
        float[] out = new float[channels * w * h];
        for (int i = 0; i < out.length; i++) out[i] = buf.getFloat();
        return out;
    }

    @Test
    void depthIsOneChannelPfmBottomRowFirstWithInfiniteBackground() throws IOException {
        ImageWriter.write(new FrameBuffer(3, 2), dir.resolve("out.png"), ImageOptions.DEFAULT, frame());
        float[] d = pfm(dir.resolve("out.depth.pfm"), "Pf", 3, 2);
        // Stored: bottom row (y = 1), then the top row (y = 0).
        assertArrayEquals(new float[] {0.125f, Float.POSITIVE_INFINITY, 3f, 1.5f, 2.25f, 1e6f}, d);
        // The shared reader agrees (it copies the channel into r, g and b).
        FrameBuffer back = Images.read(dir.resolve("out.depth.pfm"));
        assertEquals(2.25, back.get(1, 0, 0));
        assertEquals(Double.POSITIVE_INFINITY, back.get(1, 1, 2));
    }

    @Test
    void normalIsThreeChannelPfmWithZeroBackground() throws IOException {
        ImageWriter.write(new FrameBuffer(3, 2), dir.resolve("out.tga"), ImageOptions.DEFAULT, frame());
        float[] n = pfm(dir.resolve("out.normal.pfm"), "PF", 3, 2);
        assertArrayEquals(new float[] {0, 1, 0, 0, 0, 0, 0, -1, 0, 0, 0, -1, 0.6f, 0.8f, 0, -1, 0, 0}, n);
    }

    @Test
    void noiseIsThreeChannelPfmOfSamplesErrorAndZero() throws IOException {
        AovFrame f = new AovFrame(2, 2, EnumSet.of(Aov.NOISE));
        f.setNoise(0, 0, 64, 0.5);
        f.setNoise(1, 0, 80, 0.25);
        f.setNoise(0, 1, 256, 0.125);
        f.setNoise(1, 1, 4097, 0);
        ImageWriter.write(new FrameBuffer(2, 2), dir.resolve("out.png"), ImageOptions.DEFAULT, f);
        float[] n = pfm(dir.resolve("out.noise.pfm"), "PF", 2, 2);
        // Bottom row first.
        assertArrayEquals(new float[] {256, 0.125f, 0, 4097, 0, 0, 64, 0.5f, 0, 80, 0.25f, 0}, n);
    }

    @Test
    void objectIsIdPlusOneIn24BitRgbNeverSrgbEncoded() throws IOException {
        // sRGB requested for the main image: the ids must still be written as they are.
        ImageWriter.write(new FrameBuffer(3, 2), dir.resolve("out.jpg"), ImageOptions.DEFAULT.withSrgb(true), frame());
        BufferedImage img = ImageIO.read(dir.resolve("out.object.png").toFile());
        assertEquals(3, img.getWidth());
        assertEquals(2, img.getHeight());
        assertEquals(3, img.getColorModel().getNumComponents(), "RGB, no alpha");
        assertEquals(8, img.getColorModel().getComponentSize(0));
        int[][] expected = {{0x000001, 0x000002, 0x123456}, {0x0000FF, 0x000000, 0x000100}};
        for (int y = 0; y < 2; y++) {
            for (int x = 0; x < 3; x++) {
                assertEquals(expected[y][x], img.getRGB(x, y) & 0xFFFFFF, "pixel " + x + "," + y);
            }
        }
        // R is the high byte.
        assertEquals(0x12, (img.getRGB(2, 0) >>> 16) & 0xFF);
    }

    @Test
    void onlyTheRequestedPassesAreWritten() throws IOException {
        AovFrame f = new AovFrame(2, 2, EnumSet.of(Aov.NORMAL));
        assertThrows(IllegalStateException.class, () -> f.depth(0, 0));
        ImageWriter.write(new FrameBuffer(2, 2), dir.resolve("out.pfm"), ImageOptions.DEFAULT, f);
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(java.util.Set.of("out.pfm", "out.normal.pfm"),
                    files.map(p -> p.getFileName().toString()).collect(java.util.stream.Collectors.toSet()));
        }
    }

    @Test
    void anIdBeyond24BitsFailsBeforeAnyFileIsWritten() throws IOException {
        AovFrame f = new AovFrame(1, 1, EnumSet.allOf(Aov.class));
        f.setHit(0, 0, 1, 0, 0, 1, AovFrame.MAX_OBJECT_CODE); // id + 1 needs 25 bits
        Path out = dir.resolve("out.png");
        Files.writeString(out, "old");
        assertThrows(IllegalStateException.class, () -> ImageWriter.write(new FrameBuffer(1, 1), out, ImageOptions.DEFAULT, f));
        assertEquals("old", Files.readString(out));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(1, files.count(), "only the old image");
        }
    }

    @Test
    void aFailingPassLeavesNoNewFileAndKeepsTheOldOnes() throws IOException {
        Path out = dir.resolve("out.png");
        Files.writeString(out, "old image");
        Files.writeString(dir.resolve("out.depth.pfm"), "old depth");
        // The normal pass cannot be written: its name is taken by a directory.
        Files.createDirectory(dir.resolve("out.normal.pfm"));
        assertThrows(IOException.class, () -> ImageWriter.write(new FrameBuffer(3, 2), out, ImageOptions.DEFAULT, frame()));
        assertEquals("old image", Files.readString(out));
        assertEquals("old depth", Files.readString(dir.resolve("out.depth.pfm")));
        assertFalse(Files.exists(dir.resolve("out.object.png")));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(3, files.count(), "no temporary or backup file left");
        }
    }

    @Test
    void checkOutputsNamesTheBlockedPass() throws IOException {
        Files.createDirectory(dir.resolve("out.object.png"));
        IOException e = assertThrows(IOException.class,
                () -> ImageWriter.checkOutputs(dir.resolve("out.png"), EnumSet.of(Aov.DEPTH, Aov.OBJECT)));
        assertTrue(e.getMessage().contains("out.object.png") && e.getMessage().contains("is a directory"), e.getMessage());
        ImageWriter.checkOutputs(dir.resolve("out.png"), EnumSet.of(Aov.DEPTH, Aov.NORMAL));
    }

    @Test
    void frameStartsAsBackground() {
        AovFrame f = new AovFrame(2, 1, EnumSet.allOf(Aov.class));
        assertEquals(Double.POSITIVE_INFINITY, f.depth(1, 0));
        assertEquals(0, f.normal(1, 0, 2));
        assertEquals(-1, f.objectId(1, 0));
        assertArrayEquals(new int[] {0, 0}, f.objectCodes());
        assertThrows(IllegalArgumentException.class, () -> new AovFrame(2, 1, EnumSet.noneOf(Aov.class)));
        assertThrows(IndexOutOfBoundsException.class, () -> f.setBackground(2, 0));
    }
}
