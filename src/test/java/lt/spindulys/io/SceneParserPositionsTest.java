package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.scene.SubdivisionSurface.Positions;

/** The subdiv key {@code positions refined|limit}. */
class SceneParserPositionsTest {
    @TempDir Path dir;

    @BeforeEach
    void cube() throws IOException {
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
    }

    private List<GObject> objects(String scene) {
        return SceneParser.parse(scene, "s.dat", dir).objects();
    }

    @Test
    void limitPutsTheVerticesOnTheLimitSurface() {
        List<GObject> o = objects("""
                subdiv { file "cube.dat"  level 2 }
                subdiv { file "cube.dat"  level 2  positions limit }
                subdiv { file "cube.dat"  level 2  positions refined }
                """);
        SubdivisionSurface byDefault = (SubdivisionSurface) o.get(0), limit = (SubdivisionSurface) o.get(1), refined = (SubdivisionSurface) o.get(2);
        assertEquals(Positions.REFINED, byDefault.positions());
        assertEquals(Positions.LIMIT, limit.positions());
        assertEquals(Positions.REFINED, refined.positions());
        double[] p = limit.triangleData().positions();
        int[] vi = limit.triangleData().vertexIndex();
        double[] expected = limit.refined().limitPositions();
        for (int c : vi) for (int k = 0; k < 3; k++) assertEquals(expected[3 * c + k], p[3 * c + k]);
    }

    @Test
    void theSameSurfaceCacheTellsThePositionsApart() {
        List<GObject> o = objects("""
                subdiv { file "cube.dat"  level 2 }
                subdiv { file "cube.dat"  level 2  positions limit }
                subdiv { file "cube.dat"  level 2  positions limit  translate 3 0 0 }
                subdiv { file "cube.dat"  level 2  positions refined  translate -3 0 0 }
                """);
        SubdivisionSurface a = (SubdivisionSurface) o.get(0), b = (SubdivisionSurface) o.get(1), c = (SubdivisionSurface) o.get(2), d = (SubdivisionSurface) o.get(3);
        assertFalse(b.isInstance(), "limit positions are another surface than the refined ones");
        assertNotSame(a.refined(), b.refined());
        assertTrue(c.isInstance(), "the same limit surface again is an instance");
        assertSame(b.refined(), c.refined());
        assertEquals(Positions.LIMIT, c.positions());
        assertTrue(d.isInstance(), "'positions refined' is the default's surface");
        assertSame(a.refined(), d.refined());
        assertEquals(Positions.REFINED, d.positions());
    }

    @Test
    void adaptiveMethodsRefuseTheKey() {
        for (String method : new String[] {"projected", "lazy", "combined"}) {
            SceneException e = assertThrows(SceneException.class,
                    () -> objects("subdiv { file \"cube.dat\"  method " + method + "  positions limit }"));
            assertEquals("s.dat:1:" + (36 + method.length()) + ": 'positions' needs method uniform: the adaptive methods (projected, lazy, combined)"
                    + " place the vertices where the refinement puts them", e.getMessage());
        }
    }

    @Test
    void anUnknownWordIsRefused() {
        SceneException e = assertThrows(SceneException.class, () -> objects("subdiv { file \"cube.dat\"  positions exact }"));
        assertTrue(e.getMessage().startsWith("s.dat:1:"), e.getMessage());
        assertTrue(e.getMessage().contains("'exact'") && e.getMessage().contains("refined") && e.getMessage().contains("limit"), e.getMessage());
    }

    @Test
    void aLevelTooDeepForTheHeapIsRefusedRatherThanRenderedAdaptively() {
        // Without limit positions such a level falls back to the combined method ...
        try (HeapBudget.Scope ignored = HeapBudget.cap(4 << 10)) {
            assertInstanceOf(AdaptiveSubdivisionSurface.class, objects("subdiv { file \"cube.dat\"  level 5 }").get(0));
            // ... which has no limit positions: with them, the level is refused where it is.
            SceneException e = assertThrows(SceneException.class, () -> objects("subdiv { file \"cube.dat\"  level 5  positions limit }"));
            assertTrue(e.getMessage().startsWith("s.dat:1:27: subdivision level 5 of this mesh (6144 faces; uniform refinement;"), e.getMessage());
            assertTrue(e.getMessage().endsWith("; positions limit needs uniform refinement (the adaptive methods, which render such levels otherwise, have no limit positions)"), e.getMessage());
        }
    }
}
