package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;

/** Several refined meshes in one OBJ file, each an object whose indices count on from the ones before. */
class ObjWriterObjectFileTest {
    private static ControlMesh quad(double z, boolean uvs) {
        ControlMesh.Builder b = ControlMesh.builder(new double[] {0, 0, z, 1, 0, z, 1, 1, z, 0, 1, z}, new int[] {4}, new int[] {0, 1, 2, 3});
        if (uvs) b.uvs(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, new int[] {0, 1, 2, 3});
        return b.build();
    }

    @Test
    void objectsIndexPastTheObjectsBeforeThem() throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ObjWriter.ObjectFile file = new ObjWriter.ObjectFile(out, "three quads");
        file.add("plain", CatmullClark.refine(quad(0, false), 0), false, null);
        file.add("with uvs", CatmullClark.refine(quad(1, true), 0), true, null);
        file.add("line\nbreak", CatmullClark.refine(quad(2, true), 0), true, null);
        file.finish();
        String text = out.toString(StandardCharsets.UTF_8);
        assertTrue(text.startsWith("# three quads\no plain\nv 0 0 0\n"), text);
        assertTrue(text.contains("\nf 1 2 3 4\no with uvs\n"), text);
        // The second object: vertices 5-8, uvs 1-4 (the first had none), normals 1-4 (the first had none).
        assertTrue(text.contains("\nf 5/1/1 6/2/2 7/3/3 8/4/4\no line break\n"), text);
        assertTrue(text.endsWith("\nf 9/5/5 10/6/6 11/7/7 12/8/8\n"), text);
        MeshData m = ObjReader.parse(text, "three.obj");
        assertEquals(12, m.vertexCount());
        assertEquals(8, m.normals().length / 3);
        assertEquals(2.0, m.positions()[3 * 8 + 2]);
    }
}
