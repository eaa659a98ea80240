package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.scene.GObject;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivOptions;

/** The subdiv statement: files of both kinds, unwraps, levels, shading, and scene keys over the file's tags. */
class SceneParserSubdivTest {
    @TempDir Path dir;

    /** A 2 x 2 open grid of quads in the xz plane, corners at (0, 0, 0) and (2, 0, 2). */
    private static final String GRID = """
            v 0 0 0
            v 1 0 0
            v 2 0 0
            v 0 0 1
            v 1 0.5 1
            v 2 0 1
            v 0 0 2
            v 1 0 2
            v 2 0 2
            f 1 4 5 2
            f 2 5 6 3
            f 4 7 8 5
            f 5 8 9 6
            """;

    private GObject only(String scene) {
        SceneBuilder b = SceneParser.parse(scene, "s.dat", dir);
        assertEquals(1, b.objects().size());
        return b.objects().get(0);
    }

    /** True if some vertex of the refined mesh is exactly at (x, y, z). */
    private static boolean hasVertexAt(RefinedMesh r, double x, double y, double z) {
        double[] p = r.positions();
        for (int i = 0; i < p.length; i += 3) if (p[i] == x && p[i + 1] == y && p[i + 2] == z) return true;
        return false;
    }

    @Test
    void readsAnObjWithItsTagsAndTheCommonKeys() throws IOException {
        Files.createDirectories(dir.resolve("models"));
        Files.writeString(dir.resolve("models/grid.obj"), GRID + "t interpolateboundary 1/0/0 1\n");
        GObject o = only("material m { color 1 0 0 }\nsubdiv { file \"models/grid.obj\"  level 2  material m  translate 0 1 0  name \"g\" }");
        SubdivisionSurface s = assertInstanceOf(SubdivisionSurface.class, o);
        assertEquals(2, s.level());
        assertTrue(s.isSmooth());
        assertEquals("g", s.name());
        assertFalse(s.transform().isIdentity());
        assertFalse(s.isClosed());
        assertEquals(64, s.refined().faceCount());
        // The file says edge-and-corner: the grid's corners stay put.
        assertTrue(hasVertexAt(s.refined(), 0, 0, 0));
        assertTrue(hasVertexAt(s.refined(), 2, 0, 2));
    }

    @Test
    void sceneKeysOverrideTheFilesTags() throws IOException {
        Files.writeString(dir.resolve("grid.obj"), GRID + "t interpolateboundary 1/0/0 1\n");
        SubdivisionSurface s = (SubdivisionSurface) only("subdiv { file \"grid.obj\"  level 2  boundary edge-only }");
        assertFalse(hasVertexAt(s.refined(), 0, 0, 0), "edge-only boundaries round the corners off");
    }

    @Test
    void levelDefaultsToThreeAndShadingMayBeFlat() throws IOException {
        Files.writeString(dir.resolve("grid.obj"), GRID);
        SubdivisionSurface s = (SubdivisionSurface) only("subdiv { file \"grid.obj\"  shading flat }");
        assertEquals(3, s.level());
        assertFalse(s.isSmooth());
    }

    @Test
    void readsAWorkframeMeshWithItsUnwrap() throws IOException {
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.DAT"));
        Files.copy(Path.of("scenes/models/cube.tex"), dir.resolve("cube.tex"));
        SubdivisionSurface s = (SubdivisionSurface) only("subdiv { file \"cube.DAT\"  uv \"cube.tex\"  level 1 }");
        assertTrue(s.isClosed());
        assertNotNull(s.refined().uvs());
        SubdivisionSurface plain = (SubdivisionSurface) only("subdiv { file \"cube.DAT\"  level 1 }");
        assertNull(plain.refined().uvs());
    }

    @Test
    void everySchemeChoiceMapsToItsOption() {
        SubdivOptions d = SubdivOptions.DEFAULT;
        assertSame(d, SceneAssetCache.subdivOptions(d, null, null, null, null));
        String[] boundary = {"none", "edge-only", "edge-and-corner"};
        for (int i = 0; i < 3; i++) {
            assertEquals(SubdivOptions.Boundary.values()[i], SceneAssetCache.subdivOptions(d, boundary[i], null, null, null).boundary());
        }
        String[] fvar = {"none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all"};
        for (int i = 0; i < fvar.length; i++) {
            assertEquals(SubdivOptions.FaceVarying.values()[i], SceneAssetCache.subdivOptions(d.withFaceVarying(SubdivOptions.FaceVarying.NONE), null, fvar[i], null, null).fvar());
        }
        assertEquals(SubdivOptions.Creasing.CHAIKIN, SceneAssetCache.subdivOptions(d, null, null, "chaikin", null).creasing());
        assertEquals(SubdivOptions.Creasing.UNIFORM, SceneAssetCache.subdivOptions(d.withCreasing(SubdivOptions.Creasing.CHAIKIN), null, null, "uniform", null).creasing());
        assertEquals(SubdivOptions.Triangles.SMOOTH, SceneAssetCache.subdivOptions(d, null, null, null, "smooth").triangles());
        assertEquals(SubdivOptions.Triangles.CATMARK, SceneAssetCache.subdivOptions(d.withTriangles(SubdivOptions.Triangles.SMOOTH), null, null, null, "catmark").triangles());
        // Every choice the grammar offers has a mapping.
        for (String k : new String[] {"boundary", "uvinterpolation", "creasing", "triangles"}) {
            for (String c : SceneGrammar.SUBDIV.key(k).choices()) {
                assertDoesNotThrow(() -> SceneAssetCache.subdivOptions(d, k.equals("boundary") ? c : null, k.equals("uvinterpolation") ? c : null,
                        k.equals("creasing") ? c : null, k.equals("triangles") ? c : null));
            }
        }
    }

    @Test
    void aTooDeepUniformLevelBecomesTheCombinedMethodAtThatLevel() throws IOException {
        // 1,156 quads, so 4,624 corners, each 4^7 quads at level 8: over the uniform path's 2^24 faces.
        StringBuilder obj = new StringBuilder();
        int n = 34;
        for (int j = 0; j <= n; j++) for (int i = 0; i <= n; i++) obj.append("v ").append(i).append(" 0 ").append(j).append('\n');
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i + 1;
                obj.append("f ").append(a).append(' ').append(a + n + 1).append(' ').append(a + n + 2).append(' ').append(a + 1).append('\n');
            }
        }
        Files.writeString(dir.resolve("big.obj"), obj);
        // Not refused (issue 16): the combined method refines the same faces within the memory budget.
        var s = assertInstanceOf(lt.spindulys.scene.AdaptiveSubdivisionSurface.class, only("subdiv {\n  file \"big.obj\"\n  level 8\n}"));
        assertEquals(lt.spindulys.scene.AdaptiveSubdivisionSurface.Method.COMBINED, s.method());
        assertEquals(8, s.fixedLevel());
    }
}
