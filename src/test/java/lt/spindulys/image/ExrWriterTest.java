package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Random;
import java.util.Set;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/** The OpenEXR writer: half conversion, and files read back by an independent test decoder. */
class ExrWriterTest {
    @TempDir Path dir;

    @Test
    void halfConversionOfKnownValues() {
        assertEquals(0x0000, ExrWriter.halfBits(0f));
        assertEquals(0x8000, ExrWriter.halfBits(-0f));
        assertEquals(0x3C00, ExrWriter.halfBits(1f));
        assertEquals(0xBC00, ExrWriter.halfBits(-1f));
        assertEquals(0x2E66, ExrWriter.halfBits(0.1f));
        assertEquals(0x7BFF, ExrWriter.halfBits(65504f));
        assertEquals(0x0400, ExrWriter.halfBits(0x1p-14f), "smallest normal");
        assertEquals(0x03FF, ExrWriter.halfBits(1023 * 0x1p-24f), "largest subnormal");
        assertEquals(0x0001, ExrWriter.halfBits(0x1p-24f), "smallest subnormal");
        assertEquals(0x8001, ExrWriter.halfBits(-0x1p-24f));
        assertEquals(0x7C00, ExrWriter.halfBits(Float.POSITIVE_INFINITY), "depth's background stays infinite");
        assertEquals(0x7C00, ExrWriter.halfBits(Double.POSITIVE_INFINITY));
        assertEquals(0xFC00, ExrWriter.halfBits(Float.NEGATIVE_INFINITY));
    }

    @Test
    void halfConversionRoundsToNearestEven() {
        // Ties between 1 and the next half (1 + 2^-10) go to the even mantissa.
        assertEquals(0x3C00, ExrWriter.halfBits(1 + 0x1p-11f));
        assertEquals(0x3C02, ExrWriter.halfBits(1 + 3 * 0x1p-11f));
        assertEquals(0x3C01, ExrWriter.halfBits(1 + 0x1p-11f + 0x1p-20f));
        // Just above a tie, closer than a float can tell: rounded once, from the double.
        assertEquals(0x3C01, ExrWriter.halfBits(1 + 0x1p-11 + 0x1p-40));
        assertEquals(0x3C00, ExrWriter.halfBits(1 + 0x1p-11 - 0x1p-40));
        // Subnormal ties: half a unit goes to 0, one and a half units to 2.
        assertEquals(0x0000, ExrWriter.halfBits(0x1p-25f));
        assertEquals(0x0001, ExrWriter.halfBits(0x1p-25f + 0x1p-40f));
        assertEquals(0x0002, ExrWriter.halfBits(3 * 0x1p-25f));
        assertEquals(0x0000, ExrWriter.halfBits(Float.MIN_VALUE));
        // Rounding up out of the largest subnormal gives the smallest normal.
        assertEquals(0x0400, ExrWriter.halfBits(1023.75f * 0x1p-24f));
        // 65519 rounds to 65504, and beyond that finite values clamp rather than become infinite.
        assertEquals(0x7BFF, ExrWriter.halfBits(65519f));
        assertEquals(0x7BFF, ExrWriter.halfBits(65520f));
        assertEquals(0xFBFF, ExrWriter.halfBits(-1e30f));
        assertEquals(0x7BFF, ExrWriter.halfBits(Float.MAX_VALUE));
        assertEquals(0x7BFF, ExrWriter.halfBits(Double.MAX_VALUE));
        assertEquals(0x0000, ExrWriter.halfBits(Double.MIN_VALUE));
    }

    @Test
    void everyFiniteHalfSurvivesAndEveryValueGoesToItsNearestHalf() {
        for (int h = 0; h < 0x10000; h++) {
            if ((h & 0x7C00) == 0x7C00) continue;
            assertEquals(h, ExrWriter.halfBits(ExrTestDecoder.halfToFloat(h)), Integer.toHexString(h));
        }
        Random random = new Random(7);
        for (int i = 0; i < 200_000; i++) {
            // Floats up to 65504, and doubles of every half binade with bits no float holds.
            double f = i % 2 == 0 ? Float.intBitsToFloat(random.nextInt(0x477FE000))
                    : Math.min(65504, Math.scalb(1 + random.nextDouble(), random.nextInt(42) - 26));
            int h = ExrWriter.halfBits(f);
            double here = Math.abs(ExrTestDecoder.halfToFloat(h) - f);
            double below = h > 0 ? Math.abs(ExrTestDecoder.halfToFloat(h - 1) - f) : Double.POSITIVE_INFINITY;
            double above = h < 0x7BFF ? Math.abs(ExrTestDecoder.halfToFloat(h + 1) - f) : Double.POSITIVE_INFINITY;
            assertTrue(here <= below && here <= above, f + " became " + Integer.toHexString(h));
            if (here == below || here == above) assertEquals(0, h & 1, "tie of " + f + " not to even");
        }
    }

    @ParameterizedTest
    @EnumSource(ExrCompression.class)
    void imageAndPassesReadBackExactly(ExrCompression compression) throws IOException {
        for (ExrPrecision precision : ExrPrecision.values()) {
            // Odd sizes: a last ZIP block of 5 lines, and odd byte counts in the blocks' halves.
            int w = 7, h = 37;
            FrameBuffer fb = new FrameBuffer(w, h);
            // The passes of the first hit; the noise pass has its own test.
            AovFrame aovs = new AovFrame(w, h, EnumSet.complementOf(EnumSet.of(Aov.NOISE)));
            Random random = new Random(11);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    fb.set(x, y, random.nextDouble() * 4, x / 7.0, y == 3 ? 1e6 : -y * 1e-6);
                    if ((x + y) % 5 == 0) aovs.setBackground(x, y);
                    else aovs.setHit(x, y, 1 + random.nextDouble() * 1e5, 0.6, -0.8, 0, x + 1000 * y);
                }
            }
            Path out = dir.resolve("out-" + compression.keyword() + "-" + precision.keyword() + ".exr");
            ImageWriter.write(fb, out, ImageOptions.DEFAULT.withExr(precision, compression), aovs);

            ExrTestDecoder.Image image = ExrTestDecoder.read(out);
            assertEquals(w, image.width());
            assertEquals(h, image.height());
            assertEquals(compression.code(), image.compression());
            assertEquals(List.of("A", "Albedo.B", "Albedo.G", "Albedo.R", "B", "G", "IndexOB.X", "Normal.X", "Normal.Y", "Normal.Z", "R", "Z"),
                    image.channels().stream().map(ExrTestDecoder.Channel::name).toList());
            assertEquals(List.of("channels", "compression", "dataWindow", "displayWindow", "lineOrder", "pixelAspectRatio",
                    "screenWindowCenter", "screenWindowWidth"), List.copyOf(image.attributes().keySet()));
            assertEquals("chlist", image.attributeTypes().get("channels"));
            assertEquals("box2i", image.attributeTypes().get("displayWindow"));
            assertEquals("v2f", image.attributeTypes().get("screenWindowCenter"));
            int colourType = precision == ExrPrecision.HALF ? 1 : 2;
            assertEquals(colourType, image.channel("R").pixelType());
            assertEquals(colourType, image.channel("Normal.X").pixelType());
            assertEquals(2, image.channel("Z").pixelType(), "depth is always float");
            assertEquals(2, image.channel("IndexOB.X").pixelType(), "object id is always float");
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int p = y * w + x;
                    String at = x + "," + y + " " + out.getFileName();
                    assertEquals(1f, image.channel("A").values()[p], at);
                    for (int c = 0; c < 3; c++) {
                        assertEquals(stored(fb.get(x, y, c), precision), image.channel("RGB".substring(c, c + 1)).values()[p], at);
                        assertEquals(stored(aovs.normal(x, y, c), precision), image.channel("Normal." + "XYZ".charAt(c)).values()[p], at);
                    }
                    assertEquals((float) aovs.depth(x, y), image.channel("Z").values()[p], at);
                    assertEquals(aovs.objectId(x, y) + 1, image.channel("IndexOB.X").values()[p], at);
                }
            }
        }
    }

    @Test
    void theNoisePassIsTwoFloatChannels() throws IOException {
        int w = 5, h = 3;
        FrameBuffer fb = new FrameBuffer(w, h);
        AovFrame aovs = new AovFrame(w, h, EnumSet.of(Aov.NOISE));
        for (int y = 0; y < h; y++) for (int x = 0; x < w; x++) aovs.setNoise(x, y, 64 + 4097 * x + y, 0.001 * (x + 10 * y) + 1e-7);
        Path out = dir.resolve("noise.exr");
        ImageWriter.write(fb, out, ImageOptions.DEFAULT, aovs); // half colour: the pass stays float
        ExrTestDecoder.Image image = ExrTestDecoder.read(out);
        assertEquals(List.of("A", "B", "G", "Noise.X", "R", "Samples.X"), image.channels().stream().map(ExrTestDecoder.Channel::name).toList());
        assertEquals(2, image.channel("Samples.X").pixelType());
        assertEquals(2, image.channel("Noise.X").pixelType());
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int p = y * w + x;
                assertEquals(64 + 4097 * x + y, image.channel("Samples.X").values()[p], "sample counts above 2048 stay exact");
                assertEquals((float) aovs.noiseError(x, y), image.channel("Noise.X").values()[p]);
            }
        }
    }

    /** What a value becomes in a channel of the precision. */
    private static float stored(double v, ExrPrecision precision) {
        return precision == ExrPrecision.FLOAT ? (float) v : ExrTestDecoder.halfToFloat(ExrWriter.halfBits(v));
    }

    @Test
    void zipShrinksASmoothImageAndAOnePixelImageIsWritten() throws IOException {
        FrameBuffer fb = new FrameBuffer(64, 40);
        for (int y = 0; y < 40; y++) for (int x = 0; x < 64; x++) fb.set(x, y, x / 64.0, y / 40.0, 0.5);
        Path none = dir.resolve("none.exr"), zip = dir.resolve("zip.exr");
        ImageWriter.write(fb, none, ImageOptions.DEFAULT.withExr(ExrPrecision.HALF, ExrCompression.NONE));
        ImageWriter.write(fb, zip, ImageOptions.DEFAULT);
        assertTrue(Files.size(zip) < Files.size(none) / 2, Files.size(zip) + " vs " + Files.size(none));
        assertEquals(ExrTestDecoder.read(none).channel("G").values()[64 * 39 + 5], ExrTestDecoder.read(zip).channel("G").values()[64 * 39 + 5]);

        // A block too small to shrink is stored raw, which the reader recognises by its size.
        FrameBuffer one = new FrameBuffer(1, 1);
        one.set(0, 0, 0.25, 0.5, 0.75);
        Path tiny = dir.resolve("tiny.exr");
        ImageWriter.write(one, tiny, ImageOptions.DEFAULT);
        ExrTestDecoder.Image image = ExrTestDecoder.read(tiny);
        assertEquals(0.75f, image.channel("B").values()[0]);
        assertEquals(List.of("A", "B", "G", "R"), image.channels().stream().map(ExrTestDecoder.Channel::name).toList());
    }

    @Test
    void passesGoIntoTheFileAndNothingBesideIt() throws IOException {
        Path out = dir.resolve("frame.exr");
        Set<Aov> all = EnumSet.allOf(Aov.class);
        assertEquals(List.of(), Aov.filesBeside(out, all));
        assertEquals(List.of(dir.resolve("frame.depth.pfm")), Aov.filesBeside(dir.resolve("frame.png"), EnumSet.of(Aov.DEPTH)));
        ImageWriter.write(new FrameBuffer(3, 2), out, ImageOptions.DEFAULT, new AovFrame(3, 2, all));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(out), files.toList());
        }
    }

    @Test
    void aNonFinitePixelWritesNothing() {
        FrameBuffer fb = new FrameBuffer(2, 2);
        fb.set(1, 1, Double.NaN, 0, 0);
        Path out = dir.resolve("bad.exr");
        assertThrows(NonFinitePixelException.class, () -> ImageWriter.write(fb, out, ImageOptions.DEFAULT));
        assertFalse(Files.exists(out));
    }
}
