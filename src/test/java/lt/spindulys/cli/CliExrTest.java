package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.ExrTestDecoder;

/** {@code -o OUT.exr} and its options through the command line. */
class CliExrTest {
    @TempDir Path dir;

    private static final String SCENE = CliAovTest.SCENE;
    private static final String NL = System.lineSeparator();

    private Path scene() throws IOException {
        Path p = dir.resolve("scene.dat");
        Files.writeString(p, SCENE);
        return p;
    }

    private Set<String> files() throws IOException { return CliAovTest.files(dir); }

    @Test
    void writesOneFileHoldingTheImageAndItsPasses() throws IOException {
        Path out = dir.resolve("out.exr");
        CliTest.Run r = CliTest.run(scene().toString(), "-o", out.toString(), "--aov", "depth,normal,object");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().startsWith("wrote " + out + " (24x16, "), r.err());
        assertEquals(Set.of("scene.dat", "out.exr"), files());
        ExrTestDecoder.Image image = ExrTestDecoder.read(out);
        assertEquals(24, image.width());
        assertEquals(16, image.height());
        assertEquals(3, image.compression(), "ZIP by default");
        assertEquals(List.of("A", "B", "G", "IndexOB.X", "Normal.X", "Normal.Y", "Normal.Z", "R", "Z"),
                image.channels().stream().map(ExrTestDecoder.Channel::name).toList());
        assertEquals(1, image.channel("R").pixelType(), "half by default");
        // Top row: sky; centre: the sphere (id 1) about 3.5 away; bottom: the floor (id 0).
        assertEquals(Float.POSITIVE_INFINITY, image.channel("Z").values()[0]);
        assertEquals(0f, image.channel("IndexOB.X").values()[0]);
        assertEquals(3.5, image.channel("Z").values()[8 * 24 + 12], 0.1);
        assertEquals(2f, image.channel("IndexOB.X").values()[8 * 24 + 12]);
        assertEquals(1f, image.channel("IndexOB.X").values()[15 * 24]);
        assertTrue(image.channel("G").values()[8 * 24 + 12] > 0, "the lit sphere");
    }

    @Test
    void anExistingExrWithItsPassesIsSkipped() throws IOException {
        Path out = dir.resolve("again.exr");
        String[] args = {scene().toString(), "-o", out.toString(), "--aov", "depth", "--skip-existing"};
        assertEquals(0, CliTest.run(args).status());
        CliTest.Run again = CliTest.run(args);
        assertEquals(0, again.status(), again.err());
        assertTrue(again.err().startsWith("skipped " + out + ": it exists"), again.err());
    }

    @Test
    void precisionAndCompressionOptions() throws IOException {
        Path out = dir.resolve("float.exr");
        CliTest.Run r = CliTest.run(scene().toString(), "-o", out.toString(), "--exr-precision", "float", "--exr-compression", "none", "--quiet");
        assertEquals(0, r.status(), r.err());
        ExrTestDecoder.Image image = ExrTestDecoder.read(out);
        assertEquals(0, image.compression());
        assertEquals(2, image.channel("R").pixelType());
        assertEquals(List.of("A", "B", "G", "R"), image.channels().stream().map(ExrTestDecoder.Channel::name).toList());
        assertEquals(0, CliTest.run(scene().toString(), "-o", dir.resolve("zips.exr").toString(), "--exr-compression", "zips", "--quiet").status());
        assertEquals(2, ExrTestDecoder.read(dir.resolve("zips.exr")).compression());
    }

    @Test
    void badValuesAreOneLineNamingTheOption() throws IOException {
        String scene = scene().toString();
        CliTest.Run precision = CliTest.run(scene, "-o", dir.resolve("a.exr").toString(), "--exr-precision", "double");
        assertEquals(2, precision.status());
        assertEquals("render: --exr-precision: unknown OpenEXR precision 'double' (expected half or float)" + NL, precision.err());
        CliTest.Run compression = CliTest.run(scene, "-o", dir.resolve("a.exr").toString(), "--exr-compression", "piz");
        assertEquals(2, compression.status());
        assertEquals("render: --exr-compression: unknown OpenEXR compression 'piz' (expected none, zip or zips)" + NL, compression.err());
        CliTest.Run missing = CliTest.run(scene, "--exr-compression");
        assertEquals(2, missing.status());
        assertEquals("render: option --exr-compression needs a value" + NL, missing.err());
        assertEquals(Set.of("scene.dat"), files());
    }

    @Test
    void tilesAndTheirAssemblyStayInEightBits() throws IOException {
        CliTest.Run tile = CliTest.run(scene().toString(), "-o", dir.resolve("t.exr").toString(), "--tile", "1/2");
        assertEquals(2, tile.status());
        assertEquals(1, tile.err().lines().count(), tile.err());
        assertTrue(tile.err().contains("--tile 1/2") && tile.err().contains("must end in .png"), tile.err());

        assertEquals(0, CliTest.run(scene().toString(), "-o", dir.resolve("t1.png").toString(), "--tile", "1/2", "--quiet").status());
        assertEquals(0, CliTest.run(scene().toString(), "-o", dir.resolve("t2.png").toString(), "--tile", "2/2", "--quiet").status());
        CliTest.Run assemble = CliTest.run("assemble", dir.resolve("t1.png").toString(), dir.resolve("t2.png").toString(),
                "-o", dir.resolve("whole.exr").toString());
        assertEquals(2, assemble.status());
        assertEquals("render: tiles hold 8-bit pixels: the assembled frame is written as .png, .tga or .jpg, not "
                + dir.resolve("whole.exr") + NL, assemble.err());
        assertFalse(Files.exists(dir.resolve("whole.exr")));
    }
}
