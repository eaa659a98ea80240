package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SubdivTagsTest {
    static ControlMesh.Builder builder() {
        return ControlMesh.builder(ControlMeshTest.P, ControlMeshTest.SIZES, ControlMeshTest.FV);
    }

    @Test
    void parsesTheGrammar() {
        SubdivTags.Tag t = SubdivTags.parse("t crease 4/2/0 0 1 1 4 2.5 10");
        assertEquals("crease", t.name());
        assertArrayEquals(new int[] {0, 1, 1, 4}, t.ints());
        assertArrayEquals(new float[] {2.5f, 10f}, t.floats());
        assertEquals(0, t.strings().length);
        SubdivTags.Tag m = SubdivTags.parse("creasemethod 0/0/1 chaikin");
        assertArrayEquals(new String[] {"chaikin"}, m.strings());
    }

    @Test
    void appliesTagsToTheBuilder() {
        ControlMesh.Builder b = builder();
        assertTrue(SubdivTags.apply("t interpolateboundary 1/0/0 1", b));
        assertTrue(SubdivTags.apply("t facevaryinginterpolateboundary 1/0/0 1", b));
        assertTrue(SubdivTags.apply("t creasemethod 0/0/1 chaikin", b));
        assertTrue(SubdivTags.apply("t smoothtriangles 0/0/1 smooth", b));
        assertEquals(new SubdivOptions(SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.FaceVarying.CORNERS_ONLY,
                SubdivOptions.Creasing.CHAIKIN, SubdivOptions.Triangles.SMOOTH), b.options());
        assertTrue(SubdivTags.apply("t interpolateboundary 1/0/0 0", b));
        assertEquals(SubdivOptions.Boundary.NONE, b.options().boundary());
        assertFalse(SubdivTags.apply("t vertexedit 1/1/3 0 1.0 add P value", b), "Far ignores hierarchical edits");

        // A crease on the shared edge 1-4 pulls the edge point onto the edge's midpoint.
        ControlMesh.Builder c = builder();
        SubdivTags.apply("t crease 2/1/0 1 4 10", c);
        SubdivTags.apply("t corner 1/1/0 0 10", c);
        SubdivTags.apply("t hole 1/0/0 1", c);
        RefinedMesh r = CatmullClark.refine(c.build(), 1);
        int e14 = -1;
        RefinedMesh r0 = CatmullClark.refine(c.build(), 0);
        int[] ev = r0.edgeVertices();
        for (int e = 0; e < r0.edgeCount(); e++) if (ev[2 * e] + ev[2 * e + 1] == 5 && Math.abs(ev[2 * e] - ev[2 * e + 1]) == 3) e14 = e;
        assertArrayEquals(new double[] {1, 0.5, 0}, ControlMeshTest.slice(r.positions(), 6 + 2 + e14), 1e-15);
        assertArrayEquals(new double[] {0, 0, 0}, ControlMeshTest.slice(r.positions(), 0), 0);
        assertTrue(r.isHole(4) && !r.isHole(3));
    }

    @Test
    void refusesMalformedTags() {
        for (String bad : new String[] {
                "t crease 2/1 0 1 5", "t crease 2/1/0 0 1", "t crease 3/1/0 0 1 2 5", "t crease 2/x/0 0 1 5",
                "t crease 4/3/0 0 1 1 4 1 1 1", "t corner 1/0/0 3", "t interpolateboundary 1/0/0 7",
                "t creasemethod 0/0/1 fancy", "t bogus 0/0/0", "t", "t crease 2/1/0 0 a 5"}) {
            assertThrows(IllegalArgumentException.class, () -> SubdivTags.apply(bad, builder()), bad);
        }
    }
}
