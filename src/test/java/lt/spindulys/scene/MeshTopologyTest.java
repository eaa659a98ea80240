package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.mesh.MeshData;

/** The data checks, welding and edge census of indexed triangles, without a mesh object. */
class MeshTopologyTest {

    /** A tetrahedron whose vertex 4 repeats vertex 0's position (a texture seam), used by one triangle. */
    private static final double[] TETRA = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};
    private static final int[] TETRA_TRI = {0, 2, 1, 0, 1, 3, 1, 2, 3, 4, 3, 2};

    @Test
    void weldingMapsEachPositionToItsFirstVertexAndMinusZeroToZero() {
        double[] p = {0, 0, 0, 1, 0, 0, -0.0, 0, -0.0, 1, 0, 0, 1, 0, 1e-300};
        assertArrayEquals(new int[] {0, 1, 0, 1, 4}, MeshTopology.weld(p));
    }

    @Test
    void aTetrahedronSplitAtASeamIsClosed() {
        assertTrue(MeshTopology.everyEdgeTwice(TETRA_TRI, 4, TETRA));
        assertEquals(0, MeshTopology.boundaryEdgeCount(TETRA_TRI, 4, TETRA));
    }

    @Test
    void aMissingTriangleLeavesItsThreeEdgesOnTheBoundary() {
        assertFalse(MeshTopology.everyEdgeTwice(TETRA_TRI, 3, TETRA));
        assertEquals(3, MeshTopology.boundaryEdgeCount(TETRA_TRI, 3, TETRA));
    }

    @Test
    void anEdgeOfThreeTrianglesIsNeitherClosedNorBoundary() {
        double[] p = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, -1, -1, 0};
        int[] tri = {0, 1, 2, 0, 1, 3, 0, 1, 4};
        assertFalse(MeshTopology.everyEdgeTwice(tri, 3, p));
        assertEquals(6, MeshTopology.boundaryEdgeCount(tri, 3, p), "the six outer edges; the shared one is used three times");
    }

    @Test
    void inconsistentDataIsNamedWithItsSource() {
        MeshData d = new MeshData(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, null, null,
                new int[] {3}, new int[] {0, 1, 3}, null, null, "m.obj");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MeshTopology.validate(d));
        assertEquals("m.obj: vertex index 3 at corner 2 is out of range (there are 3)", e.getMessage());
    }
}
