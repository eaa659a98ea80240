package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.Color;
import java.awt.Dimension;
import java.awt.Rectangle;

import org.junit.jupiter.api.Test;

class WindowPlacementTest {
    private final Rectangle screen = new Rectangle(0, 0, 1600, 1000);

    @Test
    void theRenderWindowGoesToTheRightOfTheViewerWhenItFits() {
        assertEquals(new Rectangle(800, 50, 640, 400), WindowPlacement.beside(new Rectangle(100, 50, 700, 500), new Dimension(640, 400), screen));
    }

    @Test
    void elseToItsLeftElseAtTheScreensRightEdge() {
        assertEquals(new Rectangle(260, 0, 640, 400), WindowPlacement.beside(new Rectangle(900, 0, 700, 500), new Dimension(640, 400), screen));
        assertEquals(new Rectangle(960, 0, 640, 400), WindowPlacement.beside(new Rectangle(300, 0, 1000, 500), new Dimension(640, 400), screen));
    }

    @Test
    void itIsShrunkToTheScreenAndStaysOnIt() {
        assertEquals(new Rectangle(0, 0, 1600, 1000), WindowPlacement.beside(new Rectangle(0, 0, 800, 600), new Dimension(2000, 1200), screen));
        assertEquals(new Rectangle(800, 600, 640, 400), WindowPlacement.beside(new Rectangle(0, 900, 800, 600), new Dimension(640, 400), screen));
        Rectangle second = new Rectangle(1600, 0, 1280, 1024); // a screen right of the first
        assertEquals(new Rectangle(1700, 10, 640, 400), WindowPlacement.beside(new Rectangle(1600, 10, 100, 100), new Dimension(640, 400), second));
    }

    @Test
    void aPictureFitsItsAreaKeepingItsProportionsCentred() {
        assertEquals(new Rectangle(50, 0, 400, 300), WindowPlacement.fit(4, 3, 500, 300));
        assertEquals(new Rectangle(0, 25, 200, 50), WindowPlacement.fit(1280, 320, 200, 100));
        assertEquals(new Rectangle(0, 0, 0, 0), WindowPlacement.fit(4, 3, 0, 10));
        assertEquals(new Rectangle(0, 0, 1, 1), WindowPlacement.fit(1, 1000, 1, 1));
    }

    @Test
    void coloursTravelAsThreeNumbers() {
        assertEquals("1 0.502 0", PluginDialog.formatColour(new Color(255, 128, 0)));
        assertEquals(new Color(255, 128, 0), PluginDialog.parseColour("1 0.502 0"));
        assertEquals(null, PluginDialog.parseColour("1 0.5"));
        assertEquals(null, PluginDialog.parseColour("2 0 0"));
    }
}
