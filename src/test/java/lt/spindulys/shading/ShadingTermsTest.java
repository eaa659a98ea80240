package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * The Whitted terms checked against their formulas: a 1x1 image whose single camera ray looks
 * straight down at the origin of the floor plane y = 0, with the light placed by each test.
 */
class ShadingTermsTest {
    private static final Color C = new Color(0.8, 0.6, 0.4);
    private static final Color IA = new Color(0.5, 0.5, 0.5);

    private static SceneBuilder floorScene(Material floor, PointLight light) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(1, 1).ambient(IA).background(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 5, 0), Vec3.ZERO, Vec3.Z, 10));
        if (light != null) b.light(light);
        b.add(new Plane(Vec3.Y, 0).material(floor));
        return b;
    }

    private static double[] render(SceneBuilder b) throws InterruptedException {
        var image = Renderer.render(b.build(), 1, ProgressListener.NONE).frame();
        return new double[] {image.get(0, 0, 0), image.get(0, 0, 1), image.get(0, 0, 2)};
    }

    private static Material.Builder floor() {
        return Material.builder().color(C).ka(0.2).kd(0.7).ks(0.5).shininess(12);
    }

    @Test
    void ambientDiffuseAndBlinnPhongSpecular() throws InterruptedException {
        Vec3 lightPos = new Vec3(3, 4, 0); // l = (0.6, 0.8, 0): n.l = 0.8
        Color li = new Color(1, 0.9, 0.8);
        double[] rgb = render(floorScene(floor().build(), new PointLight(lightPos, li, 2, PointLight.Falloff.NONE)));
        double ndotl = 0.8;
        double hx = 0.6, hy = 0.8 + 1, nh = hy / Math.hypot(hx, hy); // h = normalise(l + v), v = (0, 1, 0)
        for (int c = 0; c < 3; c++) {
            double ii = 2 * li.get(c);
            double expected = 0.2 * IA.get(c) * C.get(c) + 0.7 * C.get(c) * ii * ndotl + 0.5 * ii * Math.pow(nh, 12);
            assertEquals(expected, rgb[c], 1e-9, "channel " + c);
        }
    }

    @Test
    void inverseSquareFalloffDividesByDistanceSquared() throws InterruptedException {
        Material m = floor().ks(0).build();
        double[] none = render(floorScene(m, new PointLight(new Vec3(0, 4, 0), Color.WHITE, 16, PointLight.Falloff.NONE)));
        double[] inv = render(floorScene(m, new PointLight(new Vec3(0, 4, 0), Color.WHITE, 16, PointLight.Falloff.INVERSE_SQUARE)));
        for (int c = 0; c < 3; c++) {
            double ambient = 0.2 * IA.get(c) * C.get(c);
            assertEquals((none[c] - ambient) / 16, inv[c] - ambient, 1e-9);
        }
    }

    @Test
    void lightBelowTheSurfaceGivesAmbientOnly() throws InterruptedException {
        double[] rgb = render(floorScene(floor().build(), new PointLight(new Vec3(0, -3, 0), Color.WHITE)));
        for (int c = 0; c < 3; c++) assertEquals(0.2 * IA.get(c) * C.get(c), rgb[c], 1e-12);
    }

    @Test
    void opaqueOccluderCastsAFullShadow() throws InterruptedException {
        SceneBuilder b = floorScene(floor().build(), new PointLight(new Vec3(6, 8, 0), Color.WHITE));
        b.add(new Sphere(new Vec3(3, 4, 0), 0.5)); // on the segment from the origin to the light
        double[] rgb = render(b);
        for (int c = 0; c < 3; c++) assertEquals(0.2 * IA.get(c) * C.get(c), rgb[c], 1e-12);
    }

    @Test
    void transparentOccluderTintsAndAttenuatesTheShadow() throws InterruptedException {
        Material m = floor().ks(0).build();
        PointLight light = new PointLight(new Vec3(6, 8, 0), Color.WHITE);
        double[] lit = render(floorScene(m, light));
        Color filter = new Color(1, 0.5, 0.25);
        double beta = 0.3, radius = 1;
        SceneBuilder b = floorScene(m, light);
        // Centred on the shadow ray, away from the camera ray.
        b.add(new Sphere(new Vec3(3, 4, 0), radius).material(Material.builder().kt(0.6).filter(filter).beta(beta).ior(1.5).build()));
        double[] shadowed = render(b);
        for (int c = 0; c < 3; c++) {
            double ambient = 0.2 * IA.get(c) * C.get(c);
            // Two surface crossings each transmit kt*filter; the medium absorbs over the diameter.
            double t = Math.pow(0.6 * filter.get(c), 2) * Math.exp(-beta * 2 * radius);
            assertEquals((lit[c] - ambient) * t, shadowed[c] - ambient, 1e-9, "channel " + c);
        }
    }

    @Test
    void perfectMirrorShowsWhatItReflects() throws InterruptedException {
        // The floor is a mirror with no local terms; above it hangs a matte sphere lit from above,
        // so the pixel must equal what a camera at the mirrored position sees of the sphere.
        Material mirror = Material.builder().ka(0).kd(0).ks(0).kr(1).build();
        Material matte = Material.builder().color(C).ka(0.3).kd(0.7).build();
        SceneBuilder b = floorScene(mirror, new PointLight(new Vec3(0, 10, 0), Color.WHITE));
        b.add(new Sphere(new Vec3(0, 7, 0), 1).material(matte));
        double[] seen = render(b);
        // Sphere bottom at y = 6 faces down, away from the light: ambient only.
        for (int c = 0; c < 3; c++) assertEquals(0.3 * IA.get(c) * C.get(c), seen[c], 1e-12);
    }
}
