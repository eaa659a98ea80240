package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Vec3;
import lt.spindulys.material.Material;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * Motion blur measured on the image. A white sphere lit only by ambient light (ka 1, kd 0) on
 * black, so a pixel's value is the fraction of its samples, over area and time, that see the
 * sphere; the camera looks straight at it along +z and it moves along x.
 */
class MotionBlurRenderTest {
    static final int W = 160, H = 3, SPP = 1024;
    // A strip: the vertical field of view is small so that the wide image sees about 8 units across at the sphere.
    static final double EYE = 10, FOV = 0.86, R = 0.5;

    private static RenderSettings settings(int spp, int steps) {
        return RenderSettings.builder().size(W, H).samplesPerPixel(spp).ambient(Color.WHITE).seed(3).timeSteps(steps).build();
    }

    /** The middle row of a render of a sphere at x = c0 moving by dx between start and finish. */
    private static double[] row(double c0, double dx, double start, double finish, int spp, int steps) throws InterruptedException {
        SceneBuilder b = new SceneBuilder().settings(settings(spp, steps))
                .camera(new PinholeCamera(new Vec3(0, 0, -EYE), Vec3.ZERO, Vec3.Y, FOV));
        b.add(new Sphere(new Vec3(c0, 0, 0), R).material(Material.builder().color(Color.WHITE).ka(1).kd(0).build())
                .motion(Motion.translation(new Vec3(dx, 0, 0), start, finish)));
        FrameBuffer fb = Renderer.render(b.build(), 2, ProgressListener.NONE).frame();
        double[] out = new double[W];
        for (int x = 0; x < W; x++) out[x] = fb.get(x, H / 2, 0);
        return out;
    }

    /** Film column (in pixels, continuous) where world x at depth z projects, looking along +z from (0, 0, -EYE). */
    private static double column(double tanAngle) {
        double tanHalf = Math.tan(Math.toRadians(FOV) / 2), aspect = (double) W / H;
        // The camera's right is -x (right-handed, forward x up), so larger x is further left.
        return (1 - tanAngle / (tanHalf * aspect)) / 2 * W;
    }

    /** The columns of a sphere's silhouette through its centre row, at centre x = c: the tangents from the eye. */
    private static double[] silhouette(double c) {
        double alpha = Math.atan2(c, EYE), beta = Math.asin(R / Math.hypot(c, EYE));
        return new double[] {column(Math.tan(alpha + beta)), column(Math.tan(alpha - beta))};
    }

    @Test
    void streakSpansTheMotionPlusTheSphereWithinAPixel() throws InterruptedException {
        double c0 = -1, dx = 2;
        double[] row = row(c0, dx, 0, 1, SPP, 1);
        int first = -1, last = -1;
        for (int x = 0; x < W; x++) {
            if (row[x] > 0) {
                if (first < 0) first = x;
                last = x;
            }
        }
        // Left edge: the sphere at its end (largest x); right edge: at its start.
        double expectedLeft = silhouette(c0 + dx)[0], expectedRight = silhouette(c0)[1];
        double measuredLeft = first, measuredRight = last + 1; // the streak's edges lie inside the first and last lit pixels
        System.out.printf("streak: expected columns %.2f .. %.2f (%.2f px), measured %.0f .. %.0f (%.0f px)%n",
                expectedLeft, expectedRight, expectedRight - expectedLeft, measuredLeft, measuredRight, measuredRight - measuredLeft);
        assertEquals(expectedLeft, measuredLeft, 1.0);
        assertEquals(expectedRight, measuredRight, 1.0);
        // And it is a streak, not a sphere: the motion is several diameters long.
        assertTrue(measuredRight - measuredLeft > 2.5 * (silhouette(c0)[1] - silhouette(c0)[0]));
    }

    /**
     * A sphere that moves during half of the shutter and then stands still: where it only passes
     * (between its start and end silhouettes), a point is covered for half as long as when the
     * same motion takes the whole shutter, so the streak is half as bright there. Tolerance 5%:
     * per pixel the value is a mean of 1024 stratified 0/1 samples (binomial sd about 0.012 at
     * 0.17, less with stratification), averaged over about 30 pixels, so the ratio's noise is
     * about 1%; 5% is over four times that, and a wrong clamp (0.5 or 1) is far outside.
     */
    @Test
    void objectMovingForHalfTheShutterLeavesAStreakHalfAsBright() throws InterruptedException {
        double c0 = -1.5, dx = 3;
        double[] full = row(c0, dx, 0, 1, SPP, 1), half = row(c0, dx, 0, 0.5, SPP, 1);
        // Columns covered only while moving: right of the end silhouette, left of the start one.
        int from = (int) Math.ceil(silhouette(c0 + dx)[1]) + 2, to = (int) Math.floor(silhouette(c0)[0]) - 2;
        assertTrue(to - from > 20, "the passing part is wide enough to measure: " + from + ".." + to);
        double sf = 0, sh = 0;
        for (int x = from; x < to; x++) { sf += full[x]; sh += half[x]; }
        double ratio = sh / sf;
        System.out.printf("partial shutter: mean %.4f (half) / %.4f (full) = %.4f over columns %d..%d%n", sh / (to - from), sf / (to - from), ratio, from, to);
        assertEquals(0.5, ratio, 0.025);
        // It then stands still at its end for the other half: fully covered pixels there are at least half bright.
        int endCentre = (int) Math.round((silhouette(c0 + dx)[0] + silhouette(c0 + dx)[1]) / 2);
        assertTrue(half[endCentre] > 0.5 && full[endCentre] < 0.5, half[endCentre] + " " + full[endCentre]);
    }

    /**
     * The thesis's method with two time steps renders the sphere at times 0.25 and 0.75 only: two
     * copies with black between them, where the single pass shows a continuous streak. Identical
     * for any thread count.
     */
    @Test
    void timeStepsShowSeparateCopiesTheSinglePassAContinuousStreak() throws InterruptedException {
        double c0 = -1.5, dx = 3;
        double[] single = row(c0, dx, 0, 1, 64, 1), steps = row(c0, dx, 0, 1, 64, 2);
        int mid = (int) Math.round(column(0)); // the sphere's centre passes x = 0 at t = 0.5
        assertEquals(0, steps[mid], 0.0, "no time step sees the sphere at the middle of its path");
        assertTrue(single[mid] > 0.1, "the single pass does: " + single[mid]);
        // The copies are where the sphere is at 0.25 and 0.75.
        assertEquals(1, steps[(int) Math.round(column((c0 + 0.25 * dx) / EYE))] * 2, 0.05);
        assertEquals(1, steps[(int) Math.round(column((c0 + 0.75 * dx) / EYE))] * 2, 0.05);

        SceneBuilder b = new SceneBuilder().settings(settings(8, 4).toBuilder().size(37, 23).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -EYE), Vec3.ZERO, Vec3.Y, FOV));
        b.add(new Sphere(Vec3.ZERO, R).motion(Motion.translation(Vec3.X, 0.2, 0.8)));
        double[] one = Renderer.render(b.build(), 1, ProgressListener.NONE).frame().data();
        b = new SceneBuilder().settings(settings(8, 4).toBuilder().size(37, 23).build()).camera(new PinholeCamera(new Vec3(0, 0, -EYE), Vec3.ZERO, Vec3.Y, FOV));
        b.add(new Sphere(Vec3.ZERO, R).motion(Motion.translation(Vec3.X, 0.2, 0.8)));
        double[] three = Renderer.render(b.build(), 3, ProgressListener.NONE).frame().data();
        assertArrayEquals(one, three, 0.0);
    }

    /**
     * A lit scene with a mirror floor and a sphere: moving in the thesis's linear motion (2 units
     * per unit of time along x, between the given times), or standing where that motion has it at
     * time 0.7.
     */
    private static SceneBuilder litScene(RenderSettings st, boolean moving, double start, double finish) {
        SceneBuilder b = new SceneBuilder().settings(st)
                .camera(new PinholeCamera(new Vec3(0, 2, -6), new Vec3(0, 0.5, 0), Vec3.Y, 40))
                .light(new lt.spindulys.scene.PointLight(new Vec3(3, 6, -4), Color.WHITE));
        b.add(new lt.spindulys.scene.Plane(Vec3.Y, 0).material(Material.builder().kr(0.4).build()));
        Sphere s = new Sphere(new Vec3(-1, 0.5, 0), 0.5);
        if (moving) s.motion(Motion.linear(Vec3.X, 2, start, finish));
        else s.transform(lt.spindulys.math.Transform.translate(1.4, 0, 0));
        b.add(s);
        return b;
    }

    /**
     * With the shutter open only at the instant 0.7, the moving sphere, its shadow and its
     * reflection are exactly those of a sphere standing where it is then: every ray the
     * integrator makes (camera, shadow, reflection) carries the time.
     */
    @Test
    void shadowsAndReflectionsAreTracedAtTheSameTime() throws InterruptedException {
        RenderSettings st = RenderSettings.builder().size(41, 27).samplesPerPixel(2).shutter(0.7, 0.7).build();
        double[] still = Renderer.render(litScene(st, false, 0, 1).build(), 2, ProgressListener.NONE).frame().data();
        double[] instant = Renderer.render(litScene(st, true, 0, 1).build(), 2, ProgressListener.NONE).frame().data();
        assertArrayEquals(still, instant, 1e-9);
    }

    @Test
    void singlePassIsIdenticalForAnyThreadCount() throws InterruptedException {
        RenderSettings st = RenderSettings.builder().size(41, 27).samplesPerPixel(5).shutter(0.2, 0.9).build();
        double[] one = Renderer.render(litScene(st, true, Double.NaN, Double.NaN).build(), 1, ProgressListener.NONE).frame().data();
        double[] four = Renderer.render(litScene(st, true, Double.NaN, Double.NaN).build(), 4, ProgressListener.NONE).frame().data();
        assertArrayEquals(one, four, 0.0);
    }
}
