package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

class EdgeRatesTest {
    static final int W = 300, H = 200;
    static final PinholeCamera PINHOLE = EdgeLevelsTest.PINHOLE;

    @Test
    void rateForEdgeCases() {
        assertEquals(1, EdgeRates.rateFor(0, 1, 100));
        assertEquals(1, EdgeRates.rateFor(-5, 1, 100));
        assertEquals(1, EdgeRates.rateFor(Double.NEGATIVE_INFINITY, 1, 100));
        assertEquals(1, EdgeRates.rateFor(1, 1, 100), "exactly one target: one segment");
        assertEquals(2, EdgeRates.rateFor(Math.nextUp(1.0), 1, 100));
        assertEquals(68, EdgeRates.rateFor(68, 1, 100), "any integer, not a power of two");
        assertEquals(69, EdgeRates.rateFor(68.01, 1, 100));
        assertEquals(19, EdgeRates.rateFor(18.5, 1, 100));
        assertEquals(8, EdgeRates.rateFor(12, 1.5, 100));
        assertEquals(100, EdgeRates.rateFor(Double.NaN, 1, 100), "unknown: the finest allowed");
        assertEquals(100, EdgeRates.rateFor(Double.POSITIVE_INFINITY, 1, 100));
        assertEquals(100, EdgeRates.rateFor(1e300, 1, 100), "clamped");
        assertEquals(EdgeRates.MAX_RATE, EdgeRates.rateFor(Double.MAX_VALUE, Double.MIN_VALUE, EdgeRates.MAX_RATE), "the ratio overflows");
        assertEquals(1, EdgeRates.rateFor(1e6, 1, 1));
        for (double bad : new double[] {0, -1, Double.NaN, Double.POSITIVE_INFINITY}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> EdgeRates.rateFor(3, bad, 10));
            assertTrue(e.getMessage().startsWith("target edge length must be a positive number of pixels, found "), e.getMessage());
        }
        assertEquals("maximum rate must be 1 to 4096, found 0", assertThrows(IllegalArgumentException.class, () -> EdgeRates.rateFor(3, 1, 0)).getMessage());
        assertThrows(IllegalArgumentException.class, () -> EdgeRates.rateFor(3, 1, 4097));
    }

    @Test
    void aRateIsNeverFinerThanItsLevelAndHasTheSameLevel() {
        SplittableRandom rnd = new SplittableRandom(3);
        for (int n = 0; n < 10000; n++) {
            double pixels = Math.exp(rnd.nextDouble(-2, 9)), target = Math.exp(rnd.nextDouble(-1, 2));
            int rate = EdgeRates.rateFor(pixels, target, EdgeRates.MAX_RATE), level = EdgeLevels.levelFor(pixels, target, 12);
            assertTrue(rate <= EdgeRates.ofLevel(level), pixels + " px at " + target + ": rate " + rate + ", level " + level);
            // The level of the face whose finest edge has this rate is the level of the length.
            assertEquals(level, 32 - Integer.numberOfLeadingZeros(rate - 1), pixels + " px at " + target);
            if (pixels / target < EdgeRates.MAX_RATE) assertTrue(rate >= pixels / target, "a segment is at most the target");
        }
    }

    @Test
    void ratesComeFromTheFootprintAndCoarsenOffscreen() {
        ViewFootprint v = ViewFootprint.of(PINHOLE, W, H);
        // About 2.1 units long, 10 away: 36 px in front, a quarter of that behind and beside.
        double[] pos = {0, 2, -7, 2.1, 2, -7, 0, 2, 13, 2.1, 2, 13, 11, 1, 3, 11, 3.1, 3};
        int[] ev = {0, 1, 2, 3, 4, 5};
        int[] rates = EdgeRates.perEdge(v, pos, ev, Placement.IDENTITY, 1, 4096, 4);
        double front = v.pixels(0, 2, -7, 2.1, 2, -7, 4);
        assertEquals(EdgeRates.rateFor(front, 1, 4096), rates[0]);
        assertTrue(rates[0] >= 36 && rates[0] <= 38, "in front: " + rates[0]);
        assertEquals(EdgeRates.rateFor(v.pixels(0, 2, 13, 2.1, 2, 13, 4), 1, 4096), rates[1]);
        assertTrue(Math.abs(rates[1] - front / 4) <= 1.5, "behind the camera: " + rates[1] + " for " + front / 4);
        assertTrue(Math.abs(rates[2] - front / 4) <= 1.5, "outside the frustum: " + rates[2] + " for " + front / 4);
        // Clamped, and no coarser than one segment however far.
        int[] capped = EdgeRates.perEdge(v, pos, ev, Placement.IDENTITY, 1, 20, 4);
        for (int e = 0; e < 3; e++) assertEquals(Math.min(20, rates[e]), capped[e]);
        int[] far = EdgeRates.perEdge(v, pos, ev, Placement.of(Transform.translate(0, 0, -1e6)), 1, 4096, 4);
        assertArrayEquals(new int[] {1, 1, 1}, far);
        // Never finer than the power-of-two level from the same footprint.
        int[] levels = EdgeLevels.perEdge(v, pos, ev, Placement.IDENTITY, 1, 12, 4);
        for (int e = 0; e < 3; e++) assertTrue(rates[e] <= 1 << levels[e] && rates[e] > (1 << levels[e]) / 2, "edge " + e);
    }

    @Test
    void oneRatePerControlEdgeWhateverTheOrderOfItsEnds() {
        // Both faces read the one entry of the control edge; the order of its ends (which the
        // faces would see differently) moves the footprint by rounding at most.
        ViewFootprint v = ViewFootprint.of(PINHOLE, W, H);
        SplittableRandom rnd = new SplittableRandom(11);
        int same = 0;
        for (int n = 0; n < 200; n++) {
            double[] pos = new double[6];
            for (int k = 0; k < 6; k++) pos[k] = rnd.nextDouble(-15, 15);
            int[] ab = EdgeRates.perEdge(v, pos, new int[] {0, 1}, Placement.IDENTITY, 0.5, 4096, 4);
            int[] ba = EdgeRates.perEdge(v, pos, new int[] {1, 0}, Placement.IDENTITY, 0.5, 4096, 4);
            assertTrue(Math.abs(ab[0] - ba[0]) <= 1, "one edge, its ends in either order");
            if (ab[0] == ba[0]) same++;
        }
        assertTrue(same >= 190, same + " of 200 equal");
    }

    @Test
    void aMovingEdgeTakesItsClosestTimeAndInstancesTheLargest() {
        ViewFootprint v = ViewFootprint.of(PINHOLE, W, H);
        double[] pos = {0.9, 2, -17, 1.1, 2, -17};
        int[] edge = {0, 1};
        Placement toward = Placement.IDENTITY.then(Motion.translation(new Vec3(0, 0, 18), Double.NaN, Double.NaN));
        int near = EdgeRates.perEdge(v, pos, edge, Placement.of(Transform.translate(0, 0, 18)), 0.25, 4096, 4)[0];
        int far = EdgeRates.perEdge(v, pos, edge, Placement.IDENTITY, 0.25, 4096, 4)[0];
        int moving = EdgeRates.perEdge(v, pos, edge, toward, 0.25, 4096, 4)[0];
        assertTrue(near >= 10 * far, far + " -> " + near);
        assertTrue(moving >= near && moving <= 2 * near, "moving " + moving + ", at its closest " + near);
        int[] both = EdgeRates.perEdge(v, pos, edge, Placement.IDENTITY, 0.25, 4096, 4);
        EdgeRates.perEdgeMax(v, pos, edge, Placement.of(Transform.translate(0, 0, 18)), 0.25, 4096, 4, both);
        assertEquals(near, both[0]);
    }

    @Test
    void edgesOfPolygonsAreRoundedUpToEven() {
        // A quad (edges 0 1 2 3) beside a pentagon (edges 2 4 5 6 7) and a triangle (edges 7 8 9).
        int[] sizes = {4, 5, 3};
        int[] faceEdges = {0, 1, 2, 3, 2, 4, 5, 6, 7, 7, 8, 9};
        int[] rates = {3, 5, 7, 9, 1, 2, 11, 4096, 13, 1};
        EdgeRates.evenAroundPolygons(sizes, faceEdges, rates);
        assertArrayEquals(new int[] {3, 5, 8, 9, 2, 2, 12, 4096, 14, 2}, rates, "the quad's own edges stay; the shared one is even for both");
        assertThrows(IllegalArgumentException.class, () -> EdgeRates.evenAroundPolygons(sizes, new int[] {0}, rates));
        assertThrows(IllegalArgumentException.class, () -> EdgeRates.evenAroundPolygons(new int[] {3}, new int[] {0, 1, 2}, new int[] {1, 0, 1}));
    }
}
