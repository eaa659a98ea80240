package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

import lt.spindulys.files.AtomicFile;

/**
 * Output names at the edges: the longest a file system allows (255 bytes) is written by every
 * command, render passes included; one byte more is refused before the work; a name that is only
 * an extension is refused. Nothing is left behind either way.
 */
class OutputNameTest {
    @TempDir Path dir;
    Path scene;

    @BeforeEach
    void scene() throws IOException {
        scene = dir.resolve("s.dat");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nsphere { }\n");
    }

    /** A name of exactly {@code bytes} bytes ending in {@code ext}. */
    static String name(int bytes, String ext) { return "n".repeat(bytes - ext.length()) + ext; }

    private List<String> listing() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    private void assertNoTemporary() throws IOException {
        for (String n : listing()) assertFalse(AtomicFile.isTemporaryName(n) || n.endsWith(".tmp") || n.endsWith(".bak"), n);
    }

    @ParameterizedTest
    @ValueSource(strings = {".png", ".jpg", ".tga", ".pfm"})
    void renderWritesAnImageNamedWith255Bytes(String ext) throws IOException {
        Path out = dir.resolve(name(255, ext));
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--width", "8", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.size(out) > 0);
        assertNoTemporary();
    }

    @Test
    void renderWritesPassesNamedWith255Bytes() throws IOException {
        // out.normal.pfm is the longest of the three: 255 bytes.
        String base = "n".repeat(255 - ".normal.pfm".length());
        Path out = dir.resolve(base + ".png");
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--aov", "depth,normal,object", "--width", "8", "--quiet");
        assertEquals(0, r.status(), r.err());
        for (String suffix : List.of(".png", ".depth.pfm", ".normal.pfm", ".object.png")) assertTrue(Files.exists(dir.resolve(base + suffix)), suffix);
        assertNoTemporary();
    }

    @Test
    void aPassNameTooLongIsRefusedBeforeTheRender() throws IOException {
        Path out = dir.resolve(name(255, ".png"));
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--aov", "normal", "--width", "8", "--quiet");
        assertEquals(2, r.status(), r.err());
        Path pass = dir.resolve(name(255, ".png").replace(".png", ".normal.pfm"));
        assertTrue(r.err().startsWith("render: cannot write '" + pass + "': "), r.err());
        assertEquals(List.of("s.dat"), listing(), "nothing written");
    }

    @Test
    void anImageNameTooLongIsRefusedBeforeTheRender() throws IOException {
        Path out = dir.resolve(name(256, ".png"));
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--width", "8", "--quiet");
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().startsWith("render: cannot write '" + out + "': "), r.err());
        assertEquals(List.of("s.dat"), listing());
    }

    @Test
    void framesAndTilesAndTheirAssemblyTakeNamesOf255Bytes() throws IOException {
        Path anim = dir.resolve("a.dat");
        Files.writeString(anim, "animation { frames 1 2 fps 24 }\ncamera { eye 0 0 -5 lookat 0 0 0 }\nsphere { }\n");
        String pattern = name(255, "_####.png");
        CliTest.Run r = CliTest.run(anim.toString(), "-o", dir.resolve(pattern).toString(), "--width", "8", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.exists(dir.resolve(pattern.replace("####", "0002"))));

        Path t1 = dir.resolve(name(255, ".1.png")), t2 = dir.resolve(name(255, ".2.png"));
        assertEquals(0, CliTest.run(scene.toString(), "--tile", "1/2", "--width", "8", "-o", t1.toString(), "--quiet").status());
        assertEquals(0, CliTest.run(scene.toString(), "--tile", "2/2", "--width", "8", "-o", t2.toString(), "--quiet").status());
        Path out = dir.resolve(name(255, ".tga"));
        r = CliTest.run("assemble", t1.toString(), t2.toString(), "-o", out.toString(), "--quiet");
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.size(out) > 0);
        assertNoTemporary();
    }

    @Test
    void subdivideWritesAMeshNamedWith255Bytes() throws IOException {
        Path out = dir.resolve(name(255, ".obj"));
        CliTest.Run r = CliTest.run("subdivide", "scenes/models/cube.dat", "--level", "1", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.readString(out).contains("\nf "));
        Path tooLong = dir.resolve(name(256, ".obj"));
        r = CliTest.run("subdivide", "scenes/models/cube.dat", "--level", "1", "-o", tooLong.toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().startsWith("render: cannot write '" + tooLong + "': "), r.err());
        assertNoTemporary();
    }

    @Test
    void aNameThatIsOnlyAnExtensionIsRefusedByEveryCommand() throws IOException {
        Path png = dir.resolve(".png");
        assertRefused(CliTest.run(scene.toString(), "-o", png.toString(), "--quiet"),
                "render: output '" + png + "' is only an extension; give the file a name, such as out.png");
        assertRefused(CliTest.run(scene.toString(), "-o", ".jpg", "--quiet"), "render: output '.jpg' is only an extension; give the file a name, such as out.jpg");
        assertRefused(CliTest.run(scene.toString(), "-o", png.toString(), "--aov", "depth", "--quiet"),
                "render: output '" + png + "' is only an extension; give the file a name, such as out.png");
        assertRefused(CliTest.run("assemble", dir.resolve("t.png").toString(), "-o", png.toString()),
                "render: output '" + png + "' is only an extension; give the file a name, such as out.png");
        Path obj = dir.resolve(".obj");
        assertRefused(CliTest.run("subdivide", "scenes/models/cube.dat", "--level", "1", "-o", obj.toString()),
                "render: output '" + obj + "' is only an extension; give the file a name, such as out.obj");
        // A hidden file with a name is a name.
        CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve(".hidden.png").toString(), "--width", "8", "--quiet");
        assertEquals(0, r.status(), r.err());
    }

    private void assertRefused(CliTest.Run r, String line) throws IOException {
        assertEquals(2, r.status(), r.err());
        assertEquals(line + System.lineSeparator(), r.err());
        assertEquals(List.of("s.dat"), listing());
    }
}
