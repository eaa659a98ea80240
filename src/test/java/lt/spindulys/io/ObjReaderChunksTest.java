package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.mesh.MeshData;

/**
 * A file parsed in chunks on several threads gives the same mesh, and the same error at the same
 * line and column, as parsed in one piece, whatever the number of chunks and threads.
 */
class ObjReaderChunksTest {
    private static final int[][] SPLITS = {{1, 1}, {2, 2}, {7, 2}, {7, 3}, {50, 1}, {50, 4}};

    /**
     * Every statement form: negative and positive indices, indices into earlier chunks, comments,
     * skipped statements, blank lines, continued lines, CRLF and lone CR line ends, a BOM.
     */
    private static String mixed(long seed, int rounds) {
        Random r = new Random(seed);
        StringBuilder s = new StringBuilder("\uFEFF# mixed\nmtllib m.mtl\n");
        int v = 0, t = 0, n = 0;
        for (int i = 0; i < rounds; i++) {
            String eol = switch (r.nextInt(8)) {
                case 0 -> "\r\n";
                case 1 -> "\r";
                default -> "\n";
            };
            switch (r.nextInt(12)) {
                case 0, 1, 2 -> {
                    s.append("v ").append(r.nextGaussian()).append(' ').append(r.nextInt(100) - 50).append(' ').append(r.nextFloat());
                    if (r.nextInt(5) == 0) s.append(" 0.5 0.25 1");
                    v++;
                }
                case 3 -> {
                    s.append("vt ").append(r.nextDouble()).append(r.nextBoolean() ? " 0.25" : "");
                    t++;
                }
                case 4 -> {
                    s.append("vn 0 ").append(r.nextDouble()).append(" -1e-3");
                    n++;
                }
                case 5 -> s.append(switch (r.nextInt(6)) {
                    case 0 -> "o part" + i;
                    case 1 -> "g a b";
                    case 2 -> "s " + (r.nextBoolean() ? "off" : "1");
                    case 3 -> "usemtl red";
                    case 4 -> "  # comment \\";
                    default -> "";
                });
                case 6 -> s.append("v 1 \\").append(eol).append("  2 3");
                default -> {
                    if (v < 3) continue;
                    int corners = 3 + r.nextInt(3);
                    boolean withT = t > 0 && r.nextBoolean(), withN = n > 0 && r.nextBoolean();
                    s.append('f');
                    for (int c = 0; c < corners; c++) {
                        s.append(c == 2 && r.nextInt(4) == 0 ? " \\" + eol + " " : " ");
                        s.append(index(r, v));
                        if (withT || withN) s.append('/');
                        if (withT) s.append(index(r, t));
                        if (withN) s.append('/').append(index(r, n));
                    }
                    s.append(r.nextInt(6) == 0 ? " # a face" : "");
                }
            }
            s.append(eol);
        }
        return s.toString();
    }

    /** A valid index of one of {@code count} elements: from the start, or back from the latest. */
    private static String index(Random r, int count) {
        int i = r.nextInt(count);
        return r.nextBoolean() ? Integer.toString(i + 1) : Integer.toString(i - count);
    }

    private static void assertSameMesh(MeshData expected, MeshData m, String what) {
        assertArrayEquals(expected.positions(), m.positions(), what + ": positions");
        assertArrayEquals(expected.normals(), m.normals(), what + ": normals");
        assertArrayEquals(expected.uvs(), m.uvs(), what + ": uvs");
        assertArrayEquals(expected.faceSizes(), m.faceSizes(), what + ": face sizes");
        assertArrayEquals(expected.vertexIndex(), m.vertexIndex(), what + ": vertex indices");
        assertArrayEquals(expected.normalIndex(), m.normalIndex(), what + ": normal indices");
        assertArrayEquals(expected.uvIndex(), m.uvIndex(), what + ": uv indices");
        assertEquals(expected.source(), m.source());
    }

    @Test
    void everyChunkCountGivesTheSameMesh() {
        for (long seed = 1; seed <= 4; seed++) {
            byte[] bytes = mixed(seed, 20_000).getBytes(StandardCharsets.UTF_8);
            MeshData one = ObjReader.parse(bytes, "m.obj", 1, 1);
            assertTrue(one.faceCount() > 5000 && one.normals() != null && one.uvIndex() != null, "the file has every kind of element");
            for (int[] split : SPLITS) {
                assertSameMesh(one, ObjReader.parse(bytes, "m.obj", split[0], split[1]), split[0] + " chunks on " + split[1] + " threads");
            }
        }
    }

    @Test
    void negativeIndicesIntoEarlierChunksAndMissingOptionalArrays() {
        // Only vertices first, then faces that count back into them from far later chunks.
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < 3000; i++) s.append("v ").append(i).append(" 0 0\n");
        for (int i = 0; i < 3000; i++) s.append("f -3000 ").append(i % 2998 + 2).append(" -1\n");
        byte[] bytes = s.toString().getBytes(StandardCharsets.UTF_8);
        MeshData one = ObjReader.parse(bytes, "n.obj", 1, 1);
        assertNull(one.normals());
        assertNull(one.uvIndex());
        assertEquals(0, one.vertexIndex()[0]);
        assertEquals(2999, one.vertexIndex()[2]);
        for (int[] split : SPLITS) assertSameMesh(one, ObjReader.parse(bytes, "n.obj", split[0], split[1]), split[0] + " chunks");
    }

    @Test
    void chunksAreTakenSpreadOverTheFileEachOnce() {
        assertArrayEquals(new int[] {0, 4, 2, 6, 1, 3, 5}, ObjChunks.spread(7));
        for (int n = 1; n <= 100; n++) {
            int[] order = ObjChunks.spread(n);
            int[] sorted = order.clone();
            java.util.Arrays.sort(sorted);
            for (int k = 0; k < n; k++) assertEquals(k, sorted[k], "each of " + n + " chunks once");
        }
    }

    @Test
    void chunksNeverStartInsideAContinuedStatement() {
        // Every line but the last of each face is continued: a chunk may start only after the last.
        StringBuilder s = new StringBuilder("v 0 0 0\nv 1 0 0\nv 0 1 0\n");
        for (int i = 0; i < 2000; i++) s.append("f 1 \\\n 2 \\\r\n 3").append(i % 2 == 0 ? "\n" : "\r\n");
        byte[] bytes = s.toString().getBytes(StandardCharsets.UTF_8);
        for (int chunks : new int[] {2, 7, 300}) {
            int[] starts = ObjChunks.split(bytes, chunks);
            assertEquals(bytes.length, starts[starts.length - 1]);
            for (int k = 1; k < starts.length - 1; k++) {
                String before = new String(bytes, starts[k] - 2, 2, StandardCharsets.ISO_8859_1);
                assertTrue(bytes[starts[k]] == 'f', "chunk " + k + " starts at a face, after '" + before + "'");
            }
            assertEquals(2000, ObjReader.parse(bytes, "c.obj", chunks, 2).faceCount());
        }
    }

    @Test
    void aLargeFileIsReadAndParsedInChunks(@TempDir Path dir) throws Exception {
        StringBuilder s = new StringBuilder();
        while (s.length() <= ObjReader.PARALLEL_BYTES) s.append(mixed(s.length(), 20_000));
        byte[] bytes = s.toString().replace("\uFEFF", "").getBytes(StandardCharsets.UTF_8);
        Path file = Files.write(dir.resolve("large.obj"), bytes);
        assertSameMesh(ObjReader.parse(bytes, file.toString(), 1, 1), ObjReader.read(file), "read");
    }

    /** The error in a file of valid lines with {@code bad} at line {@code at}, the same for every split. */
    private static String errorOf(String head, String bad, int tailLines) {
        StringBuilder s = new StringBuilder(head).append(bad);
        for (int i = 0; i < tailLines; i++) s.append("v ").append(i).append(" 1 2\n");
        byte[] bytes = s.toString().getBytes(StandardCharsets.UTF_8);
        String message = assertThrows(SceneException.class, () -> ObjReader.parse(bytes, "e.obj", 1, 1)).getMessage();
        for (int[] split : SPLITS) {
            SceneException e = assertThrows(SceneException.class, () -> ObjReader.parse(bytes, "e.obj", split[0], split[1]));
            assertEquals(message, e.getMessage(), split[0] + " chunks on " + split[1] + " threads");
        }
        return message;
    }

    private static String vertices(int n) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < n; i++) s.append("v ").append(i).append(" 0 0\n");
        return s.toString();
    }

    @Test
    void errorsAreTheSameForEveryChunkCount() {
        String head = vertices(4000);
        assertEquals("e.obj:4001:7: expected a number for vertex y, found 'abc'", errorOf(head, "v 1.0 abc 3\n", 4000));
        // An index past the vertices so far, which the chunk alone cannot know.
        assertEquals("e.obj:4001:7: f index 4001 out of range (the file has 4000 vertices so far)", errorOf(head, "f 1 2 4001\n", 4000));
        assertEquals("e.obj:4001:5: f index -4001 out of range (the file has 4000 vertices so far)", errorOf(head, "f 1 -4001 2\n", 4000));
        assertEquals("e.obj:4001:5: f texture coordinate index 1 out of range (the file has 0 texture coordinates so far)",
                errorOf(head, "f 1/1 2/1 3/1\n", 4000));
        // A later face that is valid only with the vertices after it: the first error in file order wins.
        assertEquals("e.obj:4001:7: f index 7000 out of range (the file has 4000 vertices so far)",
                errorOf(head, "f 1 2 7000\n" + vertices(3000) + "v 1 x 1\n", 4000));
        assertEquals("e.obj:8003:1: unknown OBJ statement 'vx'", errorOf(head + "\r\n\r" + vertices(4000), "vx 1 2 3\n", 100));
        assertEquals("e.obj:4002:3: expected a number for vertex z, found 'q'", errorOf(head, "v 0 0 \\\n  q\n", 4000));
    }
}
