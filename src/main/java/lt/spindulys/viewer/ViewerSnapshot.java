package lt.spindulys.viewer;

import java.nio.file.Path;
import java.util.List;

import lt.spindulys.math.Vec3;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * What the viewer displays at one moment, for an output plugin: every open surface with its
 * control mesh and how it is shown, and the view. Immutable (the meshes are not copied; nobody
 * changes them).
 *
 * @param surfaces the open surfaces, in the list's order
 * @param view the camera and the viewport
 */
public record ViewerSnapshot(List<Surface> surfaces, View view) {
    /**
     * Copies the list.
     *
     * @param surfaces the surfaces
     * @param view the view
     */
    public ViewerSnapshot {
        surfaces = List.copyOf(surfaces);
    }

    /**
     * One surface as the viewer shows it.
     *
     * @param name its name in the surface list (the file's name)
     * @param source the file it was read from
     * @param input the polygons, tags and UVs, with the scheme and boundary rule below in its options
     * @param control the control mesh built from {@code input}
     * @param level the subdivision level the viewer applies (uniform, with {@code scheme})
     * @param scheme the subdivision scheme the viewer applies (also in {@code control}'s options)
     * @param boundary the boundary rule the viewer applies
     * @param mode how it is shown
     * @param cageOverSurface whether the control cage is drawn over it
     */
    public record Surface(String name, Path source, SubdivInput input, ControlMesh control, int level, SubdivOptions.Scheme scheme,
                          SubdivOptions.Boundary boundary,
                          DisplayMode mode, boolean cageOverSurface) {}

    /**
     * The view.
     *
     * @param eye where the eye is
     * @param target the point looked at (the centre of the image)
     * @param up the image's up direction, perpendicular to the view direction
     * @param fovDegrees the vertical field of view
     * @param width the viewport's width in pixels
     * @param height the viewport's height in pixels
     */
    public record View(Vec3 eye, Vec3 target, Vec3 up, double fovDegrees, int width, int height) {}
}
