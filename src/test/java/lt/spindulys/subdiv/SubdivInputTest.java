package lt.spindulys.subdiv;

import lt.spindulys.scene.TestMeshes;
import static org.junit.jupiter.api.Assertions.*;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.ObjReader;
import lt.spindulys.mesh.MeshData;

/** Control meshes from file data: corner UVs welded into face-varying UVs, tags applied, sizes foreseen. */
class SubdivInputTest {
    /** Two quads sharing the edge 1-4: 0 1 4 3 and 1 2 5 4. */
    private static MeshData twoQuads() {
        double[] p = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0};
        return new MeshData(p, null, null, new int[] {4, 4}, new int[] {0, 1, 4, 3, 1, 2, 5, 4}, null, null, "two");
    }

    @Test
    void cornerUvsOfOneVertexWeldWhereTheyAgree() {
        // Corners 1 and 4 (vertex 1) agree; corners 2 and 7 (vertex 4) differ: a seam there.
        double[] uv = {0, 0, 0.5, 0, 0.5, 1, 0, 1, 0.5, 0, 1, 0, 1, 1, 0.6, 1};
        SubdivInput in = SubdivInput.of(twoQuads()).withCornerUvs(uv);
        int[] idx = in.mesh().uvIndex();
        assertEquals(idx[1], idx[4], "same vertex, same uv: one value");
        assertNotEquals(idx[2], idx[7], "same vertex, different uv: a seam");
        assertEquals(7, in.mesh().uvs().length / 2);
        for (int c = 0; c < 8; c++) {
            assertEquals(uv[2 * c], in.mesh().uvs()[2 * idx[c]]);
            assertEquals(uv[2 * c + 1], in.mesh().uvs()[2 * idx[c] + 1]);
        }
    }

    @Test
    void equalUvsAtDifferentVerticesStaySeparate() {
        double[] uv = new double[16]; // every corner at (0, 0)
        uv[9] = -0.0; // corner 4 (vertex 1) at (0, -0): the same point as corner 1
        SubdivInput in = SubdivInput.of(twoQuads()).withCornerUvs(uv);
        assertEquals(6, in.mesh().uvs().length / 2, "one value per vertex, -0.0 welded with 0.0");
    }

    @Test
    void cornerUvsMustCoverEveryCorner() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SubdivInput.of(twoQuads()).withCornerUvs(new double[14]));
        assertEquals("expected 8 UV pairs, one per face corner, found 7.0", e.getMessage());
    }

    @Test
    void refinedFaceCountGrowsFourfoldAfterTheFirstLevel() {
        SubdivInput in = SubdivInput.of(new MeshData(new double[15], null, null, new int[] {5}, new int[] {0, 1, 2, 3, 4}, null, null, null));
        assertEquals(1, in.refinedFaceCount(0));
        assertEquals(5, in.refinedFaceCount(1));
        assertEquals(80, in.refinedFaceCount(3));
        assertTrue(in.refinedFaceCount(100) > 1L << 40, "saturates rather than overflows");
    }

    @Test
    void uvsOnSomeCornersOnlyAreRefused() {
        MeshData m = twoQuads();
        MeshData partial = new MeshData(m.positions(), null, new double[] {0, 0}, m.faceSizes(), m.vertexIndex(), null,
                new int[] {0, 0, 0, 0, -1, -1, -1, -1}, "two");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SubdivInput.of(partial).toControlMesh());
        assertTrue(e.getMessage().startsWith("two: corner 4 has no texture coordinate"), e.getMessage());
    }

    @Test
    void tagsNeedMatchingSharpness() {
        assertThrows(IllegalArgumentException.class, () -> new SubdivTags(new int[] {0, 1, 1}, new float[] {1}, new int[0], new float[0], new int[0], SubdivOptions.DEFAULT, List.of()));
        assertThrows(IllegalArgumentException.class, () -> new SubdivTags(new int[0], new float[0], new int[] {1, 2}, new float[] {1}, new int[0], SubdivOptions.DEFAULT, List.of()));
    }

    static final String CUBE = TestMeshes.CUBE_OBJ;

    /** Largest |coordinate| of each vertex: 1 on the cube's surface. */
    private static double[] extent(RefinedMesh r) {
        double[] p = r.positions(), e = new double[r.vertexCount()];
        for (int v = 0; v < e.length; v++) e[v] = Math.max(Math.abs(p[3 * v]), Math.max(Math.abs(p[3 * v + 1]), Math.abs(p[3 * v + 2])));
        return e;
    }

    @Test
    void infinitelySharpEdgesKeepTheCubeACube() {
        String allEdges = "t crease 24/1/0 0 1 1 2 2 3 3 0 4 5 5 6 6 7 7 4 0 4 1 5 2 6 3 7 10\n";
        RefinedMesh sharp = CatmullClark.refine(ObjReader.parseSubdiv(CUBE + allEdges, "c.obj").toControlMesh(), 2);
        for (double e : extent(sharp)) assertEquals(1, e, 1e-12, "every vertex stays on the cube");
        RefinedMesh smooth = CatmullClark.refine(ObjReader.parseSubdiv(CUBE, "c.obj").toControlMesh(), 2);
        double min = 1;
        for (double e : extent(smooth)) min = Math.min(min, e);
        assertTrue(min < 0.95, "without creases the cube rounds off: " + min);
    }

    @Test
    void holesAreInheritedByEveryChildFace() {
        RefinedMesh r = CatmullClark.refine(ObjReader.parseSubdiv(CUBE + "t hole 2/0/0 0 4\n", "c.obj").toControlMesh(), 2);
        int holes = 0;
        for (int f = 0; f < r.faceCount(); f++) if (r.isHole(f)) holes++;
        assertEquals(2 * 16, holes);
        assertEquals(6 * 16, r.faceCount());
    }
}
