package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.awt.image.IndexColorModel;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.CRC32;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class TextureCacheTest {
    @TempDir
    Path dir;

    /** The exact sRGB decoding, written out independently of the code under test. */
    private static double srgb(int b) {
        double c = b / 255.0;
        return c <= 0.04045 ? c / 12.92 : Math.pow((c + 0.055) / 1.055, 2.4);
    }

    private static int rgbAt(int x, int y) {
        return (x * 60 + y * 5) << 16 | (255 - x * 40) << 8 | (y * 80 + 3);
    }

    private Path writeImageIo(String name, String format, int type) throws IOException {
        BufferedImage img;
        if (format.equals("gif")) {
            // GIF is palette-based: give it exactly the twelve colours used, so it is lossless.
            byte[] r = new byte[12], g = new byte[12], b = new byte[12];
            for (int i = 0; i < 12; i++) {
                int p = rgbAt(i % 4, i / 4);
                r[i] = (byte) (p >> 16);
                g[i] = (byte) (p >> 8);
                b[i] = (byte) p;
            }
            img = new BufferedImage(4, 3, BufferedImage.TYPE_BYTE_INDEXED, new IndexColorModel(8, 12, r, g, b));
        } else {
            img = new BufferedImage(4, 3, type);
        }
        for (int y = 0; y < 3; y++) for (int x = 0; x < 4; x++) img.setRGB(x, y, rgbAt(x, y));
        Path p = dir.resolve(name);
        assertTrue(ImageIO.write(img, format, p.toFile()), format);
        return p;
    }

    @Test
    void pngColourIsDecodedFromSrgbExactly() throws IOException {
        TextureImage t = new TextureCache().load(writeImageIo("c.png", "png", BufferedImage.TYPE_INT_RGB));
        assertEquals(4, t.width());
        assertEquals(3, t.height());
        for (int y = 0; y < 3; y++) {
            for (int x = 0; x < 4; x++) {
                int p = rgbAt(x, y);
                assertEquals(srgb(p >> 16 & 0xFF), t.texel(0, x, y, 0), 1e-7);
                assertEquals(srgb(p >> 8 & 0xFF), t.texel(0, x, y, 1), 1e-7);
                assertEquals(srgb(p & 0xFF), t.texel(0, x, y, 2), 1e-7);
            }
        }
        // The formula's two pieces: a dark value on the linear segment, a bright one on the curve.
        assertEquals(10 / 255.0 / 12.92, TextureCache.srgbToLinear(10 / 255.0), 1e-15);
        assertEquals(Math.pow((0.5 + 0.055) / 1.055, 2.4), TextureCache.srgbToLinear(0.5), 1e-15);
    }

    @Test
    void bmpAndGifLoadLosslessly() throws IOException {
        for (String f : new String[] {"bmp", "gif"}) {
            TextureImage t = new TextureCache().load(writeImageIo("c." + f, f, BufferedImage.TYPE_INT_RGB));
            assertEquals(4, t.width(), f);
            // Row 0 only: the JDK's GIF writer interlaces, and its round trip of a 3-row
            // interlaced image misplaces the later rows (not this code's concern).
            for (int x = 0; x < 4; x++) {
                int p = rgbAt(x, 0);
                assertEquals(srgb(p >> 16 & 0xFF), t.texel(0, x, 0, 0), 1e-7, f);
                assertEquals(srgb(p >> 8 & 0xFF), t.texel(0, x, 0, 1), 1e-7, f);
                assertEquals(srgb(p & 0xFF), t.texel(0, x, 0, 2), 1e-7, f);
            }
        }
        TextureImage j = new TextureCache().load(writeImageIo("c.jpg", "jpeg", BufferedImage.TYPE_INT_RGB));
        assertEquals(3, j.height());
    }

    @Test
    void greyPngIsLinearData() throws IOException {
        BufferedImage img = new BufferedImage(2, 1, BufferedImage.TYPE_BYTE_GRAY);
        img.getRaster().setSample(0, 0, 0, 51);
        img.getRaster().setSample(1, 0, 0, 204);
        Path p = dir.resolve("g.png");
        ImageIO.write(img, "png", p.toFile());
        TextureImage t = new TextureCache().load(p);
        assertEquals(0.2, t.texel(0, 0, 0, 0), 1e-7);
        assertEquals(0.8, t.texel(0, 1, 0, 2), 1e-7);
    }

    @Test
    void tgaFilesGoThroughTheOwnReaderWithVZeroAtTheBottom() throws IOException {
        int[] img = TgaReaderTest.colourImage();
        int w = TgaReaderTest.W, h = TgaReaderTest.H;
        Path p = dir.resolve("c.TGA");
        Files.write(p, TgaTestWriter.encode(w, h, img, 10, 24, false, false, ""));
        TextureImage t = new TextureCache().load(p);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) assertEquals(srgb(img[y * w + x] >> 8 & 0xFF), t.texel(0, x, y, 1), 1e-7);
        }
        // The bottom row of the picture (last row, top-down) is at v = 0.
        double[] rgb = new double[3];
        new ImageTexture(t, Filter.NEAREST, Wrap.CLAMP).evaluate(new TexturePoint().uv(4.5 / w, 0.01, 0), rgb);
        assertEquals(srgb(img[(h - 1) * w + 4] & 0xFF), rgb[2], 1e-7);
        // Greyscale TGA: linear.
        Path g = dir.resolve("g.tga");
        Files.write(g, TgaTestWriter.encode(w, h, TgaReaderTest.greyImage(), 3, 8, true, false, ""));
        TextureImage gt = new TextureCache().load(g);
        assertEquals((TgaReaderTest.greyImage()[5] & 0xFF) / 255.0, gt.texel(0, 5, 0, 0), 1e-7);
    }

    @Test
    void samePathIsLoadedOnceAndShared() throws IOException {
        Path a = writeImageIo("a.png", "png", BufferedImage.TYPE_INT_RGB);
        Files.createDirectories(dir.resolve("sub"));
        TextureCache cache = new TextureCache();
        TextureImage first = cache.load(a);
        assertSame(first, cache.load(dir.resolve("./a.png")));
        assertSame(first, cache.load(dir.resolve("sub/../a.png")));
        assertEquals(1, cache.size());
        TextureImage other = cache.load(writeImageIo("b.png", "png", BufferedImage.TYPE_INT_RGB));
        assertNotSame(first, other);
        assertEquals(2, cache.size());
        // Another cache (another scene) loads its own copy.
        assertNotSame(first, new TextureCache().load(a));
    }

    private static IOException loadFails(Path p) {
        IOException e = assertThrows(IOException.class, () -> new TextureCache().load(p));
        assertTrue(e.getMessage().startsWith(p.toString() + ": "), e.getMessage());
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
        return e;
    }

    @Test
    void tooLargeImagesAreRefusedWithFileAndSize() throws IOException {
        Path tga = dir.resolve("huge.tga");
        byte[] b = TgaTestWriter.encode(1, 1, new int[1], 2, 24, true, false, "");
        b[12] = (byte) 0x00;
        b[13] = (byte) 0x40;  // 16384
        b[14] = (byte) 0x01;
        b[15] = (byte) 0x10;  // 4097
        Files.write(tga, b);
        String m = loadFails(tga).getMessage();
        assertTrue(m.contains("16384x4097") && m.contains(String.valueOf(TextureCache.MAX_PIXELS)), m);

        // A PNG whose header claims 10000 x 10000 (no pixel data at all: refused from the header).
        Path png = dir.resolve("huge.png");
        Files.write(png, pngHeaderOnly(10000, 10000));
        m = loadFails(png).getMessage();
        assertTrue(m.contains("10000x10000") && m.contains("limit"), m);
    }

    /** A PNG signature, an IHDR chunk (8-bit RGB) and IEND, with valid CRCs. */
    private static byte[] pngHeaderOnly(int w, int h) {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        out.writeBytes(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
        ByteBuffer ihdr = ByteBuffer.allocate(13).putInt(w).putInt(h).put((byte) 8).put((byte) 2).put((byte) 0).put((byte) 0).put((byte) 0);
        chunk(out, "IHDR", ihdr.array());
        chunk(out, "IEND", new byte[0]);
        return out.toByteArray();
    }

    private static void chunk(ByteArrayOutputStream out, String type, byte[] data) {
        out.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        out.writeBytes(t);
        out.writeBytes(data);
        out.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }

    @Test
    void missingUnknownAndCorruptFilesGiveClearMessages() throws IOException {
        assertTrue(loadFails(dir.resolve("nope.png")).getMessage().endsWith("file not found"));
        assertTrue(loadFails(dir).getMessage().contains("directory"));

        Path text = dir.resolve("notes.png");
        Files.writeString(text, "this is not an image\n");
        assertTrue(loadFails(text).getMessage().contains("no decoder recognises"));

        // A real PNG cut in half: the header decodes, the pixels do not.
        Path good = writeImageIo("good.png", "png", BufferedImage.TYPE_INT_RGB);
        byte[] b = Files.readAllBytes(good);
        Path cut = dir.resolve("cut.png");
        Files.write(cut, java.util.Arrays.copyOf(b, 40));
        assertTrue(loadFails(cut).getMessage().contains("corrupt PNG image"));

        Path tga = dir.resolve("cut.tga");
        byte[] t = TgaTestWriter.encode(4, 4, new int[16], 2, 32, true, false, "");
        Files.write(tga, java.util.Arrays.copyOf(t, 30));
        assertTrue(loadFails(tga).getMessage().contains("truncated TGA"));
    }
}
