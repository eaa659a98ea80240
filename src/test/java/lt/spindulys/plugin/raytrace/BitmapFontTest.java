package lt.spindulys.plugin.raytrace;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;

class BitmapFontTest {
    /** A glyph's 35 pixels as a string of '#' and '.', rows from the top. */
    private static String glyph(char c) {
        StringBuilder b = new StringBuilder();
        for (int y = 0; y < BitmapFont.GLYPH_HEIGHT; y++) {
            for (int x = 0; x < BitmapFont.GLYPH_WIDTH; x++) b.append(BitmapFont.pixel(c, x, y) ? '#' : '.');
            b.append('\n');
        }
        return b.toString();
    }

    @Test
    void everyPrintableCharacterHasItsOwnGlyph() {
        Map<String, Character> seen = new HashMap<>();
        for (char c = BitmapFont.FIRST; c <= BitmapFont.LAST; c++) {
            String g = glyph(c);
            if (c != ' ') assertTrue(g.contains("#"), "'" + c + "' draws something");
            Character before = seen.put(g, c);
            assertEquals(null, before, "'" + c + "' looks like '" + before + "'");
        }
        assertFalse(glyph(' ').contains("#"));
    }

    @Test
    void lettersLookLikeThemselves() {
        assertEquals("""
                .###.
                #...#
                #...#
                #...#
                #####
                #...#
                #...#
                """, glyph('A'));
        assertEquals("""
                #####
                ..#..
                ..#..
                ..#..
                ..#..
                ..#..
                ..#..
                """, glyph('T'));
        assertEquals(glyph('?'), glyph('\u00e9'), "a character the font lacks is a question mark");
    }

    @Test
    void drawsScaledAndClipped() {
        int w = 20, h = 16;
        int[] img = new int[w * h];
        BitmapFont.draw(img, w, 1, 1, "T", 7, 2);
        // The T's bar: font row 0 at image rows 1-2, columns 1-10; its stem at font column 2: image columns 5-6.
        for (int x = 1; x <= 10; x++) assertEquals(7, img[w + x]);
        for (int y = 3; y < 15; y++) {
            assertEquals(7, img[y * w + 5]);
            assertEquals(0, img[y * w + 4]);
        }
        assertEquals(0, img[0]);
        assertEquals(2 * (2 * BitmapFont.ADVANCE - 1), BitmapFont.width("TT", 2));
        assertEquals(0, BitmapFont.width("", 1));
        BitmapFont.draw(img, w, 15, 12, "WWW", 9, 3); // mostly outside: clipped, no exception
        assertThrows(IllegalArgumentException.class, () -> BitmapFont.draw(new int[10], 3, 0, 0, "x", 1, 1));
        assertThrows(IllegalArgumentException.class, () -> BitmapFont.width("x", 0));
    }
}
