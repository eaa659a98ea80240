package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.scene.SceneBuilder;

/**
 * A path-traced image depends on the seed and nothing else: every random number of a path comes
 * from the global seed, the pixel and the sample, so the thread count, the tile order and the
 * region rendered change no bit; and another seed gives another image. Checked on the kitchen-sink
 * scene of {@link PathRobustnessTest} (every light kind, the environment as a light, CSG, a
 * texture, glass, a mirror, motion blur, depth of field), with a clamp so that its path is
 * covered too.
 */
class PathDeterminismTest {
    private static SceneBuilder scene(long seed) {
        return PathRobustnessTest.kitchenSink("seed 7 }", "seed " + seed + "  clamp 2 }");
    }

    @Test
    void oneTwoAndThreeThreadsGiveTheSameBits() throws Exception {
        SceneBuilder b = scene(7);
        double[] one = RenderJob.of(b).threads(1).run().frame().data();
        double[] two = RenderJob.of(b).threads(2).run().frame().data();
        double[] three = RenderJob.of(b).threads(3).run().frame().data();
        assertArrayEquals(one, two, "2 threads");
        assertArrayEquals(one, three, "3 threads");
    }

    @Test
    void regionsAndTilesHoldTheWholeFramesValues() throws Exception {
        SceneBuilder b = scene(7);
        FrameBuffer whole = RenderJob.of(b).threads(2).run().frame();
        for (PixelRegion r : List.of(new PixelRegion(3, 20, 5, 6), new PixelRegion(28, 29, 18, 19), new PixelRegion(0, 17, 2, 19))) {
            RegionRenderTest.assertRegionOfWhole(whole, r, RenderJob.of(b).region(r).threads(3).run().frame());
        }
        for (int i = 1; i <= 3; i++) {
            RegionRenderTest.assertRegionOfWhole(whole, PixelRegion.band(i, 3, 29, 19), RenderJob.of(b).tile(i, 3).threads(1).run().frame());
        }
    }

    /** Another seed changes the noise, hence most pixels that see anything noisy; the same seed again changes none. */
    @Test
    void theSeedAloneChangesTheImage() throws Exception {
        double[] a = RenderJob.of(scene(7)).threads(2).run().frame().data();
        double[] again = RenderJob.of(scene(7)).threads(2).run().frame().data();
        double[] b = RenderJob.of(scene(8)).threads(2).run().frame().data();
        assertArrayEquals(a, again, "the same seed");
        int differing = 0;
        for (int i = 0; i < a.length; i++) if (a[i] != b[i]) differing++;
        assertTrue(differing > a.length / 2, "values changed by the seed: " + differing + " of " + a.length);
    }
}
