import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import lt.spindulys.files.AtomicFile;
import lt.spindulys.plugin.OutputPlugins;
import lt.spindulys.viewer.PluginAdapter;
import lt.spindulys.viewer.PluginForm;
import lt.spindulys.viewer.RenderWindow;
import lt.spindulys.viewer.ViewerFrame;
import lt.spindulys.viewer.ViewerSnapshot;

/**
 * Makes README's picture of the viewer (the thesis's figure 58): the viewer as {@code render view}
 * opens it, showing a mesh smoothed with its cage, and beside it the render window with the ray
 * tracer's picture of what the viewer shows (the plugin's default options, as Plugins > Ray
 * tracer... and OK give them), captured from the screen. From the repository root, after mvn
 * compile, on a display (a virtual one will do):
 * xvfb-run -a -s "-screen 0 1600x1000x24" java -cp target/classes docs/scenes/ViewerFigures.java scenes/models/gourd.obj docs/images/viewer.png
 */
public class ViewerFigures {
    public static void main(String[] a) throws Exception {
        Robot robot = new Robot();
        AtomicReference<ViewerFrame> frame = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            ViewerFrame f = ViewerFrame.withPlugins(OutputPlugins.available(), Path.of(""));
            f.setBounds(0, 0, 780, 520);
            f.setVisible(true);
            f.open(List.of(Path.of(a[0])));
            frame.set(f);
        });
        // Opened (read and refined in the background), then the cage over it and the view turned a little.
        waitFor(robot, () -> frame.get().model().surfaces().size() == 1 && frame.get().model().pending() == 0);
        SwingUtilities.invokeAndWait(() -> {
            frame.get().model().toggleCage();
            frame.get().model().camera().orbit(-60, 30);
        });
        waitFor(robot, () -> frame.get().model().pending() == 0);

        // What choosing Plugins > Ray tracer... and OK does, without the (modal) dialog.
        Path scratch = Files.createTempDirectory("viewer-figure");
        AtomicReference<RenderWindow> window = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                ViewerSnapshot shown = frame.get().displayed();
                PluginForm form = new PluginForm(OutputPlugins.find("raytrace").orElseThrow(), PluginAdapter.surfaces(shown),
                        PluginAdapter.view(shown), scratch);
                window.set(RenderWindow.start(frame.get(), form, form.accept()));
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        });
        window.get().run().await(10, TimeUnit.MINUTES);
        waitFor(robot, () -> window.get().status().contains("wrote"));
        robot.delay(1000); // let the last paint reach the screen
        AtomicReference<Rectangle> where = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> where.set(new Rectangle(frame.get().getLocationOnScreen(), frame.get().getSize())
                .union(new Rectangle(window.get().getLocationOnScreen(), window.get().getSize()))));
        BufferedImage shot = robot.createScreenCapture(where.get());
        AtomicFile.write(Path.of(a[1]), s -> ImageIO.write(shot, "png", s));
        System.out.println(a[1] + ": " + shot.getWidth() + " x " + shot.getHeight() + "; " + window.get().status());
        System.exit(0);
    }

    /** Polls a condition on the event thread (no fixed sleeps but the last). */
    static void waitFor(Robot robot, java.util.function.BooleanSupplier condition) throws Exception {
        for (int i = 0; i < 3000; i++) {
            AtomicReference<Boolean> ok = new AtomicReference<>();
            SwingUtilities.invokeAndWait(() -> ok.set(condition.getAsBoolean()));
            if (ok.get()) return;
            robot.delay(20);
        }
        throw new IllegalStateException("timed out");
    }
}
