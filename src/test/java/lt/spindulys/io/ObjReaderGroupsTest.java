package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;

/** OBJ usemtl and mtllib: face groups (face indices to group names) and the places the scene reports. */
class ObjReaderGroupsTest {
    @TempDir Path dir;

    private static final String GROUPS = """
            mtllib a.mtl  b.mtl
            v 0 0 0
            v 1 0 0
            v 1 1 0
            v 0 1 0
            f 1 2 3
            usemtl Red paint   # a name with a space
            f 1 2 3
            f 1 3 4
            usemtl  Blue
            f 1 2 3 4
            usemtl Red paint
            f 2 3 4
            mtllib c.mtl
            """;

    @Test
    void facesKnowTheirGroup() {
        ObjReader.Read r = ObjReader.read(GROUPS.getBytes(StandardCharsets.UTF_8), "g.obj", 1, 1);
        MeshData m = r.mesh();
        assertArrayEquals(new int[] {-1, 0, 0, 1, 0}, m.faceGroups(), "faces before any usemtl are in no group");
        assertArrayEquals(new String[] {"Red paint", "Blue"}, m.groupNames());
        assertEquals(List.of(new ObjReader.Ref("Red paint", 7, 8), new ObjReader.Ref("Blue", 10, 9)), r.groups(), "each group's first usemtl");
        assertEquals(List.of(new ObjReader.Ref("a.mtl", 1, 8), new ObjReader.Ref("b.mtl", 1, 15), new ObjReader.Ref("c.mtl", 14, 8)), r.libraries());
    }

    @Test
    void withoutUsemtlThereAreNoGroups() {
        MeshData m = ObjReader.parse("mtllib x.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "t.obj");
        assertNull(m.faceGroups());
        assertNull(m.groupNames());
    }

    @Test
    void chunksGiveTheSameGroups() {
        StringBuilder b = new StringBuilder("v 0 0 0\nv 1 0 0\nv 1 1 0\n");
        String[] names = {"A", "B", "C"};
        for (int i = 0; i < 400; i++) {
            if (i % 37 == 5) b.append("usemtl ").append(names[(i / 37) % 3]).append('\n');
            if (i % 91 == 3) b.append("mtllib lib").append(i).append(".mtl\n");
            b.append("f 1 2 3\n");
        }
        byte[] bytes = b.toString().getBytes(StandardCharsets.UTF_8);
        ObjReader.Read whole = ObjReader.read(bytes, "c.obj", 1, 1);
        for (int chunks : new int[] {2, 7, 50}) {
            ObjReader.Read split = ObjReader.read(bytes, "c.obj", chunks, 3);
            assertArrayEquals(whole.mesh().faceGroups(), split.mesh().faceGroups(), chunks + " chunks");
            assertArrayEquals(whole.mesh().groupNames(), split.mesh().groupNames());
            assertEquals(whole.groups(), split.groups());
            assertEquals(whole.libraries(), split.libraries());
        }
        assertEquals(-1, whole.mesh().faceGroups()[0]);
        assertEquals(0, whole.mesh().faceGroups()[399 - 30], "the run of A continues to the end");
    }

    @Test
    void badStatementsAreLocated() {
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.parse("v 0 0 0\nusemtl   # none\n", "b.obj"));
        assertEquals("b.obj:2:10: expected a material name after 'usemtl', found a comment", e.getMessage());
        e = assertThrows(SceneException.class, () -> ObjReader.parse("mtllib\n", "b.obj"));
        assertEquals("b.obj:1:7: expected a material library file name after 'mtllib', found end of line", e.getMessage());
    }

    @Test
    void controlMeshesCarryGroupsToEveryRefinedFace() throws Exception {
        // Three separate faces (a triangle, a quad, a pentagon) ten units apart, each its own group:
        // every refined triangle's centroid tells which control face it came from.
        String obj = """
                v 0 0 0
                v 1 0 0
                v 0 1 0
                v 10 0 0
                v 11 0 0
                v 11 1 0
                v 10 1 0
                v 20 0 0
                v 21 0 0
                v 21.5 0.8 0
                v 20.5 1.5 0
                v 19.5 0.8 0
                usemtl tri
                f 1 2 3
                usemtl quad
                f 4 5 6 7
                usemtl pent
                f 8 9 10 11 12
                """;
        Files.writeString(dir.resolve("three.obj"), obj);
        ObjReader.Read r = ObjReader.readSubdivision(dir.resolve("three.obj"));
        ControlMesh control = r.subdiv().toControlMesh();
        assertArrayEquals(new int[] {0, 1, 2}, control.faceGroups());
        for (int level = 0; level <= 3; level++) {
            MeshData t = lt.spindulys.subdiv.RefinedTriangles.triangles(lt.spindulys.subdiv.Subdivision.refine(control, level), false);
            checkCentroids(t, level);
        }
        // Loop: triangles only.
        String loop = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 10 0 0\nv 11 0 0\nv 10 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 4 5 6\nt scheme 0/0/1 loop\n";
        Files.writeString(dir.resolve("loop.obj"), loop);
        ControlMesh lc = ObjReader.readSubdivision(dir.resolve("loop.obj")).subdiv().toControlMesh();
        for (int level = 0; level <= 3; level++) {
            MeshData t = lt.spindulys.subdiv.RefinedTriangles.triangles(lt.spindulys.subdiv.Subdivision.refine(lc, level), false);
            checkCentroids(t, level);
        }
    }

    /** Each triangle's group is the control face its centroid lies near (x about 0, 10 or 20). */
    private static void checkCentroids(MeshData t, int level) {
        int[] sizes = t.faceSizes(), vi = t.vertexIndex(), groups = t.faceGroups();
        double[] p = t.positions();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            double x = 0;
            for (int k = 0; k < sizes[f]; k++) x += p[3 * vi[c + k]] / sizes[f];
            assertEquals((int) Math.round(x / 10), groups[f], "level " + level + ", face " + f + " at x " + x);
        }
    }
}
