package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

import lt.spindulys.image.ExrCompression;
import lt.spindulys.image.ExrPrecision;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;

/** What the renderer writes as OpenEXR, the texture reader reads back: float exactly, half to the nearest half. */
class ExrWriteReadTest {
    @TempDir Path dir;

    @ParameterizedTest
    @CsvSource({"HALF,NONE", "HALF,ZIP", "HALF,ZIPS", "FLOAT,NONE", "FLOAT,ZIP"})
    void aRenderedFrameReadsBackAsAnEnvironment(ExrPrecision precision, ExrCompression compression) throws Exception {
        int w = 19, h = 7;
        FrameBuffer fb = new FrameBuffer(w, h);
        java.util.SplittableRandom rnd = new java.util.SplittableRandom(11);
        for (int y = 0; y < h; y++) for (int x = 0; x < w; x++) fb.set(x, y, rnd.nextDouble() * 20, rnd.nextDouble(), x * 0.25);
        Path file = dir.resolve("frame.exr");
        ImageWriter.write(fb, file, new ImageOptions(false, 0.9).withExr(precision, compression));
        HdrReader.Image img = ExrReader.read(file);
        assertEquals(w, img.width());
        assertEquals(h, img.height());
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                for (int c = 0; c < 3; c++) {
                    double written = fb.get(x, y, c), read = img.rgb()[3 * (y * w + x) + c];
                    double tolerance = precision == ExrPrecision.FLOAT ? Math.ulp((float) written) : Math.abs(written) * 0x1p-11 + 0x1p-25;
                    assertEquals((float) written, read, tolerance, "pixel " + x + "," + y + " channel " + c);
                }
            }
        }
        assertTrue(Files.size(file) > 0);
    }
}
