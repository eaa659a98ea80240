package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

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
        assertSame(d, SceneAssetCache.subdivOptions(d, null, null, null, null, null));
        String[] boundary = {"none", "edge-only", "edge-and-corner"};
        for (int i = 0; i < 3; i++) {
            assertEquals(SubdivOptions.Boundary.values()[i], SceneAssetCache.subdivOptions(d, null, boundary[i], null, null, null).boundary());
        }
        String[] fvar = {"none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all"};
        for (int i = 0; i < fvar.length; i++) {
            assertEquals(SubdivOptions.FaceVarying.values()[i], SceneAssetCache.subdivOptions(d.withFaceVarying(SubdivOptions.FaceVarying.NONE), null, null, fvar[i], null, null).fvar());
        }
        assertEquals(SubdivOptions.Creasing.CHAIKIN, SceneAssetCache.subdivOptions(d, null, null, null, "chaikin", null).creasing());
        assertEquals(SubdivOptions.Creasing.UNIFORM, SceneAssetCache.subdivOptions(d.withCreasing(SubdivOptions.Creasing.CHAIKIN), null, null, null, "uniform", null).creasing());
        assertEquals(SubdivOptions.Triangles.SMOOTH, SceneAssetCache.subdivOptions(d, null, null, null, null, "smooth").triangles());
        assertEquals(SubdivOptions.Triangles.CATMARK, SceneAssetCache.subdivOptions(d.withTriangles(SubdivOptions.Triangles.SMOOTH), null, null, null, null, "catmark").triangles());
        for (SubdivOptions.Scheme sc : SubdivOptions.Scheme.values()) {
            assertEquals(sc, SceneAssetCache.subdivOptions(d.withScheme(SubdivOptions.Scheme.LOOP), sc.keyword(), null, null, null, null).scheme());
        }
        assertEquals(SubdivOptions.Scheme.BILINEAR, SceneAssetCache.subdivOptions(d.withScheme(SubdivOptions.Scheme.BILINEAR), null, null, null, null, null).scheme(),
                "no key: the file's scheme");
        // Every choice the grammar offers has a mapping.
        for (String k : new String[] {"scheme", "boundary", "uvinterpolation", "creasing", "triangles"}) {
            for (String c : SceneGrammar.SUBDIV.key(k).choices()) {
                assertDoesNotThrow(() -> SceneAssetCache.subdivOptions(d, k.equals("scheme") ? c : null, k.equals("boundary") ? c : null, k.equals("uvinterpolation") ? c : null,
                        k.equals("creasing") ? c : null, k.equals("triangles") ? c : null));
            }
        }
    }

    /** A tetrahedron: four triangles, closed, so every scheme (Loop too) takes it. */
    private static final String TET = "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\n";

    private static SubdivOptions.Scheme scheme(GObject o) {
        return ((SubdivisionSurface) o).refined().controlMesh().options().scheme();
    }

    @Test
    void theSchemeIsTheFilesUnlessTheSceneSaysOtherwise() throws IOException {
        Files.writeString(dir.resolve("tet.obj"), TET);
        Files.writeString(dir.resolve("loop.obj"), TET + "t scheme 0/0/1 loop\n");
        assertEquals(SubdivOptions.Scheme.CATMARK, scheme(only("subdiv { file \"tet.obj\"  level 1 }")), "no tag, no key: Catmull-Clark");
        assertEquals(SubdivOptions.Scheme.LOOP, scheme(only("subdiv { file \"loop.obj\"  level 1 }")), "the file's tag");
        for (SubdivOptions.Scheme s : SubdivOptions.Scheme.values()) {
            assertEquals(s, scheme(only("subdiv { file \"loop.obj\"  level 1  scheme " + s.keyword() + " }")), "the key overrides the tag");
            assertEquals(s, scheme(only("subdiv { file \"tet.obj\"  level 1  scheme " + s.keyword() + " }")));
        }
        // A Workframe mesh has no tags: the key alone.
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        assertEquals(SubdivOptions.Scheme.BILINEAR, scheme(only("subdiv { file \"cube.dat\"  level 1  scheme bilinear }")));
    }

    @Test
    void instancesShareOneSchemeAndCsgOperandsAndMovingSurfacesKeepTheirs() throws IOException {
        Files.writeString(dir.resolve("tet.obj"), TET);
        SceneBuilder b = SceneParser.parse("""
                subdiv { file "tet.obj"  level 2  scheme loop }
                subdiv { file "tet.obj"  level 2  scheme loop  translate 3 0 0 }
                subdiv { file "tet.obj"  level 2 }
                union { subdiv { file "tet.obj"  level 2  scheme bilinear  motion { translate 1 0 0 } }  sphere { radius 0.5 } }
                """, "s.dat", dir);
        List<GObject> objects = b.objects();
        SubdivisionSurface a = (SubdivisionSurface) objects.get(0), a2 = (SubdivisionSurface) objects.get(1), c = (SubdivisionSurface) objects.get(2);
        assertSame(a.refined(), a2.refined(), "the same surface again is an instance");
        assertNotSame(a.refined(), c.refined(), "another scheme is another surface");
        assertEquals(SubdivOptions.Scheme.LOOP, scheme(a2));
        assertEquals(SubdivOptions.Scheme.CATMARK, scheme(c));
        GObject operand = ((lt.spindulys.scene.Bool) objects.get(3)).operands().get(0);
        assertEquals(SubdivOptions.Scheme.BILINEAR, scheme(operand));
        assertNotNull(operand.motion(), "the moving operand keeps its motion");
        assertTrue(((SubdivisionSurface) operand).isClosed(), "a closed bilinear surface is a CSG solid");
    }

    private static SubdivOptions.Scheme adaptiveScheme(GObject o) {
        return assertInstanceOf(lt.spindulys.scene.AdaptiveSubdivisionSurface.class, o).control().options().scheme();
    }

    @Test
    void theAdaptiveMethodsRefineWithTheSchemeToo() throws IOException {
        Files.writeString(dir.resolve("tet.obj"), TET);
        Files.writeString(dir.resolve("loop.obj"), TET + "t scheme 0/0/1 loop\n");
        assertEquals(SubdivOptions.Scheme.LOOP, adaptiveScheme(only("subdiv { file \"tet.obj\"  scheme loop  method lazy }")));
        assertEquals(SubdivOptions.Scheme.LOOP, adaptiveScheme(only("subdiv { file \"loop.obj\"  method projected }")), "the file's scheme");
        assertEquals(SubdivOptions.Scheme.CATMARK, adaptiveScheme(only("subdiv { file \"loop.obj\"  scheme catmark  method combined }")),
                "the key over the file's");
        // Placements of one control mesh share a refiner only under the same scheme.
        SceneBuilder b = SceneParser.parse("subdiv { file \"tet.obj\"  method lazy  scheme loop }\nsubdiv { file \"tet.obj\"  method lazy  scheme loop }\n"
                + "subdiv { file \"tet.obj\"  method lazy  scheme bilinear }\n", "s.dat", dir);
        var a = (lt.spindulys.scene.AdaptiveSubdivisionSurface) b.objects().get(0);
        assertSame(a.refiner(), ((lt.spindulys.scene.AdaptiveSubdivisionSurface) b.objects().get(1)).refiner());
        assertNotSame(a.refiner(), ((lt.spindulys.scene.AdaptiveSubdivisionSurface) b.objects().get(2)).refiner());
        assertEquals(SubdivOptions.Scheme.BILINEAR, adaptiveScheme(b.objects().get(2)));
    }

    /**
     * With a fixed level, 'levels' still picks the tessellation: rate (the default) grids on the
     * limit surface, edge or object the power-of-two refinement (the same at a fixed level). A
     * 'target' there would be ignored, so it is refused.
     */
    @Test
    void levelsPicksTheTessellationOfAFixedLevelButTargetIsRefusedWithIt() throws IOException {
        Files.writeString(dir.resolve("tet.obj"), TET);
        record Case(String keys, lt.spindulys.scene.AdaptiveSubdivisionSurface.Levels levels) {}
        for (Case c : List.of(new Case("", lt.spindulys.scene.AdaptiveSubdivisionSurface.Levels.RATE),
                new Case("levels rate", lt.spindulys.scene.AdaptiveSubdivisionSurface.Levels.RATE),
                new Case("levels edge", lt.spindulys.scene.AdaptiveSubdivisionSurface.Levels.EDGE),
                new Case("levels object", lt.spindulys.scene.AdaptiveSubdivisionSurface.Levels.OBJECT))) {
            for (String method : List.of("projected", "lazy", "combined")) {
                var s = assertInstanceOf(lt.spindulys.scene.AdaptiveSubdivisionSurface.class,
                        only("subdiv { file \"tet.obj\"  method " + method + "  level 2  " + c.keys() + " }"));
                assertEquals(2, s.fixedLevel(), c.keys());
                assertEquals(c.levels(), s.levels(), method + " " + c.keys());
            }
        }
        SceneException e = assertThrows(SceneException.class,
                () -> SceneParser.parse("subdiv { file \"tet.obj\"  method lazy  levels edge  level 2  target 3 }", "s.dat", dir));
        assertTrue(e.getMessage().startsWith("s.dat:1:61: 'target' chooses levels from the view, but 'level' fixes one"), e.getMessage());
        // Without an adaptive method 'levels' is still an error.
        SceneException u = assertThrows(SceneException.class, () -> SceneParser.parse("subdiv { file \"tet.obj\"  level 2  levels edge }", "s.dat", dir));
        assertTrue(u.getMessage().contains("'levels' needs an adaptive method"), u.getMessage());
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
        // The refined positions, so the power-of-two path (the uniform refinement's own triangles), not the rates' limit grids.
        assertEquals(lt.spindulys.scene.AdaptiveSubdivisionSurface.Levels.EDGE, s.levels());
        // The same for another scheme: the combined method refines it with that scheme.
        var b = assertInstanceOf(lt.spindulys.scene.AdaptiveSubdivisionSurface.class, only("subdiv {\n  file \"big.obj\"\n  level 8  scheme bilinear\n}"));
        assertEquals(8, b.fixedLevel());
        assertEquals(SubdivOptions.Scheme.BILINEAR, b.control().options().scheme());
    }

    @Test
    void aFaceRepeatedThousandsOfTimesIsRefusedByTheAdaptiveMethodsAtTheFile() throws IOException {
        // Vertex 0 (OBJ's 1) is in 3 faces of the tetrahedron and in each of the 2,000 copies.
        Files.writeString(dir.resolve("dup.obj"), TET + "f 1 4 2\n".repeat(2000));
        SceneException lazy = assertThrows(SceneException.class, () -> SceneParser.parse("subdiv {\n  file \"dup.obj\"  method lazy  level 1\n}", "s.dat", dir));
        assertTrue(lazy.getMessage().startsWith("s.dat:2:8: "), lazy.getMessage());
        assertTrue(lazy.getMessage().contains("dup.obj: vertex 0 is shared by 2003 faces (face 0 is the first); adaptive subdivision supports at most 1024"),
                lazy.getMessage());
        // A uniform level too deep to refine whole would become the combined method, which
        // cannot take the mesh either: refused at the level, saying both.
        SceneException uniform = assertThrows(SceneException.class, () -> SceneParser.parse("subdiv {\n  file \"dup.obj\"\n  level 8\n}", "s.dat", dir));
        assertTrue(uniform.getMessage().startsWith("s.dat:3:3: subdivision level 8 would make "), uniform.getMessage());
        assertTrue(uniform.getMessage().contains("; nor can the combined method, which renders such levels otherwise: "), uniform.getMessage());
        assertTrue(uniform.getMessage().contains("vertex 0 is shared by 2003 faces"), uniform.getMessage());
    }
}
