package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

class PixelRegionTest {
    @Test
    void bandsCoverEveryRowOnceInOrderAndDifferByAtMostOneRow() {
        for (int h = 1; h <= 70; h++) {
            for (int n = 1; n <= h; n++) {
                int next = 0, min = Integer.MAX_VALUE, max = 0;
                for (int i = 1; i <= n; i++) {
                    PixelRegion b = PixelRegion.band(i, n, 13, h);
                    assertEquals(next, b.y0(), h + " rows, tile " + i + "/" + n);
                    assertEquals(0, b.x0());
                    assertEquals(13, b.x1());
                    min = Math.min(min, b.height());
                    max = Math.max(max, b.height());
                    next = b.y1();
                }
                assertEquals(h, next);
                assertTrue(max - min <= 1 && min >= 1, h + " rows in " + n + " bands: " + min + " to " + max);
            }
        }
        PixelRegion last = PixelRegion.band(3_000_000, 3_000_000, 1, 3_000_000); // no overflow in i * h
        assertEquals(new PixelRegion(0, 1, 2_999_999, 3_000_000), last);
    }

    @Test
    void refusals() {
        assertEquals("the 10x5 frame has 5 rows, too few for 6 tiles of whole rows",
                assertThrows(IllegalArgumentException.class, () -> PixelRegion.band(1, 6, 10, 5)).getMessage());
        assertEquals("tile 0/3 does not exist (tiles are numbered from 1 to their count)",
                assertThrows(IllegalArgumentException.class, () -> PixelRegion.band(0, 3, 10, 5)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> PixelRegion.band(4, 3, 10, 5));
        assertThrows(IllegalArgumentException.class, () -> PixelRegion.checkTile(1, 0));
        assertThrows(IllegalArgumentException.class, () -> new PixelRegion(-1, 2, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new PixelRegion(0, 2, 1, 1));
        assertThrows(IllegalArgumentException.class, () -> PixelRegion.parse("1,2,3"));
        assertThrows(IllegalArgumentException.class, () -> PixelRegion.parse("1,2,3,x"));
        assertEquals(new PixelRegion(1, 2, 3, 4), PixelRegion.parse("1,2,3,4"));
        assertEquals("1,2,3,4", new PixelRegion(1, 2, 3, 4).toString());
        assertTrue(new PixelRegion(0, 2, 0, 2).overlaps(new PixelRegion(1, 3, 1, 3)));
        assertFalse(new PixelRegion(0, 2, 0, 2).overlaps(new PixelRegion(2, 3, 0, 2)), "half-open: touching is not overlapping");
    }

    @Test
    void placementTextRoundTrips() {
        TileFile.Placement p = new TileFile.Placement(new PixelRegion(0, 200, 37, 75), 200, 150);
        assertEquals("0,200,37,75 of 200x150", p.text());
        assertEquals(p, TileFile.Placement.parse(p.text()));
        assertThrows(IllegalArgumentException.class, () -> TileFile.Placement.parse("0,200,37,75 of 200x70"));
        assertThrows(IllegalArgumentException.class, () -> TileFile.Placement.parse("0,200,37,75"));
    }
}
