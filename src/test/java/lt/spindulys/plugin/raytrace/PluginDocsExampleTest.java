package lt.spindulys.plugin.raytrace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.OutputPlugins;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.subdiv.ControlMesh;

/** The host example of docs/plugins.md compiles and runs, and the page shows it as it is here. */
class PluginDocsExampleTest {
    @TempDir Path dir;

    @Test
    void theDocumentedHostRunsTheRayTracer() throws Exception {
        Path out = dir.resolve("cube.jpg");
        // docs/plugins.md: begin
        double[] points = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
        int[] sizes = {4, 4, 4, 4, 4, 4};                                   // six quads,
        int[] corners = {0, 3, 2, 1, 4, 5, 6, 7, 0, 4, 7, 3, 1, 2, 6, 5, 0, 1, 5, 4, 3, 7, 6, 2}; // counter-clockwise from outside
        ControlMesh cage = ControlMesh.builder(points, sizes, corners).source("cube").build();
        List<DisplayedSurface> shown = List.of(new DisplayedSurface("cube", cage, DisplayedSurface.Scheme.CATMULL_CLARK, 2));
        PluginView view = new PluginView(new Vec3(3, 2.5, -4), Vec3.ZERO, Vec3.Y, 40, 160, 120);

        OutputPlugin tracer = OutputPlugins.find("raytrace").orElseThrow();
        List<PluginOption> form = tracer.options(shown, view);   // a host builds its dialog from these
        Map<String, String> answers = Map.of("samples", "4", "surface.0.material", "transparent");
        String problem = PluginOption.check(form, answers);      // null when every answer is valid
        if (problem != null) throw new IllegalArgumentException(problem);
        PluginResult result = tracer.run(new PluginRequest(shown, view, answers, out, PluginProgress.NONE));
        System.out.println(result.summary());                    // 160 x 120, 4 samples, 0.3 s
        // docs/plugins.md: end
        BufferedImage img = ImageIO.read(out.toFile());
        assertEquals(160, img.getWidth());
        assertEquals(List.of(out), result.files());
    }

    @Test
    void thePageShowsTheExampleAsTested() throws Exception {
        String source = Files.readString(Path.of("src/test/java/lt/spindulys/plugin/raytrace/PluginDocsExampleTest.java"));
        String example = source.substring(source.indexOf("// docs/plugins.md: begin\n") + 26, source.indexOf("        // docs/plugins.md: end"));
        String page = Files.readString(Path.of("docs/plugins.md"));
        assertTrue(normalise(page).contains(normalise(example)), "docs/plugins.md shows the example of " + getClass().getSimpleName());
    }

    /** Lines stripped of their indentation, so the page may indent the code as it likes. */
    private static String normalise(String s) {
        StringBuilder b = new StringBuilder();
        for (String line : s.split("\n")) b.append(line.strip()).append('\n');
        return b.toString();
    }
}
