package lt.spindulys.cli;

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
}
