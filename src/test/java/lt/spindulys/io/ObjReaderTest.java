package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.mesh.MeshData;

class ObjReaderTest {
    private static final String QUAD = """
            # a unit quad in every face form
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0 1.0
            vt 0 0
            vt 1 0 0
            vt 1 1
            vt 0.5
            vn 0 0 1
            f 1 2 3
            f 1/1 2/2 3/3
            f 1//1 2//1 3//1
            f 1/1/1 2/2/1 3/3/1 4/4/1
            """;

    @Test
    void readsEveryFaceForm() {
        MeshData m = ObjReader.parse(QUAD, "quad.obj");
        assertArrayEquals(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, m.positions());
        assertArrayEquals(new double[] {0, 0, 1, 0, 1, 1, 0.5, 0}, m.uvs(), "w ignored, a missing v is 0");
        assertArrayEquals(new double[] {0, 0, 1}, m.normals());
        assertArrayEquals(new int[] {3, 3, 3, 4}, m.faceSizes());
        assertArrayEquals(new int[] {0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 3}, m.vertexIndex());
        assertArrayEquals(new int[] {-1, -1, -1, 0, 1, 2, -1, -1, -1, 0, 1, 2, 3}, m.uvIndex());
        assertArrayEquals(new int[] {-1, -1, -1, -1, -1, -1, 0, 0, 0, 0, 0, 0, 0}, m.normalIndex());
        assertEquals("quad.obj", m.source());
    }

    @Test
    void withoutNormalsOrUvsTheArraysAreNull() {
        MeshData m = ObjReader.parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj");
        assertNull(m.normals());
        assertNull(m.uvs());
        assertNull(m.normalIndex());
        assertNull(m.uvIndex());
        assertEquals(1, m.faceCount());
    }

    @Test
    void negativeIndicesCountBackFromTheLatestElement() {
        String text = """
                v 0 0 0
                v 1 0 0
                v 1 1 0
                v 0 1 0
                vt 0 0
                vt 1 1
                vn 0 0 1
                f -4/-2/-1 -3/-1/-1 -2/-1/-1 -1/-2/-1
                v 5 5 5
                f -1 -2 -5
                f 2 -1 +3
                """;
        MeshData m = ObjReader.parse(text, "neg.obj");
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 3, 0, 1, 4, 2}, m.vertexIndex());
        assertArrayEquals(new int[] {0, 1, 1, 0, -1, -1, -1, -1, -1, -1}, m.uvIndex());
        assertArrayEquals(new int[] {0, 0, 0, 0, -1, -1, -1, -1, -1, -1}, m.normalIndex());
    }

    @Test
    void polygonsOfAnySize() {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 7; i++) s.append("v ").append(Math.cos(i)).append(' ').append(Math.sin(i)).append(" 0\n");
        s.append("f 1 2 3 4 5 6 7\nf 1 2 3 4 5\n");
        MeshData m = ObjReader.parse(s.toString(), "poly.obj");
        assertArrayEquals(new int[] {7, 5}, m.faceSizes());
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5, 6, 0, 1, 2, 3, 4}, m.vertexIndex());
    }

    @Test
    void commentsBlankLinesSkippedStatementsAndContinuations() {
        String text = "# comment line\n"
                + "mtllib scene.mtl\n"
                + "\n"
                + "   \t  \n"
                + "o thing\n"
                + "g group one\n"
                + "s off\n"
                + "usemtl red\n"
                + "  v 1 2 3   # trailing comment\n"
                + "\tv 4 5 6\t\n"
                + "v 7 8 9#glued comment\n"
                + "t crease 2/1/0 1 2 4.0\n"
                + "f 1 2 \\\n"
                + "   3\n"
                + "#f 1 2 3 (commented out)\n"
                + "# last line without newline";
        MeshData m = ObjReader.parse(text, "c.obj");
        assertArrayEquals(new double[] {1, 2, 3, 4, 5, 6, 7, 8, 9}, m.positions());
        assertArrayEquals(new int[] {3}, m.faceSizes());
        assertArrayEquals(new int[] {0, 1, 2}, m.vertexIndex());
    }

    @Test
    void crlfAndLoneCrLineEndingsReadLikeLf() {
        MeshData lf = ObjReader.parse(QUAD, "a.obj");
        for (String eol : new String[] {"\r\n", "\r"}) {
            MeshData m = ObjReader.parse(QUAD.replace("\n", eol), "a.obj");
            assertArrayEquals(lf.positions(), m.positions());
            assertArrayEquals(lf.uvs(), m.uvs());
            assertArrayEquals(lf.vertexIndex(), m.vertexIndex());
            assertArrayEquals(lf.uvIndex(), m.uvIndex());
            assertArrayEquals(lf.normalIndex(), m.normalIndex());
        }
        SceneException e = assertThrows(SceneException.class,
                () -> ObjReader.parse("v 0 0 0\r\nv 1 0 0\r\nv 1 x 0\r\n", "crlf.obj"));
        assertEquals("crlf.obj:3:5: expected a number for vertex y, found 'x'", e.getMessage());
    }

    @Test
    void vertexColoursAreAcceptedAndIgnored() {
        MeshData m = ObjReader.parse("v 1 2 3 0.5 0.25 1\nv 4 5 6\n", "col.obj");
        assertArrayEquals(new double[] {1, 2, 3, 4, 5, 6}, m.positions());
    }

    @Test
    void numbersAreParsedExactlyLikeDoubleParseDouble() {
        Random r = new Random(7);
        StringBuilder s = new StringBuilder();
        double[] expected = new double[3 * 3000];
        for (int i = 0; i < expected.length; i++) {
            double x = switch (i % 6) {
                case 0 -> r.nextGaussian();
                case 1 -> (r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(40) - 20);
                case 2 -> r.nextInt(2000) - 1000;
                case 3 -> Double.longBitsToDouble(r.nextLong() & 0x7fefffffffffffffL) * (r.nextBoolean() ? 1 : -1);
                case 4 -> Math.scalb(r.nextDouble(), r.nextInt(200) - 100);
                default -> r.nextDouble();
            };
            // Mesh numbers are at most 1e15 in magnitude: larger ones keep their digits at a smaller exponent.
            if (Math.abs(x) > 1e14) x = Math.scalb(x, 40 - Math.getExponent(x));
            String text = switch (i % 5) {
                case 0 -> Double.toString(x);
                case 1 -> String.format(Locale.ROOT, "%.6f", x);
                case 2 -> String.format(Locale.ROOT, "%.17g", x);
                case 3 -> String.format(Locale.ROOT, "%.9e", x);
                default -> String.format(Locale.ROOT, "%.3E", x);
            };
            expected[i] = Double.parseDouble(text);
            s.append(i % 3 == 0 ? "v " : " ").append(text).append(i % 3 == 2 ? "\n" : "");
        }
        s.append("v .5 -.25 +3.\nv 1e3 -2.5E-2 0001.2500\nv 0.1234567890123456789012 123456789012345.678901234 -0.0\n");
        MeshData m = ObjReader.parse(s.toString(), "n.obj");
        double[] p = m.positions();
        for (int i = 0; i < expected.length; i++) {
            assertEquals(Double.doubleToLongBits(expected[i]), Double.doubleToLongBits(p[i]), () -> "number " + p.length);
        }
        int o = expected.length;
        assertArrayEquals(new double[] {0.5, -0.25, 3, 1000, -0.025, 1.25,
                0.1234567890123456789012, 123456789012345.678901234, -0.0}, java.util.Arrays.copyOfRange(p, o, o + 9));
        assertEquals(Double.doubleToLongBits(-0.0), Double.doubleToLongBits(p[o + 8]));
    }

    private static void assertError(String text, String expected) {
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.parse(text, "bad.obj"));
        assertEquals(expected, e.getMessage());
    }

    private static final String EIGHT = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";

    @Test
    void malformedInputIsReportedWithLineAndColumn() {
        assertError("v 0 0 0\nv 1.0 abc 3\n", "bad.obj:2:7: expected a number for vertex y, found 'abc'");
        assertError("v 0 0 0\nv 1 2\n", "bad.obj:2:6: expected a number for vertex z, found end of line");
        assertError("v 1 2 3\nv 1.5.2 0 0\n", "bad.obj:2:3: expected a number for vertex x, found '1.5.2'");
        assertError("v 1 2 1e400\n", "bad.obj:1:7: number 1e400 is too large for vertex z (mesh numbers are at most 1e15 in magnitude)");
        assertError(EIGHT + "f 1 2 12\n", "bad.obj:9:7: f index 12 out of range (the file has 8 vertices so far)");
        assertError(EIGHT + "f 1 -9 2\n", "bad.obj:9:5: f index -9 out of range (the file has 8 vertices so far)");
        assertError(EIGHT + "vt 0 0\nf 1/1 2/2 3/1\n", "bad.obj:10:9: f texture coordinate index 2 out of range (the file has 1 texture coordinate so far)");
        assertError(EIGHT + "# two corners\n  f 1 2\n", "bad.obj:10:3: face has 2 vertices, expected at least 3");
        assertError(EIGHT + "f 1 0 2\n", "bad.obj:9:5: index 0 is not valid (OBJ indices start at 1)");
        assertError(EIGHT + "\nvx 1 2 3\n", "bad.obj:10:1: unknown OBJ statement 'vx'");
        assertError(EIGHT + "vt 0 0\nf 1/1 2/1 3\n", "bad.obj:10:11: face mixes corners with and without texture coordinates");
        assertError(EIGHT + "vn 0 0 1\nf 1//1 2 3//1\n", "bad.obj:10:8: face mixes corners with and without normals");
        assertError(EIGHT + "vt 0 0\nvn 0 0 1\nf 1/1/1/1 2 3\n", "bad.obj:11:8: unexpected '/1' in face corner (expected v, v/vt, v//vn or v/vt/vn)");
        assertError(EIGHT + "f 1 2 x\n", "bad.obj:9:7: expected a vertex index, found 'x'");
        assertError("vn 0 0 1 5\n", "bad.obj:1:10: unexpected '5' after the normal (expected x y z)");
        assertError("v 1 2 3 4 5\n", "bad.obj:1:9: vertex has 5 numbers, expected 3 (x y z), 4 (x y z w) or 6 (x y z r g b)");
        assertError(EIGHT + "l 1 2\n", "bad.obj:9:1: OBJ statement 'l' (polylines) is not supported");
        // Columns count characters, not bytes, and a tab is one column.
        assertError("v 0 0 0\n\tv 1 ž 0 # ž\n", "bad.obj:2:6: expected a number for vertex y, found 'ž'");
        // A continued line reports the physical line and column.
        assertError("v 0 0 \\\n  q\n", "bad.obj:2:3: expected a number for vertex z, found 'q'");
    }

    @Test
    void readsFilesAndNamesThemInErrors(@TempDir Path dir) throws Exception {
        Path ok = dir.resolve("tri.obj");
        Files.writeString(ok, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", StandardCharsets.UTF_8);
        MeshData m = ObjReader.read(ok);
        assertEquals(3, m.vertexCount());
        assertEquals(ok.toString(), m.source());

        Path bad = dir.resolve("torus.obj");
        Files.writeString(bad, "v 0 0 0\nf 1 2 3\n", StandardCharsets.UTF_8);
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.read(bad));
        assertEquals(bad + ":2:5: f index 2 out of range (the file has 1 vertex so far)", e.getMessage());
        assertEquals(2, e.line());
        assertEquals(5, e.column());

        Path missing = dir.resolve("nope.obj");
        SceneException n = assertThrows(SceneException.class, () -> ObjReader.read(missing));
        assertTrue(n.getMessage().startsWith(missing + ": OBJ file not found (looked in "), n.getMessage());
    }

    @Test
    void largeFilesParseQuickly() {
        // A 200 x 200 grid of quads (~2.3 MB): a functional check of the growth paths.
        int n = 200;
        StringBuilder s = new StringBuilder();
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                s.append(String.format(Locale.ROOT, "v %.6f %.6f %.6f\nvt %.6f %.6f\n", i / (double) n, j / (double) n, Math.sin(i * 0.1), i / (double) n, j / (double) n));
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
                s.append("f ").append(a).append('/').append(a).append(' ').append(b).append('/').append(b).append(' ')
                        .append(c).append('/').append(c).append(' ').append(d).append('/').append(d).append('\n');
            }
        }
        MeshData m = ObjReader.parse(s.toString(), "grid.obj");
        assertEquals((n + 1) * (n + 1), m.vertexCount());
        assertEquals(n * n, m.faceCount());
        assertEquals(1.0, m.positions()[3 * n]);
        assertEquals(n * n * 4, m.uvIndex().length);
    }
}
