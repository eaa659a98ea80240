package lt.spindulys.viewer;

import static lt.spindulys.viewer.Driver.onEdt;
import static org.junit.jupiter.api.Assertions.*;

import java.awt.Component;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.datatransfer.DataFlavor;
import java.awt.datatransfer.Transferable;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.imageio.ImageIO;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import javax.swing.TransferHandler;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.ImageDiff;
import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.plugin.OutputPlugins;

/**
 * The viewer end to end in real windows, started as {@code render view} starts it
 * ({@link ViewerFrame#withPlugins} with every plugin found) and driven with {@link java.awt.Robot}:
 * modes and levels by keys and menus against golden screenshots of the viewport, File > Open by
 * typing a path into the file chooser, a dropped file, a malformed mesh, and the ray tracer run
 * from the Plugins menu (its picture beside the viewer and in the file, an unwritable output, a
 * cancelled run). Regenerate the screenshots after an intended change with
 * {@code mvn test -Dtest=ViewerDisplayTest -Dgolden.update=true} under a virtual X server, and look at them.
 */
@DisplayTest
class ViewerDisplayTest {
    static final Path GOLDEN = Path.of("src/test/resources/golden/viewer"), OUT = Path.of("target/regression");
    /** The viewport's size in the screenshots: the window is sized around it, whatever the fonts make of the menu bar. */
    static final int VW = 400, VH = 280;

    @TempDir Path dir;

    private final Driver driver = new Driver();
    private ViewerFrame frame;
    private ViewportPanel viewport;

    @AfterEach
    void closeAll() {
        Driver.disposeAll();
    }

    /** Starts the viewer as {@code render view FILES} does, its viewport VW x VH, and waits until the files are shown. */
    private void launch(Path... files) {
        frame = onEdt(() -> {
            ViewerFrame f = ViewerFrame.withPlugins(OutputPlugins.available(), dir);
            f.setLocation(0, 0);
            f.setVisible(true);
            return f;
        });
        driver.window(ViewerFrame.class);
        viewport = driver.find(ViewportPanel.class, "the viewport", c -> SwingUtilities.isDescendingFrom(c, frame));
        Driver.onEdtDo(() -> {
            frame.setSize(frame.getWidth() + VW - viewport.getWidth(), frame.getHeight() + VH - viewport.getHeight());
            frame.validate();
        });
        driver.waitFor("the viewport to be " + VW + " x " + VH, () -> viewport.getWidth() == VW && viewport.getHeight() == VH);
        if (files.length > 0) {
            Driver.onEdtDo(() -> frame.open(List.of(files)));
            driver.waitFor(files.length + " surfaces open", () -> frame.model().surfaces().size() == files.length);
        }
        settled();
    }

    /** Waits until nothing is being read or refined and every surface shows what its settings ask for. */
    private void settled() {
        driver.waitFor("the viewer to settle", () -> frame.model().pending() == 0 && frame.model().surfaces().stream().allMatch(ViewedSurface::upToDate));
    }

    private void focusViewport() {
        Driver.onEdtDo(viewport::requestFocusInWindow);
        driver.waitFor("the focus in the viewport", viewport::isFocusOwner);
    }

    private void menu(String menu, String itemPrefix) {
        driver.click(driver.find(JMenu.class, "menu " + menu, m -> m.getText().equals(menu) && SwingUtilities.isDescendingFrom(m, frame)));
        driver.click(driver.find(JMenuItem.class, "item " + itemPrefix, m -> !(m instanceof JMenu) && m.getText().startsWith(itemPrefix)));
    }

    /**
     * Waits until the screen shows the viewport as the golden {@code name}.png (a tolerant compare,
     * as ViewportGoldenTest's); with -Dgolden.update=true it first writes what the screen shows once it is steady.
     */
    private void assertViewport(String name) throws IOException {
        settled();
        Path golden = GOLDEN.resolve(name + ".png");
        if (Boolean.getBoolean("golden.update")) {
            BufferedImage last = null, now = driver.capture(viewport);
            while (last == null || !Arrays.equals(pixels(last), pixels(now))) {
                driver.robot.delay(100);
                last = now;
                now = driver.capture(viewport);
            }
            Files.createDirectories(GOLDEN);
            ImageIO.write(now, "png", golden.toFile());
        }
        assertTrue(Files.exists(golden), "no golden " + golden + "; create it with -Dgolden.update=true");
        int[] expected = pixels(ImageIO.read(golden.toFile()));
        long end = System.currentTimeMillis() + Driver.TIMEOUT_MS;
        while (true) {
            BufferedImage shot = driver.capture(viewport);
            ImageDiff.Result d = ImageDiff.compare(VW, VH, expected, pixels(shot), 3);
            if (d.fractionOver() <= 0.002) return;
            if (System.currentTimeMillis() > end) {
                Files.createDirectories(OUT);
                Path actual = OUT.resolve("viewer-" + name + "-actual.png");
                ImageIO.write(shot, "png", actual.toFile());
                fail("the viewport differs from " + golden + ": " + d + "; the screen's is in " + actual);
            }
            driver.robot.delay(20);
        }
    }

    private static int[] pixels(BufferedImage img) {
        int[] p = img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
        for (int i = 0; i < p.length; i++) p[i] &= 0xffffff;
        return p;
    }

    @Test
    void renderViewOpensTheMeshWithThePluginsMenuAndReturnsWhenClosed() throws Exception {
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        java.util.concurrent.CompletableFuture<Integer> status = java.util.concurrent.CompletableFuture.supplyAsync(() ->
                lt.spindulys.cli.Main.run(new String[] {"view", "scenes/models/crease-cube.obj"},
                        new java.io.PrintStream(new java.io.ByteArrayOutputStream()), new java.io.PrintStream(err, true)));
        frame = driver.window(ViewerFrame.class);
        driver.waitFor("crease-cube.obj open", () -> frame.model().surfaces().size() == 1);
        driver.click(driver.find(PluginsMenu.class, "pluginsMenu"));
        assertNotNull(driver.find(JMenuItem.class, "plugin:raytrace"), "the ray tracer in the Plugins menu");
        assertNotNull(driver.find(JMenuItem.class, "plugin:obj"), "and the OBJ export");
        driver.key(KeyEvent.VK_ESCAPE, 0);
        Driver.onEdtDo(frame::dispose);
        assertEquals(0, status.get(10, TimeUnit.SECONDS), "render view returns when its window closes: " + err);
    }

    @Test
    void modesAndLevelsByKeysAndMenusShowAsTheGoldens() throws IOException {
        launch(Path.of("scenes/models/crease-cube.obj"));
        ViewedSurface s = onEdt(() -> frame.model().selected());
        assertEquals(DisplayMode.SMOOTHED, onEdt(() -> s.mode()));
        assertEquals(3, onEdt(() -> s.level()), "opens at level 3");
        assertViewport("crease-cube-smoothed-3");

        focusViewport();
        driver.key(KeyEvent.VK_1, 0);
        driver.key(KeyEvent.VK_PAGE_DOWN, 0);
        driver.key(KeyEvent.VK_PAGE_DOWN, 0);
        driver.waitFor("a polyhedron at level 1", () -> s.mode() == DisplayMode.POLYHEDRON && s.level() == 1);
        assertViewport("crease-cube-polyhedron-1");

        driver.key(KeyEvent.VK_2, 0);
        driver.waitFor("the lattice", () -> s.mode() == DisplayMode.LATTICE);
        assertViewport("crease-cube-lattice");

        // The same by the menus: View > Smoothed, Surface > Level up, View > Cage over surface.
        menu("View", "Smoothed");
        menu("Surface", "Level up");
        menu("View", "Cage over surface");
        driver.waitFor("smoothed at level 2 with its cage", () -> s.mode() == DisplayMode.SMOOTHED && s.level() == 2 && s.cage());
        assertViewport("crease-cube-smoothed-2-cage");
    }

    @Test
    void openByTheFileChooserAndByDropAndAMalformedMeshSaysSoInOneLine() throws IOException {
        launch();
        Path dat = Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Files.copy(Path.of("scenes/models/cube.tex"), dir.resolve("cube.tex"));
        Path obj = Files.copy(Path.of("scenes/models/tetrahedron.obj"), dir.resolve("tetrahedron.obj"));

        // File > Open, the path typed into the chooser's name field, Enter.
        menu("File", "Open");
        JFileChooser chooser = driver.find(JFileChooser.class, "the file chooser", c -> true);
        driver.awaitFocus(onEdt(() -> SwingUtilities.getWindowAncestor(chooser)));
        JTextField name = driver.find(JTextField.class, "the chooser's file name", t -> SwingUtilities.isDescendingFrom(t, chooser));
        Driver.onEdtDo(name::requestFocusInWindow);
        driver.waitFor("the focus in the file name", name::isFocusOwner);
        driver.type(dat.toAbsolutePath().toString());
        driver.key(KeyEvent.VK_ENTER, 0);
        driver.waitFor("cube.dat open", () -> frame.model().surfaces().size() == 1);
        settled();
        ViewedSurface cube = onEdt(() -> frame.model().surfaces().get(0));
        assertEquals("cube.dat", cube.name());
        assertEquals(dir.resolve("cube.tex"), onEdt(() -> cube.unwrap()), "with the unwrap beside it");

        // Dropped: through the window's TransferHandler, as a drop hands it over (a Robot cannot start a
        // drag from outside Java, so the window system's part of drag-and-drop is not exercised).
        assertTrue(drop(obj), "the drop is taken");
        driver.waitFor("the dropped mesh open", () -> frame.model().surfaces().size() == 2);
        assertEquals("tetrahedron.obj", onEdt(() -> frame.model().surfaces().get(1).name()));

        Path bad = Files.writeString(dir.resolve("bad.obj"), "v 0 0 0\nv 1 x 0\nf 1 2 1\n");
        String expected;
        try {
            MeshLoader.load(bad);
            throw new AssertionError("bad.obj was read");
        } catch (Exception e) {
            expected = FailureMessage.of(e);
        }
        assertTrue(expected.startsWith(bad + ":2:"), expected);
        drop(bad);
        JDialog message = driver.messageDialog();
        assertEquals(expected, Driver.message(message), "the line the command line prints");
        driver.enter(message);
        settled();
        assertEquals(2, onEdt(() -> frame.model().surfaces().size()), "nothing opened, nothing lost");
        assertTrue(onEdt(frame::isShowing), "the viewer keeps running");
    }

    private boolean drop(Path file) {
        Transferable t = new Transferable() {
            @Override public DataFlavor[] getTransferDataFlavors() { return new DataFlavor[] {DataFlavor.javaFileListFlavor}; }
            @Override public boolean isDataFlavorSupported(DataFlavor f) { return DataFlavor.javaFileListFlavor.equals(f); }
            @Override public Object getTransferData(DataFlavor f) { return List.<File>of(file.toFile()); }
        };
        return onEdt(() -> viewport.getTransferHandler().importData(new TransferHandler.TransferSupport(viewport, t)));
    }

    /** Plugins > Ray tracer, its dialog filled as a user fills it (the output left for the caller); returns the dialog. */
    private PluginDialog rayTracerDialog(String width, String height, String samples) {
        driver.click(driver.find(PluginsMenu.class, "pluginsMenu"));
        driver.click(driver.find(JMenuItem.class, "plugin:raytrace"));
        PluginDialog dialog = driver.window(PluginDialog.class);
        driver.retype(driver.find(JTextField.class, "option:width"), width);
        driver.retype(driver.find(JTextField.class, "option:height"), height);
        driver.retype(driver.find(JTextField.class, "option:samples"), samples);
        return dialog;
    }

    /** Types the output, clicks OK, and returns the render window once the dialog has closed. */
    private RenderWindow run(PluginDialog dialog, Path output) {
        driver.retype(driver.find(JTextField.class, "output"), output.toAbsolutePath().toString());
        JButton ok = driver.find(JButton.class, "ok");
        driver.waitFor("OK to be enabled", ok::isEnabled);
        driver.click(ok);
        driver.waitFor("the dialog to close", () -> !dialog.isShowing());
        return driver.find(RenderWindow.class, "the render window", w -> true);
    }

    @Test
    void theRayTracerFromThePluginsMenu() throws Exception {
        launch(Path.of("scenes/models/crease-cube.obj"));
        Path jpg = dir.resolve("cube.jpg");
        RenderWindow window = run(rayTracerDialog("160", "90", "1"), jpg);
        driver.waitFor("the run to end", () -> window.status().contains("wrote"));
        Rectangle viewer = onEdt(() -> new Rectangle(frame.getLocationOnScreen(), frame.getSize()));
        Point beside = new Point(viewer.x + viewer.width, viewer.y);
        driver.waitFor("the render window beside the viewer at " + beside, () -> window.isShowing() && window.getLocationOnScreen().equals(beside));
        BufferedImage shown = onEdt(window::picture);
        assertEquals(160, shown.getWidth());
        assertEquals(90, shown.getHeight());
        BufferedImage written = ImageIO.read(jpg.toFile());
        assertNotNull(written, "the .jpg decodes");
        assertEquals(160, written.getWidth());
        assertEquals(90, written.getHeight());
        // The cube is in the middle of the picture, the background in its corner.
        assertNotEquals(shown.getRGB(0, 0) & 0xffffff, shown.getRGB(80, 45) & 0xffffff, "the picture shows the cube");
        // The final picture is on the screen: its middle pixel there is the picture's.
        Component picture = driver.find(Component.class, "the picture", c -> "picture".equals(c.getName()) && SwingUtilities.isDescendingFrom(c, window));
        assertNotEquals(shown.getRGB(0, 0) & 0xffffff, driver.pixel(picture).getRGB() & 0xffffff, "the window shows the cube");
        driver.click(driver.find(JButton.class, "Close", b -> "cancel".equals(b.getName()) && SwingUtilities.isDescendingFrom(b, window)));
        driver.waitFor("the render window to close", () -> !window.isShowing());

        // An output that cannot be written (a folder is in the way): refused in one line before anything runs.
        Path taken = Files.createDirectory(dir.resolve("taken.jpg"));
        PluginDialog dialog = rayTracerDialog("640", "360", "64");
        driver.retype(driver.find(JTextField.class, "output"), taken.toString());
        JButton ok = driver.find(JButton.class, "ok");
        javax.swing.JLabel problem = driver.find(javax.swing.JLabel.class, "problem");
        String refused = "cannot write '" + taken + "': it is a directory";
        driver.waitFor("the folder in the way to be refused", () -> problem.getText().equals(refused) && !ok.isEnabled());
        assertTrue(onEdt(dialog::isShowing), "the dialog stays open");

        // A long run cancelled as soon as it starts: said so, and nothing written.
        Path big = dir.resolve("big.jpg");
        RenderWindow cancelled = run(dialog, big);
        driver.click(driver.find(JButton.class, "Cancel", b -> "cancel".equals(b.getName()) && SwingUtilities.isDescendingFrom(b, cancelled)));
        JDialog said = driver.messageDialog();
        assertEquals(FailureMessage.CANCELLED, Driver.message(said));
        driver.enter(said);
        assertTrue(cancelled.run().await(10, TimeUnit.SECONDS));
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(Set.of("cube.jpg", "taken.jpg"), files.map(p -> p.getFileName().toString()).collect(Collectors.toSet()),
                    "no picture and no temporary file of the failed or the cancelled run");
        }
        assertTrue(onEdt(frame::isShowing), "the viewer keeps running");
    }
}
