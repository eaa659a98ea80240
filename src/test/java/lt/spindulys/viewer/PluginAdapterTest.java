package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.plugin.raytrace.RayTracePlugin;
import lt.spindulys.render.RenderJob;
import lt.spindulys.subdiv.SubdivOptions;

/** The viewer's snapshot handed to a plugin: the control meshes, levels and view, and the ray tracer's picture of it. */
class PluginAdapterTest {
    private static final Path RESOURCES = Path.of("src/test/resources/plugin/raytrace");

    @TempDir Path dir;

    /** Two surfaces at different levels and modes, seen from a camera whose numbers are exact. */
    private static ViewerModel viewer() {
        List<String> errors = new ArrayList<>();
        ViewerModel m = new ViewerModel(Runnable::run, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() {}
            @Override public void error(String message) { errors.add(message); }
        });
        m.viewport(64, 48);
        m.open(List.of(RESOURCES.resolve("cube.obj"), RESOURCES.resolve("small-cube.obj")));
        m.select(0);
        m.level(2);
        m.mode(DisplayMode.LATTICE);
        m.select(1);
        m.level(0);
        m.mode(DisplayMode.POLYHEDRON);
        m.boundary(SubdivOptions.Boundary.EDGE_AND_CORNER);
        // Yaw and pitch 0: the eye on +z of the target, up exactly y, so the hand-written scene can say the same.
        m.camera().set(new Vec3(1.2, 0, 0), 6, 0, 0);
        assertEquals(List.of(), errors);
        return m;
    }

    @Test
    void thePluginIsHandedTheControlMeshesLevelsAndView() {
        ViewerModel m = viewer();
        ViewerSnapshot snap = m.snapshot();
        List<DisplayedSurface> ds = PluginAdapter.surfaces(snap);
        assertEquals(List.of("cube.obj", "small-cube.obj"), ds.stream().map(DisplayedSurface::name).toList());
        assertEquals(DisplayedSurface.Scheme.CATMULL_CLARK, ds.get(0).scheme(), "a lattice at level 2 is the level-2 surface's cage");
        assertEquals(2, ds.get(0).level());
        assertEquals(DisplayedSurface.Scheme.NONE, ds.get(1).scheme(), "level 0: the control mesh itself");
        assertEquals(0, ds.get(1).level());
        assertEquals(DisplayedSurface.Shading.SMOOTH, ds.get(0).shading(), "a lattice stands for the smooth surface");
        assertEquals(DisplayedSurface.Shading.FLAT, ds.get(1).shading(), "a polyhedron shows facets");
        for (int i = 0; i < 2; i++) {
            ViewedSurface s = m.surfaces().get(i);
            assertSame(s.control(s.scheme(), s.boundary()), ds.get(i).control(), "the control mesh the viewer holds, not a copy");
            assertEquals(s.boundary(), ds.get(i).control().options().boundary(), "with the viewer's boundary rule");
        }
        assertEquals(SubdivOptions.Boundary.EDGE_AND_CORNER, ds.get(1).control().options().boundary());
        assertEquals(24, ds.get(0).control().faceVertices().length, "the cage, not the refined faces");

        PluginView v = PluginAdapter.view(snap);
        assertEquals(new Vec3(1.2, 0, 6), v.eye());
        assertEquals(new Vec3(1.2, 0, 0), v.target());
        assertEquals(Vec3.Y, v.up(), "the world's up, so a floor lies level");
        // Looking down from above: still the world's up, and the same picture as the image's up would give.
        m.camera().set(new Vec3(1.2, 0, 0), 6, 0.3, 0.6);
        PluginView tilted = PluginAdapter.view(m.snapshot());
        assertEquals(Vec3.Y, tilted.up());
        assertTrue(m.camera().up().dot(Vec3.Y) < 0.9, "the image's up is tilted");
        assertEquals(m.camera().eye(), tilted.eye());
        assertEquals(45, v.fovDegrees());
        assertEquals(64, v.width());
        assertEquals(48, v.height());

        // A level changed later is what the next snapshot hands over.
        m.select(1);
        m.levelUp();
        DisplayedSurface again = PluginAdapter.surfaces(m.snapshot()).get(1);
        assertEquals(DisplayedSurface.Scheme.CATMULL_CLARK, again.scheme());
        assertEquals(1, again.level());
        assertEquals(DisplayedSurface.Shading.FLAT, again.shading());
        m.mode(DisplayMode.SMOOTHED);
        assertEquals(DisplayedSurface.Shading.SMOOTH, PluginAdapter.surfaces(m.snapshot()).get(1).shading());
    }

    @Test
    void theRayTracersPictureOfTheViewerIsTheHandWrittenScenes() throws Exception {
        ViewerSnapshot snap = viewer().snapshot();
        Path viaViewer = dir.resolve("viewer.png"), byHand = dir.resolve("hand.png");
        // The image size is left to its default, the viewport's.
        Map<String, String> o = Map.of("samples", "1", "lighting", "headlight", "floor", "none",
                "surface.0.rendering", "host-level", "surface.1.rendering", "host-level");
        new RayTracePlugin().run(new PluginRequest(PluginAdapter.surfaces(snap), PluginAdapter.view(snap), o, viaViewer, PluginProgress.NONE));
        RenderJob.of(RESOURCES.resolve("from-viewer.dat")).output(byHand).run();
        assertArrayEquals(Files.readAllBytes(byHand), Files.readAllBytes(viaViewer), "the plugin's PNG is the hand-written scene's, byte for byte");
        var img = javax.imageio.ImageIO.read(viaViewer.toFile());
        assertEquals(64, img.getWidth());
        assertNotEquals(img.getRGB(0, 0), img.getRGB(20, 24), "the picture shows the cube");
        assertNotEquals(img.getRGB(0, 0), img.getRGB(52, 24), "and the small cube");
    }
}
