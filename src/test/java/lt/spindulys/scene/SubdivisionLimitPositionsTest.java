package lt.spindulys.scene;

import static lt.spindulys.scene.ShapeTestSupport.frozen;
import static org.junit.jupiter.api.Assertions.*;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.ObjReader;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;

/** {@link SubdivisionSurface.Positions#LIMIT}: the triangles' corners are the refined vertices' limit positions. */
class SubdivisionLimitPositionsTest {
    private static ControlMesh cube(String tags) {
        return ObjReader.parseSubdiv(TestMeshes.CUBE_OBJ + tags, "cube.obj").toControlMesh();
    }

    /** Every corner of every triangle is at {@code expected}[its vertex], bit for bit. */
    private static void assertCornersAt(MeshData t, double[] expected) {
        double[] p = t.positions();
        int[] vi = t.vertexIndex();
        assertTrue(vi.length > 0);
        for (int c = 0; c < vi.length; c++) {
            for (int k = 0; k < 3; k++) assertEquals(expected[3 * vi[c] + k], p[3 * vi[c] + k], "corner " + c);
        }
    }

    private static Set<String> points(double[] p) {
        Set<String> s = new HashSet<>();
        for (int i = 0; i < p.length; i += 3) s.add(p[i] + " " + p[i + 1] + " " + p[i + 2]);
        return s;
    }

    @Test
    void limitPlacesTheCornersOnTheLimitSurface() {
        for (String tags : new String[] {"", "t crease 2/1/0 0 1 10\n", "t hole 1/0/0 1\n"}) {
            for (int level : new int[] {0, 1, 3}) {
                for (boolean smooth : new boolean[] {true, false}) {
                    SubdivisionSurface s = new SubdivisionSurface(cube(tags), level, smooth, SubdivisionSurface.Positions.LIMIT);
                    assertEquals(SubdivisionSurface.Positions.LIMIT, s.positions());
                    RefinedMesh r = s.refined();
                    assertCornersAt(s.triangleData(), r.limitPositions());
                    // Not the refined positions: the cube's corners move in to the surface.
                    assertFalse(java.util.Arrays.equals(r.positions(), r.limitPositions()));
                }
            }
        }
    }

    @Test
    void polygonsOfAnySizeAtLevelZero() {
        // A square pyramid: at level 0 its triangles and quad are rendered as they are, corners on the limit surface.
        ControlMesh pyramid = ObjReader.parseSubdiv("v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nv 0 1.5 0\n"
                + "f 1 2 3 4\nf 1 5 2\nf 2 5 3\nf 3 5 4\nf 4 5 1\n", "pyramid.obj").toControlMesh();
        for (int level : new int[] {0, 2}) {
            SubdivisionSurface s = new SubdivisionSurface(pyramid, level, true, SubdivisionSurface.Positions.LIMIT);
            assertCornersAt(s.triangleData(), s.refined().limitPositions());
            assertTrue(s.isClosed());
        }
    }

    @Test
    void refinedIsTheDefaultAndKeepsTheRefinedPositions() {
        SubdivisionSurface s = new SubdivisionSurface(cube(""), 2);
        assertEquals(SubdivisionSurface.Positions.REFINED, s.positions());
        assertCornersAt(s.triangleData(), s.refined().positions());
        SubdivisionSurface same = new SubdivisionSurface(cube(""), 2, true, SubdivisionSurface.Positions.REFINED);
        assertArrayEquals(s.triangleData().positions(), same.triangleData().positions());
        assertArrayEquals(s.triangleData().vertexIndex(), same.triangleData().vertexIndex());
    }

    @Test
    void limitSurfacesLieInsideTheRefinedCubeAndInstancesKeepTheirPositions() {
        SubdivisionSurface limit = new SubdivisionSurface(cube(""), 2, true, SubdivisionSurface.Positions.LIMIT);
        SubdivisionSurface refined = new SubdivisionSurface(cube(""), 2);
        // The limit of a cube is inside its refinements: the box shrinks.
        assertTrue(limit.localBounds().max().x() < refined.localBounds().max().x());
        SubdivisionSurface copy = limit.instance();
        assertTrue(copy.isInstance());
        assertEquals(SubdivisionSurface.Positions.LIMIT, copy.positions());
        // Built into a scene the vertices are reordered, but still the limit positions.
        SubdivisionSurface built = frozen(limit);
        assertEquals(points(built.refined().limitPositions()), points(built.triangleData().positions()));
        assertEquals(limit.triangleCount(), refined.triangleCount());
    }
}
