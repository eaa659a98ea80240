import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import lt.spindulys.files.AtomicFile;
import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.*;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.viewer.PluginDialog;
import lt.spindulys.viewer.PluginForm;

/**
 * Makes docs/images/plugin-dialog.png: the dialog the viewer builds from a plugin's options (the
 * thesis's figure 60), captured from the screen as a user sees it. From the repository root, after
 * mvn compile, on a display (a virtual one will do):
 * xvfb-run -a -s "-screen 0 1600x1000x24" java -cp target/classes docs/scenes/PluginDialogFigure.java raytrace docs/images/plugin-dialog.png
 */
public class PluginDialogFigure {
    public static void main(String[] a) throws Exception {
        double[] points = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
        int[] corners = {0, 3, 2, 1, 4, 5, 6, 7, 0, 4, 7, 3, 1, 2, 6, 5, 0, 1, 5, 4, 3, 7, 6, 2};
        ControlMesh cube = ControlMesh.builder(points, new int[] {4, 4, 4, 4, 4, 4}, corners).source("cube.obj").build();
        double[] tp = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
        ControlMesh tetra = ControlMesh.builder(tp, new int[] {3, 3, 3, 3}, new int[] {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2}).source("tetrahedron.dat").build();
        List<DisplayedSurface> shown = List.of(
                new DisplayedSurface("cube.obj", cube, DisplayedSurface.Scheme.CATMULL_CLARK, 3),
                new DisplayedSurface("tetrahedron.dat", tetra, DisplayedSurface.Scheme.NONE, 0));
        PluginView view = new PluginView(new Vec3(3, 2.5, -4), Vec3.ZERO, Vec3.Y, 40, 640, 360);
        OutputPlugin plugin = OutputPlugins.find(a[0]).orElseThrow(() -> new IllegalArgumentException("no plugin " + a[0]));
        PluginForm form = new PluginForm(plugin, shown, view, Path.of(System.getProperty("user.home")));
        AtomicReference<PluginDialog> dialog = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> dialog.set(new PluginDialog(null, form)));
        SwingUtilities.invokeLater(() -> dialog.get().ask());
        Robot robot = new Robot();
        for (int i = 0; i < 500 && !(dialog.get().isShowing() && dialog.get().isFocused()); i++) robot.delay(20);
        robot.waitForIdle();
        robot.delay(500); // let the first paint reach the screen
        AtomicReference<Rectangle> where = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> where.set(new Rectangle(dialog.get().getLocationOnScreen(), dialog.get().getSize())));
        BufferedImage shot = robot.createScreenCapture(where.get());
        AtomicFile.write(Path.of(a[1]), s -> ImageIO.write(shot, "png", s));
        System.out.println(a[1] + ": " + shot.getWidth() + " x " + shot.getHeight());
        System.exit(0);
    }
}
