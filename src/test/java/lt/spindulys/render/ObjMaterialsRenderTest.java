package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.io.SceneException;
import lt.spindulys.io.SceneParser;
import lt.spindulys.material.Material;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.TriangleMesh;

/**
 * OBJ materials in pictures: a cube whose front faces are usemtl Red and whose right faces are
 * usemtl Blue (its top in no group), as a mesh and as subdivision surfaces of every method, seen
 * from the front, off to +x: the right face shows on the left of the silhouette (blue), the front
 * on the right (red); the scene's material and its usemtl override them.
 */
class ObjMaterialsRenderTest {
    @TempDir Path dir;

    private static final String CUBE = """
            mtllib cube.mtl
            v -1 -1 -1
            v 1 -1 -1
            v 1 1 -1
            v -1 1 -1
            v -1 -1 1
            v 1 -1 1
            v 1 1 1
            v -1 1 1
            f 1 4 8 5
            f 1 5 6 2
            f 4 3 7 8
            usemtl Red
            f 1 2 3 4
            usemtl Blue
            f 2 6 7 3
            usemtl Back
            f 5 8 7 6
            """;

    private static final String MTL = """
            newmtl Red
            Kd 0.9 0.05 0.05
            Ka 1
            illum 1
            newmtl Blue
            Kd 0.05 0.05 0.9
            Ka 1
            illum 1
            newmtl Back
            Kd 0.5 0.5 0.5
            """;

    @BeforeEach
    void files() throws IOException {
        Files.writeString(dir.resolve("cube.obj"), CUBE);
        Files.writeString(dir.resolve("cube.mtl"), MTL);
    }

    private FrameBuffer render(String object) throws InterruptedException {
        Scene s = SceneParser.parse("settings { width 48  height 32  samples 1  ambient 0.3 }\ncamera { eye 2.2 0.4 -4  lookat 0 0 0  fov 50 }\n"
                + "light { position 3 1 -6 }\n" + object, "s.dat", dir).build();
        return Renderer.render(s, 2, ProgressListener.NONE).frame();
    }

    /** The left and right quarters of the middle row's object pixels: {r, g, b} of each, summed. */
    private static double[][] sides(FrameBuffer f) {
        int y = f.height() / 2, first = -1, last = -1;
        for (int x = 0; x < f.width(); x++) {
            if (f.get(x, y, 0) + f.get(x, y, 1) + f.get(x, y, 2) > 0) {
                if (first < 0) first = x;
                last = x;
            }
        }
        assertTrue(first >= 0 && last - first > 8, "the cube fills part of the middle row");
        double[][] out = new double[2][3];
        int q = (last - first + 1) / 4;
        for (int x = first; x < first + q; x++) for (int c = 0; c < 3; c++) out[0][c] += f.get(x, y, c);
        for (int x = last - q + 1; x <= last; x++) for (int c = 0; c < 3; c++) out[1][c] += f.get(x, y, c);
        return out;
    }

    private static void assertBlueLeftRedRight(FrameBuffer f, String what) {
        double[][] s = sides(f);
        assertTrue(s[0][2] > 3 * s[0][0], what + ": the left (the +x face, usemtl Blue) is blue: " + java.util.Arrays.toString(s[0]));
        assertTrue(s[1][0] > 3 * s[1][2], what + ": the right (the front face, usemtl Red) is red: " + java.util.Arrays.toString(s[1]));
    }

    @Test
    void twoFaceGroupsShowTheirColours() throws InterruptedException {
        assertBlueLeftRedRight(render("mesh { file \"cube.obj\" }"), "mesh");
        assertBlueLeftRedRight(render("subdiv { file \"cube.obj\"  level 2 }"), "subdiv uniform");
        assertBlueLeftRedRight(render("subdiv { file \"cube.obj\"  level 2  scheme bilinear }"), "subdiv bilinear");
        assertBlueLeftRedRight(render("subdiv { file \"cube.obj\"  method projected }"), "subdiv projected");
        assertBlueLeftRedRight(render("subdiv { file \"cube.obj\"  method lazy }"), "subdiv lazy");
        assertBlueLeftRedRight(render("subdiv { file \"cube.obj\"  method combined  level 2 }"), "subdiv combined");
        // CSG spans take the faces' materials too.
        assertBlueLeftRedRight(render("difference { mesh { file \"cube.obj\" }  sphere { center 0 0 5  radius 0.1 } }"), "mesh in CSG");
        assertBlueLeftRedRight(render("difference { subdiv { file \"cube.obj\"  level 1 }  sphere { center 0 0 5  radius 0.1 } }"), "subdiv in CSG");
    }

    @Test
    void theLazyAndUniformSurfacesAgree() throws InterruptedException {
        double[] uniform = render("subdiv { file \"cube.obj\"  level 2 }").data();
        double[] lazy = render("subdiv { file \"cube.obj\"  method lazy  levels edge  level 2 }").data();
        assertArrayEquals(uniform, lazy, 1e-9, "the same triangles in the same groups");
    }

    @Test
    void theSceneOverridesTheFile() throws InterruptedException {
        // The object's material overrides every group.
        double[][] all = sides(render("mesh { file \"cube.obj\"  material { color 1 1 0 } }"));
        for (double[] side : all) assertTrue(side[0] > 3 * side[2] && side[1] > 3 * side[2], "yellow everywhere: " + java.util.Arrays.toString(side));
        // usemtl in the block overrides one group; the other keeps the file's.
        double[][] one = sides(render("material green { color 0 1 0 }\nsubdiv { file \"cube.obj\"  level 1  usemtl \"Red\" green }"));
        assertTrue(one[1][1] > 3 * one[1][0], "the front is green: " + java.util.Arrays.toString(one[1]));
        assertTrue(one[0][2] > 3 * one[0][0], "the +x face is still blue");
        // Faces in no group take the object's (inherited) material: here the default grey on top.
        FrameBuffer f = render("mesh { file \"cube.obj\"  usemtl \"Blue\" { color 0 1 0 } }");
        double[][] s = sides(f);
        assertTrue(s[0][1] > 3 * s[0][2], "the +x face is green now");
    }

    @Test
    void everyTriangleTakesItsGroupsMaterial() {
        Scene s = SceneParser.parse("mesh { file \"cube.obj\"  usemtl \"Back\" { color 0 1 0 } }", "s.dat", dir).build();
        TriangleMesh m = (TriangleMesh) s.objects().get(0);
        MeshData t = m.data();
        String[] names = m.groupNames();
        int none = 0;
        for (int i = 0; i < m.triangleCount(); i++) {
            int g = t.faceGroups()[i];
            Material mat = m.material(i, 0);
            if (g < 0) {
                none++;
                assertSame(m.material(), mat, "faces in no group take the object's material");
            } else if (names[g].equals("Back")) {
                assertNull(mat.name(), "the scene's inline material for Back");
            } else {
                assertEquals(names[g], mat.name(), "triangle " + i + ": the .mtl material of its group");
            }
        }
        assertEquals(6, none, "three faces, six triangles, in no group");
        assertEquals(Material.DEFAULT, m.material());
    }

    @Test
    void placementsOfOneFileHaveTheirOwnGroupMaterials() {
        Scene s = SceneParser.parse("material green { color 0 1 0 }\nmaterial white { color 1 1 1 }\n"
                + "mesh { file \"cube.obj\" }\nmesh { file \"cube.obj\"  usemtl \"Red\" green }\nmesh { file \"cube.obj\"  material white }\n"
                + "subdiv { file \"cube.obj\"  level 1 }\nsubdiv { file \"cube.obj\"  level 1  usemtl \"Red\" green }", "s.dat", dir).build();
        TriangleMesh a = (TriangleMesh) s.objects().get(0), b = (TriangleMesh) s.objects().get(1), c = (TriangleMesh) s.objects().get(2);
        assertTrue(b.isInstance(), "the second statement places the first's geometry again");
        int red = -1;
        for (int i = 0; i < a.triangleCount() && red < 0; i++) if (a.data().faceGroups()[i] == 0) red = i;
        assertEquals("Red", a.material(red, 0).name());
        assertEquals("green", b.material(red, 0).name(), "the instance's own usemtl");
        assertEquals("white", c.material(red, 0).name(), "the object's material overrides the groups");
        lt.spindulys.scene.SubdivisionSurface d = (lt.spindulys.scene.SubdivisionSurface) s.objects().get(3),
                e = (lt.spindulys.scene.SubdivisionSurface) s.objects().get(4);
        assertTrue(e.isInstance());
        int[] groups = d.triangleData().faceGroups();
        for (int i = 0; i < groups.length; i++) {
            if (groups[i] != 0) continue;
            assertEquals("Red", d.material(i, 0).name());
            assertEquals("green", e.material(i, 0).name());
        }
    }

    @Test
    void groupsWithoutMaterialsAreLocated() throws IOException, InterruptedException {
        Files.writeString(dir.resolve("cube.mtl"), "newmtl Red\nKd 1 0 0\nnewmtl Back\n");
        SceneException e = assertThrows(SceneException.class, () -> render("mesh { file \"cube.obj\" }"));
        assertEquals(dir.resolve("cube.obj") + ":15:8: no material 'Blue': no material library it names (cube.mtl) defines it, and the scene gives none"
                + " (write usemtl \"Blue\" and a material in the 'mesh' block at 4:1)", e.getMessage());
        // The scene giving it is enough.
        render("mesh { file \"cube.obj\"  usemtl \"Blue\" { color 0 0 1 } }");
        // As is the object's own material, which overrides them all.
        render("subdiv { file \"cube.obj\"  material { color 0 0 1 } }");
        e = assertThrows(SceneException.class, () -> render("mesh { file \"cube.obj\"  usemtl \"Bleu\" { color 0 0 1 } }"));
        assertEquals("s.dat:4:32: usemtl 'Bleu': 'cube.obj' has no usemtl of that name (did you mean 'Blue'?) (its names: Red, Blue, Back)", e.getMessage());
    }
}
