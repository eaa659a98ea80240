package lt.spindulys.viewer;

import java.awt.Color;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.Rectangle;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;

import javax.swing.JComponent;

/**
 * A picture scaled to fit the component and centred: blocky (nearest pixel) while a coarse
 * preview is enlarged, smooth when shrunk. Shared by the plugin run's window and the scene preview.
 */
final class FittedPicture extends JComponent {
    private static final long serialVersionUID = 1L;

    private transient BufferedImage image;

    /** Shows {@code next} instead of the picture shown. Call on the event thread. */
    void show(BufferedImage next) {
        image = next;
        repaint();
    }

    /** {@return the picture shown, or null} */
    BufferedImage image() { return image; }

    @Override
    protected void paintComponent(Graphics g) {
        g.setColor(Color.DARK_GRAY);
        g.fillRect(0, 0, getWidth(), getHeight());
        if (image == null) return;
        Rectangle r = WindowPlacement.fit(image.getWidth(), image.getHeight(), getWidth(), getHeight());
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            boolean enlarged = r.width > image.getWidth();
            g2.setRenderingHint(RenderingHints.KEY_INTERPOLATION, enlarged
                    ? RenderingHints.VALUE_INTERPOLATION_NEAREST_NEIGHBOR : RenderingHints.VALUE_INTERPOLATION_BILINEAR);
            g2.drawImage(image, r.x, r.y, r.width, r.height, null);
        } finally {
            g2.dispose();
        }
    }
}
