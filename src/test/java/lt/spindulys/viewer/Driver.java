package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.fail;

import java.awt.AWTException;
import java.awt.Color;
import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.lang.reflect.InvocationTargetException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import java.util.function.Predicate;

import javax.swing.JDialog;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;

/**
 * Drives real windows with {@link Robot} for the display tests: clicks and keys go through the
 * window system like a user's; conditions are polled on the event thread until they hold or a
 * timeout fails the test with what was awaited, so no test depends on a fixed sleep.
 */
final class Driver {
    static final long TIMEOUT_MS = 15_000;

    final Robot robot;

    /** A driver of the display the tests run on (the AWT's refusal, which a display test never meets, unchecked). */
    Driver() {
        try {
            robot = new Robot();
        } catch (AWTException e) {
            throw new IllegalStateException(e);
        }
        robot.setAutoDelay(10);
    }

    /** Runs {@code task} on the event thread and returns its result. */
    static <T> T onEdt(Callable<T> task) {
        AtomicReference<T> result = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                try {
                    result.set(task.call());
                } catch (Exception e) {
                    throw new RuntimeException(e);
                }
            });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new AssertionError("interrupted", e);
        } catch (InvocationTargetException e) {
            throw new AssertionError(e.getCause());
        }
        return result.get();
    }

    static void onEdtDo(Runnable task) {
        onEdt(() -> {
            task.run();
            return null;
        });
    }

    /** Waits until {@code condition} (evaluated on the event thread) holds; fails naming {@code what}. */
    void waitFor(String what, BooleanSupplier condition) {
        long end = System.currentTimeMillis() + TIMEOUT_MS;
        while (!onEdt(condition::getAsBoolean)) {
            if (System.currentTimeMillis() > end) fail("timed out after " + TIMEOUT_MS + " ms waiting for " + what + screenshot());
            robot.delay(20);
        }
    }

    /** The showing component of this type and name in any showing window, waiting for it to appear. */
    <T extends Component> T find(Class<T> type, String name) {
        return find(type, "'" + name + "'", c -> name.equals(c.getName()));
    }

    /** The showing component of this type that passes {@code test} (run on the event thread), waiting for it. */
    <T extends Component> T find(Class<T> type, String what, Predicate<T> test) {
        AtomicReference<T> found = new AtomicReference<>();
        waitFor(type.getSimpleName() + " " + what + " to show", () -> {
            found.set(search(type, test));
            return found.get() != null;
        });
        return found.get();
    }

    /**
     * The showing window of this type, waiting for it to have the focus: Java calls a window
     * showing before the window system has mapped it, and a click before that would land on the
     * window below; the focus arrives from the window system once it is mapped.
     */
    <T extends Window> T window(Class<T> type) {
        AtomicReference<T> found = new AtomicReference<>();
        waitFor(type.getSimpleName() + " to show with the focus", () -> {
            for (Window w : Window.getWindows()) if (type.isInstance(w) && w.isShowing() && w.isFocused()) found.set(type.cast(w));
            return found.get() != null;
        });
        return found.get();
    }

    /**
     * Closes a dialog of the JDK's (a message, a colour chooser) with Enter, its default button, as
     * a user may: those dialogs are packed before they are placed, and without a window manager
     * Java can then believe them elsewhere than they are (see docs/plugin-host.md), so a click at
     * the button's believed place could miss; the keyboard goes to the focused window wherever it is.
     */
    void enter(Window dialog) {
        awaitFocus(dialog);
        key(KeyEvent.VK_ENTER, 0);
        waitFor("window '" + dialog.getName() + "' to close", () -> !dialog.isShowing());
    }

    /** Waits until a window the test found has the focus, that is, until the window system has mapped it (see {@link #window}). */
    void awaitFocus(Window w) {
        waitFor("window '" + w.getName() + "' to have the focus", () -> w.isShowing() && w.isFocused());
    }

    /** The message of the showing option pane (a message dialog), waiting for it. */
    JDialog messageDialog() {
        AtomicReference<JDialog> found = new AtomicReference<>();
        waitFor("a message dialog to show with the focus", () -> {
            for (Window w : Window.getWindows()) {
                if (w instanceof JDialog d && d.isShowing() && d.isFocused() && search(d, JOptionPane.class, c -> true) != null) found.set(d);
            }
            return found.get() != null;
        });
        return found.get();
    }

    static String message(JDialog d) {
        return onEdt(() -> String.valueOf(search(d, JOptionPane.class, c -> true).getMessage()));
    }

    private static <T extends Component> T search(Class<T> type, Predicate<T> test) {
        for (Window w : Window.getWindows()) {
            if (!w.isShowing()) continue;
            T t = search(w, type, test);
            if (t != null) return t;
        }
        return null;
    }

    private static <T extends Component> T search(Container root, Class<T> type, Predicate<T> test) {
        List<Component> todo = new ArrayList<>(List.of(root.getComponents()));
        if (type.isInstance(root) && test.test(type.cast(root))) return type.cast(root);
        while (!todo.isEmpty()) {
            Component c = todo.remove(todo.size() - 1);
            if (type.isInstance(c) && c.isShowing() && test.test(type.cast(c))) return type.cast(c);
            if (c instanceof Container k) todo.addAll(List.of(k.getComponents()));
        }
        return null;
    }

    /** Saves the screen for a failed wait, so a CI log can be followed by a picture; returns where, for the message. */
    String screenshot() {
        try {
            java.nio.file.Path dir = java.nio.file.Path.of("target", "display-failures");
            java.nio.file.Files.createDirectories(dir);
            java.nio.file.Path file = dir.resolve("screen-" + System.nanoTime() + ".png");
            java.awt.Rectangle all = new java.awt.Rectangle(java.awt.Toolkit.getDefaultToolkit().getScreenSize());
            javax.imageio.ImageIO.write(robot.createScreenCapture(all), "png", file.toFile());
            return " (the screen is in " + file + ")";
        } catch (java.io.IOException | RuntimeException e) {
            return " (no screenshot: " + e + ")";
        }
    }

    /**
     * Clicks the middle of a showing component, as a user would. A window just shown may not yet be
     * where it will be (the window system moves it after mapping), so the pointer is moved until the
     * component itself says the pointer is over it.
     */
    void click(Component c) {
        waitFor("the pointer over " + c.getName(), () -> {
            if (!c.isShowing()) return false;
            Point p = c.getLocationOnScreen();
            robot.mouseMove(p.x + c.getWidth() / 2, p.y + c.getHeight() / 2);
            return c.getMousePosition() != null;
        });
        // No Robot.waitForIdle here or below: under a virtual X server without a window manager it
        // can stall for seconds at a time; callers wait for what the click does instead.
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
    }

    /** Clicks into a text field, waits for its focus, and replaces its text by typing. */
    void retype(Component field, String text) {
        click(field);
        waitFor("the focus in " + field.getName(), field::isFocusOwner);
        key(KeyEvent.VK_A, InputEvent.CTRL_DOWN_MASK);
        key(KeyEvent.VK_DELETE, 0);
        type(text);
        if (field instanceof javax.swing.text.JTextComponent t) waitFor("'" + text + "' in " + field.getName(), () -> t.getText().equals(text));
    }

    /** Types {@code text} into whatever has the focus, key by key, as a user would. */
    void type(String text) {
        for (char ch : text.toCharArray()) {
            switch (ch) {
                case ' ' -> key(KeyEvent.VK_SPACE, 0);
                case '.' -> key(KeyEvent.VK_PERIOD, 0);
                case '-' -> key(KeyEvent.VK_MINUS, 0);
                case '/' -> key(KeyEvent.VK_SLASH, 0);
                case '_' -> key(KeyEvent.VK_MINUS, InputEvent.SHIFT_DOWN_MASK);
                default -> {
                    if (Character.isDigit(ch) || (ch >= 'a' && ch <= 'z')) key(KeyEvent.getExtendedKeyCodeForChar(ch), 0);
                    else throw new IllegalArgumentException("the driver types digits, small letters, space, '.', '-', '/' and '_', not '" + ch + "'");
                }
            }
        }
    }

    /** Presses and releases a key, with modifiers (only Ctrl and Shift). */
    void key(int code, int modifiers) {
        if ((modifiers & InputEvent.CTRL_DOWN_MASK) != 0) robot.keyPress(KeyEvent.VK_CONTROL);
        if ((modifiers & InputEvent.SHIFT_DOWN_MASK) != 0) robot.keyPress(KeyEvent.VK_SHIFT);
        robot.keyPress(code);
        robot.keyRelease(code);
        if ((modifiers & InputEvent.SHIFT_DOWN_MASK) != 0) robot.keyRelease(KeyEvent.VK_SHIFT);
        if ((modifiers & InputEvent.CTRL_DOWN_MASK) != 0) robot.keyRelease(KeyEvent.VK_CONTROL);
    }

    /** What the screen shows of a showing component: its rectangle captured from the screen. */
    java.awt.image.BufferedImage capture(Component c) {
        java.awt.Rectangle r = onEdt(() -> new java.awt.Rectangle(c.getLocationOnScreen(), c.getSize()));
        return robot.createScreenCapture(r);
    }

    /** The colour on the screen at the middle of a showing component. */
    Color pixel(Component c) {
        Point p = centre(c);
        return robot.getPixelColor(p.x, p.y);
    }

    static Point centre(Component c) {
        return onEdt(() -> {
            Point p = c.getLocationOnScreen();
            return new Point(p.x + c.getWidth() / 2, p.y + c.getHeight() / 2);
        });
    }

    /** Closes every window the test left open. */
    static void disposeAll() {
        onEdtDo(() -> {
            for (Window w : Window.getWindows()) w.dispose();
        });
    }
}
