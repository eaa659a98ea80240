package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.io.SceneException;
import lt.spindulys.io.SceneParser;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Cylinder;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * Area lights measured: a disc light of radius {@value #R} at height {@value #H} above the plane
 * y = 0, facing down, and an opaque disc (a very flat cylinder) of radius {@value #OR} at height
 * {@value #OH} on the same axis. The plane's irradiance along the x axis is estimated by tracing
 * straight down onto it with the stratified samples of one pixel, as the renderer does.
 */
class AreaLightTest {
    static final double R = 1, H = 4, OR = 0.5, OH = 1;
    /** Width of a pixel of the measured profile, in scene units: 160 pixels over the 4 units across the shadow. */
    static final double PIXEL = 0.025;

    private static final Material WHITE = Material.builder().color(Color.WHITE).ka(0).kd(1).build();

    private static SceneBuilder base(AreaLight light, boolean occluder) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(8, 8).seed(5).ambient(Color.BLACK).build())
                .areaLight(light);
        b.add(new Plane(Vec3.Y, 0).material(WHITE));
        if (occluder) b.add(new Cylinder(new Vec3(0, OH - 1e-4, 0), new Vec3(0, OH, 0), OR).material(WHITE));
        return b;
    }

    private static AreaLight disc(int samples) {
        return AreaLight.disc(new Vec3(0, H, 0), new Vec3(0, -1, 0), R, Color.WHITE, 1, false, samples);
    }

    @Test
    void aThreadsStrataAreCheckedAgainstTheHeapBeforeTheyAreMade() {
        // 65,536 pixel samples times 1,024 light samples: 256 MiB of strata for one thread.
        SceneBuilder b = base(disc(AreaLight.MAX_SAMPLES), false);
        b.settings(RenderSettings.builder().size(8, 8).samplesPerPixel(65536).build());
        WhittedIntegrator w = new WhittedIntegrator(b.build());
        try (lt.spindulys.limits.HeapBudget.Scope cap = lt.spindulys.limits.HeapBudget.cap(64L << 20)) {
            lt.spindulys.limits.InsufficientMemoryException e = assertThrows(lt.spindulys.limits.InsufficientMemoryException.class, w::newScratch);
            assertTrue(e.getMessage().startsWith("the area lights' sample strata of one render thread needs 256"), e.getMessage());
        }
        TracerScratch small = new WhittedIntegrator(base(disc(4), false).build()).newScratch();
        assertEquals(4, small.lightStrata[0].length, "one pixel sample times the light's four");
    }

    /**
     * The plane's brightness at (x, 0, z): the mean over the n samples of pixel (px, 0), each
     * tracing from just above the plane straight down.
     */
    private static double irradiance(WhittedIntegrator w, TracerScratch s, double x, double z, long seed, int px, int n) {
        Ray ray = new Ray();
        double[] out = new double[4];
        double sum = 0;
        for (int i = 0; i < n; i++) {
            s.setSample(seed, px, 0, i, n);
            ray.set(x, 1e-3, z, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
            w.traceCamera(ray, s, out);
            sum += out[0];
        }
        return sum / n;
    }

    /** Irradiance from a disc of radius r parallel to the receiver at height z, at horizontal offset x from its axis (radiance 1). */
    static double discIrradiance(double r, double z, double x) {
        double a = z * z + x * x - r * r;
        return Math.PI / 2 * (1 - a / Math.sqrt(Math.pow(z * z + x * x + r * r, 2) - 4 * r * r * x * x));
    }

    @Test
    void penumbraRadiiMatchSimilarTriangles() {
        Scene shadowed = base(disc(1), true).build(), free = base(disc(1), false).build();
        WhittedIntegrator ws = new WhittedIntegrator(shadowed), wf = new WhittedIntegrator(free);
        TracerScratch ss = ws.newScratch(), sf = wf.newScratch();
        int n = 4096;
        double inner = Double.NaN, outer = Double.NaN;
        for (int k = 0; k * PIXEL <= 2; k++) {
            double x = k * PIXEL;
            double e = irradiance(ws, ss, x, 0, 1, k, n), ef = irradiance(wf, sf, x, 0, 1, k, n);
            if (Double.isNaN(inner) && e > 0) inner = x;
            if (Double.isNaN(outer) && e == ef) outer = x;
            if (!Double.isNaN(outer)) assertEquals(ef, e, 0, "fully lit beyond the penumbra, x = " + x);
        }
        // A ray from the light's far edge past the occluder's edge, and from its near edge.
        double predictedOuter = OR + (OR + R) * OH / (H - OH), predictedInner = OR - (R - OR) * OH / (H - OH);
        assertEquals(predictedInner, inner, PIXEL, "umbra radius");
        assertEquals(predictedOuter, outer, PIXEL, "penumbra's outer radius");
    }

    @Test
    void unoccludedIrradianceMatchesTheDiscsSolidAngle() {
        Scene shadowed = base(disc(1), true).build();
        WhittedIntegrator w = new WhittedIntegrator(shadowed);
        TracerScratch s = w.newScratch();
        for (double x : new double[] {1.5, 2, 3}) {
            double expected = discIrradiance(R, H, x);
            assertEquals(expected, irradiance(w, s, x, 0, 3, 0, 1024), 0.003 * expected, "at x = " + x);
        }
        // On the axis without the occluder: pi R^2 / (H^2 + R^2), the disc's projected solid angle.
        WhittedIntegrator wf = new WhittedIntegrator(base(disc(1), false).build());
        assertEquals(Math.PI * R * R / (H * H + R * R), irradiance(wf, wf.newScratch(), 0, 0, 3, 0, 1024), 1e-3);
    }

    @Test
    void sphereAndRectangleIrradianceMatchTheirSolidAngles() {
        // A sphere of radius 1 whose centre is 3 above the point: pi (r/d)^2.
        WhittedIntegrator ws = new WhittedIntegrator(base(AreaLight.sphere(new Vec3(0, 3, 0), 1, Color.WHITE, 1, 1), false).build());
        assertEquals(Math.PI / 9, irradiance(ws, ws.newScratch(), 0, 0, 3, 0, 1024), 1e-3 * Math.PI / 9);
        // A 2 x 1 rectangle 2 above the point, centred: four corner rectangles' form factors.
        WhittedIntegrator wr = new WhittedIntegrator(base(AreaLight.rectangle(new Vec3(0, 2, 0), new Vec3(0, -1, 0), Vec3.X, 2, 1,
                Color.WHITE, 1, true, 1), false).build());
        double a = 1 / 2.0, b = 0.5 / 2.0;
        double f = (a / Math.sqrt(1 + a * a) * Math.atan(b / Math.sqrt(1 + a * a)) + b / Math.sqrt(1 + b * b) * Math.atan(a / Math.sqrt(1 + b * b))) / (2 * Math.PI);
        double expected = 4 * Math.PI * f;
        assertEquals(expected, irradiance(wr, wr.newScratch(), 0, 0, 3, 0, 1024), 2e-3 * expected);
        // One-sided, facing up: nothing reaches the plane below.
        WhittedIntegrator wb = new WhittedIntegrator(base(AreaLight.rectangle(new Vec3(0, 2, 0), Vec3.Y, Vec3.X, 2, 1,
                Color.WHITE, 1, true, 1), false).build());
        assertEquals(0, irradiance(wb, wb.newScratch(), 0, 0, 3, 0, 16));
    }

    /**
     * The variance over seeds of a penumbra point's estimate, at 4, 16 and 64 samples per pixel:
     * it falls at least as 1/spp within a factor 2 (each 4x more samples divide it by at least 2),
     * and stratification makes it fall faster, but not faster than 1/spp^2.
     */
    @Test
    void softShadowVarianceFallsAsOneOverSamples() {
        WhittedIntegrator w = new WhittedIntegrator(base(disc(1), true).build());
        TracerScratch s = w.newScratch();
        double x = 0.66; // mid-penumbra
        double[] variance = new double[3];
        int[] spp = {4, 16, 64};
        int seeds = 400;
        for (int k = 0; k < spp.length; k++) {
            double sum = 0, sum2 = 0;
            for (int seed = 0; seed < seeds; seed++) {
                double e = irradiance(w, s, x, 0, 1000 + seed, 0, spp[k]);
                sum += e;
                sum2 += e * e;
            }
            double mean = sum / seeds;
            variance[k] = (sum2 / seeds - mean * mean) * seeds / (seeds - 1);
        }
        for (int k = 0; k + 1 < spp.length; k++) {
            double ratio = variance[k] / variance[k + 1];
            assertTrue(ratio >= 4 / 2.0 && ratio <= 4 * 4, "variance at " + spp[k] + " / at " + spp[k + 1] + " spp = " + ratio);
        }
    }

    /**
     * A transparent occluder tints the umbra exactly as it tints a point light's shadow: each of
     * the flat cylinder's two caps passes kt * filter, so the umbra receives (kt * filter)^2 of
     * the unoccluded light, channel by channel; a CSG occluder (a box minus a sphere) casts an
     * umbra of its own.
     */
    @Test
    void transparentAndCsgOccludersCastSoftShadows() {
        Material glass = Material.builder().color(Color.WHITE).kd(0).kt(0.5).filter(new Color(1, 0.5, 0.25)).build();
        SceneBuilder b = base(disc(1), false);
        b.add(new Cylinder(new Vec3(0, OH - 1e-4, 0), new Vec3(0, OH, 0), OR).material(glass));
        WhittedIntegrator wt = new WhittedIntegrator(b.build()), wf = new WhittedIntegrator(base(disc(1), false).build());
        TracerScratch st = wt.newScratch(), sf = wf.newScratch();
        Ray ray = new Ray();
        double[] tinted = new double[4], free = new double[4];
        double[] expected = {0.25, 0.0625, 0.015625};
        for (int i = 0; i < 64; i++) {
            st.setSample(7, 0, 0, i, 64);
            sf.setSample(7, 0, 0, i, 64);
            ray.set(0, 1e-3, 0, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
            wt.traceCamera(ray, st, tinted);
            ray.set(0, 1e-3, 0, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
            wf.traceCamera(ray, sf, free);
            for (int c = 0; c < 3; c++) assertEquals(free[c] * expected[c], tinted[c], 1e-12 * free[c], "channel " + c + ", sample " + i);
        }
        SceneBuilder csg = base(disc(1), false);
        csg.add(new lt.spindulys.scene.Bool(lt.spindulys.scene.Bool.Op.DIFFERENCE, java.util.List.of(
                new lt.spindulys.scene.Box(new Vec3(-0.5, OH - 0.1, -0.5), new Vec3(0.5, OH, 0.5)),
                new Sphere(new Vec3(0.5, OH, 0.5), 0.2))).material(WHITE));
        WhittedIntegrator wc = new WhittedIntegrator(csg.build());
        assertEquals(0, irradiance(wc, wc.newScratch(), 0, 0, 3, 0, 64), "umbra under the CSG occluder");
        assertTrue(irradiance(wc, wc.newScratch(), 0.45, 0, 3, 0, 64) > 0, "penumbra at its edge");
    }

    /**
     * A mirror floor shows the disc light's radiance times kr where the reflected ray meets the
     * disc, and the background beside it; a refracting slab (index 1) shows it times kt.
     */
    @Test
    void lightsAreSeenInReflectionsAndRefractions() {
        Material mirror = Material.builder().color(Color.WHITE).ka(0).kd(0).kr(0.8).build();
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(8, 8).ambient(Color.BLACK).background(Color.BLACK).build())
                .areaLight(AreaLight.disc(new Vec3(0, H, 0), new Vec3(0, -1, 0), R, new Color(1, 0.5, 0.25), 2, false, 1));
        b.add(new Plane(Vec3.Y, 0).material(mirror));
        WhittedIntegrator w = new WhittedIntegrator(b.build());
        TracerScratch s = w.newScratch();
        Ray ray = new Ray();
        double[] out = new double[4];
        // From (0, 1, -1) to the floor at (0, 0, -0.9): reflected up through (0, 4, -0.5), within the disc.
        ray.set(0, 1, -1, 0, -1, 0.1, 0, Double.POSITIVE_INFINITY);
        w.traceCamera(ray, s, out);
        assertArrayEquals(new double[] {1.6, 0.8, 0.4}, java.util.Arrays.copyOf(out, 3), 1e-12);
        // To the floor at (0, 0, -0.4): reflected through (0, 4, 2), outside the disc: background.
        ray.set(0, 1, -1, 0, -1, 0.6, 0, Double.POSITIVE_INFINITY);
        w.traceCamera(ray, s, out);
        assertArrayEquals(new double[] {0, 0, 0}, java.util.Arrays.copyOf(out, 3), 0);

        Material clear = Material.builder().color(Color.WHITE).ka(0).kd(0).kt(0.5).ior(1).build();
        SceneBuilder g = new SceneBuilder()
                .settings(RenderSettings.builder().size(8, 8).ambient(Color.BLACK).background(Color.BLACK).build())
                .areaLight(AreaLight.disc(new Vec3(0, H, 0), new Vec3(0, -1, 0), R, Color.WHITE, 2, false, 1));
        g.add(new lt.spindulys.scene.Box(new Vec3(-1, 1, -1), new Vec3(1, 2, 1)).material(clear));
        WhittedIntegrator wg = new WhittedIntegrator(g.build());
        ray.set(0.1, 0, 0, 0, 1, 0, 0, Double.POSITIVE_INFINITY);
        wg.traceCamera(ray, wg.newScratch(), out);
        assertArrayEquals(new double[] {0.5, 0.5, 0.5}, java.util.Arrays.copyOf(out, 3), 1e-12);
    }

    /**
     * A subdivision surface (the thesis's cube) casts a soft shadow's umbra on the floor below it
     * and receives one from a sphere above it, while the floor beside it is lit.
     */
    @Test
    void subdivisionSurfacesCastAndReceiveSoftShadows() {
        double[] shaded = subdivProbes(true), open = subdivProbes(false);
        assertEquals(0, shaded[0], "the cube's top in the sphere's umbra");
        assertTrue(open[0] > 0, "the cube's top lit without the sphere");
        assertEquals(0, shaded[1], "the floor in the cube's umbra");
        assertTrue(shaded[2] > 0, "the floor beside the cube is lit");
    }

    /** Brightness, over 64 samples, of the cube's top, the floor under it and the floor beside it. */
    private static double[] subdivProbes(boolean sphere) {
        Scene scene = SceneParser.parse("settings { ambient 0 }\n"
                + "disclight { center 0 6 0 radius 0.5 }\n"
                + (sphere ? "sphere { center 0 3 0 radius 0.8 material { kd 1 ka 0 } }\n" : "")
                + "subdiv { file \"models/cube.dat\" level 3 material { kd 1 ka 0 } }\n"
                + "plane { normal 0 1 0 offset -1.2 material { kd 1 ka 0 } }\n", "cube.dat", Path.of("scenes")).build();
        WhittedIntegrator w = new WhittedIntegrator(scene);
        TracerScratch s = w.newScratch();
        Ray ray = new Ray();
        double[] out = new double[4];
        double[][] probes = {{0, 2, 0}, {0, -1.15, 0}, {4, -1.15, 0}};
        double[] seen = new double[3];
        for (int k = 0; k < probes.length; k++) {
            for (int i = 0; i < 64; i++) {
                s.setSample(11, k, 0, i, 64);
                ray.set(probes[k][0], probes[k][1], probes[k][2], 0, -1, 0, 0, Double.POSITIVE_INFINITY);
                w.traceCamera(ray, s, out);
                seen[k] += out[0] / 64;
            }
        }
        return seen;
    }

    private static String sceneText() {
        return """
                settings { width 40 height 30 samples 4 seed 9 ambient 0 }
                camera { eye 0 3 -6 lookat 0 0.5 0 fov 40 }
                disclight { center 0 4 0 radius 1 intensity 3 samples 2 }
                spherelight { center 1.5 2 -1 radius 0.4 intensity 4 }
                rectlight { center -2 3 0 width 1 height 0.5 onesided true }
                plane { normal 0 1 0 offset 0 }
                sphere { center 0 0.6 0 radius 0.5 material { color 0.9 0.8 0.7 kt 0.6 filter 1 0.5 0.2 ior 1.3 ks 0.3 } }
                difference { box { min 1 0 1 max 2 1 2 } sphere { center 2 1 2 radius 0.6 } }
                """;
    }

    @Test
    void imageIsTheSameForOneAndFourThreads() throws Exception {
        Scene scene = SceneParser.parse(sceneText(), "soft.dat", Path.of(".")).build();
        double[] one = Renderer.render(scene, 1, ProgressListener.NONE).frame().data();
        double[] four = Renderer.render(scene, 4, ProgressListener.NONE).frame().data();
        assertArrayEquals(one, four);
        // The lights are seen: some pixel shows the sphere light's radiance 4 exactly.
        boolean seen = false;
        for (int i = 0; i < one.length; i += 3) seen |= one[i] == 4 && one[i + 1] == 4 && one[i + 2] == 4;
        assertTrue(seen, "the sphere light is visible to the camera");
    }

    @Test
    void areaLightStatementsParseAndBadKeysAreLocated() {
        SceneBuilder b = SceneParser.parse(sceneText(), "soft.dat", Path.of("."));
        assertEquals(3, b.areaLights().size());
        AreaLight rect = b.areaLights().get(2);
        assertEquals(AreaLight.Shape.RECTANGLE, rect.shape());
        assertTrue(rect.oneSided());
        assertEquals(0.5, rect.area(), 1e-12);
        assertEquals(2, b.areaLights().get(0).samples());

        SceneException e = assertThrows(SceneException.class,
                () -> SceneParser.parse("disclight {\n  center 0 1 0 radius 1\n  widht 2 }", "a.dat", Path.of(".")));
        assertTrue(e.getMessage().startsWith("a.dat:3:3: "), e.getMessage());
        e = assertThrows(SceneException.class, () -> SceneParser.parse("spherelight { center 0 1 0 radius -1 }", "b.dat", Path.of(".")));
        assertTrue(e.getMessage().startsWith("b.dat:1:"), e.getMessage());
        assertTrue(e.getMessage().contains("radius"), e.getMessage());
        e = assertThrows(SceneException.class, () -> SceneParser.parse("rectlight { center 0 1 0 width 1 height 1 samples 0 }", "c.dat", Path.of(".")));
        assertTrue(e.getMessage().startsWith("c.dat:1:") && e.getMessage().contains("samples"), e.getMessage());
        e = assertThrows(SceneException.class, () -> SceneParser.parse("rectlight { center 0 1 0 width 1 height 1 tangent 0 1 0 }", "d.dat", Path.of(".")));
        assertTrue(e.getMessage().startsWith("d.dat:1:") && e.getMessage().contains("tangent"), e.getMessage());
        e = assertThrows(SceneException.class, () -> SceneParser.parse("disclight { center 0 1 0 radius 1 power 3\n intensity 2 }", "e.dat", Path.of(".")));
        assertEquals("e.dat:2:2: disclight has both 'intensity' and 'power': give one", e.getMessage());

        // Power is the emitted flux: pi * area * intensity, twice for both faces.
        AreaLight two = SceneParser.parse("disclight { center 0 1 0 radius 2 power 8 }", "f.dat", Path.of(".")).areaLights().get(0);
        assertEquals(8 / (Math.PI * Math.PI * 4 * 2), two.intensity(), 1e-15);
        AreaLight ball = SceneParser.parse("spherelight { center 0 1 0 radius 0.5 power 2 }", "g.dat", Path.of(".")).areaLights().get(0);
        assertEquals(2 / (4 * Math.PI * Math.PI * 0.25), ball.intensity(), 1e-15);
    }
}
