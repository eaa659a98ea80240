package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.awt.image.WritableRaster;
import java.nio.file.Path;
import java.util.Random;
import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;

/**
 * Texels of 8-bit images are kept as bytes and 16-bit greyscale as chars: every sample must be
 * exactly what the image stored as floats (the storage before) gives, for every filter and wrap
 * mode, and the mip chain, now built a row at a time, exactly what building it through a whole
 * intermediate image gave. Also: repeat and mirror keep tiling exactly at any coordinate, and the
 * heap is asked for an image before it is decoded.
 */
class TextureStorageTest {
    @TempDir Path dir;

    /** Odd sizes, so the mip chain has fractional box weights and a level of width 1. */
    private static final int W = 13, H = 7;

    private static int[] randomRgb(int n, long seed, boolean grey) {
        Random r = new Random(seed);
        int[] p = new int[n];
        for (int i = 0; i < n; i++) {
            int g = r.nextInt(256);
            p[i] = grey ? g << 16 | g << 8 | g : r.nextInt(1 << 24);
        }
        return p;
    }

    /** The image as it was stored before: three floats per texel, each the float of its byte. */
    private static TextureImage floats(int w, int h, int[] rgb, boolean srgb) {
        float[] f = new float[3 * rgb.length];
        for (int i = 0; i < rgb.length; i++) {
            for (int c = 0; c < 3; c++) {
                int b = rgb[i] >> (16 - 8 * c) & 0xFF;
                f[3 * i + c] = (float) (srgb ? TextureCache.srgbToLinear(b / 255.0) : b / 255.0);
            }
        }
        return TextureImage.wrap(w, h, f);
    }

    private static void assertSamplesEqual(TextureImage expected, TextureImage actual) {
        Random r = new Random(7);
        double[] a = new double[3], b = new double[3];
        TexturePoint p = new TexturePoint();
        for (Filter f : Filter.values()) {
            for (Wrap wr : Wrap.values()) {
                ImageTexture te = new ImageTexture(expected, f, wr), ta = new ImageTexture(actual, f, wr);
                for (int k = 0; k < 3000; k++) {
                    double u = r.nextDouble() * 6 - 3, v = r.nextDouble() * 6 - 3;
                    double footprint = k % 3 == 0 ? 0 : r.nextDouble() * 0.6;
                    te.evaluate(p.uv(u, v, footprint), a);
                    ta.evaluate(p.uv(u, v, footprint), b);
                    assertArrayEquals(a, b, 0, f + " " + wr + " at " + u + ", " + v + ", " + footprint);
                }
            }
        }
        assertEquals(expected.levelCount(), actual.levelCount());
        for (int l = 0; l < expected.levelCount(); l++) {
            for (int y = 0; y < expected.height(l); y++) {
                for (int x = 0; x < expected.width(l); x++) {
                    for (int c = 0; c < 3; c++) assertEquals(expected.texel(l, x, y, c), actual.texel(l, x, y, c), 0, "level " + l);
                }
            }
        }
    }

    @Test
    void colourBytesSampleAsTheFloatsDid() {
        int[] rgb = randomRgb(W * H, 1, false);
        TextureImage bytes = TextureCache.fromRgb8(W, H, rgb, true);
        assertNotNull(bytes.baseBytes());
        assertEquals(3, bytes.channels());
        assertSamplesEqual(floats(W, H, rgb, true), bytes);
    }

    @Test
    void greyBytesKeepOneByteATexelAndSampleAsTheFloatsDid() {
        int[] rgb = randomRgb(W * H, 2, true);
        TextureImage bytes = TextureCache.fromRgb8(W, H, rgb, false);
        assertEquals(1, bytes.channels());
        assertEquals(W * H, bytes.baseBytes().length);
        assertSamplesEqual(floats(W, H, rgb, false), bytes);
    }

    @Test
    void imageFilesLoadAsBytesOrCharsWithTheSameValues() throws Exception {
        // 8-bit colour PNG: bytes with the sRGB table.
        int[] rgb = randomRgb(W * H, 3, false);
        BufferedImage colour = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        colour.setRGB(0, 0, W, H, rgb, 0, W);
        Path c = dir.resolve("c.png");
        ImageIO.write(colour, "png", c.toFile());
        TextureImage ci = new TextureCache().load(c);
        assertNotNull(ci.baseBytes());
        assertSamplesEqual(floats(W, H, rgb, true), ci);

        // 16-bit greyscale PNG: one char a texel, value / 65535 as before.
        BufferedImage g16 = new BufferedImage(W, H, BufferedImage.TYPE_USHORT_GRAY);
        WritableRaster raster = g16.getRaster();
        Random r = new Random(4);
        float[] f = new float[3 * W * H];
        for (int y = 0, q = 0; y < H; y++) {
            for (int x = 0; x < W; x++, q += 3) {
                int s = r.nextInt(65536);
                raster.setSample(x, y, 0, s);
                f[q] = f[q + 1] = f[q + 2] = (float) (s / 65535.0);
            }
        }
        Path g = dir.resolve("g16.png");
        ImageIO.write(g16, "png", g.toFile());
        TextureImage gi = new TextureCache().load(g);
        assertNotNull(gi.baseChars());
        assertSamplesEqual(TextureImage.wrap(W, H, f), gi);
    }

    @Test
    void oneBitImagesLoadAsZeroAndOne() throws Exception {
        BufferedImage bits = new BufferedImage(W, H, BufferedImage.TYPE_BYTE_BINARY);
        for (int y = 0; y < H; y++) for (int x = 0; x < W; x++) bits.getRaster().setSample(x, y, 0, (x * 3 + y) % 2);
        Path b = dir.resolve("bits.png");
        ImageIO.write(bits, "png", b.toFile());
        TextureImage img = new TextureCache().load(b);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) for (int c = 0; c < 3; c++) assertEquals((x * 3 + y) % 2, img.texel(0, x, y, c), 0);
        }
    }

    /** The mip chain as it was built before: every row halved into a whole intermediate image, then the columns. */
    @Test
    void mipChainIsTheOneBuiltThroughAWholeIntermediateImage() {
        int w = 37, h = 11;
        double[] lin = new double[3 * w * h];
        Random r = new Random(5);
        for (int i = 0; i < lin.length; i++) lin[i] = r.nextDouble() * 2;
        TextureImage img = TextureImage.fromLinear(w, h, lin);
        float[] prev = new float[lin.length];
        for (int i = 0; i < lin.length; i++) prev[i] = (float) lin[i];
        for (int k = 1; k < img.levelCount(); k++) {
            int sw = img.width(k - 1), sh = img.height(k - 1), dw = img.width(k), dh = img.height(k);
            float[] tmp = new float[dw * sh * 3];
            for (int row = 0; row < sh; row++) oldDownsample(prev, row * sw * 3, 3, sw, tmp, row * dw * 3, 3, dw);
            float[] dst = new float[dw * dh * 3];
            for (int x = 0; x < dw; x++) oldDownsample(tmp, x * 3, dw * 3, sh, dst, x * 3, dw * 3, dh);
            for (int y = 0; y < dh; y++) {
                for (int x = 0; x < dw; x++) {
                    for (int c = 0; c < 3; c++) assertEquals(dst[(y * dw + x) * 3 + c], img.texel(k, x, y, c), 0, "level " + k);
                }
            }
            prev = dst;
        }
    }

    /** TextureImage's box filter as it was (a copy, so the comparison does not test the code against itself). */
    private static void oldDownsample(float[] src, int so, int ss, int sn, float[] dst, int d0, int ds, int dn) {
        if (sn == dn) {
            for (int i = 0; i < dn; i++) for (int c = 0; c < 3; c++) dst[d0 + i * ds + c] = src[so + i * ss + c];
            return;
        }
        double ratio = (double) sn / dn, inv = 1 / ratio;
        for (int i = 0; i < dn; i++) {
            double a = i * ratio, b = (i + 1) * ratio;
            double rr = 0, g = 0, bl = 0;
            for (int s = (int) Math.floor(a); s < b && s < sn; s++) {
                double wgt = Math.min(b, s + 1) - Math.max(a, s);
                if (wgt <= 0) continue;
                int p = so + s * ss;
                rr += wgt * src[p];
                g += wgt * src[p + 1];
                bl += wgt * src[p + 2];
            }
            int q = d0 + i * ds;
            dst[q] = (float) (rr * inv);
            dst[q + 1] = (float) (g * inv);
            dst[q + 2] = (float) (bl * inv);
        }
    }

    @Test
    void repeatAndMirrorTileExactlyFarOut() {
        TextureImage img = TextureCache.fromRgb8(W, H, randomRgb(W * H, 6, false), true);
        double[] near = new double[3], far = new double[3];
        TexturePoint p = new TexturePoint();
        double[] fractions = {0, 0.03125, 0.25, 0.5, 0.71875, 0.96875};
        double[] periods = {0x1p30, 0x1p30 + 2, 0x1p31, 0x1p31 + 6, 0x1p40, 0x1p53, 0x1p60, -0x1p31, -0x1p53};
        for (Filter f : Filter.values()) {
            for (double period : periods) {
                for (double fr : fractions) {
                    ImageTexture rep = new ImageTexture(img, f, Wrap.REPEAT);
                    // u = period + fr is exact for these (fr has few bits), as long as it fits 53 bits.
                    double u = period + fr;
                    if (u - period != fr) continue;
                    rep.evaluate(p.uv(fr, 0.375, 0.01), near);
                    rep.evaluate(p.uv(u, 0.375, 0.01), far);
                    assertArrayEquals(near, far, 0, "repeat " + f + " u = " + u);
                    rep.evaluate(p.uv(0.375, u, 0.01), far);
                    rep.evaluate(p.uv(0.375, fr, 0.01), near);
                    assertArrayEquals(near, far, 0, "repeat " + f + " v = " + u);

                    // Mirror: period 2; an even offset is the image itself, an odd one its mirror.
                    ImageTexture mir = new ImageTexture(img, f, Wrap.MIRROR);
                    mir.evaluate(p.uv(fr, 0.375, 0.01), near);
                    mir.evaluate(p.uv(u, 0.375, 0.01), far);
                    assertArrayEquals(near, far, 0, "mirror " + f + " u = " + u);
                    if ((u + 1) - u == 1) {
                        mir.evaluate(p.uv(1 + fr, 0.375, 0.01), near);
                        mir.evaluate(p.uv(u + 1, 0.375, 0.01), far);
                        assertArrayEquals(near, far, 0, "mirror " + f + " u = " + (u + 1));
                    }
                }
            }
        }
        // Any finite coordinate samples something finite; the largest are whole periods.
        ImageTexture rep = new ImageTexture(img, Filter.BILINEAR, Wrap.REPEAT);
        rep.evaluate(p.uv(0, 0.375, 0), near);
        rep.evaluate(p.uv(Double.MAX_VALUE, 0.375, 0), far);
        assertArrayEquals(near, far, 0);
        rep.evaluate(p.uv(-Double.MAX_VALUE, 0.375, 0), far);
        assertArrayEquals(near, far, 0);
        // Clamp far out is the edge texel.
        ImageTexture clamp = new ImageTexture(img, Filter.NEAREST, Wrap.CLAMP);
        clamp.evaluate(p.uv(0x1p53, 0.375, 0), far);
        clamp.evaluate(p.uv(0.999, 0.375, 0), near);
        assertArrayEquals(near, far, 0);
    }

    @Test
    void nearestPicksTheTexelTheModuloSaysAt2To31() {
        // A 4-wide ramp: u * 4 at u = 2^31 + (i + 0.5) / 4 is texel i of the period (exact up to 2^48).
        double[] lin = new double[3 * 4];
        for (int i = 0; i < 4; i++) lin[3 * i] = lin[3 * i + 1] = lin[3 * i + 2] = i;
        TextureImage img = TextureImage.fromLinear(4, 1, lin);
        ImageTexture t = new ImageTexture(img, Filter.NEAREST, Wrap.REPEAT);
        double[] rgb = new double[3];
        for (int i = 0; i < 4; i++) {
            for (double base : new double[] {0x1p30, 0x1p31, 0x1p32, 0x1p48}) {
                t.evaluate(new TexturePoint().uv(base + (i + 0.5) / 4, 0.5, 0), rgb);
                assertEquals(i, rgb[0], 0, "u = " + base + " + " + (i + 0.5) / 4);
            }
        }
    }

    @Test
    void theMipChainAsksTheHeapBeforeItIsBuilt() {
        TextureImage img = TextureImage.fromLinear(4, 4, new double[3 * 16]);
        try (HeapBudget.Scope s = HeapBudget.cap(0)) {
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> new ImageTexture(img, Filter.TRILINEAR, Wrap.REPEAT));
            assertEquals((4 + 1) * 12, e.needed(), "levels 2x2 and 1x1, three floats a texel");
            assertTrue(e.getMessage().startsWith("the mip chain of the 4x4 texture needs 60 bytes of heap, but only 0 bytes is free"), e.getMessage());
            new ImageTexture(img, Filter.BILINEAR, Wrap.REPEAT); // no chain, nothing asked
        }
        assertEquals(3, new ImageTexture(img, Filter.TRILINEAR, Wrap.REPEAT).image().levelCount());
    }

    @Test
    void anImageIsRefusedBeforeDecodingWhenTheHeapCannotHoldIt() throws Exception {
        // The figure counted for an 8192 x 8192 true-colour TGA: 4 bytes a pixel for the decoder,
        // 3 for the texels, and the mip chain.
        long mip = TextureImage.mipBytes(8192, 8192);
        assertTrue(mip < 4L * 8192 * 8192 && mip > 3.99 * 8192 * 8192, "a third of the texels, 12 bytes each: " + mip);
        try (HeapBudget.Scope s = HeapBudget.cap(64L << 20)) {
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class,
                    () -> TextureCache.checkHeap(8192, 8192, 4L * 8192 * 8192, 3));
            assertEquals(7L * 8192 * 8192 + mip, e.needed());
            assertTrue(e.getMessage().startsWith("the 8192x8192 image needs 704 MiB of heap, but only 64 MiB is free"), e.getMessage());
        }
    }
}
