package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.io.SceneParser;
import lt.spindulys.camera.PixelFilter;
import lt.spindulys.scene.SceneBuilder;

/**
 * Rendered images under each pixel filter: a flat colour stays exactly flat (Mitchell's negative
 * weights included), a sharp edge is blurred into the filter's own step response, and the image
 * does not depend on the thread count.
 */
class PixelFilterRenderTest {
    private static SceneBuilder scene(String text) {
        return SceneParser.parse(text, "filter.dat", Path.of("."));
    }

    private static FrameBuffer render(SceneBuilder b, int threads) throws Exception {
        return RenderJob.of(b).threads(threads).run().frame();
    }

    /** Nothing but the background: every sample sees the same colour, so every pixel must be it. */
    @Test
    void aFlatColourStaysFlatUnderEveryFilterAndSampleCount() throws Exception {
        for (PixelFilter f : PixelFilter.values()) {
            for (int spp : new int[] {1, 2, 3, 4, 5, 9, 16}) {
                FrameBuffer fb = render(scene("""
                        settings { width 23 height 17 samples %d background 0.25 0.5 0.75 filter %s }
                        camera { eye 0 0 -5 lookat 0 0 0 }
                        """.formatted(spp, f.keyword())), 2);
                for (int y = 0; y < fb.height(); y++) {
                    for (int x = 0; x < fb.width(); x++) {
                        assertEquals(0.25, fb.get(x, y, 0), 1e-12, f + " at " + spp + " spp, pixel " + x + "," + y);
                        assertEquals(0.75, fb.get(x, y, 2), 1e-12, f + " at " + spp + " spp, pixel " + x + "," + y);
                    }
                }
            }
        }
    }

    private static final String EDGE = """
            settings { width 40 height 4 samples 1024 ambient 1 1 1 filter %s filterwidth %s }
            camera { eye 0 0 -10 lookat 0 0 0 fov 30 }
            box { min -100 -100 0  max 0 100 1  material { color 1 1 1 ka 1 kd 0 ks 0 } }
            """;

    /** The profile across a vertical edge at film x = 20 (black left, white right), averaged over the rows and divided by the white. */
    private static double[] edgeProfile(PixelFilter f, double width) throws Exception {
        FrameBuffer fb = render(scene(EDGE.formatted(f.keyword(), width)), 3);
        double white = fb.get(39, 0, 0);
        assertTrue(white > 0);
        double[] p = new double[fb.width()];
        for (int x = 0; x < fb.width(); x++) {
            for (int y = 0; y < fb.height(); y++) p[x] += fb.get(x, y, 0);
            p[x] /= fb.height() * white;
        }
        return p;
    }

    /** The filter's step response at pixel centre x: the share of its weight beyond the edge at 20. */
    private static double stepResponse(PixelFilter f, double width, double x) {
        double r = f.radius(width), all = 0, beyond = 0;
        int steps = 100_000;
        for (int i = 0; i < steps; i++) {
            double t = -r + (i + 0.5) * 2 * r / steps, v = f.evaluate(t, width);
            all += v;
            if (x + t > 20) beyond += v;
        }
        return beyond / all;
    }

    @ParameterizedTest
    @EnumSource(PixelFilter.class)
    void aSharpEdgeTakesTheFiltersStepResponse(PixelFilter f) throws Exception {
        double width = f.defaultWidth();
        double[] p = edgeProfile(f, width);
        for (int x = 0; x < p.length; x++) {
            assertEquals(stepResponse(f, width, x + 0.5), p[x], 0.01, f + " at pixel " + x);
        }
        if (f != PixelFilter.MITCHELL) {
            for (int x = 1; x < p.length; x++) assertTrue(p[x] >= p[x - 1] - 1e-3, f + ": the profile rises monotonically, at " + x);
        } else {
            // The negative lobes ring: a dip below black before the edge and a rise above white after it.
            assertTrue(p[18] < -0.005 && p[21] > 1.005, "Mitchell rings: " + p[18] + " " + p[21]);
        }
    }

    /** The width over which the edge rises from 10% to 90%, interpolated between pixel centres. */
    private static double riseWidth(double[] p) {
        return crossing(p, 0.9) - crossing(p, 0.1);
    }

    private static double crossing(double[] p, double level) {
        for (int x = 1; x < p.length; x++) {
            if (p[x - 1] < level && p[x] >= level) return x - 1 + (level - p[x - 1]) / (p[x] - p[x - 1]);
        }
        throw new AssertionError("no crossing of " + level);
    }

    /** A 10-90% rise width per filter: the box sharpest, the Gaussian next, Blackman-Harris (over 3 px) smoother; wider, smoother still. */
    @Test
    void theBoxIsSharpestAndTheSmoothFiltersBlurMore() throws Exception {
        double box = riseWidth(edgeProfile(PixelFilter.BOX, 1));
        double gauss = riseWidth(edgeProfile(PixelFilter.GAUSSIAN, 1.5));
        double bh = riseWidth(edgeProfile(PixelFilter.BLACKMAN_HARRIS, 1.5));
        double mitchell = riseWidth(edgeProfile(PixelFilter.MITCHELL, 4));
        double wideGauss = riseWidth(edgeProfile(PixelFilter.GAUSSIAN, 3));
        // Measured: box 0.80 px (a linear ramp over one pixel, sampled at pixel centres), Gaussian 0.98,
        // Blackman-Harris 1.31, Mitchell-Netravali 1.34 (its rise is steep, but starts from its dip).
        assertTrue(box < gauss && gauss < bh && box < mitchell && gauss < wideGauss,
                "rise widths: box " + box + ", mitchell " + mitchell + ", gaussian " + gauss + ", blackman-harris " + bh + ", wide gaussian " + wideGauss);
    }

    @ParameterizedTest
    @EnumSource(PixelFilter.class)
    void theImageDoesNotDependOnTheThreadCount(PixelFilter f) throws Exception {
        SceneBuilder b = scene("""
                settings { width 37 height 21 samples 6 filter %s }
                camera { eye 0 1 -5 lookat 0 0.5 0 }
                light { position 2 4 -3 }
                sphere { center 0 0.5 0 radius 1 material { color 1 0.3 0.2 } }
                plane { normal 0 1 0 offset -0.5 }
                """.formatted(f.keyword()));
        FrameBuffer one = render(b, 1), many = render(b, 5);
        assertArrayEquals(one.data(), many.data(), 0.0);
    }
}
