package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.mesh.MeshData;

/** {@code render subdivide --uv} reads both forms of a Workframe unwrap. */
class SubdivideUnwrapFormsTest {
    @TempDir Path dir;

    private static final String CUBE_DAT = "scenes/models/cube.dat";

    @Test
    void bothFormsOfTheCubeUnwrapWriteTheSameRefinement() throws IOException {
        Path corners = dir.resolve("corners.obj"), points = dir.resolve("points.obj");
        CliTest.Run a = CliTest.run("subdivide", CUBE_DAT, "--uv", "scenes/models/cube.tex", "--level", "2", "--limit", "-o", corners.toString());
        CliTest.Run b = CliTest.run("subdivide", CUBE_DAT, "--uv", "scenes/models/cube-points.tex", "--level", "2", "--limit", "-o", points.toString());
        assertEquals(0, a.status(), a.err());
        assertEquals(0, b.status(), b.err());
        MeshData ma = ObjReader.read(corners), mb = ObjReader.read(points);
        assertArrayEquals(ma.positions(), mb.positions());
        assertArrayEquals(ma.vertexIndex(), mb.vertexIndex());
        assertNotNull(ma.uvIndex());
        for (int c = 0; c < ma.uvIndex().length; c++) {
            assertEquals(ma.uvs()[2 * ma.uvIndex()[c]], mb.uvs()[2 * mb.uvIndex()[c]], "u of corner " + c);
            assertEquals(ma.uvs()[2 * ma.uvIndex()[c] + 1], mb.uvs()[2 * mb.uvIndex()[c] + 1], "v of corner " + c);
        }
    }

    @Test
    void aBadPointsUnwrapIsOneLineAndWritesNothing() throws IOException {
        Path out = dir.resolve("out.obj");
        Path bad = dir.resolve("bad.tex");
        // Face 3 of the cube is a quad; the unwrap gives it three corners.
        Files.writeString(bad, Files.readString(Path.of("scenes/models/cube-points.tex")).replace("4  12 13 19 18", "3  12 13 19"));
        CliTest.Run r = CliTest.run("subdivide", CUBE_DAT, "--uv", bad.toString(), "--level", "1", "-o", out.toString());
        assertEquals(2, r.status());
        assertEquals(bad + ":33:1: face 3 has 3 corners but face 3 of the mesh " + CUBE_DAT
                + " has 4 (a texture face has the corners of its mesh face, in the same order)" + System.lineSeparator(), r.err());
        assertFalse(Files.exists(out));
    }
}
