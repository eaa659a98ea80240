package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.Images;

/** {@code --aov} and the scene's {@code aov} setting through the command line. */
class CliAovTest {
    @TempDir Path dir;

    /** A small lit scene with two objects, for the pass tests here and in {@link CliExrTest}. */
    static final String SCENE = """
            settings { width 24 height 16 }
            camera { eye 0 1 -4 lookat 0 0.5 0 }
            light { position 3 5 -4 }
            plane { normal 0 1 0 }
            sphere { center 0 0.5 0 radius 0.5 }
            """;

    private Path scene(String text) throws IOException {
        Path p = dir.resolve("scene.dat");
        Files.writeString(p, text);
        return p;
    }

    /** The names of the files in {@code dir}. */
    static Set<String> files(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).collect(Collectors.toSet());
        }
    }

    private Set<String> files() throws IOException { return files(dir); }

    @Test
    void writesTheThreePassesBesideTheImage() throws IOException {
        Path scene = scene(SCENE);
        CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("out.tga").toString(), "--aov", "depth,normal,object", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertEquals(Set.of("scene.dat", "out.tga", "out.depth.pfm", "out.normal.pfm", "out.object.png"), files());
        FrameBuffer depth = Images.read(dir.resolve("out.depth.pfm"));
        assertEquals(24, depth.width());
        assertEquals(16, depth.height());
        // Top row: sky; centre: the sphere (id 1, code 2) at about 4 - 0.5 from the eye; bottom: the floor (code 1).
        int[] ids = Images.read(dir.resolve("out.object.png"), false).toRgb8(false);
        assertEquals(0, ids[0]);
        assertEquals(Double.POSITIVE_INFINITY, depth.get(0, 0, 0));
        assertEquals(2, ids[8 * 24 + 12]);
        assertEquals(3.5, depth.get(12, 8, 0), 0.1);
        assertEquals(1, ids[15 * 24]);
    }

    @Test
    void theSceneAsksForPassesAndTheCommandLineOverrides() throws IOException {
        Path scene = scene(SCENE.replace("settings { width 24 height 16 }", "settings { width 24 height 16 aov depth normal }"));
        assertEquals(0, CliTest.run(scene.toString(), "-o", dir.resolve("a.png").toString(), "--quiet").status());
        assertEquals(0, CliTest.run(scene.toString(), "-o", dir.resolve("b.png").toString(), "--aov", "object", "--quiet").status());
        assertEquals(Set.of("scene.dat", "a.png", "a.depth.pfm", "a.normal.pfm", "b.png", "b.object.png"), files());
    }

    @Test
    void unknownPassIsAUsageError() throws IOException {
        Path scene = scene(SCENE);
        CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--aov", "depth,shadow");
        assertEquals(2, r.status());
        assertEquals("render: --aov: unknown AOV 'shadow' (expected depth, normal, object, albedo or noise)" + System.lineSeparator(), r.err());
        CliTest.Run twice = CliTest.run(scene.toString(), "--aov", "depth,depth");
        assertEquals(2, twice.status());
        assertEquals("render: --aov: AOV 'depth' listed twice" + System.lineSeparator(), twice.err());
        assertEquals(2, CliTest.run(scene.toString(), "--aov").status());
        assertEquals(Set.of("scene.dat"), files());
    }

    @Test
    void aFailingRunLeavesNoneOfTheFiles() throws IOException {
        Path bad = scene(SCENE + "sphere { radius -1 }\n");
        CliTest.Run r = CliTest.run(bad.toString(), "-o", dir.resolve("out.png").toString(), "--aov", "depth,normal,object");
        assertEquals(2, r.status());
        assertEquals(Set.of("scene.dat"), files());
    }

    @Test
    void aBlockedPassFailsBeforeRenderingAndKeepsTheOldFiles() throws IOException {
        Path out = dir.resolve("out.png");
        Files.writeString(out, "old image");
        Files.createDirectory(dir.resolve("out.normal.pfm"));
        // Asked for on the command line, and by the scene (known only after parsing it).
        Path scene = scene(SCENE);
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--aov", "depth,normal,object", "--quiet");
        assertEquals(2, r.status());
        assertEquals("render: cannot write '" + dir.resolve("out.normal.pfm") + "': it is a directory" + System.lineSeparator(), r.err());
        scene(SCENE.replace("settings { width 24 height 16 }", "settings { width 24 height 16 aov object normal }"));
        CliTest.Run s = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet");
        assertEquals(2, s.status());
        assertEquals(r.err(), s.err());
        assertEquals("old image", Files.readString(out));
        assertEquals(Set.of("scene.dat", "out.png", "out.normal.pfm"), files());
    }
}
