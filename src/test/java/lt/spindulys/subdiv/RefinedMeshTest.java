package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class RefinedMeshTest {
    @Test
    void levelZeroIsTheControlMesh() {
        ControlMesh m = Corpus.load("catmark_nonquads");
        RefinedMesh r = CatmullClark.refine(m, 0);
        assertEquals(0, r.level());
        assertSame(m.positions(), r.positions());
        assertArrayEquals(m.faceSizes(), r.faceSizes());
        assertArrayEquals(m.faceVertices(), r.faceVertices());
        assertSame(m.uvs(), r.uvs());
        assertSame(m.faceUvIndices(), r.faceUvs());
        assertThrows(IllegalArgumentException.class, () -> CatmullClark.refine(m, -1));
    }

    @Test
    void refinedLevelsAreQuads() {
        ControlMesh m = Corpus.load("catmark_nonquads");
        RefinedMesh r = CatmullClark.refine(m, 2);
        assertEquals(2, r.level());
        int corners = 0;
        for (int s : m.faceSizes()) corners += s;
        assertEquals(4 * corners, r.faceCount());
        for (int s : r.faceSizes()) assertEquals(4, s);
        assertEquals(4 * r.faceCount(), r.faceUvs().length);
        int nUv = r.uvs().length / 2;
        for (int u : r.faceUvs()) assertEquals(true, u >= 0 && u < nUv);
        assertNull(CatmullClark.refine(Corpus.load("catmark_pole8"), 1).uvs());
    }

    /** The last level keeps only its parent's edge codes; rebuilt, they are the same as refined directly. */
    @Test
    void compactedLastLevelRefinesLikeAFullOne() {
        for (String shape : new String[] {"catmark_nonquads", "catmark_nonman_edges", "catmark_cubes_semisharp", "catmark_chaikin1"}) {
            ControlMesh m = Corpus.load(shape);
            RefinedMesh chain = CatmullClark.refine(m, 0).refine().refine();
            RefinedMesh compact = CatmullClark.refine(m, 2);
            assertArrayEquals(chain.edgeVertices(), compact.edgeVertices(), shape);
            assertArrayEquals(chain.limitPositions(), compact.limitPositions(), shape);
            RefinedMesh a = chain.refine(), b = CatmullClark.refine(m, 2).refine();
            assertArrayEquals(a.positions(), b.positions(), shape);
            assertArrayEquals(a.faceVertices(), b.faceVertices(), shape);
            assertArrayEquals(a.uvs(), b.uvs(), shape);
        }
    }
}
