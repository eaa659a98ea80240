package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.PriorityQueue;
import java.util.function.IntBinaryOperator;

import org.junit.jupiter.api.Test;

import lt.spindulys.render.TileOrder;

/**
 * The remaining-time estimate, headless: renders simulated with synthetic tile costs (no clock),
 * handed out as the Renderer hands them out ({@link TileOrder}), on one or more simulated threads.
 */
class TerminalProgressTest {
    /** 800x450 in 16-pixel tiles. */
    private static final int TILES_X = 50, TILES_Y = 29;

    /**
     * A frame like the one in the report: cheap sky over the top 40 %, an object seven times the
     * cost below it, and a band of glass (more costly again) over part of the width.
     */
    private static double cost(int col, int row) {
        if (row < 12) return 1;
        return col >= 10 && col < 20 ? 20 : 7;
    }

    /**
     * Simulates a render: {@code threads} workers take tiles from one counter in the order
     * {@code order} gives (k-th tile handed out -> {col, row} packed as row * TILES_X + col), and
     * each report (at a tile's completion, in time order) is checked against the true remaining
     * time. Returns the worst ratio, estimated / true, as {min, max} over reports between 5 % and
     * 95 % of the render's time.
     */
    private static double[] worstRatios(int threads, IntBinaryOperator order) {
        int tiles = TILES_X * TILES_Y;
        // Events: completion time and pixels of each tile, workers taking the next tile when free.
        PriorityQueue<double[]> free = new PriorityQueue<>((a, b) -> Double.compare(a[0], b[0]));
        for (int w = 0; w < threads; w++) free.add(new double[] {0});
        double[] finish = new double[tiles];
        for (int k = 0; k < tiles; k++) {
            int packed = order.applyAsInt(k, tiles);
            double[] worker = free.poll();
            worker[0] += cost(packed % TILES_X, packed / TILES_X);
            finish[k] = worker[0];
            free.add(worker);
        }
        double[] sorted = finish.clone();
        java.util.Arrays.sort(sorted);
        double end = sorted[tiles - 1];
        long pixels = 256L * tiles;
        double min = Double.POSITIVE_INFINITY, max = 0;
        for (int i = 0; i < tiles; i++) {
            double now = sorted[i];
            if (now < 0.05 * end || now > 0.95 * end) continue;
            double estimate = TerminalProgress.remainingSeconds(256L * (i + 1), pixels, now);
            assertFalse(Double.isNaN(estimate), "an estimate after 5 % of the time");
            double ratio = estimate / (end - now);
            min = Math.min(min, ratio);
            max = Math.max(max, ratio);
        }
        return new double[] {min, max};
    }

    /** The Renderer's order. */
    private static int rendererOrder(int k, int tiles) {
        return TileOrder.tileAt(k, tiles, TileOrder.spreadStride(tiles));
    }

    @Test
    void theEstimateFollowsTheWorkInTheRenderersTileOrder() {
        for (int threads : new int[] {1, 2, 8}) {
            double[] r = worstRatios(threads, TerminalProgressTest::rendererOrder);
            assertTrue(r[0] > 0.75 && r[1] < 1.25, threads + " threads: estimate / true remaining time between " + r[0] + " and " + r[1]);
        }
    }

    /** Why the order matters: top to bottom, the sky makes the first estimates far too short. */
    @Test
    void topToBottomTheEstimateWouldBeFarOff() {
        double[] r = worstRatios(2, (k, tiles) -> k);
        assertTrue(r[0] < 0.3, "top to bottom, the estimate falls to " + r[0] + " of the true remaining time");
    }

    @Test
    void everyTileComesExactlyOnce() {
        for (int tiles = 1; tiles <= 2000; tiles++) assertPermutation(tiles);
        // The largest frame: 32768 x 32768 pixels in 16-pixel tiles.
        assertPermutation((32768 / TileOrder.TILE) * (32768 / TileOrder.TILE));
    }

    private static void assertPermutation(int tiles) {
        int stride = TileOrder.spreadStride(tiles);
        java.util.BitSet seen = new java.util.BitSet(tiles);
        for (int k = 0; k < tiles; k++) {
            int t = TileOrder.tileAt(k, tiles, stride);
            assertTrue(t >= 0 && t < tiles && !seen.get(t), tiles + " tiles: tile " + t + " at " + k);
            seen.set(t);
        }
    }

    @Test
    void noEstimateFromTheFirstTilesNorAtTheEnd() {
        assertTrue(Double.isNaN(TerminalProgress.remainingSeconds(0, 1000, 1)));
        assertTrue(Double.isNaN(TerminalProgress.remainingSeconds(9, 1000, 1)));
        assertEquals(99, TerminalProgress.remainingSeconds(10, 1000, 1), 1e-9);
        assertEquals(1, TerminalProgress.remainingSeconds(500, 1000, 1), 1e-9);
        assertTrue(Double.isNaN(TerminalProgress.remainingSeconds(1000, 1000, 5)));
        assertTrue(Double.isNaN(TerminalProgress.remainingSeconds(0, 0, 0)));
    }

    @Test
    void theBarShowsTheEstimateAndIsErased() {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(bytes, true, StandardCharsets.UTF_8);
        TerminalProgress bar = new TerminalProgress(out);
        bar.progress(5, 1000); // too early for an estimate
        String first = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(first.startsWith("\r[") && first.contains("elapsed") && !first.contains("remaining"), first);
        bar.progress(1000, 1000);
        bar.finish();
        String all = bytes.toString(StandardCharsets.UTF_8);
        assertTrue(all.endsWith("\r"), "erased: " + all);
    }
}
