package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Reading files written by other programs' conventions, which our own writer never produces. */
class ImagesTest {
    @TempDir Path dir;

    /** A 2x2 test pattern: top row red, green; bottom row blue, white-ish. */
    private static final int[] PATTERN = {0xFF0000, 0x00FF00, 0x0000FF, 0x102030};

    private static byte[] tga(int depth, int descriptor, int idLength, int[] storedOrder) {
        int bpp = depth / 8;
        byte[] b = new byte[18 + idLength + 4 * bpp];
        b[0] = (byte) idLength;
        b[2] = 2;
        b[12] = 2;
        b[14] = 2;
        b[16] = (byte) depth;
        b[17] = (byte) descriptor;
        int p = 18 + idLength;
        for (int v : storedOrder) {
            b[p] = (byte) v;
            b[p + 1] = (byte) (v >>> 8);
            b[p + 2] = (byte) (v >>> 16);
            if (bpp == 4) b[p + 3] = (byte) 0x80;   // alpha, to be ignored
            p += bpp;
        }
        return b;
    }

    private int[] readTga(byte[] bytes) throws IOException {
        Path f = Files.write(dir.resolve("t.tga"), bytes);
        return Images.read(f, false).toRgb8(false);
    }

    @Test
    void tgaBottomUp24Bit() throws IOException {
        // Bottom-left origin (descriptor 0): the bottom row is stored first.
        int[] stored = {PATTERN[2], PATTERN[3], PATTERN[0], PATTERN[1]};
        assertArrayEquals(PATTERN, readTga(tga(24, 0, 0, stored)));
    }

    @Test
    void tgaTopDown32BitWithImageIdAndAlpha() throws IOException {
        assertArrayEquals(PATTERN, readTga(tga(32, 0x28, 5, PATTERN)));
    }

    @Test
    void tgaRightToLeft() throws IOException {
        int[] stored = {PATTERN[1], PATTERN[0], PATTERN[3], PATTERN[2]};
        assertArrayEquals(PATTERN, readTga(tga(24, 0x30, 0, stored)));
    }

    @Test
    void tgaUnsupportedOrBrokenFilesAreReported() throws IOException {
        byte[] mapped = tga(24, 0, 0, PATTERN);
        mapped[2] = 1;  // colour-mapped: not read
        IOException e = assertThrows(IOException.class, () -> readTga(mapped));
        assertTrue(e.getMessage().contains("image type 1 "), e.getMessage());
        byte[] sixteen = tga(24, 0, 0, PATTERN);
        sixteen[16] = 16;
        e = assertThrows(IOException.class, () -> readTga(sixteen));
        assertTrue(e.getMessage().contains("16 bits per pixel"), e.getMessage());
        byte[] full = tga(24, 0, 0, PATTERN);
        byte[] cut = java.util.Arrays.copyOf(full, full.length - 1);
        e = assertThrows(IOException.class, () -> readTga(cut));
        assertTrue(e.getMessage().contains("truncated"), e.getMessage());
    }

    private static byte[] pfm(String header, ByteOrder order, float... values) {
        byte[] h = header.getBytes(StandardCharsets.US_ASCII);
        ByteBuffer buf = ByteBuffer.allocate(h.length + 4 * values.length).order(order);
        buf.put(h);
        for (float v : values) buf.putFloat(v);
        return buf.array();
    }

    @Test
    void pfmGreyBigEndian() throws IOException {
        // Positive scale means big-endian; bottom row (y = 1) first. Extra header whitespace is allowed.
        Path f = Files.write(dir.resolve("g.pfm"), pfm("Pf\n2  2\n1.0\n", ByteOrder.BIG_ENDIAN, 1, 2, 3, -4));
        FrameBuffer fb = Images.read(f);
        for (int c = 0; c < 3; c++) {
            assertEquals(1, fb.get(0, 1, c));
            assertEquals(2, fb.get(1, 1, c));
            assertEquals(3, fb.get(0, 0, c));
            assertEquals(-4, fb.get(1, 0, c));
        }
    }

    @Test
    void pfmColourLittleEndianIgnoresTheScaleMagnitude() throws IOException {
        Path f = Files.write(dir.resolve("c.pfm"), pfm("PF\n1 1\n-4.0\n", ByteOrder.LITTLE_ENDIAN, 0.25f, 8, -1));
        FrameBuffer fb = Images.read(f);
        assertEquals(0.25, fb.get(0, 0, 0));
        assertEquals(8, fb.get(0, 0, 1));
        assertEquals(-1, fb.get(0, 0, 2));
    }

    @Test
    void pfmBrokenFilesAreReported() throws IOException {
        Path f = Files.write(dir.resolve("t.pfm"), pfm("PF\n2 2\n-1.0\n", ByteOrder.LITTLE_ENDIAN, 1, 2, 3));
        IOException e = assertThrows(IOException.class, () -> Images.read(f));
        assertTrue(e.getMessage().contains("truncated"), e.getMessage());
        Files.write(f, pfm("P6\n2 2\n255\n", ByteOrder.LITTLE_ENDIAN));
        e = assertThrows(IOException.class, () -> Images.read(f));
        assertTrue(e.getMessage().contains("magic 'P6'"), e.getMessage());
        Files.write(f, pfm("PF\n2 x\n-1\n", ByteOrder.LITTLE_ENDIAN, new float[12]));
        e = assertThrows(IOException.class, () -> Images.read(f));
        assertTrue(e.getMessage().contains("height 'x'"), e.getMessage());
    }

    @Test
    void greyPngIsReadFromItsStoredSamples() throws IOException {
        BufferedImage img = new BufferedImage(3, 1, BufferedImage.TYPE_BYTE_GRAY);
        img.getRaster().setSample(0, 0, 0, 0);
        img.getRaster().setSample(1, 0, 0, 100);
        img.getRaster().setSample(2, 0, 0, 255);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        assertTrue(ImageIO.write(img, "png", bytes));
        Path f = Files.write(dir.resolve("grey.png"), bytes.toByteArray());
        assertArrayEquals(new int[] {0, 0x646464, 0xFFFFFF}, Images.read(f).toRgb8(true));
    }

    @Test
    void unreadableInputsAreReported() throws IOException {
        IllegalArgumentException u = assertThrows(IllegalArgumentException.class, () -> Images.read(dir.resolve("a.gif")));
        assertEquals("unsupported input format '.gif' (expected .tga, .png, .jpg, .jpeg or .pfm)", u.getMessage());
        Path junk = Files.writeString(dir.resolve("junk.png"), "not an image at all");
        IOException e = assertThrows(IOException.class, () -> Images.read(junk));
        assertTrue(e.getMessage().contains("junk.png"), e.getMessage());
        assertThrows(IOException.class, () -> Images.read(dir.resolve("missing.png")));
    }
}
