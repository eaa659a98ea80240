package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.util.EnumSet;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.Camera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.PixelFilter;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.image.AovFrame;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.material.Material;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Triangle;

/**
 * Depth of field measured on the image: a white half-plane (lit by the ambient term only) on a
 * black background, its straight edge through the view axis at depth d, seen in a strip of
 * {@value #W} x {@value #H} pixels; the edge profile is the strip's column means.
 */
class DepthOfFieldRenderTest {
    static final int W = 128, H = 8;
    static final double FOV = 1.2, APERTURE = 0.5, FOCUS = 10;
    static final PinholeCamera VIEW = new PinholeCamera(Vec3.ZERO, new Vec3(0, 0, 1), Vec3.Y, FOV);

    /** The edge x = 0 at depth d: the white side x > 0 is the image's left (right is forward x up = -x). */
    private static FrameBuffer render(Camera camera, double d, int spp, int threads) throws InterruptedException {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(W, H).samplesPerPixel(spp).seed(17).ambient(Color.WHITE)
                        .filter(PixelFilter.BOX).build()) // the box: edge widths are then the lens's alone
                .camera(camera);
        b.add(new Triangle(new Vec3(0, -1000, d), new Vec3(0, 1000, d), new Vec3(1000, 0, d))
                .material(Material.builder().color(Color.WHITE).ka(1).kd(0).build()));
        return Renderer.render(b.build(), threads, ProgressListener.NONE).frame();
    }

    private static double[] profile(Camera camera, double d, int spp) throws InterruptedException {
        FrameBuffer img = render(camera, d, spp, 2);
        double[] p = new double[W];
        for (int x = 0; x < W; x++) {
            for (int y = 0; y < H; y++) p[x] += img.get(x, y, 0) / H;
        }
        return p;
    }

    /** Where the falling profile crosses {@code level}, in pixels from the image's left edge (column i's centre is i + 0.5). */
    private static double crossing(double[] p, double level) {
        for (int i = 0; i + 1 < p.length; i++) {
            if (p[i] >= level && p[i + 1] < level) return i + 0.5 + (p[i] - level) / (p[i] - p[i + 1]);
        }
        throw new AssertionError("profile never falls through " + level);
    }

    private static double width1090(double[] p) { return crossing(p, 0.1) - crossing(p, 0.9); }

    /** Film pixels per unit of the film plane at distance 1, where the image is 2 tan(fov/2) high. */
    private static double pixelsPerFilmUnit() { return H / (2 * Math.tan(Math.toRadians(FOV) / 2)); }

    @Test
    void anEdgeOnTheFocalPlaneIsAsSharpAsWithThePinhole() throws InterruptedException {
        int spp = 64;
        double[] pinhole = profile(VIEW, FOCUS, spp);
        double[] lens = profile(new ThinLensCamera(VIEW, APERTURE, FOCUS, LensPattern.CONCENTRIC), FOCUS, spp);
        // The same film samples reach the same focal-plane points, so at most a sample that lands
        // within rounding of the edge may differ.
        for (int x = 0; x < W; x++) assertEquals(pinhole[x], lens[x], 1.0 / spp / H + 1e-12, "column " + x);
        assertEquals(width1090(pinhole), width1090(lens), 0.02);
        assertTrue(width1090(lens) < 1, "sharp: " + width1090(lens) + " px");
        assertEquals(W / 2.0, crossing(lens, 0.5), 0.1, "the edge stays on the view axis");
    }

    /**
     * The measured 10-90% width of an out-of-focus edge against the thin-lens prediction. A lens
     * point at l (aperture A times a point of the unit disk, in the lens plane) aims at the focal
     * point f·s of film point s (s in units of the film plane at distance 1), so at depth d the ray
     * is at d·s + A·l·(1 − d/f): a point at depth d is seen from the film points of a disk of radius
     * A·|f − d| / (f·d), that is of diameter 2·A·|d − f| / (d·f) film units, or times
     * {@link #pixelsPerFilmUnit()} in pixels (the aperture diameter times |d − f| / d is the circle
     * of confusion on the focal plane; seen from the eye it is divided by f). An edge blurred by a
     * uniform disk of radius R has the profile E(x) = 1/2 + (asin(x/R) + (x/R)·sqrt(1 − (x/R)²))/π;
     * each pixel further averages E over its own width (the film samples are stratified across
     * it), so the prediction is the 10-90% width of E convolved with a 1-pixel box.
     */
    @Test
    void anOutOfFocusEdgeIsBlurredByTheCircleOfConfusion() throws InterruptedException {
        ThinLensCamera lens = new ThinLensCamera(VIEW, APERTURE, FOCUS, LensPattern.CONCENTRIC);
        for (double d : new double[] {5, 20}) { // in front of the focal plane and behind it
            double diameter = 2 * APERTURE * Math.abs(d - FOCUS) / (d * FOCUS) * pixelsPerFilmUnit();
            double predicted = predicted1090(diameter / 2);
            double measured = width1090(profile(lens, d, 256));
            System.out.printf("depth of field: edge at d=%.0f, focus %.0f: CoC %.2f px, 10-90%% width predicted %.2f px, measured %.2f px%n",
                    d, FOCUS, diameter, predicted, measured);
            assertTrue(diameter > 15, "the blur is wide enough to measure: " + diameter);
            assertEquals(predicted, measured, 0.1 * predicted, "10-90% blur width at d = " + d);
        }
    }

    /**
     * The thesis's ring puts half the lens samples on the rim, so the blur has the full width of
     * the circle of confusion: the columns neither fully white nor fully black span its diameter
     * (give or take the partly covered columns at both ends).
     */
    @Test
    void theRingPatternBlursAcrossTheWholeCircleOfConfusion() throws InterruptedException {
        double d = 5, diameter = 2 * APERTURE * Math.abs(d - FOCUS) / (d * FOCUS) * pixelsPerFilmUnit();
        double[] p = profile(new ThinLensCamera(VIEW, APERTURE, FOCUS, LensPattern.RING), d, 64);
        int grey = 0;
        for (double v : p) if (v > 1e-9 && v < 1 - 1e-9) grey++;
        System.out.printf("depth of field, ring lens: CoC %.2f px, blurred columns %d%n", diameter, grey);
        assertEquals(diameter, grey, 0.1 * diameter);
    }

    /** 10-90% width, in pixels, of the edge profile of a disk of radius r pixels convolved with a 1-pixel box. */
    private static double predicted1090(double r) {
        int steps = 20000;
        double lo = -r - 1, hi = r + 1, dx = (hi - lo) / steps;
        double[] xs = new double[steps + 1], e = new double[steps + 1];
        for (int i = 0; i <= steps; i++) {
            double x = lo + i * dx, sum = 0;
            int m = 200; // midpoint rule over the pixel's width
            for (int k = 0; k < m; k++) sum += disk(x - 0.5 + (k + 0.5) / m, r);
            xs[i] = x;
            e[i] = sum / m;
        }
        return at(xs, e, 0.9) - at(xs, e, 0.1);
    }

    private static double disk(double x, double r) {
        if (x <= -r) return 0;
        if (x >= r) return 1;
        double u = x / r;
        return 0.5 + (Math.asin(u) + u * Math.sqrt(1 - u * u)) / Math.PI;
    }

    private static double at(double[] xs, double[] e, double level) {
        for (int i = 0; i + 1 < xs.length; i++) {
            if (e[i] <= level && e[i + 1] > level) return xs[i] + (level - e[i]) / (e[i + 1] - e[i]) * (xs[i + 1] - xs[i]);
        }
        throw new AssertionError();
    }

    @Test
    void lensImagesAreIdenticalForAnyThreadCount() throws InterruptedException {
        for (LensPattern pattern : LensPattern.values()) {
            ThinLensCamera lens = new ThinLensCamera(VIEW, APERTURE, FOCUS, pattern);
            assertArrayEquals(render(lens, 6, 9, 1).data(), render(lens, 6, 9, 3).data(), 0.0, pattern.keyword());
        }
    }

    /** The render passes come from the lens centre: with the lens open they are the pinhole's, value for value. */
    @Test
    void renderPassesAreTracedFromTheLensCentre() throws InterruptedException {
        AovFrame pinhole = passes(VIEW), lens = passes(new ThinLensCamera(VIEW, APERTURE, FOCUS, LensPattern.CONCENTRIC));
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                assertEquals(pinhole.depth(x, y), lens.depth(x, y), 0.0);
                assertEquals(pinhole.objectId(x, y), lens.objectId(x, y));
            }
        }
    }

    private static AovFrame passes(Camera camera) throws InterruptedException {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(W, H).samplesPerPixel(4).aovs(EnumSet.of(Aov.DEPTH, Aov.OBJECT)).build())
                .camera(camera);
        b.add(new Triangle(new Vec3(0, -1000, 5), new Vec3(0, 1000, 5), new Vec3(1000, 0, 5)));
        return Renderer.render(b.build(), 2, ProgressListener.NONE).passes().orElse(null);
    }
}
