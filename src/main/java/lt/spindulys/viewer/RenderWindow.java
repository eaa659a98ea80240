package lt.spindulys.viewer;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.GraphicsConfiguration;
import java.awt.Insets;
import java.awt.Rectangle;
import java.awt.Toolkit;
import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.awt.image.BufferedImage;
import java.awt.image.ColorModel;
import java.awt.image.DataBufferInt;
import java.awt.image.DirectColorModel;
import java.awt.image.Raster;
import java.awt.image.WritableRaster;
import java.nio.file.Path;
import java.util.stream.Collectors;

import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;

import lt.spindulys.plugin.PluginResult;

/**
 * The window beside the viewer where a plugin run shows itself (the thesis's figure 58): the
 * picture scaled to fit, refined as previews arrive, a progress bar with the stage, and Cancel;
 * at the end the summary and the file written, or the failure's one line (also in a message
 * dialog). The run itself is on its own thread ({@link PluginRun}); this class only shows it, on
 * the event thread.
 */
public final class RenderWindow extends JDialog implements PluginRun.Listener {
    private static final int BAR_STEPS = 1000;

    private final String pluginName;
    private final Path output;
    private final FittedPicture picture = new FittedPicture();
    private final JProgressBar bar = new JProgressBar(0, BAR_STEPS);
    private final JLabel stage = new JLabel("starting");
    private final JLabel status = new JLabel(" ");
    private final JButton cancel = new JButton("Cancel");
    private PluginRun run;
    private boolean ended;

    private RenderWindow(Window owner, String pluginName, Path output, Dimension pictureSize) {
        super(owner, pluginName + " - " + output.getFileName(), ModalityType.MODELESS);
        this.pluginName = pluginName;
        this.output = output;
        setName("renderWindow");
        picture.setName("picture");
        bar.setName("progress");
        stage.setName("stage");
        status.setName("status");
        cancel.setName("cancel");
        picture.setPreferredSize(pictureSize);
        bar.setStringPainted(true);
        JPanel south = new JPanel(new BorderLayout(6, 4));
        south.setBorder(BorderFactory.createEmptyBorder(6, 8, 8, 8));
        JPanel line = new JPanel(new BorderLayout(6, 0));
        line.add(bar, BorderLayout.CENTER);
        line.add(cancel, BorderLayout.EAST);
        south.add(stage, BorderLayout.NORTH);
        south.add(line, BorderLayout.CENTER);
        south.add(status, BorderLayout.SOUTH);
        getContentPane().add(picture, BorderLayout.CENTER);
        getContentPane().add(south, BorderLayout.SOUTH);
        cancel.addActionListener(e -> cancelOrClose());
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override public void windowClosing(WindowEvent e) {
                // Closing the window stops the run: nobody would see its end.
                if (run != null && !ended) run.cancel();
                dispose();
            }

            @Override public void windowClosed(WindowEvent e) {
                // Also when the viewer closes and disposes the windows it owns (no windowClosing
                // then): the run stops before it writes, rather than dying with the JVM mid-file.
                if (run != null && !ended) run.cancel();
            }
        });
    }

    /**
     * Opens the window beside {@code owner} and starts the run. Call on the event thread.
     *
     * @param owner    the viewer's window
     * @param form     the dialog's model (plugin, surfaces, view)
     * @param accepted what the user accepted
     * @return the window, showing
     */
    public static RenderWindow start(Window owner, PluginForm form, PluginForm.Accepted accepted) {
        if (!SwingUtilities.isEventDispatchThread()) throw new IllegalStateException("RenderWindow.start must be called on the event thread");
        Dimension size = new Dimension(form.view().width(), form.view().height());
        RenderWindow w = new RenderWindow(owner, form.plugin().name(), accepted.output(), size);
        // Sized and placed before the window has a peer: packing first would map it at the origin,
        // and without a window manager (a virtual X server) that early placement can win over ours.
        Dimension wanted = w.getPreferredSize();
        GraphicsConfiguration gc = owner != null && owner.getGraphicsConfiguration() != null
                ? owner.getGraphicsConfiguration() : w.getGraphicsConfiguration();
        Rectangle screen = gc.getBounds();
        Insets insets = Toolkit.getDefaultToolkit().getScreenInsets(gc);
        screen = new Rectangle(screen.x + insets.left, screen.y + insets.top,
                screen.width - insets.left - insets.right, screen.height - insets.top - insets.bottom);
        Rectangle ownerBounds = owner != null ? owner.getBounds() : new Rectangle(screen.x, screen.y, 0, 0);
        w.setBounds(WindowPlacement.beside(ownerBounds, wanted, screen));
        // Started before it shows, so a request that cannot be made leaves no window; the run's
        // reports are posted to this (the event) thread, so none arrives before the window shows.
        w.run = PluginRun.start(form.plugin(), form.surfaces(), form.view(), accepted, SwingUtilities::invokeLater, w);
        w.setVisible(true);
        return w;
    }

    /** @return the run shown, to wait for or cancel */
    public PluginRun run() { return run; }

    /** @return the status line: the summary and file at the end, or the failure */
    public String status() { return status.getText(); }

    /** @return the picture shown last, or null before the first preview */
    public BufferedImage picture() { return picture.image(); }

    @Override
    public void progress(double fraction, String text) {
        if (ended) return;
        bar.setValue((int) Math.round(fraction * BAR_STEPS));
        bar.setString(Math.round(fraction * 100) + " %");
        stage.setText(text.isEmpty() ? " " : text);
    }

    @Override
    public void preview(int width, int height, int[] argb, boolean last) {
        // The array is ours after the call: wrap it rather than copy a full picture on the event thread.
        DirectColorModel argbModel = (DirectColorModel) ColorModel.getRGBdefault();
        WritableRaster raster = Raster.createPackedRaster(new DataBufferInt(argb, argb.length), width, height, width,
                argbModel.getMasks(), null);
        picture.show(new BufferedImage(argbModel, raster, false, null));
    }

    @Override
    public void finished(PluginResult result) {
        end();
        bar.setValue(BAR_STEPS);
        bar.setString("100 %");
        stage.setText("done");
        String files = result.files().stream().map(Path::toString).collect(Collectors.joining(", "));
        status.setText(result.summary() + (files.isEmpty() ? "" : "; wrote " + files));
        status.setToolTipText(status.getText());
        setTitle(pluginName + " - " + (result.files().isEmpty() ? output.getFileName() : result.files().get(0).getFileName()));
    }

    @Override
    public void failed(String message, boolean cancelled) {
        end();
        stage.setText(cancelled ? "cancelled" : "failed");
        status.setText(message);
        status.setToolTipText(message);
        setTitle(pluginName + " - " + (cancelled ? "cancelled" : "failed"));
        if (isDisplayable()) {
            JOptionPane.showMessageDialog(this, message, pluginName, cancelled ? JOptionPane.INFORMATION_MESSAGE : JOptionPane.ERROR_MESSAGE);
        }
    }

    private void end() {
        ended = true;
        cancel.setText("Close");
        cancel.setEnabled(true);
    }

    private void cancelOrClose() {
        if (ended || run == null) {
            dispose();
        } else {
            run.cancel();
            cancel.setEnabled(false);
            stage.setText("cancelling");
        }
    }
}
