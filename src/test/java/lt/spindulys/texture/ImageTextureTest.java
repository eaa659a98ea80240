package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class ImageTextureTest {
    // 2x2 image; the channel-0 values are powers of two so every mix is exact in binary.
    // Rows are given top-down: top row T0 T1, bottom row B0 B1 (v = 0 is the bottom).
    static final double B0 = 1, B1 = 2, T0 = 4, T1 = 8;

    static TextureImage twoByTwo() {
        // Channel 1 = 10x channel 0 and channel 2 = -channel 0, so channels cannot be mixed up.
        double[] top = {T0, T1}, bottom = {B0, B1};
        double[] rgb = new double[12];
        for (int i = 0; i < 2; i++) {
            put(rgb, i, top[i]);
            put(rgb, 2 + i, bottom[i]);
        }
        return TextureImage.fromLinear(2, 2, rgb);
    }

    private static void put(double[] rgb, int texel, double value) {
        rgb[texel * 3] = value;
        rgb[texel * 3 + 1] = 10 * value;
        rgb[texel * 3 + 2] = -value;
    }

    static double[] sample(Texture t, double u, double v, double footprint) {
        double[] rgb = new double[3];
        t.evaluate(new TexturePoint().uv(u, v, footprint), rgb);
        return rgb;
    }

    private static void expect(Texture t, double u, double v, double expected) {
        double[] rgb = sample(t, u, v, 0);
        String at = t + " at (" + u + ", " + v + ")";
        assertEquals(expected, rgb[0], 1e-12, at);
        assertEquals(10 * expected, rgb[1], 1e-11, at);
        assertEquals(-expected, rgb[2], 1e-12, at);
    }

    @Test
    void bilinearIsTheExactWeightedMixInside() {
        for (Wrap w : Wrap.values()) {
            ImageTexture t = new ImageTexture(twoByTwo(), Filter.BILINEAR, w);
            expect(t, 0.25, 0.25, B0);                 // texel centres reproduce texels exactly
            expect(t, 0.75, 0.25, B1);
            expect(t, 0.25, 0.75, T0);
            expect(t, 0.75, 0.75, T1);
            expect(t, 0.5, 0.25, (B0 + B1) / 2);
            expect(t, 0.375, 0.25, 0.75 * B0 + 0.25 * B1);
            expect(t, 0.5, 0.5, (B0 + B1 + T0 + T1) / 4);
            // fx = 0.25, fy = 0.75
            expect(t, 0.375, 0.625, 0.75 * 0.25 * B0 + 0.25 * 0.25 * B1 + 0.75 * 0.75 * T0 + 0.25 * 0.75 * T1);
        }
    }

    @Test
    void bilinearAtTheEdgesFollowsTheWrapMode() {
        ImageTexture rep = new ImageTexture(twoByTwo(), Filter.BILINEAR, Wrap.REPEAT);
        ImageTexture clamp = new ImageTexture(twoByTwo(), Filter.BILINEAR, Wrap.CLAMP);
        ImageTexture mirror = new ImageTexture(twoByTwo(), Filter.BILINEAR, Wrap.MIRROR);
        // u = 0 and u = 1: half-way between the two columns' texels across the border.
        expect(rep, 0, 0.25, (B0 + B1) / 2);          // seam blends across u = 0/1
        expect(rep, 1, 0.25, (B0 + B1) / 2);
        expect(clamp, 0, 0.25, B0);
        expect(clamp, 1, 0.25, B1);
        expect(mirror, 0, 0.25, B0);
        expect(mirror, 1, 0.25, B1);
        // Outside [0, 1]: texel index -1 and -2.
        expect(rep, -0.25, 0.25, B1);
        expect(clamp, -0.25, 0.25, B0);
        expect(mirror, -0.25, 0.25, B0);
        expect(rep, -0.75, 0.25, B0);
        expect(clamp, -0.75, 0.25, B0);
        expect(mirror, -0.75, 0.25, B1);
        expect(rep, 1.75, 0.75, T1);
        expect(clamp, 1.75, 0.75, T1);
        expect(mirror, 1.75, 0.75, T0);
        // v = 0 and v = 1 (bottom and top edges).
        expect(rep, 0.25, 0, (B0 + T0) / 2);
        expect(rep, 0.25, 1, (B0 + T0) / 2);
        expect(clamp, 0.25, 0, B0);
        expect(clamp, 0.25, 1, T0);
        expect(mirror, 0.25, 0, B0);
        expect(mirror, 0.25, 1, T0);
        // The corner under REPEAT mixes all four.
        expect(rep, 0, 0, (B0 + B1 + T0 + T1) / 4);
        expect(clamp, 0, 0, B0);
        expect(clamp, 1, 1, T1);
    }

    @Test
    void nearestPicksTheContainingTexel() {
        ImageTexture rep = new ImageTexture(twoByTwo(), Filter.NEAREST, Wrap.REPEAT);
        ImageTexture clamp = new ImageTexture(twoByTwo(), Filter.NEAREST, Wrap.CLAMP);
        ImageTexture mirror = new ImageTexture(twoByTwo(), Filter.NEAREST, Wrap.MIRROR);
        for (ImageTexture t : new ImageTexture[] {rep, clamp, mirror}) {
            expect(t, 0.1, 0.1, B0);
            expect(t, 0.9, 0.1, B1);
            expect(t, 0.1, 0.9, T0);
            expect(t, 0.6, 0.6, T1);
            expect(t, 0.49, 0.49, B0);
        }
        expect(rep, 1.1, 0.1, B0);
        expect(clamp, 1.1, 0.1, B1);
        expect(mirror, 1.1, 0.1, B1);
        expect(rep, -0.1, 0.1, B1);
        expect(clamp, -0.1, 0.1, B0);
        expect(mirror, -0.1, 0.1, B0);
        expect(rep, 0.1, -0.1, T0);
        expect(clamp, 0.1, -0.1, B0);
        expect(mirror, 0.1, 2.9, T0);
        expect(mirror, 0.1, 2.1, B0);
    }

    @Test
    void hugeAndNanCoordinatesStayInsideTheImage() {
        for (Wrap w : Wrap.values()) {
            for (Filter f : Filter.values()) {
                ImageTexture t = new ImageTexture(twoByTwo(), f, w);
                for (double c : new double[] {1e300, -1e300, Double.POSITIVE_INFINITY, Double.NaN}) {
                    double[] rgb = sample(t, c, 0.3, 0.1);
                    assertEquals(true, rgb[0] >= B0 && rgb[0] <= T1, t + " at u = " + c + ": " + rgb[0]);
                }
            }
        }
    }

    /** 4x4 image of 2x2 blocks: white top-left and bottom-right, black elsewhere. */
    static TextureImage blockChecker() {
        double[] rgb = new double[48];
        for (int row = 0; row < 4; row++) {
            for (int x = 0; x < 4; x++) {
                double g = ((row / 2 + x / 2) % 2 == 0) ? 1 : 0;
                for (int c = 0; c < 3; c++) rgb[(row * 4 + x) * 3 + c] = g;
            }
        }
        return TextureImage.fromLinear(4, 4, rgb);
    }

    @Test
    void mipChainBoxFiltersTheChecker() {
        TextureImage img = blockChecker();
        assertEquals(3, img.levelCount());
        assertEquals(2, img.width(1));
        assertEquals(1, img.height(2));
        // Level 1 is the 2x2 checker of the blocks; level 2 is their grey average.
        assertEquals(1, img.texel(1, 0, 0, 0));
        assertEquals(0, img.texel(1, 1, 0, 1));
        assertEquals(0, img.texel(1, 0, 1, 2));
        assertEquals(1, img.texel(1, 1, 1, 0));
        for (int c = 0; c < 3; c++) assertEquals(0.5, img.texel(2, 0, 0, c), 1e-7);
    }

    @Test
    void mipChainOfOddSizesKeepsTheMean() {
        for (int[] size : new int[][] {{3, 1}, {5, 3}, {7, 5}, {1, 9}, {6, 3}}) {
            int w = size[0], h = size[1];
            double[] rgb = new double[w * h * 3];
            for (int i = 0; i < rgb.length; i++) rgb[i] = (i * 7919 % 13) / 13.0;
            TextureImage img = TextureImage.fromLinear(w, h, rgb);
            double[] mean0 = mean(img, 0);
            for (int k = 1; k < img.levelCount(); k++) {
                assertEquals(Math.max(1, w >> k), img.width(k));
                double[] m = mean(img, k);
                for (int c = 0; c < 3; c++) assertEquals(mean0[c], m[c], 1e-6, w + "x" + h + " level " + k);
            }
            assertEquals(1, img.width(img.levelCount() - 1));
            assertEquals(1, img.height(img.levelCount() - 1));
        }
        // 3x1 -> 1x1 averages all three texels (none dropped).
        TextureImage three = TextureImage.fromLinear(3, 1, new double[] {0, 0, 0, 3, 3, 3, 9, 9, 9});
        assertEquals(2, three.levelCount());
        assertEquals(4, three.texel(1, 0, 0, 0), 1e-6);
    }

    private static double[] mean(TextureImage img, int k) {
        double[] m = new double[3];
        int w = img.width(k), h = img.height(k);
        for (int y = 0; y < h; y++) for (int x = 0; x < w; x++) for (int c = 0; c < 3; c++) m[c] += img.texel(k, x, y, c) / (w * h);
        return m;
    }

    @Test
    void mipLevelFollowsTheFootprint() {
        ImageTexture t = new ImageTexture(blockChecker(), Filter.TRILINEAR, Wrap.REPEAT);
        assertEquals(0, t.mipLevel(0));
        assertEquals(0, t.mipLevel(0.1));              // below one texel: sharpest level
        assertEquals(0, t.mipLevel(0.25), 1e-12);      // one texel of 4
        assertEquals(0.5, t.mipLevel(Math.sqrt(2) / 4), 1e-12);
        assertEquals(1, t.mipLevel(0.5), 1e-12);
        assertEquals(2, t.mipLevel(1), 1e-12);
        assertEquals(2, t.mipLevel(100), 1e-12);       // clamped to the 1x1 level
        // A non-square image uses its larger side.
        TextureImage wide = TextureImage.fromLinear(8, 2, new double[48]);
        ImageTexture tw = new ImageTexture(wide, Filter.TRILINEAR, Wrap.CLAMP);
        assertEquals(4, wide.levelCount());
        assertEquals(1, tw.mipLevel(0.25), 1e-12);
    }

    @Test
    void trilinearBlendsTheTwoLevels() {
        TextureImage img = blockChecker();
        ImageTexture tri = new ImageTexture(img, Filter.TRILINEAR, Wrap.REPEAT);
        ImageTexture bi = new ImageTexture(img, Filter.BILINEAR, Wrap.REPEAT);
        // Footprint 0: identical to bilinear.
        for (double u = 0; u < 1; u += 0.07) {
            assertEquals(sample(bi, u, 0.3, 0)[0], sample(tri, u, 0.3, 0)[0], 1e-12);
        }
        // Whole-texture footprint: the grey top level everywhere, so no shimmer far away.
        for (double u = 0; u < 1; u += 0.07) assertEquals(0.5, sample(tri, u, 0.8, 1)[1], 1e-6);
        // Level 1 exactly (footprint = 2 texels): bilinear in the 2x2 level at its texel centre.
        assertEquals(1, sample(tri, 0.25, 0.75, 0.5)[0], 1e-6);  // top-left block is white
        // Level 0.5: the mean of level 0 and level 1 bilinear values.
        double l0 = sample(bi, 0.3, 0.6, 0)[0];
        double l1 = 0.3 * 2 - 0.5;                                 // fx in level 1
        double fy = 0.6 * 2 - 0.5;
        double level1 = (1 - l1) * (1 - fy) * 0 + l1 * (1 - fy) * 1 + (1 - l1) * fy * 1 + l1 * fy * 0;
        assertEquals((l0 + level1) / 2, sample(tri, 0.3, 0.6, Math.sqrt(2) / 4)[0], 1e-6);
    }

    @Test
    void fromLinearValidates() {
        assertThrows(IllegalArgumentException.class, () -> TextureImage.fromLinear(0, 1, new double[0]));
        assertThrows(IllegalArgumentException.class, () -> TextureImage.fromLinear(2, 1, new double[3]));
        assertThrows(IllegalArgumentException.class, () -> TextureImage.fromLinear(1, 1, new double[] {0, Double.NaN, 0}));
    }
}
