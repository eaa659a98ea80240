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
    void aLevelTooDeepForTheHeapIsRenderedByTheCombinedMethodWithItsPositions() {
        AdaptiveSubdivisionSurface refined, limit;
        try (HeapBudget.Scope ignored = HeapBudget.cap(4 << 10)) {
            // Refined positions: the power-of-two levels, the uniform refinement's own triangles ...
            refined = assertInstanceOf(AdaptiveSubdivisionSurface.class, objects("subdiv { file \"cube.dat\"  level 5 }").get(0));
            // ... limit positions: grids on the limit surface at rate 2^level on every edge.
            limit = assertInstanceOf(AdaptiveSubdivisionSurface.class, objects("subdiv { file \"cube.dat\"  level 5  positions limit }").get(0));
        }
        assertEquals(AdaptiveSubdivisionSurface.Method.COMBINED, refined.method());
        assertEquals(AdaptiveSubdivisionSurface.Levels.EDGE, refined.levels());
        assertEquals(5, refined.fixedLevel());
        assertEquals(AdaptiveSubdivisionSurface.Method.COMBINED, limit.method());
        assertEquals(AdaptiveSubdivisionSurface.Levels.RATE, limit.levels());
        assertEquals(5, limit.fixedLevel());
        // Its vertices are the uniform limit surface's (to float rounding), which the heap could not hold whole.
        lt.spindulys.scene.SceneBuilder b = new lt.spindulys.scene.SceneBuilder();
        b.add(limit);
        lt.spindulys.scene.Scene scene = b.build();
        var built = (AdaptiveSubdivisionSurface) scene.objects().get(0);
        double[] grid = built.tessellation().positions();
        double[] uniform = new SubdivisionSurface(limit.control(), 5, true, Positions.LIMIT).triangleData().positions();
        java.util.Map<List<Long>, List<Integer>> cells = new java.util.HashMap<>();
        double cell = 1e-3;
        for (int i = 0; i < uniform.length; i += 3) {
            cells.computeIfAbsent(List.of(Math.round(uniform[i] / cell), Math.round(uniform[i + 1] / cell), Math.round(uniform[i + 2] / cell)),
                    k -> new java.util.ArrayList<>()).add(i);
        }
        int off = 0;
        for (int i = 0; i < grid.length; i += 3) {
            boolean found = false;
            long cx = Math.round(grid[i] / cell), cy = Math.round(grid[i + 1] / cell), cz = Math.round(grid[i + 2] / cell);
            for (long dx = -1; dx <= 1 && !found; dx++) {
                for (long dy = -1; dy <= 1 && !found; dy++) {
                    for (long dz = -1; dz <= 1 && !found; dz++) {
                        for (int u : cells.getOrDefault(List.of(cx + dx, cy + dy, cz + dz), List.of())) {
                            double d = Math.abs(grid[i] - uniform[u]) + Math.abs(grid[i + 1] - uniform[u + 1]) + Math.abs(grid[i + 2] - uniform[u + 2]);
                            if (d <= 1e-6) { found = true; break; }
                        }
                    }
                }
            }
            if (!found) off++;
        }
        assertTrue(grid.length > 3000, "a level-5 tessellation: " + grid.length / 3 + " vertices");
        assertEquals(0, off, off + " of " + grid.length / 3 + " grid vertices are not on the uniform limit surface's vertices");
    }
}
