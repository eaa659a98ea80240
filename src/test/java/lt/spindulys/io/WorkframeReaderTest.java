package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.mesh.MeshData;

/** The Workframe .dat mesh and .tex unwrap formats of docs/mesh-formats.md. */
class WorkframeReaderTest {
    @TempDir Path dir;

    /** A square pyramid: a quad base and four triangles. */
    static final String PYRAMID = """
            # a pyramid
            5 5   # points, faces

            -1 0 -1
             1 0 -1
             1 0  1
            -1 0  1
             0 1.5e0 0
            4 0 1 2 3
            3 0 4 1
            3 1 4 2
            3 2 4 3
            3 3 4 0
            """;

    @Test
    void readsPointsAndFaces() {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        assertArrayEquals(new double[] {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1, 0, 1.5, 0}, m.positions());
        assertArrayEquals(new int[] {4, 3, 3, 3, 3}, m.faceSizes());
        assertArrayEquals(new int[] {0, 1, 2, 3, 0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0}, m.vertexIndex());
        assertNull(m.uvs());
        assertNull(m.uvIndex());
        assertNull(m.normals());
        assertEquals("pyramid.dat", m.source());
    }

    @Test
    void readsTheShippedCubeAndItsUnwrap() throws IOException {
        MeshData m = WorkframeReader.readMesh(Path.of("scenes/models/cube.dat"));
        assertEquals(8, m.vertexCount());
        assertEquals(6, m.faceCount());
        double[] uv = WorkframeReader.readUnwrap(Path.of("scenes/models/cube.tex"), m);
        assertEquals(2 * 24, uv.length);
        for (double c : uv) assertTrue(c >= 0 && c <= 1, "uv in the unit square");
    }

    @Test
    void readsAnUnwrapWithOnePointPerCorner() {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        StringBuilder tex = new StringBuilder("16 # corners\n");
        for (int i = 0; i < 16; i++) tex.append(i * 0.0625).append(' ').append(1 - i * 0.0625).append('\n');
        double[] uv = WorkframeReader.parseUnwrap(tex.toString(), "p.tex", m);
        assertEquals(32, uv.length);
        assertEquals(0.0625 * 5, uv[10]);
        assertEquals(1 - 0.0625 * 5, uv[11]);
    }

    @Test
    void windowsLineEndsAndAByteOrderMark() {
        MeshData m = WorkframeReader.parseMesh("\uFEFF" + PYRAMID.replace("\n", "\r\n"), "p.dat");
        assertEquals(5, m.faceCount());
    }

    record Bad(String name, String text, String expected) {
        @Override public String toString() { return name; }
    }

    static Stream<Bad> badMeshes() {
        return Stream.of(
                new Bad("empty", "# nothing\n", "2:1: empty mesh file: expected the header 'point_count face_count'"),
                new Bad("header with one number", "5\n", "1:2: expected the header 'point_count face_count' (two integers), found '5'"),
                new Bad("header with three numbers", "5 5 5\n", "1:5: expected the header 'point_count face_count' (two integers), found '5 5 5'"),
                new Bad("fractional count", "5.5 1\n", "1:1: expected an integer for the point count, found '5.5'"),
                new Bad("too few points for a face", "2 1\n0 0 0\n1 0 0\n", "1:1: point count must be between 3 and 100000000, found 2"),
                new Bad("no faces", "3 0\n", "1:3: face count must be between 1 and 100000000, found 0"),
                new Bad("point with two numbers", "3 1\n0 0 0\n1 0\n", "3:4: point 1 has 2 numbers, expected 3 (x y z)"),
                new Bad("point with a word", "3 1\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", "3:3: expected a number for point 1 y, found 'x'"),
                new Bad("header counts too many points", PYRAMID.replace("5 5   #", "6 5   #"), "9:1: point 5 has 5 numbers, expected 3 (x y z); this looks like a face: does the header at 2:1 count too many points?"),
                new Bad("header counts too few points", PYRAMID.replace("5 5   #", "4 5   #"), "8:2: expected face 0 ('n i0 i1 ...'), found a point: does the header at 2:1 count too few points?"),
                new Bad("face lists fewer indices", "3 1\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", "5:8: face 0 says 4 vertices but lists 3 indices"),
                new Bad("face lists more indices", "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 0\n", "5:9: face 0 says 3 vertices but lists 4 indices"),
                new Bad("face with two vertices", "3 1\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "5:1: face 0 has 2 vertices, expected at least 3"),
                new Bad("index out of range", "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "5:7: face 0 uses point 3, out of range (the mesh has 3 points, numbered from 0)"),
                new Bad("1-based indices", "3 1\n0 0 0\n1 0 0\n0 1 0\n3 1 2 3\n", "5:7: face 0 uses point 3, out of range (the mesh has 3 points, numbered from 0)"),
                new Bad("header counts too many faces", PYRAMID.replace("5 5   #", "5 6   #"), "14:1: the file ends after 5 of the 6 faces the header announces (at 2:3)"),
                new Bad("header counts too few faces", PYRAMID.replace("5 5   #", "5 4   #"), "13:1: unexpected '3 3 4 0' after the last of the 4 faces the header announces (at 2:3)"),
                new Bad("file ends in the points", "3 1\n0 0 0\n1 0 0", "3:6: the file ends after 2 of the 3 points the header announces (at 1:1)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badMeshes")
    void malformedMeshesNameLineAndColumn(Bad c) {
        SceneException e = assertThrows(SceneException.class, () -> WorkframeReader.parseMesh(c.text(), "m.dat"));
        assertEquals("m.dat:" + c.expected(), e.getMessage());
    }

    static Stream<Bad> badUnwraps() {
        return Stream.of(
                new Bad("empty", "", "1:1: empty unwrap file: expected the header 'point_count face_count' (texture points and faces) or 'corner_count' (one point per face corner)"),
                new Bad("header with three numbers", "16 2 1\n", "1:6: expected the header 'point_count face_count' (two integers: texture points and faces) or 'corner_count' (one integer: one point per face corner), found '16 2 1'"),
                new Bad("corner count that is no integer", "16.0\n", "1:1: expected an integer for the corner count, found '16.0'"),
                new Bad("wrong number of corners", "# unwrap\n12\n", "2:1: the unwrap has 12 corners but the mesh pyramid.dat has 16 face corners (one 'u v' per corner, face after face)"),
                new Bad("point with three numbers", "16\n0 0\n0 0 0\n", "3:5: corner 1 has 3 numbers, expected 2 (u v)"),
                new Bad("NaN", "16\n0 NaN\n", "2:3: expected a number for corner 0 v, found 'NaN'"),
                new Bad("too few lines", "16\n" + "0 0\n".repeat(15), "17:1: the file ends after 15 of the 16 corners the header announces (at 1:1)"),
                new Bad("too many lines", "16\n" + "0 0\n".repeat(17), "18:1: unexpected '0 0' after the last of the 16 corners the header announces (at 1:1)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badUnwraps")
    void malformedUnwrapsNameLineAndColumn(Bad c) {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        SceneException e = assertThrows(SceneException.class, () -> WorkframeReader.parseUnwrap(c.text(), "p.tex", m));
        assertEquals("p.tex:" + c.expected(), e.getMessage());
    }

    /** The pyramid's unwrap in the points-and-faces form: the base's corners and its apex at the middle. */
    static final String PYRAMID_TEX = """
            5 5
            0 0
            1 0
            1 1
            0 1
            0.5 0.5
            4 0 1 2 3
            3 0 4 1
            3 1 4 2
            3 2 4 3
            3 3 4 0
            """;

    @Test
    void readsAnUnwrapWithPointsAndFaces() {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        Unwrap u = WorkframeReader.parseTex("# the thesis's form\n" + PYRAMID_TEX, "p.tex", m);
        assertTrue(u.hasOwnFaces());
        assertArrayEquals(new double[] {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5}, u.uvs());
        assertArrayEquals(new int[] {0, 1, 2, 3, 0, 4, 1, 1, 4, 2, 2, 4, 3, 3, 4, 0}, u.uvIndex());
        assertEquals(16, u.cornerCount());
        // The per-corner view expands the points: corner 5 is face 1's apex.
        double[] corners = WorkframeReader.parseUnwrap(PYRAMID_TEX, "p.tex", m);
        assertEquals(32, corners.length);
        assertEquals(0.5, corners[10]);
        assertEquals(0.5, corners[11]);
    }

    @Test
    void pointsMayHaveAThirdNumberThatIsIgnored() {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        String uvw = PYRAMID_TEX.replace("0 0\n", "0 0 7\n").replace("1 0\n", "1 0 0\n").replace("1 1\n", "1 1 -2.5\n")
                .replace("0 1\n", "0 1 0\n").replace("0.5 0.5\n", "0.5 0.5 1e3\n");
        assertNotEquals(PYRAMID_TEX, uvw);
        Unwrap u = WorkframeReader.parseTex(uvw, "p.tex", m);
        assertArrayEquals(WorkframeReader.parseTex(PYRAMID_TEX, "p.tex", m).uvs(), u.uvs());
        assertArrayEquals(WorkframeReader.parseTex(PYRAMID_TEX, "p.tex", m).uvIndex(), u.uvIndex());
    }

    @Test
    void theShippedCubeUnwrapInBothFormsHasTheSameCorners() throws IOException {
        MeshData m = WorkframeReader.readMesh(Path.of("scenes/models/cube.dat"));
        Unwrap corners = WorkframeReader.readTex(Path.of("scenes/models/cube.tex"), m);
        Unwrap points = WorkframeReader.readTex(Path.of("scenes/models/cube-points.tex"), m);
        assertFalse(corners.hasOwnFaces());
        assertTrue(points.hasOwnFaces());
        assertEquals(24, points.uvs().length / 2);
        assertArrayEquals(corners.cornerUvs(), points.cornerUvs());
    }

    static Stream<Bad> badPointUnwraps() {
        String t = PYRAMID_TEX;
        return Stream.of(
                new Bad("face count differs", t.replaceFirst("5 5", "5 4"),
                        "1:3: the unwrap has 4 faces but the mesh pyramid.dat has 5 (one texture face per face of the mesh, in the same order)"),
                new Bad("face size differs", t.replace("3 0 4 1", "4 0 4 1 2"),
                        "8:1: face 1 has 4 corners but face 1 of the mesh pyramid.dat has 3 (a texture face has the corners of its mesh face, in the same order)"),
                new Bad("index out of range", t.replace("3 0 4 1", "3 0 5 1"), "8:5: face 1 uses texture point 5, out of range (the unwrap has 5 points, numbered from 0)"),
                new Bad("negative index", t.replace("3 0 4 1", "3 0 -1 1"), "8:5: face 1 uses texture point -1, out of range (the unwrap has 5 points, numbered from 0)"),
                new Bad("index that is no integer", t.replace("3 0 4 1", "3 a 4 1"), "8:3: expected an integer for the face 1 texture point index, found 'a'"),
                new Bad("face lists fewer indices", t.replace("3 0 4 1", "3 0 4"), "8:6: face 1 says 3 corners but lists 2 indices"),
                new Bad("face 0 cut short", t.replace("4 0 1 2 3", "4 0 1"), "7:6: face 0 says 4 corners but lists 2 indices"),
                new Bad("face lists more indices", t.replace("3 0 4 1", "3 0 4 1 1"), "8:9: face 1 says 3 corners but lists 4 indices"),
                new Bad("header counts too many points", t.replaceFirst("5 5", "6 5"),
                        "7:1: texture point 5 has 5 numbers, expected 2 (u v) or 3 (u v w, w ignored); this looks like a face: does the header at 1:1 count too many points?"),
                new Bad("header counts too few points", t.replaceFirst("5 5", "4 5"),
                        "6:1: expected face 0 ('n i0 i1 ...'), found a point: does the header at 1:1 count too few points?"),
                new Bad("points of two kinds", t.replace("1 0\n", "1 0 0\n"),
                        "3:5: texture point 1 has 3 numbers but point 0 (at 2:1) has 2 (every point 'u v', or every point 'u v w')"),
                new Bad("point with one number", t.replace("1 0\n", "1\n"), "3:2: texture point 1 has 1 number, expected 2 (u v) or 3 (u v w, w ignored)"),
                new Bad("w that is no number", t.replace("0 0\n", "0 0 x\n"), "2:5: expected a number for texture point 0 w, found 'x'"),
                new Bad("NaN", t.replace("1 1\n", "1 NaN\n"), "4:3: expected a number for texture point 2 v, found 'NaN'"),
                new Bad("no points", "0 5\n", "1:1: texture point count must be between 1 and 100000000, found 0"),
                new Bad("header announces more than the file holds", "100000 5\n",
                        "1:1: the header announces 100000 texture points and 5 faces, but the rest of the file (0 characters) has room for at most 0 lines"),
                new Bad("file ends in the points", "5 5\n0 0\n1 0\n" + "#\n".repeat(6), "10:1: the file ends after 2 of the 5 texture points the header announces (at 1:1)"),
                new Bad("file ends in the faces", t.replace("3 3 4 0\n", ""), "11:1: the file ends after 4 of the 5 faces the header announces (at 1:3)"),
                new Bad("line after the faces", t + "0 0\n", "12:1: unexpected '0 0' after the last of the 5 faces the header announces (at 1:3)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("badPointUnwraps")
    void malformedPointUnwrapsNameLineAndColumn(Bad c) {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        SceneException e = assertThrows(SceneException.class, () -> WorkframeReader.parseTex(c.text(), "p.tex", m));
        assertEquals("p.tex:" + c.expected(), e.getMessage());
    }

    @Test
    void aPointUnwrapIsCheckedAgainstTheHeapBeforeItsArraysAreMade() {
        MeshData m = WorkframeReader.parseMesh(PYRAMID, "pyramid.dat");
        try (HeapBudget.Scope ignored = HeapBudget.cap(100)) {
            SceneException e = assertThrows(SceneException.class, () -> WorkframeReader.parseTex(PYRAMID_TEX, "p.tex", m));
            // 5 points at 16 bytes and 16 corner indices at 4.
            assertTrue(e.getMessage().startsWith("p.tex:1:1: the unwrap's 5 texture points and 16 face corners needs 144 bytes of heap"), e.getMessage());
        }
    }

    @Test
    void missingAndUndecodableFiles() throws IOException {
        SceneException e = assertThrows(SceneException.class, () -> WorkframeReader.readMesh(dir.resolve("none.dat")));
        assertEquals(dir.resolve("none.dat") + ": mesh file not found (looked in " + dir.resolve("none.dat").toAbsolutePath() + ")", e.getMessage());
        Path latin1 = dir.resolve("latin1.dat");
        Files.write(latin1, new byte[] {'3', ' ', '1', '\n', (byte) 0xE9, '\n'});
        e = assertThrows(SceneException.class, () -> WorkframeReader.readMesh(latin1));
        assertEquals(latin1 + ":2:1: the mesh file is not UTF-8 text: byte 0xE9 cannot be decoded", e.getMessage());
        // The unwrap is decoded alike, placed where an editor shows the byte.
        Path mesh = dir.resolve("tri.dat");
        Files.writeString(mesh, "3 1\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
        Path tex = dir.resolve("tri.tex");
        Files.write(tex, new byte[] {'3', '\r', '\n', '0', ' ', '0', '\n', '1', ' ', (byte) 0xFF, '\n'});
        e = assertThrows(SceneException.class, () -> WorkframeReader.readUnwrap(tex, WorkframeReader.readMesh(mesh)));
        assertEquals(tex + ":3:3: the unwrap file is not UTF-8 text: byte 0xFF cannot be decoded", e.getMessage());
    }
}
