package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

class ImageDiffTest {
    private static final int W = 5, H = 4;

    private static int[] image(long seed) {
        Random rnd = new Random(seed);
        int[] rgb = new int[W * H];
        // Keep channels away from 0 and 255 so that edits below cannot wrap.
        for (int i = 0; i < rgb.length; i++) {
            rgb[i] = (20 + rnd.nextInt(200)) << 16 | (20 + rnd.nextInt(200)) << 8 | (20 + rnd.nextInt(200));
        }
        return rgb;
    }

    @Test
    void identicalImagesHaveNoDifference() {
        int[] a = image(1);
        ImageDiff.Result r = ImageDiff.compare(W, H, a, a.clone(), 0);
        assertEquals(0, r.maxDifference());
        assertEquals(0, r.pixelsOver());
        assertEquals(0.0, r.rmse());
        assertEquals(0.0, r.fractionOver());
        assertTrue(r.withinThreshold());
        assertEquals(-1, r.firstOverX());
        assertEquals(-1, r.firstOverY());
        for (double v : r.diffImage().data()) assertEquals(0.0, v);
    }

    @Test
    void countsPixelsStrictlyOverTheThreshold() {
        int[] a = image(2), b = a.clone();
        b[1 * W + 2] += 5 << 16;      // (2, 1): red +5
        b[3 * W + 0] -= 3;            // (0, 3): blue -3
        b[3 * W + 4] += 2 << 8;       // (4, 3): green +2

        ImageDiff.Result r = ImageDiff.compare(W, H, a, b, 3);
        assertEquals(5, r.maxDifference());
        assertEquals(1, r.pixelsOver(), "a difference equal to the threshold is tolerated");
        assertEquals(1.0 / (W * H), r.fractionOver());
        assertEquals(Math.sqrt((25 + 9 + 4) / (3.0 * W * H)), r.rmse(), 1e-12);
        assertEquals(2, r.firstOverX());
        assertEquals(1, r.firstOverY());
        assertFalse(r.withinThreshold());
        assertEquals(Math.min(1, 5 * ImageDiff.DIFF_GAIN / 255), r.diffImage().get(2, 1, 0), 1e-15);
        assertEquals(0.0, r.diffImage().get(2, 1, 1));
        assertEquals(Math.min(1, 3 * ImageDiff.DIFF_GAIN / 255), r.diffImage().get(0, 3, 2), 1e-15);

        ImageDiff.Result strict = ImageDiff.compare(W, H, a, b, 0);
        assertEquals(3, strict.pixelsOver());
        assertEquals(2, strict.firstOverX());
        assertEquals(1, strict.firstOverY());
        assertTrue(strict.toString().contains("3 of 20 pixels"), strict.toString());
        assertTrue(ImageDiff.compare(W, H, a, b, 5).withinThreshold());
    }

    @Test
    void largeDifferencesSaturateTheDiffImage() {
        int[] a = {0x000000}, b = {0xFF8001};
        ImageDiff.Result r = ImageDiff.compare(1, 1, a, b, 10);
        assertEquals(255, r.maxDifference());
        assertEquals(1.0, r.diffImage().get(0, 0, 0));
        assertEquals(1.0, r.diffImage().get(0, 0, 1));
        assertEquals(ImageDiff.DIFF_GAIN / 255, r.diffImage().get(0, 0, 2), 1e-15);
    }

    @Test
    void frameBuffersAreComparedInTheirEightBitEncoding() {
        int[] a = image(3), b = image(4);
        FrameBuffer fa = FrameBuffer.fromRgb8(W, H, a, true), fb = FrameBuffer.fromRgb8(W, H, b, true);
        ImageDiff.Result packed = ImageDiff.compare(W, H, a, b, 7);
        ImageDiff.Result buffers = ImageDiff.compare(fa, fb, 7);
        assertEquals(packed.maxDifference(), buffers.maxDifference());
        assertEquals(packed.pixelsOver(), buffers.pixelsOver());
        assertEquals(packed.rmse(), buffers.rmse());
        // The same buffers read as linear 8-bit values differ by different amounts.
        ImageDiff.Result linear = ImageDiff.compare(fa, fb, 7, false);
        assertTrue(linear.rmse() != packed.rmse(), linear + " vs " + packed);
    }

    @Test
    void rejectsMismatchedInputs() {
        assertThrows(IllegalArgumentException.class,
                () -> ImageDiff.compare(new FrameBuffer(2, 2), new FrameBuffer(2, 3), 0));
        assertThrows(IllegalArgumentException.class, () -> ImageDiff.compare(2, 2, new int[4], new int[3], 0));
        assertThrows(IllegalArgumentException.class, () -> ImageDiff.compare(2, 2, new int[4], new int[4], -1));
        assertThrows(IllegalArgumentException.class, () -> ImageDiff.compare(2, 2, new int[4], new int[4], 256));
    }
}
