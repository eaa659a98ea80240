package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.Function;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.TextureImage;

/**
 * An environment hidden from camera rays or shown dimmer to them: camera rays that miss see the
 * background colour or the visible intensity, while reflections and the light still see the map,
 * in both integrators.
 */
class EnvironmentCameraViewTest {
    private static final Color BACKGROUND = new Color(0.25, 0, 0);
    private static final double[] SKY = {0.5, 1, 2};

    private static TextureImage uniform() {
        int w = 8, h = 4;
        double[] rgb = new double[3 * w * h];
        for (int i = 0; i < w * h; i++) System.arraycopy(SKY, 0, rgb, 3 * i, 3);
        return TextureImage.fromLinear(w, h, rgb);
    }

    /** A plane of {@code floor} at y = 0 under a uniform sky that is a light. */
    private static Scene scene(Environment env, Material floor) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(8, 8).seed(5).ambient(Color.BLACK).background(BACKGROUND).build())
                .environment(env);
        b.add(new Plane(Vec3.Y, 0).material(floor));
        return b.build();
    }

    private static Environment sky() { return new Environment(uniform(), 0, 1, true, 4); }

    /** The mean of n samples of a camera ray from (0, 1, 0) along d. */
    private static double[] trace(Function<Scene, Integrator> kind, Scene scene, Vec3 d, int n) {
        Integrator in = kind.apply(scene);
        TracerScratch s = in instanceof WhittedIntegrator w ? w.newScratch() : new TracerScratch(0);
        Ray ray = new Ray();
        double[] out = new double[4], sum = new double[3];
        for (int i = 0; i < n; i++) {
            s.setSample(7, 2, 3, i, n);
            ray.set(0, 1, 0, d.x(), d.y(), d.z(), 0, Double.POSITIVE_INFINITY);
            in.traceCamera(ray, s, out);
            for (int c = 0; c < 3; c++) sum[c] += out[c] / n;
        }
        return sum;
    }

    private static void checks(Function<Scene, Integrator> kind) {
        Material white = Material.builder().color(Color.WHITE).kd(1).build();
        Material mirror = Material.builder().color(Color.WHITE).kd(0).ks(0).kr(1).build();
        Vec3 up = new Vec3(0, 1, 0), down = new Vec3(0, -1, 0);
        // A camera ray into the sky: the map, the background colour when hidden, the visible intensity when dimmed.
        assertArrayEquals(SKY, trace(kind, scene(sky(), white), up, 1), 1e-12);
        assertArrayEquals(new double[] {0.25, 0, 0}, trace(kind, scene(sky().withCameraView(false, 1), white), up, 1), 0);
        assertArrayEquals(new double[] {0.15, 0.3, 0.6}, trace(kind, scene(sky().withCameraView(true, 0.3), white), up, 1), 1e-12);
        // The floor is lit by the sky just the same, hidden or dimmed.
        double[] lit = trace(kind, scene(sky(), white), down, 64);
        assertTrue(lit[2] > 1, "the sky lights the floor: " + lit[2]);
        assertArrayEquals(lit, trace(kind, scene(sky().withCameraView(false, 1), white), down, 64), 0);
        assertArrayEquals(lit, trace(kind, scene(sky().withCameraView(true, 0.3), white), down, 64), 0);
        // A mirror still shows the map.
        double[] reflected = trace(kind, scene(sky(), mirror), down, 16);
        assertTrue(reflected[2] > 1, "the mirror shows the sky: " + reflected[2]);
        assertArrayEquals(reflected, trace(kind, scene(sky().withCameraView(false, 1), mirror), down, 16), 0);
        assertArrayEquals(reflected, trace(kind, scene(sky().withCameraView(true, 0.3), mirror), down, 16), 0);
    }

    @Test
    void whitted() { checks(WhittedIntegrator::new); }

    @Test
    void pathTraced() { checks(PathIntegrator::new); }

    @Test
    void theCameraViewSurvivesMakingItALight() {
        Environment e = new Environment(uniform(), 0, 1).withCameraView(false, 0.5).asLight(3);
        assertTrue(!e.isBackground() && e.visibleIntensity() == 0.5 && e.isLight());
    }
}
