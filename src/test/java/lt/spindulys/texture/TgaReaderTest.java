package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.Arrays;
import org.junit.jupiter.api.Test;

class TgaReaderTest {
    static final int W = 7, H = 3;

    /** Rows top-down; the left three columns repeat (RLE runs, also across rows), the rest differ. */
    static int[] colourImage() {
        int[] rgb = new int[W * H];
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) rgb[y * W + x] = x < 3 ? 0x204060 : ((y * 37 + x * 91) & 0xFF) << 16 | (x * 13) << 8 | (y * 70 + x);
        }
        // The last pixel of row 0 equals the first of row 1, so a run crosses a scanline.
        rgb[W - 1] = 0x204060;
        return rgb;
    }

    static int[] greyImage() {
        int[] rgb = colourImage();
        for (int i = 0; i < rgb.length; i++) {
            int g = rgb[i] & 0xFF;
            rgb[i] = g << 16 | g << 8 | g;
        }
        return rgb;
    }

    private static TgaReader.Image decode(byte[] b) throws IOException {
        return TgaReader.read(new ByteArrayInputStream(b));
    }

    @Test
    void roundTripsEveryTypeDepthAndOrigin() throws IOException {
        int[][] kinds = {{2, 24}, {2, 32}, {10, 24}, {10, 32}, {3, 8}, {11, 8}};
        for (int[] kind : kinds) {
            boolean grey = kind[0] == 3 || kind[0] == 11;
            int[] img = grey ? greyImage() : colourImage();
            for (boolean topDown : new boolean[] {true, false}) {
                for (boolean rtl : new boolean[] {false, true}) {
                    byte[] file = TgaTestWriter.encode(W, H, img, kind[0], kind[1], topDown, rtl, topDown ? "id!" : "");
                    TgaReader.Image t = decode(file);
                    String what = "type " + kind[0] + " depth " + kind[1] + " topDown " + topDown + " rtl " + rtl;
                    assertEquals(W, t.width(), what);
                    assertEquals(H, t.height(), what);
                    assertEquals(grey, t.grey(), what);
                    assertArrayEquals(img, t.rgb(), what);
                }
            }
        }
    }

    @Test
    void rleIsActuallyCompressed() {
        int[] flat = new int[64 * 64];
        Arrays.fill(flat, 0x123456);
        byte[] raw = TgaTestWriter.encode(64, 64, flat, 2, 24, false, false, "");
        byte[] rle = TgaTestWriter.encode(64, 64, flat, 10, 24, false, false, "");
        assertTrue(rle.length < raw.length / 20, rle.length + " vs " + raw.length);
    }

    @Test
    void bottomUpAndTopDownFilesDescribeTheSameImage() throws IOException {
        int[] img = colourImage();
        TgaReader.Image a = decode(TgaTestWriter.encode(W, H, img, 2, 24, true, false, ""));
        TgaReader.Image b = decode(TgaTestWriter.encode(W, H, img, 10, 32, false, false, ""));
        assertArrayEquals(a.rgb(), b.rgb());
        // And the files differ: bottom-up stores the last row first.
        byte[] td = TgaTestWriter.encode(W, H, img, 2, 24, true, false, "");
        byte[] bu = TgaTestWriter.encode(W, H, img, 2, 24, false, false, "");
        assertFalse(Arrays.equals(td, bu));
    }

    @Test
    void corruptFilesGiveOneLineReasons() {
        int[] img = colourImage();
        byte[] good = TgaTestWriter.encode(W, H, img, 2, 24, true, false, "");
        byte[] rle = TgaTestWriter.encode(W, H, img, 10, 24, true, false, "");
        assertReason(Arrays.copyOf(good, 10), "truncated header");
        assertReason(Arrays.copyOf(good, good.length - 1), "truncated");
        assertReason(Arrays.copyOf(rle, rle.length - 2), "truncated");
        byte[] type1 = good.clone();
        type1[2] = 1;
        assertReason(type1, "image type 1");
        byte[] depth16 = good.clone();
        depth16[16] = 16;
        assertReason(depth16, "16 bits");
        // A run packet longer than what is left of the image.
        byte[] longRun = Arrays.copyOf(rle, 18 + 4);
        longRun[18] = (byte) 0xFF;  // run of 128 > 21 pixels
        assertReason(longRun, "past the end");
        byte[] empty = good.clone();
        empty[12] = 0;
        empty[13] = 0;
        assertReason(empty, "empty");
    }

    private static void assertReason(byte[] b, String part) {
        IOException e = assertThrows(IOException.class, () -> decode(b));
        assertTrue(e.getMessage().contains(part), e.getMessage());
        assertFalse(e.getMessage().contains("\n"), e.getMessage());
    }

    @Test
    void hugeHeaderIsRefusedBeforeReadingPixels() {
        byte[] b = TgaTestWriter.encode(1, 1, new int[1], 2, 24, true, false, "");
        b[12] = (byte) 0xFF;
        b[13] = (byte) 0xFF;
        b[14] = (byte) 0xFF;
        b[15] = (byte) 0xFF;
        IOException e = assertThrows(IOException.class, () -> decode(b));
        assertTrue(e.getMessage().contains("65535x65535") && e.getMessage().contains("limit"), e.getMessage());
    }
}
