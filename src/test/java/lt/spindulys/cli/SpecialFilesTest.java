package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.io.ObjReader;
import lt.spindulys.io.SceneException;
import lt.spindulys.io.SceneParser;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.TgaReader;

/**
 * Only regular files are read: a named pipe (which would block a reader forever), a directory and
 * a link to /dev/zero (which never ends) are refused before they are opened, by every reader and
 * by the command line, promptly, with exit status 2 and one line saying what the path is. And
 * outputs that cannot be created are refused before any parsing or rendering.
 */
@Timeout(value = 20, unit = TimeUnit.SECONDS)
class SpecialFilesTest {
    @TempDir Path dir;

    /** A special file, what the refusal must say it is. */
    record Special(String kind, String says) {
        @Override public String toString() { return kind; }
    }

    static Stream<Special> specials() {
        return Stream.of(new Special("pipe", "is a named pipe, not a regular file"),
                new Special("directory", "is a directory, not a regular file"),
                new Special("link to /dev/zero", "is a character device, not a regular file"));
    }

    /** Makes {@code name} in dir as the given kind of special file; skips the test if the platform cannot. */
    private Path make(Special s, String name) throws IOException, InterruptedException {
        Path p = dir.resolve(name);
        switch (s.kind) {
            case "pipe" -> {
                Process mk;
                try {
                    mk = new ProcessBuilder("mkfifo", p.toString()).redirectErrorStream(true).start();
                } catch (IOException e) {
                    assumeTrue(false, "no mkfifo on this platform: " + e.getMessage());
                    return null;
                }
                assumeTrue(mk.waitFor(10, TimeUnit.SECONDS) && mk.exitValue() == 0, "mkfifo failed");
            }
            case "directory" -> Files.createDirectory(p);
            case "link to /dev/zero" -> {
                assumeTrue(Files.exists(Path.of("/dev/zero")), "no /dev/zero on this platform");
                try {
                    Files.createSymbolicLink(p, Path.of("/dev/zero"));
                } catch (UnsupportedOperationException | IOException e) {
                    assumeTrue(false, "no symbolic links here: " + e.getMessage());
                }
            }
            default -> throw new AssertionError(s.kind);
        }
        return p;
    }

    record Run(int status, String out, String err) {}

    private static Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    private static void assertOneLine(Run r, String... parts) {
        assertEquals(2, r.status, r.err);
        assertEquals(1, r.err.lines().count(), r.err);
        for (String p : parts) assertTrue(r.err.contains(p), "expected '" + p + "' in: " + r.err);
    }

    private void assertNoImage(Path out) throws IOException {
        assertFalse(Files.exists(out), "an image was written");
        try (Stream<Path> files = Files.list(dir)) {
            List<String> tmp = new ArrayList<>();
            files.filter(f -> f.getFileName().toString().endsWith(".tmp")).forEach(f -> tmp.add(f.toString()));
            assertEquals(List.of(), tmp);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("specials")
    void sceneFile(Special s) throws Exception {
        Path scene = make(s, "scene.dat");
        Path out = dir.resolve("out.png");
        assertOneLine(run(scene.toString(), "-o", out.toString()), scene + ": scene file " + s.says);
        assertNoImage(out);
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(scene));
        assertEquals(scene + ": scene file " + s.says, e.getMessage());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("specials")
    void meshOfScene(Special s) throws Exception {
        make(s, "m.obj");
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "mesh { file \"m.obj\" }\n");
        Path out = dir.resolve("out.png");
        assertOneLine(run(scene.toString(), "-o", out.toString()), scene + ":1:13: mesh file 'm.obj' " + s.says);
        assertNoImage(out);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("specials")
    void subdivAndUnwrapOfScene(Special s) throws Exception {
        make(s, "c.dat");
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "subdiv { file \"c.dat\" }\n");
        Path out = dir.resolve("out.png");
        assertOneLine(run(scene.toString(), "-o", out.toString()), scene + ":1:15: subdivision mesh file 'c.dat' " + s.says);

        Files.writeString(dir.resolve("cube.dat"), CUBE_DAT);
        make(s, "c.tex");
        Files.writeString(scene, "subdiv { file \"cube.dat\" uv \"c.tex\" }\n");
        assertOneLine(run(scene.toString(), "-o", out.toString()), scene + ":1:29: unwrap file 'c.tex' " + s.says);
        assertNoImage(out);
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("specials")
    void textureImageOfScene(Special s) throws Exception {
        make(s, "t.png");
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "texture t { image \"t.png\" }\n");
        Path out = dir.resolve("out.png");
        assertOneLine(run(scene.toString(), "-o", out.toString()), scene + ":1:19: texture image 't.png' " + s.says);
        assertNoImage(out);
    }

    /** The readers themselves, as a library user calls them, refuse too. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("specials")
    void readers(Special s) throws Exception {
        Path obj = make(s, "x.obj"), dat = make(s, "x.dat"), tex = make(s, "x.tex"), png = make(s, "x.png"), tga = make(s, "x.tga");
        assertTrue(assertThrows(SceneException.class, () -> ObjReader.read(obj)).getMessage().startsWith(obj + ": OBJ file " + s.says));
        assertTrue(assertThrows(SceneException.class, () -> ObjReader.readSubdiv(obj)).getMessage().startsWith(obj + ": OBJ file " + s.says));
        assertTrue(assertThrows(SceneException.class, () -> WorkframeReader.readMesh(dat)).getMessage().startsWith(dat + ": mesh file " + s.says));
        MeshData cube = WorkframeReader.parseMesh(CUBE_DAT, "cube.dat");
        assertTrue(assertThrows(SceneException.class, () -> WorkframeReader.readUnwrap(tex, cube)).getMessage().startsWith(tex + ": unwrap file " + s.says));
        assertEquals(png + ": " + s.says, assertThrows(IOException.class, () -> new TextureCache().load(png)).getMessage());
        assertEquals(tga + ": " + s.says, assertThrows(IOException.class, () -> new TextureCache().load(tga)).getMessage());
        assertEquals(tga + " " + s.says, assertThrows(IOException.class, () -> TgaReader.read(tga)).getMessage());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("specials")
    void subdivideCommand(Special s) throws Exception {
        Path out = dir.resolve("out.obj");
        Path obj = make(s, "m.obj");
        assertOneLine(run("subdivide", obj.toString(), "--level", "1", "-o", out.toString()), obj + ": OBJ file " + s.says);
        Path dat = make(s, "m.dat");
        assertOneLine(run("subdivide", dat.toString(), "--level", "1", "-o", out.toString()), dat + ": mesh file " + s.says);
        Path cube = dir.resolve("cube.dat");
        Files.writeString(cube, CUBE_DAT);
        Path tex = make(s, "m.tex");
        assertOneLine(run("subdivide", cube.toString(), "--uv", tex.toString(), "--level", "1", "-o", out.toString()), tex + ": unwrap file " + s.says);
        assertNoImage(out);
    }

    // ---- outputs that cannot be created ----

    /** A folder in which even root cannot create a file, or a skip. */
    private static Path unwritableFolder() {
        for (String d : new String[] {"/sys", "/proc"}) {
            Path p = Path.of(d);
            if (!Files.isDirectory(p)) continue;
            try {
                AtomicFile.checkWritable(p.resolve("probe.png"));
            } catch (IOException e) {
                return p;
            }
        }
        assumeTrue(false, "no folder here in which file creation fails (no /sys or /proc)");
        return null;
    }

    @Test
    void unwritableImageIsRefusedBeforeParsing() throws IOException {
        Path folder = unwritableFolder();
        Path scene = dir.resolve("scene.dat");
        // A scene that would fail to parse: the output is refused first, so parsing never starts.
        Files.writeString(scene, "sphere { radius -1 }\n");
        Path out = folder.resolve("r.png");
        Run r = run(scene.toString(), "-o", out.toString());
        assertOneLine(r, "render: cannot write '" + out + "': cannot create a file in '" + folder + "': ");
    }

    @Test
    void unwritableAovIsRefusedBeforeParsing() throws IOException {
        Path folder = unwritableFolder();
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "sphere { radius -1 }\n");
        // Passes are probed too; here the image, checked first, already fails.
        Path out = folder.resolve("r.pfm");
        Run r = run(scene.toString(), "-o", out.toString(), "--aov", "depth");
        assertOneLine(r, "render: cannot write '" + out);
    }

    @Test
    void unwritableSubdivideOutputIsRefusedBeforeReading() throws IOException {
        Path folder = unwritableFolder();
        Path mesh = dir.resolve("m.obj");
        Files.writeString(mesh, "this is not OBJ\n");
        Path out = folder.resolve("r.obj");
        Run r = run("subdivide", mesh.toString(), "--level", "1", "-o", out.toString());
        assertOneLine(r, "render: cannot write '" + out + "': cannot create a file in '" + folder + "': ");
    }

    @Test
    void writableOutputLeavesNoProbeBehind() throws IOException {
        Path out = dir.resolve("x.png");
        AtomicFile.checkWritable(out);
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(0, files.count());
        }
    }

    static final String CUBE_DAT = """
            8 6
            -1 -1 -1
            1 -1 -1
            1 1 -1
            -1 1 -1
            -1 -1 1
            1 -1 1
            1 1 1
            -1 1 1
            4 0 3 2 1
            4 4 5 6 7
            4 0 1 5 4
            4 1 2 6 5
            4 2 3 7 6
            4 3 0 4 7
            """;
}
