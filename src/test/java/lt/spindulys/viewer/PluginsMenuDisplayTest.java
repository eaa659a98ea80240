package lt.spindulys.viewer;

import static lt.spindulys.viewer.Driver.onEdt;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JColorChooser;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.filechooser.FileNameExtensionFilter;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.plugin.DisplayedSurface;

/** The Plugins menu, the dialog and the render window in real windows, driven by {@link java.awt.Robot}. */
@DisplayTest
class PluginsMenuDisplayTest {
    @TempDir
    Path dir;

    private Driver driver;
    private JFrame frame;
    private PluginsMenu menu;
    private final FakePlugin plugin = new FakePlugin();
    private volatile List<DisplayedSurface> shown = Fixtures.surfaces();

    @BeforeEach
    void openViewer() throws Exception {
        driver = new Driver();
        frame = onEdt(() -> {
            JFrame f = new JFrame("viewer");
            JMenuBar bar = new JMenuBar();
            menu = new PluginsMenu(f, List.of(plugin), () -> shown, () -> Fixtures.view(320, 240), dir);
            bar.add(menu);
            f.setJMenuBar(bar);
            f.setBounds(10, 10, 500, 400);
            f.setVisible(true);
            return f;
        });
        driver.waitFor("the viewer to show", frame::isShowing);
    }

    @AfterEach
    void closeAll() {
        plugin.release(); // a run still waiting ends now, so no thread outlives the test
        Driver.disposeAll();
    }

    private void choosePlugin() {
        driver.click(driver.find(PluginsMenu.class, "pluginsMenu"));
        driver.click(driver.find(JMenuItem.class, "plugin:fake"));
    }

    @Test
    void theDialogValidatesRunsAndTheWindowBesideTheViewerRefines() throws Exception {
        choosePlugin();
        PluginDialog dialog = driver.window(PluginDialog.class);
        JButton ok = driver.find(JButton.class, "ok");
        JLabel problem = driver.find(JLabel.class, "problem");
        JTextField size = driver.find(JTextField.class, "option:size");
        JTextField output = driver.find(JTextField.class, "output");
        assertEquals(dir.resolve("cube.png").toString(), onEdt(output::getText), "named after the first surface");
        assertTrue(onEdt(ok::isEnabled));

        driver.retype(size, "0");
        driver.waitFor("the size to be refused", () -> problem.getText().equals("Size (size) must be between 1 and 256, found 0") && !ok.isEnabled());
        driver.retype(size, "40");
        driver.waitFor("the size to be accepted", () -> ok.isEnabled() && problem.getText().isBlank());

        JTextField colour = driver.find(JTextField.class, "option:color");
        driver.retype(colour, "0 0 2");
        driver.waitFor("the colour to be refused", () -> problem.getText().startsWith("Colour (color) must be three numbers") && !ok.isEnabled());
        driver.retype(colour, "0 0 1");
        driver.waitFor("the colour to be accepted", ok::isEnabled);

        Path missing = dir.resolve("missing").resolve("out.png");
        Driver.onEdtDo(() -> output.setText(missing.toString()));
        driver.waitFor("the missing folder to be refused", () -> problem.getText().endsWith("directory '" + missing.getParent() + "' does not exist") && !ok.isEnabled());
        if (Files.isDirectory(Path.of("/proc/self"))) {
            // A folder that exists but takes no new file (even for root): OK is refused there, in one line.
            Driver.onEdtDo(() -> output.setText("/proc/square.png"));
            driver.waitFor("/proc to pass the live check", ok::isEnabled);
            driver.click(ok);
            driver.waitFor("OK to be refused for /proc", () -> problem.getText().startsWith(
                    "render: cannot write '/proc/square.png': cannot create a file in '/proc': ") && !ok.isEnabled());
            assertTrue(onEdt(dialog::isShowing), "the dialog stays open");
        }
        Path out = dir.resolve("square.png");
        Driver.onEdtDo(() -> output.setText(out.toString()));
        driver.waitFor("the output to be accepted", ok::isEnabled);

        driver.click(ok);
        RenderWindow window = driver.window(RenderWindow.class);
        driver.waitFor("the dialog to close", () -> !dialog.isShowing());
        // Where the windows are on the screen (without a window manager getBounds may not say).
        Rectangle viewer = onEdt(() -> new Rectangle(frame.getLocationOnScreen(), frame.getSize()));
        Point beside = new Point(viewer.x + viewer.width, viewer.y);
        driver.waitFor("the render window's left edge at the viewer's right edge " + beside,
                () -> window.isShowing() && window.getLocationOnScreen().equals(beside));

        assertTrue(plugin.waiting.await(10, TimeUnit.SECONDS));
        JComponent picture = driver.find(JComponent.class, "picture");
        driver.waitFor("the coarse red preview", () -> window.picture() != null && window.picture().getWidth() == 4);
        awaitColour(picture, new Color(FakePlugin.COARSE));
        assertFalse(Files.exists(out), "nothing is written before the run ends");

        plugin.release();
        driver.waitFor("the end of the run", () -> window.status().contains("wrote"));
        awaitColour(picture, Color.BLUE);
        assertEquals("40 x 40 square; wrote " + out, onEdt(window::status));
        assertEquals("Fake painter - square.png", onEdt(window::getTitle));
        BufferedImage written = ImageIO.read(out.toFile());
        assertEquals(40, written.getWidth());
        assertEquals(0xFF0000FF, written.getRGB(20, 20));
        assertFalse(plugin.ranOnEventThread, "the plugin ran off the event thread");
        assertEquals("40", plugin.request.options().get("size"));
        assertEquals("0 0 1", plugin.request.options().get("color"));

        driver.click(driver.find(JButton.class, "cancel")); // now Close
        driver.waitFor("the render window to close", () -> !window.isShowing());
        assertTrue(onEdt(frame::isShowing), "the viewer keeps running");
    }

    @Test
    void browseAndChooseFillTheFields() {
        choosePlugin();
        driver.window(PluginDialog.class);
        JTextField output = driver.find(JTextField.class, "output");

        driver.click(driver.find(JButton.class, "outputBrowse"));
        JFileChooser chooser = driver.find(JFileChooser.class, "a file chooser", c -> true);
        FileNameExtensionFilter filter = onEdt(() -> (FileNameExtensionFilter) chooser.getFileFilter());
        assertEquals(List.of("png"), List.of(filter.getExtensions()), "only the plugin's extensions");
        assertEquals(dir.resolve("cube.png").toFile(), onEdt(chooser::getSelectedFile), "starts at the current output");
        Driver.onEdtDo(() -> {
            chooser.setSelectedFile(dir.resolve("picture").toFile()); // a name typed without an extension
            chooser.approveSelection();
        });
        driver.waitFor("the chosen file in the output field", () -> output.getText().equals(dir.resolve("picture.png").toString()));

        JTextField colour = driver.find(JTextField.class, "option:color");
        driver.click(driver.find(JButton.class, "colour:color"));
        JColorChooser colours = driver.find(JColorChooser.class, "a colour chooser", c -> true);
        assertEquals(Color.GREEN, onEdt(colours::getColor), "starts at the field's colour");
        Driver.onEdtDo(() -> colours.setColor(new Color(255, 128, 0)));
        driver.enter(onEdt(() -> SwingUtilities.getWindowAncestor(colours)));
        driver.waitFor("the chosen colour in the field", () -> colour.getText().equals("1 0.502 0"));
        JLabel swatch = driver.find(JLabel.class, "swatch:color");
        assertEquals(new Color(255, 128, 0), onEdt(swatch::getBackground));
    }

    @Test
    void cancellingTheRunSaysSoAndWritesNothing() throws Exception {
        choosePlugin();
        driver.window(PluginDialog.class);
        driver.click(driver.find(JButton.class, "ok"));
        RenderWindow window = driver.window(RenderWindow.class);
        assertTrue(plugin.waiting.await(10, TimeUnit.SECONDS));
        driver.click(driver.find(JButton.class, "cancel"));
        JDialog message = driver.messageDialog();
        assertEquals("cancelled; nothing written", Driver.message(message));
        driver.enter(message);
        assertTrue(window.run().await(10, TimeUnit.SECONDS));
        assertEquals("cancelled; nothing written", onEdt(window::status));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "no output and no temporary file");
        }
        assertTrue(onEdt(frame::isShowing), "the viewer keeps running");
    }

    @Test
    void closingTheViewerCancelsItsRunsAndTheHostCanWaitForThem() throws Exception {
        choosePlugin();
        driver.window(PluginDialog.class);
        driver.click(driver.find(JButton.class, "ok"));
        RenderWindow window = driver.window(RenderWindow.class);
        assertTrue(plugin.waiting.await(10, TimeUnit.SECONDS));
        // The viewer closes (File > Quit disposes it): its render window goes with it, without windowClosing.
        onEdt(() -> {
            frame.dispose();
            return null;
        });
        assertTrue(menu.awaitRuns(10, TimeUnit.SECONDS), "the run was cancelled and ended");
        assertTrue(window.run().isCancelled());
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(List.of(), files.toList(), "no output and no temporary file");
        }
    }

    @Test
    void aFailedRunShowsTheCommandLinesLineAndTheViewerGoesOn() throws Exception {
        plugin.failure = new IOException("cannot write 'x.png': disk full");
        choosePlugin();
        driver.window(PluginDialog.class);
        driver.click(driver.find(JButton.class, "ok"));
        plugin.release();
        JDialog message = driver.messageDialog();
        assertEquals("render: cannot write 'x.png': disk full", Driver.message(message));
        driver.enter(message);
        assertFalse(Files.exists(dir.resolve("cube.png")));
        assertTrue(onEdt(frame::isShowing), "the viewer keeps running");
    }

    @Test
    void withNothingDisplayedTheMenuSaysSoInOneLine() {
        shown = List.of();
        choosePlugin();
        JDialog message = driver.messageDialog();
        assertEquals(PluginForm.NO_SURFACE, Driver.message(message));
        driver.enter(message);
    }

    /** Waits until the screen shows {@code expected} in the middle of {@code picture}: what a user sees, not the model. */
    private void awaitColour(JComponent picture, Color expected) {
        long end = System.currentTimeMillis() + Driver.TIMEOUT_MS;
        Color seen;
        while (!(seen = driver.pixel(picture)).equals(expected)) {
            if (System.currentTimeMillis() > end) {
                throw new AssertionError("the picture's middle shows " + seen + ", expected " + expected);
            }
            driver.robot.delay(20);
        }
    }
}
