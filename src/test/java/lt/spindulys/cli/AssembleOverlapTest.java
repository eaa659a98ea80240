package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.PixelRegion;
import lt.spindulys.image.TileFile;

/**
 * The overlap check of {@code render assemble} on synthetic placements (no files): it takes
 * O(n log n) for n tiles, so a frame of 100,000 column tiles is checked at once, and it still
 * finds an overlap among many, whichever the tiles' shapes and order.
 */
class AssembleOverlapTest {
    private static final int W = 100_000, H = 8;

    private static List<Path> names(int n) {
        List<Path> files = new ArrayList<>(n);
        for (int k = 0; k < n; k++) files.add(Path.of("t" + k + ".png"));
        return files;
    }

    private static TileFile.Placement at(int x0, int x1, int y0, int y1) {
        return new TileFile.Placement(new PixelRegion(x0, x1, y0, y1), W, H, null);
    }

    /** 100,000 one-pixel-wide columns: every tile spans every row, which made the old check quadratic. */
    private static List<TileFile.Placement> columns() {
        List<TileFile.Placement> p = new ArrayList<>(W);
        for (int x = 0; x < W; x++) p.add(at(x, x + 1, 0, H));
        return p;
    }

    @Test
    void oneHundredThousandColumnsAreCheckedAndCoverTheFrame() {
        List<TileFile.Placement> p = columns();
        // Given in a shuffled order, as a pattern's matches in name order are.
        java.util.Collections.shuffle(p, new Random(1));
        AssembleCommand.checkCover(names(W), p, W, H);
        List<TileFile.Placement> rows = new ArrayList<>();
        for (int y = 0; y < H; y++) rows.add(at(0, W, y, y + 1));
        AssembleCommand.checkCover(names(H), rows, W, H);
    }

    @Test
    void anOverlapAmongOneHundredThousandColumnsIsFound() {
        List<TileFile.Placement> p = columns();
        // Column 70000 also reaches one pixel into its right neighbour, on the last row only.
        p.set(70_000, at(70_000, 70_002, H - 1, H));
        p.add(at(70_000, 70_001, 0, H - 1));
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> AssembleCommand.checkCover(names(p.size()), p, W, H));
        // The tile met first going down the rows is named first, as before.
        assertEquals("t70001.png and t70000.png overlap (regions 70001,70002,0,8 and 70000,70002,7,8): each pixel must come from one tile", e.getMessage());
    }

    /** Random grids with one tile moved: the sweep agrees with comparing every pair. */
    @Test
    void theSweepFindsAnOverlapExactlyWhenTwoTilesShareAPixel() {
        Random random = new Random(7);
        for (int round = 0; round < 300; round++) {
            int n = 2 + random.nextInt(30);
            List<TileFile.Placement> p = new ArrayList<>();
            for (int k = 0; k < n; k++) {
                int x0 = random.nextInt(40), y0 = random.nextInt(H);
                p.add(at(x0, x0 + 1 + random.nextInt(6), y0, y0 + 1 + random.nextInt(H - y0)));
            }
            boolean any = false;
            for (int a = 0; a < n && !any; a++) {
                for (int b = a + 1; b < n; b++) any |= p.get(a).region().overlaps(p.get(b).region());
            }
            List<Path> files = names(n);
            if (any) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> AssembleCommand.checkOverlaps(files, p), p::toString);
                // The two tiles named do share a pixel.
                String[] two = e.getMessage().substring(0, e.getMessage().indexOf(" overlap")).split(" and ");
                PixelRegion r0 = p.get(Integer.parseInt(two[0].substring(1, two[0].length() - 4))).region();
                PixelRegion r1 = p.get(Integer.parseInt(two[1].substring(1, two[1].length() - 4))).region();
                assertTrue(r0.overlaps(r1), e.getMessage());
                assertNotEquals(two[0], two[1]);
            } else {
                AssembleCommand.checkOverlaps(files, p);
            }
        }
    }
}
