package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.io.BadInputCases;

/**
 * Every malformed scene of {@link BadInputCases}, and malformed OBJ meshes, run through the
 * command line: exit status 2, exactly one line on stderr with the location and message, and no
 * image (nor temporary file) left behind.
 */
class CliBadInputTest {
    @TempDir Path dir;

    static List<BadInputCases.Case> scenes() { return BadInputCases.scenes(); }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void malformedSceneFailsCleanly(BadInputCases.Case c) throws IOException {
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, c.scene());
        c.writeFiles(dir);
        assertFailsCleanly(scene, c.expectedMessage(scene.toString(), dir));
    }

    /** A malformed OBJ file and the message expected after its path. */
    record ObjCase(String name, String obj, String expected) {
        @Override public String toString() { return name; }
    }

    static Stream<ObjCase> objs() {
        return Stream.of(
                new ObjCase("letters for a coordinate", "v 0 0 0\nv 1 abc 0\n", "2:5: expected a number for vertex y, found 'abc'"),
                new ObjCase("vertex with two coordinates", "v 0 0\n", "1:6: expected a number for vertex z, found end of line"),
                new ObjCase("face index out of range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "4:7: f index 4 out of range (the file has 3 vertices so far)"),
                new ObjCase("face index zero", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "4:3: index 0 is not valid (OBJ indices start at 1)"),
                new ObjCase("face with two corners", "v 0 0 0\nv 1 0 0\nf 1 2\n", "3:1: face has 2 vertices, expected at least 3"),
                new ObjCase("unknown statement", "v 0 0 0\nvx 1 2 3\n", "2:1: unknown OBJ statement 'vx'"),
                new ObjCase("negative index too far back", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n", "4:9: f index -4 out of range (the file has 3 vertices so far)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("objs")
    void malformedObjFailsCleanly(ObjCase c) throws IOException {
        Path obj = dir.resolve("m.obj");
        Files.writeString(obj, c.obj());
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nmesh { file \"m.obj\" }\n");
        assertFailsCleanly(scene, obj.toAbsolutePath().normalize() + ":" + c.expected());
    }

    /** A file given as the scene, its content, and whether it is a mesh (and of which kind) rather than a scene. */
    record MeshCase(String file, String content, String kind, String at) {
        MeshCase(String file, String content, String kind) { this(file, content, kind, kind == null || kind.contains("OBJ") ? "" : ":1:1"); }

        @Override public String toString() { return file + " " + (kind == null ? "is no mesh" : kind); }
    }

    static Stream<MeshCase> meshesGivenAsScenes() {
        return Stream.of(
                new MeshCase("knot.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "an OBJ mesh"),
                new MeshCase("KNOT.OBJ", "# exported\nv 0 0 0\n", "an OBJ mesh"),
                new MeshCase("cube.dat", "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "a Workframe mesh"),
                new MeshCase("commented.dat", "\uFEFF# a cube from the modeller\r\n\r\n  # points, faces\n\t8 6\n", "a Workframe mesh", ":4:2"),
                new MeshCase("signed.dat", "+3 1\n", "a Workframe mesh"),
                // Not meshes: the scene parser reports these as it always did.
                new MeshCase("decimal.dat", "2.5 1\n", null),
                new MeshCase("word.dat", "sphere { radius 1e }\n", null),
                new MeshCase("digits-then-letters.dat", "3x 1\n", null),
                new MeshCase("empty.dat", "", null),
                // Known by content, whatever the extension.
                new MeshCase("numbers.txt", "3 1\n", "a Workframe mesh"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("meshesGivenAsScenes")
    void aMeshGivenAsTheSceneIsNamedAsOne(MeshCase c) throws IOException {
        Path file = dir.resolve(c.file());
        Files.writeString(file, c.content());
        assertEquals(c.kind() != null && c.kind().contains("OBJ"), RenderCommand.isObjMesh(file));
        if (c.kind() == null) {
            CliTest.Run r = CliTest.run(file.toString(), "-o", dir.resolve("out.png").toString(), "--quiet");
            assertFalse(r.err().contains("not a scene"), r.err());
            return;
        }
        assertFailsCleanly(file, file + c.at() + ": this is " + c.kind() + ", not a scene: to render it, name it in a scene's mesh { file \""
                + c.file() + "\" } or subdiv { file \"" + c.file() + "\" } block, or refine it with render subdivide");
    }

    @Test
    void theRepositorysOwnMeshesAreNamedAsMeshes() throws IOException {
        assertTrue(RenderCommand.isObjMesh(Path.of("scenes/models/knot.obj")));
        CliTest.Run r = CliTest.run("scenes/models/cube.dat", "-o", dir.resolve("out.png").toString(), "--quiet");
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("this is a Workframe mesh, not a scene"), r.err());
        assertFalse(RenderCommand.isObjMesh(Path.of("scenes/spheres.dat")));
    }

    /** Scenes whose error echoes hostile input: huge tokens, control characters, line separators. */
    static Stream<String> hostileScenes() {
        String mb = "7".repeat(1 << 20), tenMb = "q".repeat(10 << 20);
        return Stream.of(
                "sphere { " + tenMb + " 1 }",
                tenMb + " { }",
                "sphere { radius " + mb + " }",
                "settings { encoding " + tenMb + " }",
                "material m { kd 1 }\nsphere { material " + tenMb + " }",
                "material " + tenMb + " { kd 1 }\nsphere { material " + tenMb.substring(1) + " }",
                "sphere { radius 1\u0000\u007F\u2028\u2029\u0085 }",
                "sphere { name \"\u0000\u0007\u001B[2J\u009B\" radius \"\u2028\" }",
                "mesh { file \"a\u2028b\u0000" + mb + ".obj\" }");
    }

    @ParameterizedTest
    @MethodSource("hostileScenes")
    void anErrorIsOneShortLineWhateverTheInput(String text) throws IOException {
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, text);
        assertOneShortLine(CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--quiet"));
    }

    @Test
    void aFileNameWithALineBreakStaysOnOneLine() {
        CliTest.Run r = CliTest.run(dir.resolve("two\nlines\u2028.dat").toString(), "-o", dir.resolve("out.png").toString());
        assertOneShortLine(r);
        assertTrue(r.err().contains("two\\nlines\\u2028.dat"), r.err());
    }

    /** A motion that fits the file's shutter but not the one given on the command line is reported at its object's statement. */
    @Test
    void aMotionOutsideTheShutterGivenIsReportedAtItsObject() throws IOException {
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nunion {\n  box { min 0 0 0 max 1 1 1 }\n"
                + "  sphere { motion { translate 1 0 0  start 0.5 } }\n}\n");
        Path out = dir.resolve("out.png");
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet", "--shutter", "0,0.2");
        assertEquals(2, r.status(), r.err());
        assertEquals(scene + ":4:3: sphere: motion finish must be after its start, found start 0.5 and finish 0.2"
                + " (finish is the shutter close time) (with --shutter 0.0,0.2)" + System.lineSeparator(), r.err());
        assertFalse(Files.exists(out), "no image written");
    }

    private static void assertOneShortLine(CliTest.Run r) {
        assertEquals(2, r.status(), r.err());
        String line = r.err();
        assertTrue(line.endsWith(System.lineSeparator()), line);
        line = line.substring(0, line.length() - System.lineSeparator().length());
        assertTrue(line.length() < 300, line.length() + " characters: " + line.substring(0, Math.min(line.length(), 300)));
        assertTrue(line.chars().allMatch(c -> c >= 0x20 && !(c >= 0x7F && c <= 0x9F) && c != 0x2028 && c != 0x2029), line);
    }

    /** Adaptive subdivision options refused with one line naming the option; no image written. */
    static Stream<List<String>> badSubdivOptions() {
        return Stream.of(
                List.of("--subdiv-target", "0", "render: --subdiv-target must be between 0.01 and 1000000, found 0"),
                List.of("--subdiv-target", "NaN", "render: --subdiv-target must be between 0.01 and 1000000, found NaN"),
                List.of("--subdiv-target", "-1", "render: --subdiv-target must be between 0.01 and 1000000, found -1"),
                List.of("--subdiv-target", "fine", "render: --subdiv-target expects a number, found 'fine'"),
                List.of("--subdiv-memory", "-1", "render: --subdiv-memory must be between 0 and 16777216, found -1"),
                List.of("--subdiv-memory", "1e12", "render: --subdiv-memory must be between 0 and 16777216, found 1e12"),
                List.of("--subdiv-cache", "0", "render: --subdiv-cache must be more than 0 (mebibytes of the lazy patches' cache), found 0"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badSubdivOptions")
    void badSubdivOptionFailsCleanly(List<String> c) throws IOException {
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, "camera { eye 0 0 -5 lookat 0 0 0 }\nsubdiv { file \"cube.dat\"  method lazy }\n");
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Path out = dir.resolve("out.png");
        List<String> args = new java.util.ArrayList<>(List.of(scene.toString(), "-o", out.toString(), "--quiet", "--width", "16"));
        args.addAll(c.subList(0, c.size() - 1));
        CliTest.Run r = CliTest.run(args.toArray(new String[0]));
        assertEquals(2, r.status(), r.err());
        assertEquals(c.get(c.size() - 1) + System.lineSeparator(), r.err());
        assertFalse(Files.exists(out), "no image written");
    }

    private void assertFailsCleanly(Path scene, String expected) throws IOException {
        Path out = dir.resolve("out.png");
        CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet");
        assertEquals(2, r.status(), r.err());
        assertEquals(expected + System.lineSeparator(), r.err());
        assertFalse(Files.exists(out), "no image written");
        try (Stream<Path> files = Files.list(dir)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().endsWith(".tmp")), "no temporary file left");
        }
    }
}
