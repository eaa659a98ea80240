package lt.spindulys.plugin;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.obj.ObjExportPlugin;
import lt.spindulys.plugin.raytrace.RayTracePlugin;
import lt.spindulys.render.RenderJob;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.Subdivision;

/** Loop and bilinear surfaces handed to the library's plugins: the ray tracer renders them with their scheme, the OBJ export keeps it. */
class SchemesTest {
    @TempDir Path dir;

    private static final PluginView VIEW = new PluginView(new Vec3(1, 2, -5), new Vec3(0, 0, 0), Vec3.Y, 40, 48, 36);

    /** A tetrahedron with a crease, under a scheme. */
    static ControlMesh tetrahedron(SubdivOptions.Scheme scheme) {
        double[] p = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
        return ControlMesh.builder(p, new int[] {3, 3, 3, 3}, new int[] {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2})
                .crease(0, 1, 2).options(SubdivOptions.DEFAULT.withScheme(scheme)).source("tet").build();
    }

    @Test
    void aDisplayedSurfacesSchemeIsItsControlMeshes() {
        for (SubdivOptions.Scheme s : SubdivOptions.Scheme.values()) {
            DisplayedSurface d = new DisplayedSurface("tet", tetrahedron(s), DisplayedSurface.Scheme.of(s), 2);
            assertEquals(DisplayedSurface.Scheme.of(s).label() + ", level 2", d.subdivisionLabel());
            assertEquals("control mesh", new DisplayedSurface("tet", tetrahedron(s), DisplayedSurface.Scheme.NONE, 0).subdivisionLabel());
        }
        assertEquals("Loop, level 2", new DisplayedSurface("tet", tetrahedron(SubdivOptions.Scheme.LOOP), DisplayedSurface.Scheme.LOOP, 2).subdivisionLabel());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new DisplayedSurface("tet", tetrahedron(SubdivOptions.Scheme.CATMARK), DisplayedSurface.Scheme.LOOP, 2));
        assertEquals("surface tet: scheme LOOP given, but its control mesh's options say catmark (set the scheme in the options, SubdivOptions.withScheme)",
                e.getMessage());
    }

    @Test
    void theRayTracerRendersALoopSurfaceAsLoopAndItsSavedSceneSaysSo() throws Exception {
        ControlMesh loop = tetrahedron(SubdivOptions.Scheme.LOOP);
        List<DisplayedSurface> shown = List.of(new DisplayedSurface("tet", loop, DisplayedSurface.Scheme.LOOP, 2));
        RayTracePlugin plugin = new RayTracePlugin();
        PluginOption rendering = plugin.options(shown, VIEW).stream().filter(o -> o.key().equals("surface.0.rendering")).findFirst().orElseThrow();
        assertEquals(List.of("limit", "host-level", "adaptive"), rendering.choices());
        assertEquals("limit", rendering.defaultValue());

        Map<String, String> o = new HashMap<>();
        o.put("width", "48");
        o.put("height", "36");
        o.put("samples", "1");
        o.put("floor", "none");
        o.put("save-scene", "true");
        o.put("surface.0.rendering", "host-level");
        Path out = dir.resolve("loop.png");
        plugin.run(new PluginRequest(shown, VIEW, o, out, PluginProgress.NONE));
        String scene = Files.readString(dir.resolve("loop.dat"));
        assertTrue(scene.contains("subdiv { file \"loop.0-tet.obj\"  level 2  scheme loop\n"), scene);
        SubdivInput saved = ObjReader.readSubdiv(dir.resolve("loop.0-tet.obj"));
        assertEquals(SubdivOptions.Scheme.LOOP, saved.options().scheme(), "the mesh beside the scene keeps the scheme");
        Path again = dir.resolve("again.png");
        RenderJob.of(dir.resolve("loop.dat")).output(again).run();
        assertArrayEquals(Files.readAllBytes(out), Files.readAllBytes(again), "the saved scene renders the plugin's picture");

        // The picture is of the Loop surface: the same cage as Catmull-Clark gives another.
        List<DisplayedSurface> catmark = List.of(new DisplayedSurface("tet", tetrahedron(SubdivOptions.Scheme.CATMARK), DisplayedSurface.Scheme.CATMULL_CLARK, 2));
        Path cc = dir.resolve("catmark.png");
        o.remove("save-scene");
        plugin.run(new PluginRequest(catmark, VIEW, o, cc, PluginProgress.NONE));
        assertTrue(loopDiffersFromCatmark(), "the library refines Loop by its own rules");
        assertFalse(java.util.Arrays.equals(Files.readAllBytes(out), Files.readAllBytes(cc)), "the picture is the Loop surface's");

        // Adaptive: the combined method refines the Loop surface too, and its saved scene renders the same picture.
        o.put("surface.0.rendering", "adaptive");
        o.put("save-scene", "true");
        Path adaptive = dir.resolve("adaptive.png");
        plugin.run(new PluginRequest(shown, VIEW, o, adaptive, PluginProgress.NONE));
        String adaptiveScene = Files.readString(dir.resolve("adaptive.dat"));
        assertTrue(adaptiveScene.contains("method combined") && adaptiveScene.contains("scheme loop"), adaptiveScene);
        Path adaptiveAgain = dir.resolve("adaptive-again.png");
        RenderJob.of(dir.resolve("adaptive.dat")).output(adaptiveAgain).run();
        assertArrayEquals(Files.readAllBytes(adaptive), Files.readAllBytes(adaptiveAgain));
    }

    /** Whether the subdivision library refines the tetrahedron differently under Loop. */
    private static boolean loopDiffersFromCatmark() {
        return !java.util.Arrays.equals(Subdivision.refine(tetrahedron(SubdivOptions.Scheme.LOOP), 2).positions(),
                Subdivision.refine(tetrahedron(SubdivOptions.Scheme.CATMARK), 2).positions());
    }

    @Test
    void theObjExportKeepsTheScheme() throws Exception {
        ObjExportPlugin plugin = new ObjExportPlugin();
        List<DisplayedSurface> shown = List.of(new DisplayedSurface("tet", tetrahedron(SubdivOptions.Scheme.BILINEAR), DisplayedSurface.Scheme.BILINEAR, 1));
        Path control = dir.resolve("control.obj");
        plugin.run(new PluginRequest(shown, VIEW, Map.of(ObjExportPlugin.EXPORT, ObjExportPlugin.CONTROL), control, PluginProgress.NONE));
        assertTrue(Files.readString(control).startsWith("# Spindulys OBJ export: the control mesh of tet (shown as bilinear, level 1)"));
        assertEquals(SubdivOptions.Scheme.BILINEAR, ObjReader.readSubdiv(control).options().scheme());
        Path refined = dir.resolve("refined.obj");
        plugin.run(new PluginRequest(shown, VIEW, Map.of(ObjExportPlugin.EXPORT, ObjExportPlugin.REFINED), refined, PluginProgress.NONE));
        SubdivInput back = ObjReader.readSubdiv(refined);
        assertEquals(SubdivOptions.Scheme.BILINEAR, back.options().scheme(), "the refined mesh reads back with its scheme");
        assertArrayEquals(Subdivision.refine(shown.get(0).control(), 1).positions(), back.mesh().positions());
    }
}
