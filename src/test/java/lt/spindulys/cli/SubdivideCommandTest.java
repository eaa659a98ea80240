package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;

/** {@code render subdivide}, run in-process through {@link Main#run}. */
class SubdivideCommandTest {
    @TempDir Path dir;

    private static final Path CUBE_DAT = Path.of("scenes/models/cube.dat"), CUBE_TEX = Path.of("scenes/models/cube.tex");

    private static CliTest.Run run(String... args) {
        return CliTest.run(args);
    }

    private static RefinedMesh expected(int level, boolean uv) throws IOException {
        MeshData m = WorkframeReader.readMesh(CUBE_DAT);
        SubdivInput in = SubdivInput.of(m);
        if (uv) in = in.withCornerUvs(WorkframeReader.readUnwrap(CUBE_TEX, m));
        return CatmullClark.refine(in.toControlMesh(), level);
    }

    @Test
    void writesTheRefinedMeshAsObj() throws IOException {
        Path out = dir.resolve("cube2.obj");
        CliTest.Run r = run("subdivide", CUBE_DAT.toString(), "--level", "2", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        RefinedMesh e = expected(2, false);
        MeshData m = ObjReader.read(out);
        assertArrayEquals(e.positions(), m.positions(), "positions read back exactly");
        assertArrayEquals(e.faceSizes(), m.faceSizes());
        assertArrayEquals(e.faceVertices(), m.vertexIndex());
        assertNull(m.uvs());
        assertNull(m.normals());
        assertTrue(Files.readString(out).startsWith("# Catmull-Clark subdivision of cube.dat at level 2"));
    }

    @Test
    void limitPositionsNormalsAndUvs() throws IOException {
        Path out = dir.resolve("cube1.obj");
        CliTest.Run r = run("subdivide", CUBE_DAT.toString(), "--limit", "--uv", CUBE_TEX.toString(), "--level", "1", "--output", out.toString());
        assertEquals(0, r.status(), r.err());
        RefinedMesh e = expected(1, true);
        MeshData m = ObjReader.read(out);
        assertArrayEquals(e.limitPositions(), m.positions());
        assertArrayEquals(e.limitNormals(), m.normals());
        assertArrayEquals(e.uvs(), m.uvs());
        assertArrayEquals(e.faceUvs(), m.uvIndex());
        assertArrayEquals(e.faceVertices(), m.normalIndex(), "one normal per vertex");
    }

    @Test
    void holesAreLeftOutAndIgnoredTagsNoted() throws IOException {
        Path in = dir.resolve("holed.obj");
        Files.writeString(in, Files.readString(Path.of("scenes/models/crease-cube.obj")) + "t hole 1/0/0 2\nt vertexedit 0/0/0\n");
        Path out = dir.resolve("holed1.obj");
        CliTest.Run r = run("subdivide", in.toString(), "--level", "1", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals(in + ": note: tag 'vertexedit' is ignored (OpenSubdiv's Far does not apply it either)" + System.lineSeparator(), r.err());
        MeshData m = ObjReader.read(out);
        assertEquals(24 - 4, m.faceCount());
    }

    @Test
    void helpIsPrinted() {
        CliTest.Run r = run("subdivide", "--help");
        assertEquals(0, r.status());
        assertTrue(r.out().startsWith("usage: render subdivide MESH.obj|MESH.dat --level N -o OUT.obj"), r.out());
        assertTrue(run("--help").out().contains("render subdivide"), "the main help mentions it");
    }

    @Test
    void badUsageIsOneLineExitsTwoAndWritesNothing() throws IOException {
        String in = CUBE_DAT.toString(), out = dir.resolve("o.obj").toString();
        String[][] cases = {
                {"render: subdivide needs --level N (see render subdivide --help)", "subdivide", in, "-o", out},
                {"render: subdivide needs an output file: -o OUT.obj (see render subdivide --help)", "subdivide", in, "--level", "1"},
                {"render: no mesh given to subdivide (see render subdivide --help)", "subdivide", "--level", "1", "-o", out},
                {"render: --level must be between 0 and 8, found 9", "subdivide", in, "--level", "9", "-o", out},
                {"render: --level expects a whole number, found 'two'", "subdivide", in, "--level", "two", "-o", out},
                {"render: option --level needs a value", "subdivide", in, "--level"},
                {"render: unknown option '--levle' for subdivide (see render subdivide --help)", "subdivide", in, "--levle", "1", "-o", out},
                {"render: the output of subdivide must be an .obj file, found '" + dir.resolve("o.ply") + "'", "subdivide", in, "--level", "1", "-o", dir.resolve("o.ply").toString()},
                {"render: the mesh to subdivide must be an .obj or a .dat file, found 'cube.ply'", "subdivide", "cube.ply", "--level", "1", "-o", out},
                {"render: more than one mesh given: '" + in + "' and 'x.obj'", "subdivide", in, "x.obj", "--level", "1", "-o", out},
                {"render: cannot write '" + dir.resolve("no/o.obj") + "': directory '" + dir.resolve("no") + "' does not exist", "subdivide", in, "--level", "1", "-o", dir.resolve("no/o.obj").toString()},
        };
        for (String[] c : cases) {
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            CliTest.Run r = run(args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(c[0] + System.lineSeparator(), r.err(), String.join(" ", args));
        }
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(0, files.count(), "nothing written");
        }
    }

    @Test
    void badInputNamesTheFileAndLeavesAnExistingOutput() throws IOException {
        Path out = dir.resolve("keep.obj");
        Files.writeString(out, "old");
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1 x\n");
        Path badTex = dir.resolve("bad.tex");
        Files.writeString(badTex, "23\n" + "0 0\n".repeat(23));
        Path missing = dir.resolve("missing.dat");
        String[][] cases = {
                {bad + ":5:20: expected a number for sharpness 1 of 1 of tag 'crease' (its counts 2/1/0 say 2 integers, 1 float and 0 strings), found 'x'",
                        "subdivide", bad.toString(), "--level", "1", "-o", out.toString()},
                {badTex + ":1:1: the unwrap has 23 corners but the mesh " + CUBE_DAT + " has 24 face corners (one 'u v' per corner, face after face)",
                        "subdivide", CUBE_DAT.toString(), "--uv", badTex.toString(), "--level", "1", "-o", out.toString()},
                {missing + ": mesh file not found (looked in " + missing.toAbsolutePath() + ")", "subdivide", missing.toString(), "--level", "1", "-o", out.toString()},
        };
        for (String[] c : cases) {
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            CliTest.Run r = run(args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(c[0] + System.lineSeparator(), r.err());
        }
        assertEquals("old", Files.readString(out), "existing output untouched");
        try (Stream<Path> files = Files.list(dir)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().endsWith(".tmp")), "no temporary file left");
        }
    }
}
