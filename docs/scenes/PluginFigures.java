import java.nio.file.*;
import java.util.*;
import lt.spindulys.io.ObjReader;
import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.*;
import lt.spindulys.subdiv.*;

/**
 * Makes the pictures of docs/plugins.md through the ray-tracing plugin, as a host would. From the
 * repository root, after mvn compile: java -cp target/classes docs/scenes/PluginFigures.java OUT.png
 */
public class PluginFigures {
    static ControlMesh read(String file, double s, double dx, double dy, double dz) throws Exception {
        SubdivInput in = ObjReader.readSubdiv(Path.of("scenes/models", file));
        double[] p = in.mesh().positions(); // the host places its surfaces itself
        for (int i = 0; i < p.length; i += 3) { p[i] = p[i] * s + dx; p[i + 1] = p[i + 1] * s + dy; p[i + 2] = p[i + 2] * s + dz; }
        return in.toControlMesh();
    }
    public static void main(String[] a) throws Exception {
        List<DisplayedSurface> shown = List.of(
            new DisplayedSurface("crease-cube.obj", read("crease-cube.obj", 0.8, -2.7, 0.8, 0), DisplayedSurface.Scheme.CATMULL_CLARK, 2),
            new DisplayedSurface("gourd.obj", read("gourd.obj", 1, 0, 0, 0), DisplayedSurface.Scheme.CATMULL_CLARK, 3),
            new DisplayedSurface("tetrahedron.obj", read("tetrahedron.obj", 1.6, 2.7, 0.93, 0), DisplayedSurface.Scheme.NONE, 0));
        PluginView view = new PluginView(new Vec3(0.5, 3.2, -7.5), new Vec3(0, 0.9, 0), Vec3.Y, 40, 480, 270);
        OutputPlugin tracer = OutputPlugins.find("raytrace").orElseThrow();
        Map<String, String> o = new HashMap<>();
        o.put("samples", "4");
        o.put("identify", "true");
        o.put("save-scene", "true");
        o.put("surface.0.texture", "textures/grid.png");
        o.put("surface.0.mapping", "planar");
        o.put("surface.1.material", "transparent");
        o.put("surface.1.tint", "0.85 0.95 0.9");
        o.put("surface.2.material", "mirror");
        o.put("surface.2.rendering", "host-level");
        String problem = PluginOption.check(tracer.options(shown, view), o);
        if (problem != null) throw new IllegalArgumentException(problem);
        PluginResult r = tracer.run(new PluginRequest(shown, view, o, Path.of(a[0]), PluginProgress.NONE));
        System.out.println(r.files() + " " + r.summary());
    }
}
