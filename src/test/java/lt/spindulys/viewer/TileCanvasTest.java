package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.FrameBuffer;

/** A pass filling in over the picture before it, enlarged; its tiles exactly the 8 bits of the finished picture. */
class TileCanvasTest {
    @Test
    void tilesFillInOverTheEnlargedPictureBefore() {
        BufferedImage before = new BufferedImage(2, 1, BufferedImage.TYPE_INT_RGB);
        before.setRGB(0, 0, 0x112233);
        before.setRGB(1, 0, 0x445566);
        List<BufferedImage> shown = new ArrayList<>();
        List<Double> fractions = new ArrayList<>();
        TileCanvas canvas = new TileCanvas(4, 2, true, before, (img, f) -> {
            shown.add(img);
            fractions.add(f);
        }, 0);
        FrameBuffer frame = new FrameBuffer(4, 2);
        for (int y = 0; y < 2; y++) for (int x = 0; x < 4; x++) frame.set(x, y, 0.25 * x, 0.5, 1);
        canvas.tileDone(frame, 0, 0, 2, 2);
        assertEquals(1, shown.size());
        assertEquals(List.of(0.5), fractions);
        BufferedImage img = shown.get(0);
        int[] expected = frame.toRgb8(true);
        for (int y = 0; y < 2; y++) {
            assertEquals(expected[y * 4], img.getRGB(0, y) & 0xFFFFFF);
            assertEquals(expected[y * 4 + 1], img.getRGB(1, y) & 0xFFFFFF);
            assertEquals(0x445566, img.getRGB(2, y) & 0xFFFFFF, "the picture before, enlarged where no tile is yet");
            assertEquals(0x445566, img.getRGB(3, y) & 0xFFFFFF);
        }
        canvas.tileDone(frame, 2, 0, 4, 2);
        assertEquals(1, shown.size(), "the finished pass is not shown as partial: its own picture follows");
    }

    @Test
    void withoutAPictureBeforeTheCanvasStartsBlack() {
        List<BufferedImage> shown = new ArrayList<>();
        TileCanvas canvas = new TileCanvas(2, 2, false, null, (img, f) -> shown.add(img), 0);
        FrameBuffer frame = new FrameBuffer(2, 2);
        frame.set(0, 0, 1, 1, 1);
        canvas.tileDone(frame, 0, 0, 1, 1);
        assertEquals(0xFFFFFF, shown.get(0).getRGB(0, 0) & 0xFFFFFF);
        assertEquals(0, shown.get(0).getRGB(1, 1) & 0xFFFFFF);
    }
}
