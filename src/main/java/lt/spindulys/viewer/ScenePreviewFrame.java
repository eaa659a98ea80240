package lt.spindulys.viewer;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Point;
import java.awt.Toolkit;
import java.awt.datatransfer.StringSelection;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;

import javax.swing.BorderFactory;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTextArea;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

import lt.spindulys.frontend.FailureMessage;

/**
 * The window of {@code render view SCENE.dat}: the scene's picture, refined pass by pass and
 * rendered again whenever the scene's files change ({@link ScenePreview}), with the error of a
 * file that does not read shown above the last good picture. Dragging turns the view around the
 * camera's look-at point, the wheel moves the camera nearer or farther; the Camera menu resets the
 * view, copies it as a {@code camera} block, or saves that block into the scene file. Everything
 * here runs on the event thread; reading and rendering run on the preview's own.
 */
public final class ScenePreviewFrame extends JFrame implements ScenePreview.Listener {
    private final ScenePreview preview;
    private final FittedPicture picture = new FittedPicture();
    private final JLabel status = new JLabel("starting");
    private final JLabel error = new JLabel();
    private String lastStatus = "";
    /** True once the picture area has the scene's aspect. */
    private boolean shaped;

    private ScenePreviewFrame(Path file, Integer frame) {
        super(file.getFileName() + " - Spindulys preview");
        setName("scenePreview");
        preview = new ScenePreview(file, frame, SwingUtilities::invokeLater, this, Runtime.getRuntime().availableProcessors());
        picture.setName("picture");
        status.setName("status");
        error.setName("error");
        error.setForeground(new Color(0xB00020));
        error.setVisible(false);
        status.setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        error.setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        picture.setPreferredSize(new Dimension(640, 480));
        JPanel content = new JPanel(new BorderLayout());
        content.add(error, BorderLayout.NORTH);
        content.add(picture, BorderLayout.CENTER);
        content.add(status, BorderLayout.SOUTH);
        setContentPane(content);
        setJMenuBar(menus());
        MouseAdapter mouse = new MouseAdapter() {
            private Point last;

            @Override public void mousePressed(MouseEvent e) { last = e.getPoint(); }

            @Override public void mouseDragged(MouseEvent e) {
                if (last == null) return;
                preview.dragged(e.getX() - last.x, e.getY() - last.y);
                last = e.getPoint();
            }

            @Override public void mouseReleased(MouseEvent e) {
                if (last != null) preview.released();
                last = null;
            }

            @Override public void mouseWheelMoved(MouseWheelEvent e) { preview.dollied(e.getPreciseWheelRotation()); }
        };
        picture.addMouseListener(mouse);
        picture.addMouseMotionListener(mouse);
        picture.addMouseWheelListener(mouse);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override public void windowClosed(WindowEvent e) { preview.close(); }
        });
        pack();
    }

    /**
     * Opens the preview of a scene file and starts reading and rendering it. Call on the event thread.
     *
     * @param file  the scene file
     * @param frame the animation frame to show, or null (a still, or the animation's first frame)
     * @return the window, not yet visible
     * @throws IOException if the file system cannot watch files
     */
    public static ScenePreviewFrame open(Path file, Integer frame) throws IOException {
        if (!SwingUtilities.isEventDispatchThread()) throw new IllegalStateException("ScenePreviewFrame.open must be called on the event thread");
        ScenePreviewFrame f = new ScenePreviewFrame(file, frame);
        f.preview.start();
        return f;
    }

    private JMenuBar menus() {
        JMenu camera = new JMenu("Camera");
        camera.setName("cameraMenu");
        camera.setMnemonic(KeyEvent.VK_C);
        camera.add(item("Reset view", "resetView", KeyStroke.getKeyStroke(KeyEvent.VK_HOME, 0), preview::reset));
        camera.add(item("Copy camera block", "copyCamera", KeyStroke.getKeyStroke(KeyEvent.VK_C, InputEvent.CTRL_DOWN_MASK), this::copyCamera));
        camera.add(item("Save camera to scene file...", "saveCamera", KeyStroke.getKeyStroke(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK), this::saveCamera));
        JMenuBar bar = new JMenuBar();
        bar.add(camera);
        return bar;
    }

    private static JMenuItem item(String text, String name, KeyStroke key, Runnable action) {
        JMenuItem i = new JMenuItem(text);
        i.setName(name);
        i.setAccelerator(key);
        i.addActionListener(e -> action.run());
        return i;
    }

    private void copyCamera() {
        String block = preview.cameraBlock();
        if (block == null) {
            JOptionPane.showMessageDialog(this, "There is no camera yet: the scene has not been read.", "Copy camera block", JOptionPane.INFORMATION_MESSAGE);
            return;
        }
        StringSelection s = new StringSelection(block);
        Toolkit.getDefaultToolkit().getSystemClipboard().setContents(s, s);
        lastStatus = "copied: " + block;
        status.setText(lastStatus);
    }

    private void saveCamera() {
        String block = preview.cameraBlock();
        if (block == null) {
            JOptionPane.showMessageDialog(this, "There is no camera yet: the scene has not been read.", "Save camera", JOptionPane.INFORMATION_MESSAGE);
            return;
        }
        JTextArea text = new JTextArea(block);
        text.setEditable(false);
        text.setLineWrap(true);
        text.setColumns(60);
        JPanel ask = new JPanel(new BorderLayout(0, 6));
        ask.add(new JLabel("Replace the camera statement of " + preview.file() + " with this one? The rest of the file stays as it is."), BorderLayout.NORTH);
        ask.add(new JScrollPane(text), BorderLayout.CENTER);
        if (JOptionPane.showConfirmDialog(this, ask, "Save camera", JOptionPane.OK_CANCEL_OPTION) != JOptionPane.OK_OPTION) return;
        // Off the event thread: the write is flushed to disk before the rename.
        Thread t = new Thread(() -> {
            String outcome;
            boolean ok;
            try {
                outcome = "saved the camera into " + preview.file() + ": " + preview.saveCamera();
                ok = true;
            } catch (IOException | RuntimeException e) {
                outcome = FailureMessage.of(e);
                ok = false;
            }
            String message = outcome;
            boolean saved = ok;
            SwingUtilities.invokeLater(() -> {
                if (saved) {
                    lastStatus = message;
                    status.setText(message);
                } else if (isDisplayable()) {
                    JOptionPane.showMessageDialog(this, message, "Save camera", JOptionPane.ERROR_MESSAGE);
                }
            });
        }, "spindulys-preview-save");
        t.start();
    }

    @Override
    public void picture(BufferedImage image, String text) {
        if (!shaped) shape(image.getWidth(), image.getHeight());
        picture.show(image);
    }

    /** The largest picture area the window opens with, before the user resizes it. */
    static final int MAX_OPENING_WIDTH = 960, MAX_OPENING_HEIGHT = 640;

    /** Gives the picture area the scene's aspect once, at its first picture, so it is not letterboxed. */
    private void shape(int w, int h) {
        shaped = true;
        double scale = Math.min((double) MAX_OPENING_WIDTH / w, (double) MAX_OPENING_HEIGHT / h);
        picture.setPreferredSize(new Dimension(Math.max(160, (int) Math.round(w * scale)), Math.max(120, (int) Math.round(h * scale))));
        pack();
    }

    @Override
    public void partial(BufferedImage image, String text) {
        picture.show(image);
        status.setText(text);
    }

    @Override
    public void status(String text, String errorText) {
        lastStatus = text;
        status.setText(text);
        error.setText(errorText == null ? "" : errorText);
        error.setToolTipText(errorText);
        error.setVisible(errorText != null);
    }

    /** {@return the preview shown} */
    public ScenePreview preview() { return preview; }

    /** {@return the picture shown, or null before the first pass} */
    public BufferedImage picture() { return picture.image(); }

    /** {@return the error shown, or null when there is none} */
    public String error() { return error.isVisible() ? error.getText() : null; }

    /** {@return the status line} */
    public String status() { return lastStatus; }
}
