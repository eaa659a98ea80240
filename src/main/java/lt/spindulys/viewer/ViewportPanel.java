package lt.spindulys.viewer;

import java.awt.Dimension;
import java.awt.Graphics;
import java.awt.event.KeyAdapter;
import java.awt.event.KeyEvent;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;

import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * The viewport: paints the rasterizer's frame (a BufferedImage over its int array, remade only
 * when the size changes) and passes keys and mouse to {@link ViewerInput}. Thin on purpose: what
 * an event does is decided in the model.
 */
final class ViewportPanel extends JComponent {
    private final ViewerModel model;
    private final Rasterizer rasterizer;
    private BufferedImage image;
    private int[] pixels;

    ViewportPanel(ViewerModel model, Rasterizer rasterizer) {
        this.model = model;
        this.rasterizer = rasterizer;
        setPreferredSize(new Dimension(960, 640));
        setFocusable(true);
        ViewerInput input = new ViewerInput(model);
        MouseAdapter mouse = new MouseAdapter() {
            @Override public void mousePressed(MouseEvent e) {
                requestFocusInWindow();
                input.press(e.getX(), e.getY(), SwingUtilities.isRightMouseButton(e) || SwingUtilities.isMiddleMouseButton(e) || e.isShiftDown());
            }
            @Override public void mouseDragged(MouseEvent e) { input.drag(e.getX(), e.getY()); }
            @Override public void mouseReleased(MouseEvent e) { input.release(); }
            @Override public void mouseWheelMoved(MouseWheelEvent e) { input.wheel(e.getPreciseWheelRotation()); }
        };
        // The model fits and pans for the viewport's size, known before the first paint.
        addComponentListener(new java.awt.event.ComponentAdapter() {
            @Override public void componentResized(java.awt.event.ComponentEvent e) { model.viewport(getWidth(), getHeight()); }
        });
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        addKeyListener(new KeyAdapter() {
            @Override public void keyPressed(KeyEvent e) {
                // Menu shortcuts (Ctrl or Meta) belong to the menus.
                if ((e.getModifiersEx() & (KeyEvent.CTRL_DOWN_MASK | KeyEvent.META_DOWN_MASK | KeyEvent.ALT_DOWN_MASK)) != 0) return;
                if (input.key(e.getKeyCode(), e.getKeyChar())) e.consume();
            }
        });
    }

    @Override
    protected void paintComponent(Graphics g) {
        int w = getWidth(), h = getHeight();
        if (w < 1 || h < 1) return;
        if (image == null || image.getWidth() != w || image.getHeight() != h) {
            image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
            pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        }
        model.viewport(w, h);
        rasterizer.render(model.drawList(), model.camera(), pixels, w, h);
        g.drawImage(image, 0, 0, null);
    }
}
