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
import lt.spindulys.viewer.RenderWindow;

/**
 * Makes the pictures of docs/plugin-host.md, captured from the screen as a user sees them: the
 * dialog the viewer builds from a plugin's options (the thesis's figure 60), and the render window
 * at the end of the run (figure 58, without the viewer). From the repository root, after mvn
 * compile, on a display (a virtual one will do):
 * xvfb-run -a -s "-screen 0 1600x1000x24" java -cp target/classes docs/scenes/PluginHostFigures.java raytrace docs/images/plugin-dialog.png docs/images/plugin-render-window.png
 */
public class PluginHostFigures {
    public static void main(String[] a) throws Exception {
        double[] points = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
        int[] corners = {0, 3, 2, 1, 4, 5, 6, 7, 0, 4, 7, 3, 1, 2, 6, 5, 0, 1, 5, 4, 3, 7, 6, 2};
        for (int i = 0; i < points.length; i += 3) points[i] -= 1.4; // side by side, as a viewer would place them
        ControlMesh cube = ControlMesh.builder(points, new int[] {4, 4, 4, 4, 4, 4}, corners).source("cube.obj").build();
        double[] tp = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
        for (int i = 0; i < tp.length; i += 3) tp[i] += 1.6;
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
        capture(robot, where.get(), a[1]);

        // The run, with its output in a scratch folder, shown in the render window.
        Path scratch = java.nio.file.Files.createTempDirectory("plugin-figure");
        form.setOutput(scratch.resolve("cube." + form.extensions().get(0)).toString());
        PluginForm.Accepted accepted = form.accept();
        SwingUtilities.invokeAndWait(() -> dialog.get().dispose());
        AtomicReference<RenderWindow> window = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> window.set(RenderWindow.start(null, form, accepted)));
        window.get().run().await(10, java.util.concurrent.TimeUnit.MINUTES);
        for (int i = 0; i < 500 && !window.get().status().contains("wrote"); i++) robot.delay(20);
        robot.waitForIdle();
        robot.delay(500);
        SwingUtilities.invokeAndWait(() -> where.set(new Rectangle(window.get().getLocationOnScreen(), window.get().getSize())));
        capture(robot, where.get(), a[2]);
        System.exit(0);
    }

    static void capture(Robot robot, Rectangle where, String file) throws Exception {
        BufferedImage shot = robot.createScreenCapture(where);
        AtomicFile.write(Path.of(file), s -> ImageIO.write(shot, "png", s));
        System.out.println(file + ": " + shot.getWidth() + " x " + shot.getHeight());
    }
}
