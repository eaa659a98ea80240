package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

/**
 * The photographed sky shipped in {@code textures/}, in its two encodings: {@code forest.exr}
 * (PIZ, HALF, re-saved losslessly by Blender) and {@code forest.hdr} (Radiance RGBE), both written
 * from the same 512x256 reduction of Blender's studio light. Decoded by our two readers they must
 * agree to the coarser format's precision, so a real photographic PIZ file, not only our
 * synthetic ones, decodes to the right pixels.
 */
class ShippedHdriTest {
    @Test
    void theExrAndTheHdrCopiesOfTheForestAgreePixelForPixel() throws IOException {
        HdrReader.Image exr = ExrReader.read(Path.of("textures/forest.exr"));
        HdrReader.Image hdr = HdrReader.read(Path.of("textures/forest.hdr"));
        assertEquals(512, exr.width());
        assertEquals(256, exr.height());
        assertEquals(hdr.width(), exr.width());
        assertEquals(hdr.height(), exr.height());
        double worst = 0, sumExr = 0, sumHdr = 0;
        int clamped = 0;
        float[] a = exr.rgb(), b = hdr.rgb();
        for (int i = 0; i < a.length; i++) {
            // The original holds a few small negatives (its lossy DWAB coding rings): the EXR
            // reader clamps them to 0, while RGBE, having no sign, stored something else.
            if (a[i] == 0 && b[i] != 0) {
                clamped++;
                continue;
            }
            // RGBE keeps 8 bits of mantissa under the pixel's largest component's exponent: a
            // component is good to 1/256 of that maximum (plus half's 2^-11 relative).
            int p = i - i % 3;
            double max = Math.max(b[p], Math.max(b[p + 1], b[p + 2]));
            double err = Math.abs(a[i] - b[i]) / (max * (1.0 / 128) + 1e-6 + Math.abs(b[i]) * 1e-3);
            worst = Math.max(worst, err);
            sumExr += a[i];
            sumHdr += b[i];
        }
        assertTrue(clamped < 100, clamped + " components read as 0 from the EXR but not from the HDR");
        assertTrue(worst <= 1, "largest difference, in units of RGBE's precision: " + worst);
        // A real sky: bright, wide in range, and both files hold the same total light.
        assertEquals(sumHdr, sumExr, 2e-3 * sumHdr);
        float peak = 0;
        for (float v : a) peak = Math.max(peak, v);
        assertTrue(peak > 20 * (sumExr / a.length), "peak " + peak + " against mean " + sumExr / a.length);
    }
}
