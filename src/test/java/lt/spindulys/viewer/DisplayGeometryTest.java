package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;

class DisplayGeometryTest {
    /** A pentagon and a quad sharing an edge, in the z = 0 plane, counter-clockwise seen from +z. */
    static ControlMesh.Builder pentagonAndQuad() {
        double[] p = {0, 0, 0, 1, 0, 0, 1.3, 0.8, 0, 0.5, 1.3, 0, -0.3, 0.8, 0, 2, 0, 0, 2, 0.8, 0};
        return ControlMesh.builder(p, new int[] {5, 4}, new int[] {0, 1, 2, 3, 4, 1, 5, 6, 2});
    }

    @Test
    void polyhedronFansEachFaceWithOneNormalAndLeavesHolesOut() {
        DisplayGeometry g = DisplayGeometry.polyhedron(CatmullClark.refine(pentagonAndQuad().build(), 0));
        assertEquals(3 + 2, g.triangleCount());
        assertEquals(2, g.normals().length / 3);
        for (int i = 0; i < 2; i++) assertEquals(1f, g.normals()[3 * i + 2], 1e-6f, "facing +z");
        for (int c = 0; c < 9; c++) assertEquals(0, g.cornerNormals()[c], "the pentagon's triangles share its normal");
        DisplayGeometry holed = DisplayGeometry.polyhedron(CatmullClark.refine(pentagonAndQuad().hole(1).build(), 0));
        assertEquals(3, holed.triangleCount(), "the hole's quad is left out");
        DisplayGeometry lattice = DisplayGeometry.lattice(pentagonAndQuad().hole(1).build());
        assertEquals(5 + 3, lattice.edgeCount(), "the cage keeps the hole's edges, the shared one once");
        assertEquals(0, lattice.triangleCount());
    }

    @Test
    void smoothedUsesTheLimitNormalsAtSmoothVertices() {
        ControlMesh cube = ControlMesh.builder(new double[] {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1},
                new int[] {4, 4, 4, 4, 4, 4},
                new int[] {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 0, 4, 7, 3}).build();
        RefinedMesh r = CatmullClark.refine(cube, 2);
        DisplayGeometry g = DisplayGeometry.smoothed(r);
        assertEquals(2 * r.faceCount(), g.triangleCount());
        assertEquals(r.vertexCount(), g.vertexCount());
        double[] limit = r.limitNormals();
        int[] t = g.triangles(), cn = g.cornerNormals();
        for (int c = 0; c < t.length; c++) {
            int v = t[c], n = cn[c];
            for (int k = 0; k < 3; k++) assertEquals(limit[3 * v + k], g.normals()[3 * n + k], 1e-6, "corner " + c);
            // Outward: the normal points away from the cube's centre.
            float[] p = g.positions();
            double dot = p[3 * v] * g.normals()[3 * n] + p[3 * v + 1] * g.normals()[3 * n + 1] + p[3 * v + 2] * g.normals()[3 * n + 2];
            assertTrue(dot > 0);
        }
    }
}
