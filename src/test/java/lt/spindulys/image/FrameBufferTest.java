package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class FrameBufferTest {

    /** The sRGB OETF written out independently of the production code. */
    private static double oetf(double v) {
        return v <= 0.0031308 ? 12.92 * v : 1.055 * Math.pow(v, 1 / 2.4) - 0.055;
    }

    private static int encode8(double linear) {
        FrameBuffer fb = new FrameBuffer(1, 1);
        fb.set(0, 0, linear, 0, 0);
        return fb.toRgb8(true)[0] >>> 16;
    }

    @Test
    void storesRowMajorTopRowFirstThreeValuesPerPixel() {
        FrameBuffer fb = new FrameBuffer(4, 3);
        fb.set(2, 1, 0.25, -1.5, 7.0);
        int i = 3 * (1 * 4 + 2);
        double[] d = fb.data();
        assertEquals(36, d.length);
        assertEquals(0.25, d[i]);
        assertEquals(-1.5, d[i + 1]);
        assertEquals(7.0, d[i + 2]);
        assertEquals(-1.5, fb.get(2, 1, 1));
        assertSame(d, fb.data(), "data() is the backing array, not a copy");
        d[0] = 3;
        assertEquals(3, fb.get(0, 0, 0));
    }

    @Test
    void rejectsBadSizesAndCoordinates() {
        assertThrows(IllegalArgumentException.class, () -> new FrameBuffer(0, 5));
        assertThrows(IllegalArgumentException.class, () -> new FrameBuffer(5, -1));
        assertThrows(IllegalArgumentException.class, () -> new FrameBuffer(100_000, 100_000));
        FrameBuffer fb = new FrameBuffer(4, 3);
        // x = width must not silently wrap into the next row.
        assertThrows(IndexOutOfBoundsException.class, () -> fb.set(4, 0, 0, 0, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> fb.get(0, 3, 0));
        assertThrows(IndexOutOfBoundsException.class, () -> fb.get(0, 0, 3));
        assertThrows(IndexOutOfBoundsException.class, () -> fb.get(-1, 0, 0));
    }

    @Test
    void linearConversionClampsAndRoundsToNearest() {
        FrameBuffer fb = new FrameBuffer(6, 1);
        fb.set(0, 0, 1, 0, 0);
        fb.set(1, 0, 0.5, 0.25, 1.0 / 255);
        fb.set(2, 0, -0.5, 2.0, Double.POSITIVE_INFINITY);
        fb.set(3, 0, Double.NaN, Double.NEGATIVE_INFINITY, 0.4999 / 255);
        fb.set(4, 0, 0.5001 / 255, 254.6 / 255, 254.49 / 255);
        fb.set(5, 0, 0, 1e-300, 1 - 1e-12);
        int[] rgb = fb.toRgb8(false);
        assertEquals(0xFF0000, rgb[0]);
        // 0.5 * 255 = 127.5 rounds up; 0.25 * 255 = 63.75 -> 64.
        assertEquals(128 << 16 | 64 << 8 | 1, rgb[1]);
        assertEquals(0x00FFFF, rgb[2]);
        assertEquals(0x000000, rgb[3], "NaN and negative values become 0");
        assertEquals(1 << 16 | 255 << 8 | 254, rgb[4]);
        assertEquals(0x0000FF, rgb[5]);
    }

    @Test
    void srgbEncodingFollowsTheStandardFormula() {
        for (double v : new double[] {0.5, 0.18, 0.001, 0.0031308, 0.0031309, 0.04, 0.2140, 0.9, 0.99}) {
            assertEquals((int) Math.round(255 * oetf(v)), encode8(v), "linear " + v);
        }
        assertEquals(188, encode8(0.5), "mid grey: 255 * (1.055 * 0.5^(1/2.4) - 0.055) = 187.52");
        assertEquals(0, encode8(0));
        assertEquals(255, encode8(1));
    }

    @Test
    void srgbThresholdSelectsTheLinearSegmentInclusively() {
        assertEquals(12.92 * 0.0031308, FrameBuffer.linearToSrgb(0.0031308));
        assertEquals(1.055 * Math.pow(0.0031309, 1 / 2.4) - 0.055, FrameBuffer.linearToSrgb(0.0031309));
        // The two segments meet, up to the ~1e-6 step left by the rounding of the published constants.
        assertEquals(FrameBuffer.linearToSrgb(0.0031308), FrameBuffer.linearToSrgb(0.0031309), 1e-5);
        assertEquals(0.04045 / 12.92, FrameBuffer.srgbToLinear(0.04045));
        assertEquals(Math.pow((0.5 + 0.055) / 1.055, 2.4), FrameBuffer.srgbToLinear(0.5));
        for (int k = 0; k <= 1000; k++) {
            double v = k / 1000.0;
            assertEquals(v, FrameBuffer.srgbToLinear(FrameBuffer.linearToSrgb(v)), 1e-12);
        }
    }

    @Test
    void fromRgb8IsTheExactInverseForAllLevels() {
        int[] packed = new int[256];
        for (int k = 0; k < 256; k++) packed[k] = k << 16 | (255 - k) << 8 | (k * 7 & 0xFF);
        for (boolean srgb : new boolean[] {true, false}) {
            FrameBuffer fb = FrameBuffer.fromRgb8(16, 16, packed, srgb);
            assertArrayEquals(packed, fb.toRgb8(srgb), "srgb=" + srgb);
        }
        FrameBuffer lin = FrameBuffer.fromRgb8(16, 16, packed, false);
        assertEquals(3 / 255.0, lin.get(3, 0, 0));
        FrameBuffer dec = FrameBuffer.fromRgb8(16, 16, packed, true);
        assertEquals(Math.pow((188 / 255.0 + 0.055) / 1.055, 2.4), dec.get(188 % 16, 188 / 16, 0), 1e-15);
        assertEquals(10 / 255.0 / 12.92, dec.get(10, 0, 0), 1e-15);
    }

    @Test
    void fromRgb8IgnoresTheTopByteAndChecksTheLength() {
        FrameBuffer fb = FrameBuffer.fromRgb8(1, 1, new int[] {0xFF102030}, false);
        assertEquals(0x102030, fb.toRgb8(false)[0]);
        assertThrows(IllegalArgumentException.class, () -> FrameBuffer.fromRgb8(2, 2, new int[3], true));
    }
}
