package lt.spindulys.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.ObjReader;
import lt.spindulys.scene.TriangleMesh;

class BenchMeshesTest {
    @Test
    void numbersAreFormattedAsThePeerKitsPrintf() {
        assertEquals("0", BenchMeshes.number(0.0));
        assertEquals("0", BenchMeshes.number(-0.0));
        assertEquals("-0", BenchMeshes.number(-1e-17)); // printf: -0.000000
        assertEquals("1", BenchMeshes.number(1.0));
        assertEquals("-20", BenchMeshes.number(-20.0));
        assertEquals("0.03125", BenchMeshes.number(1 / 32.0));
        assertEquals("0.333333", BenchMeshes.number(1 / 3.0));
        // Powers of two are exact: the rounding sees the true binary value.
        assertEquals("0.000001", BenchMeshes.number(0x1p-20)); // 9.54e-7
        assertEquals("0", BenchMeshes.number(0x1p-21));        // 4.77e-7
        assertEquals("-0", BenchMeshes.number(-0x1p-21));
        assertEquals("1.4", BenchMeshes.number(1.4));
    }

    /** The committed 1k torus came from the peer kit's own generator; ours must write the same bytes. */
    @Test
    void generatedTorusMatchesTheCommittedPeerMesh() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        BenchMeshes.writeTorus(out, BenchMeshes.size("1k"));
        Path committed = Path.of("scenes", "bench", "meshes", "torus_1k.obj");
        assertArrayEquals(Files.readAllBytes(committed), out.toByteArray());
        ByteArrayOutputStream ground = new ByteArrayOutputStream();
        BenchMeshes.writeGround(ground);
        assertArrayEquals(Files.readAllBytes(Path.of("scenes", "bench", "meshes", "ground.obj")), ground.toByteArray());
    }

    @Test
    void torusIsClosedWithTwoTrianglesPerQuad(@org.junit.jupiter.api.io.TempDir Path dir) throws IOException {
        BenchMeshes.Size s = BenchMeshes.size("1k");
        BenchMeshes.ensure(dir, s);
        TriangleMesh m = new TriangleMesh(ObjReader.read(dir.resolve(s.file())));
        assertEquals(s.triangles(), m.triangleCount());
        assertEquals(0, m.degenerateCount());
        assertTrue(m.isClosed());
        assertTrue(Files.exists(dir.resolve(BenchMeshes.GROUND_FILE)));
    }

    /** A small knot of the same shape as the bench's, quick to check. */
    private static final BenchMeshes.Knot SMALL_KNOT = new BenchMeshes.Knot("test", 2, 3, 1.0, 0.45, 0.25, Math.PI / 2, 150, 12);

    private static byte[] knotBytes(BenchMeshes.Knot k) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        k.write(out);
        return out.toByteArray();
    }

    @Test
    void knotIsDeterministic() throws IOException {
        assertArrayEquals(knotBytes(SMALL_KNOT), knotBytes(SMALL_KNOT));
    }

    /**
     * Closed and consistently wound: every directed edge once and its reverse once (so every
     * edge is shared by exactly two faces, in opposite directions), no degenerate triangle, and
     * a positive enclosed volume (the faces point out of the tube).
     */
    @Test
    void knotIsClosedAndWoundOutward() throws IOException {
        lt.spindulys.mesh.MeshData m = ObjReader.parse(new String(knotBytes(SMALL_KNOT), java.nio.charset.StandardCharsets.US_ASCII), "knot.obj");
        assertEquals(SMALL_KNOT.quads(), m.faceCount());
        assertEquals(SMALL_KNOT.quads(), m.vertexCount());
        java.util.Map<Long, Integer> directed = new java.util.HashMap<>();
        int[] v = m.vertexIndex();
        double[] p = m.positions();
        double volume = 0;
        for (int f = 0; f < m.faceCount(); f++) {
            assertEquals(4, m.faceSizes()[f]);
            for (int k = 0; k < 4; k++) directed.merge((long) v[4 * f + k] << 32 | v[4 * f + (k + 1) % 4], 1, Integer::sum);
            for (int k = 1; k <= 2; k++) volume += signedVolume(p, v[4 * f], v[4 * f + k], v[4 * f + k + 1]);
        }
        for (var e : directed.entrySet()) {
            assertEquals(1, e.getValue(), "directed edge used twice");
            long key = e.getKey();
            assertTrue(directed.containsKey((key & 0xFFFFFFFFL) << 32 | key >>> 32), "edge without its twin");
        }
        assertEquals(4 * SMALL_KNOT.quads(), directed.size(), "directed edges");
        // A tube of radius a around a curve of length L encloses about pi a^2 L (the knot is 15.3 long).
        assertEquals(Math.PI * 0.25 * 0.25 * 15.34, volume, 0.05 * Math.PI * 0.25 * 0.25 * 15.34);
        TriangleMesh t = new TriangleMesh(m);
        assertEquals(0, t.degenerateCount());
        assertTrue(t.isClosed());
    }

    private static double signedVolume(double[] p, int a, int b, int c) {
        double ax = p[3 * a], ay = p[3 * a + 1], az = p[3 * a + 2], bx = p[3 * b], by = p[3 * b + 1], bz = p[3 * b + 2];
        double cx = p[3 * c], cy = p[3 * c + 1], cz = p[3 * c + 2];
        return (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6;
    }

    /** The knot rests on the ground: its lowest points touch y = -0.4 and none goes below. */
    @Test
    void knotRestsOnTheGround() throws IOException {
        BenchMeshes.Knot k = new BenchMeshes.Knot("t", 2, 3, 1.0, 0.45, 0.25, Math.PI / 2, 300, 24);
        lt.spindulys.mesh.MeshData m = ObjReader.parse(new String(knotBytes(k), java.nio.charset.StandardCharsets.US_ASCII), "knot.obj");
        double min = Double.MAX_VALUE;
        for (int i = 1; i < m.positions().length; i += 3) min = Math.min(min, m.positions()[i]);
        assertTrue(min >= BenchMeshes.GROUND_Y - 1e-6, "below the ground: " + min);
        assertEquals(BenchMeshes.GROUND_Y, min, 0.01);
    }

    @Test
    void benchKnotHasAMillionQuadsAndEnsureWritesTheMaterialLibrary(@org.junit.jupiter.api.io.TempDir Path dir) throws IOException {
        assertEquals(1_000_000, BenchMeshes.KNOT_1M.quads());
        assertEquals("knot_1m.obj", BenchMeshes.KNOT_1M.file());
        BenchMeshes.ensure(dir, BenchMeshes.size("1k"));
        assertEquals(BenchMeshes.MATERIAL_TEXT, Files.readString(dir.resolve(BenchMeshes.MATERIAL_FILE)));
        // The committed copy beside the committed meshes is the same text.
        assertEquals(BenchMeshes.MATERIAL_TEXT, Files.readString(Path.of("scenes", "bench", "meshes", BenchMeshes.MATERIAL_FILE)));
    }
}
