package lt.spindulys.viewer;

import static lt.spindulys.viewer.Driver.onEdt;
import static org.junit.jupiter.api.Assertions.*;

import java.awt.Toolkit;
import java.awt.datatransfer.DataFlavor;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The scene preview in a real window, as {@code render view scene.dat} opens it: a picture shows;
 * the scene file edited on disk so that it no longer reads shows the located error with the old
 * picture kept; fixed, it shows a new picture and no error. A drag on the picture turns the view,
 * Ctrl+C copies it as a camera block and Ctrl+S, once confirmed, saves it into the file.
 */
@DisplayTest
class ScenePreviewDisplayTest {
    @TempDir Path dir;

    private final Driver driver = new Driver();

    @AfterEach
    void closeAll() {
        Driver.disposeAll();
    }

    private void write(Path f, String text) throws Exception {
        Path tmp = dir.resolve("editing.tmp");
        Files.writeString(tmp, text);
        Files.move(tmp, f, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }

    @Test
    void anEditThatBreaksTheFileShowsItsErrorOverTheOldPictureAndAFixShowsANewOne() throws Exception {
        Path scene = dir.resolve("scene.dat");
        write(scene, ScenePreviewTest.SCENE);
        ScenePreviewFrame frame = onEdt(() -> {
            ScenePreviewFrame f = ScenePreviewFrame.open(scene, null);
            f.setLocation(0, 0);
            f.setVisible(true);
            return f;
        });
        driver.waitFor("the full picture", () -> frame.picture() != null && frame.picture().getWidth() == 12 && frame.status().startsWith("done"));
        BufferedImage good = onEdt(frame::picture);
        assertNull(onEdt(frame::error));

        write(scene, ScenePreviewTest.SCENE.replace("radius 1", "radius oops"));
        driver.waitFor("the error shown", () -> frame.error() != null);
        assertTrue(onEdt(frame::error).startsWith(scene + ":6:17: "), onEdt(frame::error));
        JLabelText error = new JLabelText(driver.find(javax.swing.JLabel.class, "error"));
        assertTrue(error.showing(), "the error is on the screen");
        assertSame(good, onEdt(frame::picture), "the last good picture is kept");

        write(scene, ScenePreviewTest.SCENE.replace("0.9 0.2 0.1", "0.1 0.3 0.9"));
        driver.waitFor("a new full picture", () -> frame.picture() != good && frame.picture().getWidth() == 12 && frame.status().startsWith("done"));
        assertNull(onEdt(frame::error));
        assertFalse(error.showing(), "the error is gone");

        // A drag on the picture turns the view: the camera is no longer the file's.
        var picture = driver.find(FittedPicture.class, "picture");
        java.awt.Point c = Driver.centre(picture);
        driver.robot.mouseMove(c.x, c.y);
        driver.robot.mousePress(java.awt.event.InputEvent.BUTTON1_DOWN_MASK);
        for (int i = 1; i <= 10; i++) driver.robot.mouseMove(c.x + 4 * i, c.y);
        driver.robot.mouseRelease(java.awt.event.InputEvent.BUTTON1_DOWN_MASK);
        driver.waitFor("the view turned", () -> !frame.preview().cameraBlock().contains("eye 0 1 -5"));
        driver.waitFor("the turned view's full picture", () -> frame.status().startsWith("done"));

        // Ctrl+C copies the view as a camera block; Ctrl+S asks, then writes it into the file.
        String block = onEdt(() -> frame.preview().cameraBlock());
        driver.window(ScenePreviewFrame.class);
        driver.key(KeyEvent.VK_C, InputEvent.CTRL_DOWN_MASK);
        driver.waitFor("the block on the clipboard", () -> block.equals(clipboard()));
        String before = Files.readString(scene);
        driver.key(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK);
        javax.swing.JDialog ask = driver.messageDialog();
        assertTrue(Driver.message(ask).contains("javax.swing.JPanel"), "the question shows the block in a panel");
        driver.enter(ask);
        driver.waitFor("the camera saved", () -> read(scene).contains(block));
        String after = Files.readString(scene);
        assertEquals(before.replace("camera { eye 0 1 -5  lookat 0 0 0  fov 40 }", block), after);
        // The preview reads the saved file; the view stays where it was.
        driver.waitFor("the saved file's full picture", () -> frame.status().startsWith("done") && frame.preview().camera() != null
                && block.equals(frame.preview().cameraBlock()));
    }

    private static String read(Path f) {
        try {
            return Files.readString(f);
        } catch (java.io.IOException e) {
            return "";
        }
    }

    private static String clipboard() {
        try {
            return (String) Toolkit.getDefaultToolkit().getSystemClipboard().getData(DataFlavor.stringFlavor);
        } catch (java.awt.datatransfer.UnsupportedFlavorException | java.io.IOException | IllegalStateException e) {
            return null;
        }
    }

    /** A label's visibility as the screen shows it, read on the event thread. */
    private record JLabelText(javax.swing.JLabel label) {
        boolean showing() { return onEdt(() -> label.isShowing() && !label.getText().isEmpty()); }
    }
}
