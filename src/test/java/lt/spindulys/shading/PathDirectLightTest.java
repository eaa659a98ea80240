package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.EnvironmentLightTest;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.scene.Triangle;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.TextureImage;
import lt.spindulys.texture.Uniform;
import lt.spindulys.texture.Uv;

/**
 * Direct light through the path tracer (maxdepth 0), where next-event estimation and BSDF
 * sampling both find every light that has a surface and multiple importance sampling weighs
 * them: a diffuse plane of albedo {@value #ALBEDO} at the origin must show albedo / pi times the
 * light's irradiance, known in closed form for each kind of light; and a glossy surface must show
 * the same whether a light is an area light (both strategies, MIS) or emitting geometry of the
 * same shape (found by BSDF sampling alone). Each estimate is the mean of one ray's samples,
 * traced by the integrator as the renderer does, with the standard error of those samples as
 * the tolerance ({@link PixelStatistics}).
 */
class PathDirectLightTest {
    private static final double ALBEDO = 0.5;
    private static final int SAMPLES = 16384;
    private static final Material DIFFUSE = Material.builder().color(Color.WHITE).ka(0).kd(ALBEDO).build();
    /** Diffuse under a GGX lobe of alpha sqrt(2/52) = 0.2: light found by both strategies in comparable measure. */
    private static final Material GLOSSY = Material.builder().color(Color.WHITE).ka(0).kd(0.3).ks(0.6).shininess(50).build();

    private static SceneBuilder plane(Material m) {
        SceneBuilder b = new SceneBuilder().settings(RenderSettings.builder().size(8, 8).seed(11).maxDepth(0)
                .integrator(IntegratorKind.PATH).build());
        b.add(new Plane(Vec3.Y, 0).material(m));
        return b;
    }

    /** The statistics of the red channel of {@value #SAMPLES} samples of the radiance seen along (o, d). */
    private static PixelStatistics radiance(Scene scene, Vec3 o, Vec3 d, long seed) { return radiance(scene, o, d, seed, SAMPLES); }

    /** The statistics of the red channel of n samples of the radiance seen along (o, d). */
    private static PixelStatistics radiance(Scene scene, Vec3 o, Vec3 d, long seed, int n) {
        PathIntegrator path = new PathIntegrator(scene);
        TracerScratch s = new TracerScratch(0);
        Ray ray = new Ray();
        double[] out = new double[4];
        PixelStatistics stats = new PixelStatistics();
        for (int i = 0; i < n; i++) {
            s.setSample(seed, 3, 5, i, n);
            ray.set(o.x(), o.y(), o.z(), d.x(), d.y(), d.z(), 0, Double.POSITIVE_INFINITY);
            path.traceCamera(ray, s, out);
            assertTrue(Double.isFinite(out[0]) && out[0] >= 0, "sample " + i + " is " + out[0]);
            stats.add(out[0]);
        }
        return stats;
    }

    /** The plane's radiance at the origin, seen from just above it straight down. */
    private static PixelStatistics belowTheLight(SceneBuilder b, long seed) {
        return radiance(b.build(), new Vec3(0, 1e-3, 0), new Vec3(0, -1, 0), seed);
    }

    private static double diffuse(double irradiance) { return ALBEDO / Math.PI * irradiance; }

    @Test
    void discLightGivesItsIrradianceOnAndOffItsAxis() {
        // Radius 1, 2 above the origin, facing down: pi R^2 / (h^2 + R^2) on the axis.
        SceneBuilder b = plane(DIFFUSE).areaLight(AreaLight.disc(new Vec3(0, 2, 0), new Vec3(0, -1, 0), 1, Color.WHITE, 3, true, 1));
        belowTheLight(b, 1).assertMean(diffuse(3 * Math.PI / 5), "disc light, on its axis");
        // The same disc moved 1.5 sideways: the disc's view factor off the axis.
        SceneBuilder off = plane(DIFFUSE).areaLight(AreaLight.disc(new Vec3(1.5, 2, 0), new Vec3(0, -1, 0), 1, Color.WHITE, 3, true, 1));
        belowTheLight(off, 2).assertMean(diffuse(3 * AreaLightTest.discIrradiance(1, 2, 1.5)), "disc light, 1.5 off its axis");
    }

    @Test
    void rectangleLightGivesItsIrradianceAndNothingFromItsBack() {
        // A 2 x 1 rectangle 2 above the point, centred: four corner rectangles' form factors.
        SceneBuilder b = plane(DIFFUSE).areaLight(AreaLight.rectangle(new Vec3(0, 2, 0), new Vec3(0, -1, 0), Vec3.X, 2, 1,
                Color.WHITE, 2, true, 1));
        double a = 1 / 2.0, c = 0.5 / 2.0;
        double f = (a / Math.sqrt(1 + a * a) * Math.atan(c / Math.sqrt(1 + a * a)) + c / Math.sqrt(1 + c * c) * Math.atan(a / Math.sqrt(1 + c * c))) / (2 * Math.PI);
        belowTheLight(b, 3).assertMean(diffuse(2 * 4 * Math.PI * f), "rectangle light");
        SceneBuilder back = plane(DIFFUSE).areaLight(AreaLight.rectangle(new Vec3(0, 2, 0), Vec3.Y, Vec3.X, 2, 1, Color.WHITE, 2, true, 1));
        PixelStatistics dark = belowTheLight(back, 4);
        assertEquals(0, dark.mean(), 0, "a one-sided light seen from its back: " + dark);
    }

    @Test
    void sphereLightGivesItsIrradiance() {
        // Radius 1, centre 3 above the point: pi (r / d)^2.
        SceneBuilder b = plane(DIFFUSE).areaLight(AreaLight.sphere(new Vec3(0, 3, 0), 1, Color.WHITE, 2, 1));
        belowTheLight(b, 5).assertMean(diffuse(2 * Math.PI / 9), "sphere light");
        // Off to the side and low, so part of the cone it fills is below the horizon: only its visible part counts.
        SceneBuilder low = plane(DIFFUSE).areaLight(AreaLight.sphere(new Vec3(3, 0.5, 0), 1, Color.WHITE, 2, 1));
        // The sphere seen from the origin: a cap of half-angle asin(1/d) around a direction at
        // elevation e; its irradiance on the plane is found by integrating cos(theta) over the
        // part of the cap above the horizon, done here on a fine grid.
        belowTheLight(low, 6).assertMean(diffuse(2 * capIrradiance(new Vec3(3, 0.5, 0), 1)), "sphere light near the horizon");
    }

    /** Irradiance at the origin (normal +Y) from a sphere of radiance 1, clipped by the horizon: a midpoint rule in (theta, phi), fine enough for 1e-4. */
    private static double capIrradiance(Vec3 centre, double radius) {
        int nt = 1500, np = 3000;
        double d2 = centre.dot(centre), cosMax = Math.sqrt(1 - radius * radius / d2);
        Vec3 axis = centre.times(1 / Math.sqrt(d2));
        double sum = 0;
        for (int i = 0; i < nt; i++) {
            double theta = (i + 0.5) / nt * Math.PI / 2; // polar angle from the plane's normal
            double st = Math.sin(theta), ct = Math.cos(theta);
            for (int j = 0; j < np; j++) {
                double phi = (j + 0.5) / np * 2 * Math.PI;
                double wx = st * Math.cos(phi), wy = ct, wz = st * Math.sin(phi);
                if (wx * axis.x() + wy * axis.y() + wz * axis.z() >= cosMax) sum += ct * st;
            }
        }
        return sum * (Math.PI / 2 / nt) * (2 * Math.PI / np);
    }

    @Test
    void pointLightGivesIntensityOverDistanceSquaredTimesCosine() {
        Vec3 at = new Vec3(1, 2, 0.5);
        double intensity = 7, d2 = at.dot(at), cos = at.y() / Math.sqrt(d2);
        SceneBuilder b = plane(DIFFUSE).light(new PointLight(at, Color.WHITE, intensity, PointLight.Falloff.INVERSE_SQUARE));
        PixelStatistics s = belowTheLight(b, 7);
        // A delta light: one light sample, no random choice, so every sample is the same value.
        assertEquals(diffuse(intensity / d2 * cos), s.mean(), 1e-12, s.toString());
        assertEquals(0, s.standardDeviation(), 1e-12, s.toString());
    }

    /**
     * A 4 x 3 texel patch of radiance 20 in a 64 x 32 environment: its irradiance is known in
     * closed form ({@link EnvironmentLightTest#patchIrradiance}). As a light (brightness-sampled
     * and BSDF-sampled, MIS) and only seen (BSDF sampling alone) the plane shows the same.
     */
    @Test
    void environmentPatchGivesItsIrradianceAsALightAndOnlySeen() {
        int w = 64, h = 32, i0 = 20, i1 = 24, j0 = 6, j1 = 9;
        TextureImage map = EnvironmentLightTest.patchMap(w, h, i0, i1, j0, j1, 20);
        double expected = diffuse(EnvironmentLightTest.patchIrradiance(w, h, i0, i1, j0, j1, 20));
        belowTheLight(plane(DIFFUSE).environment(new Environment(map, 0, 1, true, 1)), 8).assertMean(expected, "environment patch as a light");
        belowTheLight(plane(DIFFUSE).environment(new Environment(map, 0, 1, false, 1)), 9).assertMean(expected, "environment patch only seen");
    }

    /** Geometry that emits {@code radiance} (a uniform emission texture) and scatters nothing. */
    private static Material emitter(double radiance) {
        return Material.builder().color(Color.BLACK).ka(0).kd(0).texture(Channel.EMISSION, new Uniform(Color.grey(radiance)), new Uv(1, 1)).build();
    }

    /** Asserts two independent means agree within {@link PixelStatistics#MEAN_SIGMAS} standard errors of their difference. */
    private static void assertAgree(PixelStatistics a, PixelStatistics b, String what) {
        double se = Math.sqrt(a.standardError() * a.standardError() + b.standardError() * b.standardError());
        double tolerance = PixelStatistics.MEAN_SIGMAS * se + PixelStatistics.ROUNDING;
        assertTrue(Math.abs(a.mean() - b.mean()) <= tolerance, what + ": " + a + " against " + b + ", tolerance " + tolerance);
        assertTrue(a.mean() > 0.01, what + ": the light is seen at all: " + a);
    }

    /**
     * A glossy surface seen obliquely, its highlight on the light: the rectangle light (sampled,
     * MIS) and two emitting triangles covering the same rectangle (BSDF sampling only) agree; and
     * so do a sphere light and an emitting sphere. BSDF sampling alone is the noisier estimate,
     * so it gets more samples.
     */
    @Test
    void glossyReflectionIsTheSameWhetherTheLightIsSampledOrOnlyHit() {
        Vec3 eye = new Vec3(-1, 1, 0.1), down = new Vec3(1, -1, -0.1).normalized();
        double radiance = 3;
        // Mirror of the view direction off the plane passes (2, 2, -0.2): the light sits around it.
        Vec3 centre = new Vec3(2, 2, -0.2);
        SceneBuilder lit = plane(GLOSSY).areaLight(AreaLight.rectangle(centre, new Vec3(0, -1, 0), Vec3.X, 1.2, 0.8,
                Color.WHITE, radiance, true, 1));
        SceneBuilder emitting = plane(GLOSSY);
        Vec3 a = centre.plus(new Vec3(-0.6, 0, -0.4)), b = centre.plus(new Vec3(0.6, 0, -0.4)),
                c = centre.plus(new Vec3(0.6, 0, 0.4)), d = centre.plus(new Vec3(-0.6, 0, 0.4));
        emitting.add(triangle(a, b, c, emitter(radiance)));
        emitting.add(triangle(a, c, d, emitter(radiance)));
        assertAgree(radiance(lit.build(), eye, down, 10), radiance(emitting.build(), eye, down, 11, 4 * SAMPLES), "rectangle light against emitting triangles");

        Vec3 ball = new Vec3(2.2, 2.1, -0.3);
        SceneBuilder sphereLit = plane(GLOSSY).areaLight(AreaLight.sphere(ball, 0.5, Color.WHITE, radiance, 1));
        SceneBuilder sphereEmitting = plane(GLOSSY);
        sphereEmitting.add(new Sphere(ball, 0.5).material(emitter(radiance)));
        assertAgree(radiance(sphereLit.build(), eye, down, 12), radiance(sphereEmitting.build(), eye, down, 13, 4 * SAMPLES), "sphere light against an emitting sphere");
    }

    /**
     * An emitting mesh is a light: a 2 x 1 quad (two triangles of a {@link TriangleMesh}) 2 above
     * the point gives the rectangle light's irradiance, found by its own light samples and by
     * BSDF samples weighed against them (MIS), whichever face it shows; and the same quad as two
     * loose triangles, found by BSDF samples alone, agrees.
     */
    @Test
    void anEmittingMeshLightsLikeTheRectangleItCovers() {
        double radiance = 2, a = 1 / 2.0, c = 0.5 / 2.0;
        double f = (a / Math.sqrt(1 + a * a) * Math.atan(c / Math.sqrt(1 + a * a)) + c / Math.sqrt(1 + c * c) * Math.atan(a / Math.sqrt(1 + c * c))) / (2 * Math.PI);
        double expected = diffuse(radiance * 4 * Math.PI * f);
        for (boolean facingDown : new boolean[] {true, false}) {
            double[] corners = {-1, 2, -0.5, 1, 2, -0.5, 1, 2, 0.5, -1, 2, 0.5};
            int[] quad = facingDown ? new int[] {0, 1, 2, 3} : new int[] {3, 2, 1, 0};
            TriangleMesh mesh = new TriangleMesh(new lt.spindulys.mesh.MeshData(corners, null, null, new int[] {4}, quad, null, null, "quad"));
            mesh.material(emitter(radiance));
            PixelStatistics sampled = belowTheLight(plane(DIFFUSE).add(mesh), facingDown ? 14 : 15);
            sampled.assertMean(expected, "emitting mesh, facing " + (facingDown ? "down" : "up"));
        }
        PixelStatistics hitOnly = belowTheLight(plane(DIFFUSE)
                .add(triangle(new Vec3(-1, 2, -0.5), new Vec3(1, 2, -0.5), new Vec3(1, 2, 0.5), emitter(radiance)))
                .add(triangle(new Vec3(-1, 2, -0.5), new Vec3(1, 2, 0.5), new Vec3(-1, 2, 0.5), emitter(radiance))), 16);
        hitOnly.assertMean(expected, "emitting triangles found by paths alone");
    }

    private static GObject triangle(Vec3 a, Vec3 b, Vec3 c, Material m) {
        return new Triangle(a, b, c).material(m);
    }
    /**
     * A one-sided rectangle light facing up, 1 above the plane, shows the plane its black back
     * and hides a part of a uniform sky of radiance 1. A path that reaches a light ends there
     * (as a Whitted camera ray does), so the light must hide the sky from the sky's light samples
     * too: the plane then shows albedo * (1 - F), F the rectangle's form factor, whether the sky
     * is a light (light samples and BSDF samples, MIS) or only seen (BSDF samples alone). Were
     * the two strategies to disagree on what is visible, MIS would mix two answers.
     */
    @Test
    void aLightHidesTheSkyFromLightSamplesAsFromPaths() {
        double a = 1, c = 1; // half-sides over height, for the corner rectangles' form factors
        double corner = (a / Math.sqrt(1 + a * a) * Math.atan(c / Math.sqrt(1 + a * a)) + c / Math.sqrt(1 + c * c) * Math.atan(a / Math.sqrt(1 + c * c))) / (2 * Math.PI);
        double expected = ALBEDO * (1 - 4 * corner);
        for (boolean skyIsLight : new boolean[] {true, false}) {
            SceneBuilder b = plane(DIFFUSE).environment(new Environment(PathFurnaceTest.uniform(1), 0, 1, skyIsLight, 1))
                    .areaLight(AreaLight.rectangle(new Vec3(0, 1, 0), Vec3.Y, Vec3.X, 2, 2, Color.WHITE, 1, true, 1));
            belowTheLight(b, skyIsLight ? 14 : 15).assertMean(expected, "the sky past a one-sided light's back, the sky " + (skyIsLight ? "a light" : "only seen"));
        }
    }
}
