package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.Cylinder;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.texture.TextureImage;

/**
 * The environment as a light, through the integrator: a white plane under a uniform sky, under a
 * small bright patch, beside and under occluders (opaque and transparent), and the same image
 * for any thread count. The plane's brightness at a point is measured as in {@link AreaLightTest}:
 * the mean over one pixel's samples of a ray from just above the point straight down.
 */
class EnvironmentLightingTest {
    private static final Material WHITE = Material.builder().color(Color.WHITE).ka(0).kd(1).build();

    private static TextureImage uniform(double r, double g, double b) {
        int w = 8, h = 4;
        double[] rgb = new double[3 * w * h];
        for (int i = 0; i < w * h; i++) { rgb[3 * i] = r; rgb[3 * i + 1] = g; rgb[3 * i + 2] = b; }
        return TextureImage.fromLinear(w, h, rgb);
    }

    private static SceneBuilder sky(TextureImage map, int samples) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(8, 8).seed(5).ambient(Color.BLACK).build())
                .environment(new Environment(map, 0, 1, true, samples));
        b.add(new Plane(Vec3.Y, 0).material(WHITE));
        return b;
    }

    /** The mean of the n samples of pixel (px, 0), each tracing down onto (x, 0, z); all three channels. */
    private static double[] brightness(WhittedIntegrator w, TracerScratch s, double x, double z, long seed, int px, int n) {
        Ray ray = new Ray();
        double[] out = new double[4], sum = new double[3];
        for (int i = 0; i < n; i++) {
            s.setSample(seed, px, 0, i, n);
            ray.set(x, 1e-3, z, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
            w.traceCamera(ray, s, out);
            for (int c = 0; c < 3; c++) sum[c] += out[c] / n;
        }
        return sum;
    }

    /**
     * A uniform sky of radiance (0.5, 1, 2) over an open plane of kd 1: pi times the radiance,
     * as an area light filling the sky would give, within 1% (the uniform map is sampled
     * uniformly over the sphere; half the rays go below the horizon and count nothing); with kd
     * 0.5 and a coloured surface, kd * colour * pi * radiance.
     */
    @Test
    void aUniformSkyLightsAnOpenPlaneWithPiTimesItsRadiance() {
        WhittedIntegrator w = new WhittedIntegrator(sky(uniform(0.5, 1, 2), 4).build());
        TracerScratch s = w.newScratch();
        double[] e = brightness(w, s, 0.3, -0.2, 1, 0, 1024);
        double[] radiance = {0.5, 1, 2};
        for (int c = 0; c < 3; c++) assertEquals(Math.PI * radiance[c], e[c], 0.01 * Math.PI * radiance[c], "channel " + c);

        Material clay = Material.builder().color(new Color(0.8, 0.4, 0.2)).ka(0).kd(0.5).build();
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(8, 8).seed(5).ambient(Color.BLACK).build())
                .environment(new Environment(uniform(1, 1, 1), 0, 2, true, 1));
        b.add(new Plane(Vec3.Y, 0).material(clay));
        WhittedIntegrator wc = new WhittedIntegrator(b.build());
        double[] ec = brightness(wc, wc.newScratch(), 0, 0, 2, 0, 4096);
        double[] colour = {0.8, 0.4, 0.2};
        for (int c = 0; c < 3; c++) assertEquals(0.5 * colour[c] * Math.PI * 2, ec[c], 0.01 * Math.PI * colour[c], "coloured channel " + c);
    }

    /** The 4 x 3 patch of scene.EnvironmentLightTest lights the plane with its analytic irradiance, within 1%. */
    @Test
    void aSmallBrightPatchGivesItsAnalyticIrradiance() {
        int w = 64, h = 32, i0 = 20, i1 = 24, j0 = 6, j1 = 9;
        TextureImage map = lt.spindulys.scene.EnvironmentLightTest.patchMap(w, h, i0, i1, j0, j1, 80);
        double expected = lt.spindulys.scene.EnvironmentLightTest.patchIrradiance(w, h, i0, i1, j0, j1, 80);
        WhittedIntegrator wi = new WhittedIntegrator(sky(map, 16).build());
        assertEquals(expected, brightness(wi, wi.newScratch(), 0, 0, 3, 0, 64)[0], 0.01 * expected);
    }

    /**
     * A sphere of radius 1 resting on the plane under a uniform sky: the contact shadow is soft,
     * darkest at the point of contact's edge and brighter step by step outwards, and far away
     * the plane gets nearly the open sky's pi L.
     */
    @Test
    void anOccluderCastsASoftContactShadow() {
        SceneBuilder b = sky(uniform(1, 1, 1), 16);
        b.add(new Sphere(new Vec3(0, 1, 0), 1).material(WHITE));
        WhittedIntegrator w = new WhittedIntegrator(b.build());
        TracerScratch s = w.newScratch();
        double[] distances = {0.2, 0.6, 1.2, 2.5, 20};
        double[] e = new double[distances.length];
        for (int k = 0; k < distances.length; k++) e[k] = brightness(w, s, distances[k], 0, 7, k, 64)[0];
        for (int k = 0; k + 1 < e.length; k++) assertTrue(e[k] < e[k + 1], "brighter away from the sphere: " + java.util.Arrays.toString(e));
        assertTrue(e[0] < 0.25 * Math.PI, "dark near the contact: " + e[0]);
        assertEquals(Math.PI, e[e.length - 1], 0.02 * Math.PI, "open sky far away");
        // The unoccluded value under a sphere seen from distance d along the plane: the sphere
        // hides at most its solid angle's cosine-weighted share, pi (1 - cos^2 of its half-angle) below.
        double d = 2.5, sinHalf = 1 / Math.sqrt(d * d + 1);
        assertTrue(e[3] >= Math.PI * (1 - sinHalf * sinHalf) - 0.05, "at distance 2.5: " + e[3]);
    }

    /**
     * A thin transparent disc above the point: each direction that crosses it is tinted by
     * (kt * filter)^2, one factor per face, so per pixel sample the tinted result is the opaque
     * disc's plus the light the opaque disc blocks times (kt * filter)^2, channel by channel.
     */
    @Test
    void transparentOccludersTintTheSkyLight() {
        Material glass = Material.builder().color(Color.WHITE).kd(0).kt(0.5).filter(new Color(1, 0.5, 0.25)).build();
        SceneBuilder tinted = sky(uniform(1, 1, 1), 8), opaque = sky(uniform(1, 1, 1), 8), free = sky(uniform(1, 1, 1), 8);
        tinted.add(new Cylinder(new Vec3(0, 0.5 - 1e-4, 0), new Vec3(0, 0.5, 0), 1).material(glass));
        opaque.add(new Cylinder(new Vec3(0, 0.5 - 1e-4, 0), new Vec3(0, 0.5, 0), 1).material(WHITE));
        WhittedIntegrator wt = new WhittedIntegrator(tinted.build()), wo = new WhittedIntegrator(opaque.build()), wf = new WhittedIntegrator(free.build());
        double[] factor = {0.25, 0.0625, 0.015625};
        for (int i = 0; i < 8; i++) {
            double[] t = brightness(wt, wt.newScratch(), 0.1, 0, 9, i, 4), o = brightness(wo, wo.newScratch(), 0.1, 0, 9, i, 4),
                    f = brightness(wf, wf.newScratch(), 0.1, 0, 9, i, 4);
            assertTrue(o[0] < 0.5 * f[0], "the opaque disc shades the point");
            for (int c = 0; c < 3; c++) assertEquals(o[c] + (f[c] - o[c]) * factor[c], t[c], 1e-12, "channel " + c + ", pixel " + i);
        }
        // Under an absorbing half-space (a transparent plane at y = 1 whose normal faces down, so
        // upward rays enter it and never leave): light from infinitely far away is gone in the
        // channels with beta > 0 and unchanged in the one with beta 0.
        Material ink = Material.builder().color(Color.WHITE).kd(0).kt(1).ior(1).beta(new Color(0, 1, 1)).build();
        SceneBuilder under = sky(uniform(1, 1, 1), 8);
        under.add(new Plane(new Vec3(0, -1, 0), -1).material(ink));
        WhittedIntegrator wi = new WhittedIntegrator(under.build());
        double[] open = brightness(wf, wf.newScratch(), 0, 0, 4, 0, 16);
        double[] through = brightness(wi, wi.newScratch(), 0, 0, 4, 0, 16);
        assertEquals(open[0], through[0], 1e-12, "beta 0: nothing absorbed");
        assertEquals(0, through[1], "beta 1 over an infinite path");
        assertEquals(0, through[2], "beta 1 over an infinite path");
    }

    /** A scene with the environment light, an area light, glass and a shadowing box: the same image for 1 and 2 threads. */
    @Test
    void imageIsTheSameForOneAndTwoThreads() throws InterruptedException {
        Random r = new Random(4);
        double[] rgb = new double[3 * 32 * 16];
        for (int i = 0; i < rgb.length; i++) rgb[i] = r.nextDouble() * (i % 97 == 0 ? 60 : 1);
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(24, 16).samplesPerPixel(4).seed(3).ambient(Color.BLACK).build())
                .camera(new lt.spindulys.camera.PinholeCamera(new Vec3(0, 2, -5), new Vec3(0, 0.5, 0), Vec3.Y, 50))
                .environment(new Environment(TextureImage.fromLinear(32, 16, rgb), 40, 1, true, 3))
                .areaLight(AreaLight.disc(new Vec3(0, 4, 0), new Vec3(0, -1, 0), 0.5, Color.WHITE, 2, false, 2));
        b.add(new Plane(Vec3.Y, 0).material(WHITE));
        b.add(new Box(new Vec3(-1.5, 0, -0.5), new Vec3(-0.5, 1, 0.5)).material(WHITE));
        b.add(new Sphere(new Vec3(1, 0.6, 0), 0.6).material(Material.builder().color(Color.WHITE).kd(0.1).ks(0.5).kt(0.8).ior(1.4).build()));
        Scene scene = b.build();
        double[] one = Renderer.render(scene, 1, ProgressListener.NONE).frame().data();
        double[] two = Renderer.render(scene, 2, ProgressListener.NONE).frame().data();
        assertArrayEquals(one, two);
        double sum = 0;
        for (double v : one) sum += v;
        assertTrue(sum > 0);
    }
}
