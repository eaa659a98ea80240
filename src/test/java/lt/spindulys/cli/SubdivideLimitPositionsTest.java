package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;

/** {@code render subdivide --scene} writes a {@code positions limit} statement's vertices where it renders them. */
class SubdivideLimitPositionsTest {
    @TempDir Path dir;

    private Path scene(String subdiv) throws IOException {
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Path scene = dir.resolve("s.dat");
        Files.writeString(scene, "camera { eye 0 1 -5  lookat 0 0 0 }\n" + subdiv + "\n");
        return scene;
    }

    @Test
    void aLimitStatementIsWrittenAtItsLimitPositions() throws IOException {
        Path scene = scene("subdiv { file \"cube.dat\"  level 2  positions limit }");
        Path out = dir.resolve("out.obj");
        CliTest.Run r = CliTest.run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        RefinedMesh expected = CatmullClark.refine(SubdivInput.of(WorkframeReader.readMesh(dir.resolve("cube.dat"))).toControlMesh(), 2);
        MeshData m = ObjReader.read(out);
        assertArrayEquals(expected.limitPositions(), m.positions());
        assertArrayEquals(expected.limitNormals(), m.normals());
        assertTrue(Files.readString(out).contains("method uniform, positions limit: limit positions and normals"));
    }

    @Test
    void statementsThatDifferOnlyInPositionsAreNoted() throws IOException {
        Path scene = scene("subdiv { file \"cube.dat\"  level 2 }\nsubdiv { file \"cube.dat\"  level 2  positions limit }");
        Path out = dir.resolve("out.obj");
        CliTest.Run r = CliTest.run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("refine " + dir.resolve("cube.dat") + " differently"), r.err());
        RefinedMesh expected = CatmullClark.refine(SubdivInput.of(WorkframeReader.readMesh(dir.resolve("cube.dat"))).toControlMesh(), 2);
        assertArrayEquals(expected.positions(), ObjReader.read(out).positions(), "the first statement's, refined");
    }
}
