package lt.spindulys.viewer;

import java.util.List;

import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.subdiv.ControlMesh;

/** Surfaces and views for the viewer's tests. */
final class Fixtures {
    private Fixtures() {}

    /** A unit quad named {@code name}. */
    static DisplayedSurface quad(String name) {
        ControlMesh m = ControlMesh.builder(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, new int[] {4}, new int[] {0, 1, 2, 3})
                .source(name).build();
        return new DisplayedSurface(name, m, DisplayedSurface.Scheme.CATMULL_CLARK, 2);
    }

    static List<DisplayedSurface> surfaces() {
        return List.of(quad("cube.obj"), quad("torus.dat"));
    }

    static PluginView view(int width, int height) {
        return new PluginView(new Vec3(0, 0, 5), new Vec3(0, 0, 0), new Vec3(0, 1, 0), 40, width, height);
    }
}
