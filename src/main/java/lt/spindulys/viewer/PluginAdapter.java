package lt.spindulys.viewer;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginView;

/**
 * What the viewer hands an output plugin, made from what it displays ({@link ViewerSnapshot}):
 * each surface's control mesh as the viewer holds it (boundary rule, creases, UVs and holes in it)
 * with the viewer's subdivision, and the viewer's camera with the viewport's size. The one place
 * where the viewer's terms become the plugin interface's.
 */
public final class PluginAdapter {
    private PluginAdapter() {}

    /**
     * The surfaces, in the viewer's list order. Level 0 is the control mesh itself
     * ({@link DisplayedSurface.Scheme#NONE}); any other level is the surface's scheme (Catmull-Clark,
     * Loop or bilinear, as the viewer refines it) at that level, in
     * every display mode: a lattice or a polyhedron shows the cage or the facets of the same
     * subdivided surface, and a plugin that makes a picture of it should see that surface. The
     * shading is flat for a polyhedron, smooth for the smoothed surface and for a lattice.
     *
     * @param snapshot what is displayed
     * @return the surfaces
     */
    public static List<DisplayedSurface> surfaces(ViewerSnapshot snapshot) {
        List<DisplayedSurface> out = new ArrayList<>(snapshot.surfaces().size());
        for (ViewerSnapshot.Surface s : snapshot.surfaces()) {
            DisplayedSurface.Scheme scheme = s.level() == 0 ? DisplayedSurface.Scheme.NONE : DisplayedSurface.Scheme.of(s.control().options().scheme());
            // A polyhedron shows facets; the smoothed surface and the lattice (which stands for it) are smooth.
            DisplayedSurface.Shading shading = s.mode() == DisplayMode.POLYHEDRON ? DisplayedSurface.Shading.FLAT : DisplayedSurface.Shading.SMOOTH;
            out.add(new DisplayedSurface(s.name(), s.control(), scheme, s.level(), shading));
        }
        return out;
    }

    /**
     * The viewer's camera and viewport. The up direction handed over is the world's, +y, about
     * which the viewer orbits (its pitch stops short of the poles, so it is never along the view):
     * the picture is the same as with the image's own up, and a plugin that puts a floor under the
     * surfaces (the ray tracer) puts it level in the world rather than tilted with the camera.
     *
     * @param snapshot what is displayed
     * @return the view
     */
    public static PluginView view(ViewerSnapshot snapshot) {
        ViewerSnapshot.View v = snapshot.view();
        return new PluginView(v.eye(), v.target(), Vec3.Y, v.fovDegrees(), v.width(), v.height());
    }

    /**
     * The Plugins menu of {@code frame}: {@code plugins} handed what the frame displays when one is chosen.
     *
     * @param frame   the viewer
     * @param plugins the plugins, usually {@code OutputPlugins.available()}
     * @param folder  where outputs go until the user picks another folder
     * @return the menu (not yet added)
     */
    public static PluginsMenu menu(ViewerFrame frame, List<OutputPlugin> plugins, Path folder) {
        return new PluginsMenu(frame, plugins, () -> surfaces(frame.displayed()), () -> view(frame.displayed()), folder);
    }
}
