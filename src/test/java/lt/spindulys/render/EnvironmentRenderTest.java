package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.material.Material;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.texture.TextureImage;

/**
 * A lat-long environment seen by camera rays, a mirror sphere and a glass sphere, checked pixel by
 * pixel against the analytic directions: a synthetic map whose value encodes its own direction
 * ({@code 0.5 + 0.5 d}, from the documented convention) shows that each pixel sees the map along
 * exactly the direction it should.
 */
class EnvironmentRenderTest {
    private static final int W = 40, H = 30, MW = 512, MH = 256;
    private static final double FOV = 40, R = 1.5;

    /** The map: each texel holds 0.5 + 0.5 d of the direction d through its centre (u = atan2(dx, -dz) / 2pi, v = acos(dy) / pi). */
    static TextureImage directionMap() {
        double[] rgb = new double[3 * MW * MH];
        for (int y = 0; y < MH; y++) {
            for (int x = 0; x < MW; x++) {
                double phi = 2 * Math.PI * (x + 0.5) / MW, theta = Math.PI * (y + 0.5) / MH;
                int q = 3 * (y * MW + x);
                rgb[q] = 0.5 + 0.5 * Math.sin(theta) * Math.sin(phi);
                rgb[q + 1] = 0.5 + 0.5 * Math.cos(theta);
                rgb[q + 2] = 0.5 - 0.5 * Math.sin(theta) * Math.cos(phi);
            }
        }
        return TextureImage.fromLinear(MW, MH, rgb);
    }

    private static Scene scene(Environment env, Material m, int spp) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(W, H).samplesPerPixel(spp).seed(5).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, FOV))
                .environment(env);
        if (m != null) b.add(new Sphere(Vec3.ZERO, R).material(m));
        return b.build();
    }

    /** The unit direction of the ray through the centre of pixel (x, y): forward +z, right -x, up +y. */
    private static double[] cameraRay(int x, int y) {
        double tanHalf = Math.tan(Math.toRadians(FOV) / 2), aspect = (double) W / H;
        double sx = (2 * (x + 0.5) / W - 1) * tanHalf * aspect, sy = (1 - 2 * (y + 0.5) / H) * tanHalf;
        double dx = -sx, dy = sy, dz = 1, len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        return new double[] {dx / len, dy / len, dz / len};
    }

    /** Distance along unit d from o to the sphere at the origin (the far hit if {@code far}), or NaN; NaN too within a margin of the silhouette. */
    private static double hitSphere(double[] o, double[] d, boolean far) {
        double b = dot(o, d), disc = b * b - (dot(o, o) - R * R);
        if (disc < 1e-3) return Double.NaN;
        return far ? -b + Math.sqrt(disc) : -b - Math.sqrt(disc);
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    /** Snell's law for unit d through unit n (facing d's side), eta = n1 / n2; null for total internal reflection. */
    private static double[] refract(double[] d, double[] n, double eta) {
        double cosi = -dot(d, n), k = 1 - eta * eta * (1 - cosi * cosi);
        if (k < 0) return null;
        double a = eta * cosi - Math.sqrt(k);
        return new double[] {eta * d[0] + a * n[0], eta * d[1] + a * n[1], eta * d[2] + a * n[2]};
    }

    private static double[] rendered(FrameBuffer f, int x, int y) {
        return new double[] {f.get(x, y, 0), f.get(x, y, 1), f.get(x, y, 2)};
    }

    private static double[] lookup(Environment env, double[] d) {
        double[] out = new double[3];
        env.lookup(d[0], d[1], d[2], out);
        return out;
    }

    /** The angle between d and the direction the direction map's value c encodes. */
    private static double angleTo(double[] c, double[] d) {
        double ex = 2 * c[0] - 1, ey = 2 * c[1] - 1, ez = 2 * c[2] - 1, len = Math.sqrt(ex * ex + ey * ey + ez * ez);
        return Math.acos(Math.min(1, (ex * d[0] + ey * d[1] + ez * d[2]) / len));
    }

    @Test
    void aMirrorSphereReflectsEachPixelsExactDirection() throws InterruptedException {
        Environment env = new Environment(directionMap(), 0, 1);
        Material mirror = Material.builder().ka(0).kd(0).ks(0).kr(1).build();
        FrameBuffer f = Renderer.render(scene(env, mirror, 1), 2, lt.spindulys.render.ProgressListener.NONE).frame();
        double[] eye = {0, 0, -5};
        int sphere = 0, sky = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double[] d = cameraRay(x, y), seen;
                double t = hitSphere(eye, d, false);
                if (Double.isNaN(t)) {
                    double b = dot(eye, d), disc = b * b - (dot(eye, eye) - R * R);
                    if (disc > -1e-3) continue;  // near the silhouette
                    seen = d;
                    sky++;
                } else {
                    double[] n = {(eye[0] + t * d[0]) / R, (eye[1] + t * d[1]) / R, (eye[2] + t * d[2]) / R};
                    double dn = dot(d, n);
                    seen = new double[] {d[0] - 2 * dn * n[0], d[1] - 2 * dn * n[1], d[2] - 2 * dn * n[2]};
                    sphere++;
                }
                double[] c = rendered(f, x, y);
                String at = "pixel " + x + "," + y;
                assertArrayEquals(lookup(env, seen), c, 1e-9, at);
                // The value encodes the direction it was looked up along (bilinear: within a texel).
                assertTrue(angleTo(c, seen) < 0.01, at + ": sees " + angleTo(c, seen) + " rad off");
            }
        }
        assertTrue(sphere > 200 && sky > 200, sphere + " sphere, " + sky + " sky pixels");
    }

    @Test
    void theConventionPutsTheImageCentreAheadOfTheDefaultCameraAndXAQuarterAcross() {
        Environment env = new Environment(directionMap(), 0, 1);
        double[][] dirs = {{0, 0, 1}, {1, 0, 0}, {-1, 0, 0}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {0.6, 0.48, -0.64}};
        for (double[] d : dirs) assertTrue(angleTo(lookup(env, d), d) < 0.01, java.util.Arrays.toString(d));
        // And by texel: +X is a quarter across the middle rows, +Z the centre.
        TextureImage m = env.map();
        assertEquals(1.0, m.texel(0, MW / 4, MH / 2, 0), 1e-3);
        assertEquals(1.0, m.texel(0, MW / 2, MH / 2, 2), 1e-3);
    }

    @Test
    void rotationTurnsTheMapAboutUpByTheRightHandRuleAndIntensityScalesIt() throws InterruptedException {
        TextureImage map = directionMap();
        Environment base = new Environment(map, 0, 1), turned = new Environment(map, 90 + 360, 2.5);
        Random rnd = new Random(7);
        double a = Math.toRadians(90), cos = Math.cos(a), sin = Math.sin(a);
        for (int i = 0; i < 1000; i++) {
            double[] d = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double len = Math.sqrt(dot(d, d));
            for (int c = 0; c < 3; c++) d[c] /= len;
            // What was seen along d is seen along R_y(90) d, 2.5 times brighter.
            double[] rd = {d[0] * cos + d[2] * sin, d[1], -d[0] * sin + d[2] * cos};
            double[] want = lookup(base, d), got = lookup(turned, rd);
            for (int c = 0; c < 3; c++) assertEquals(2.5 * want[c], got[c], 1e-9, "direction " + i);
        }
        // Rendered: the camera's rays see the turned map.
        FrameBuffer f = Renderer.render(scene(turned, null, 1), 1, ProgressListener.NONE).frame();
        for (int y = 0; y < H; y += 3) {
            for (int x = 0; x < W; x += 3) {
                double[] d = cameraRay(x, y);
                double[] back = {d[0] * cos - d[2] * sin, d[1], d[0] * sin + d[2] * cos};  // R_y(-90) d
                double[] want = lookup(base, back);
                for (int c = 0; c < 3; c++) assertEquals(2.5 * want[c], f.get(x, y, c), 1e-9, "pixel " + x + "," + y);
            }
        }
    }

    @Test
    void aGlassSphereShowsTheMapRefractedThrough() throws InterruptedException {
        Environment env = new Environment(directionMap(), 30, 1);
        double ior = 1.5;
        Material glass = Material.builder().ka(0).kd(0).ks(0).kr(0).kt(1).ior(ior).build();
        FrameBuffer f = Renderer.render(scene(env, glass, 1), 2, ProgressListener.NONE).frame();
        double[] eye = {0, 0, -5};
        int through = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double[] d = cameraRay(x, y);
                double t = hitSphere(eye, d, false);
                if (Double.isNaN(t)) continue;
                double[] p = {eye[0] + t * d[0], eye[1] + t * d[1], eye[2] + t * d[2]};
                double[] in = refract(d, new double[] {p[0] / R, p[1] / R, p[2] / R}, 1 / ior);
                double t2 = hitSphere(p, in, true);
                double[] q = {p[0] + t2 * in[0], p[1] + t2 * in[1], p[2] + t2 * in[2]};
                double[] out = refract(in, new double[] {-q[0] / R, -q[1] / R, -q[2] / R}, ior);
                assertTrue(out != null, "a sphere never reflects totally on the way out");
                assertArrayEquals(lookup(env, out), rendered(f, x, y), 1e-7, "pixel " + x + "," + y);
                through++;
            }
        }
        assertTrue(through > 200, through + " pixels through the glass");
        // The centre pixels look straight through: almost what the camera would see without the sphere.
        double[] centre = cameraRay(W / 2, H / 2);
        assertTrue(angleTo(rendered(f, W / 2, H / 2), rotatedBack(centre, 30)) < 0.05);
    }

    /** R_y(-degrees) d: where the map rotated by {@code degrees} looks up d. */
    private static double[] rotatedBack(double[] d, double degrees) {
        double a = Math.toRadians(-degrees), cos = Math.cos(a), sin = Math.sin(a);
        return new double[] {d[0] * cos + d[2] * sin, d[1], -d[0] * sin + d[2] * cos};
    }

    @Test
    void imagesAreIdenticalForOneAndFourThreads() throws InterruptedException {
        Environment env = new Environment(directionMap(), 15, 1.2);
        Material glass = Material.builder().ka(0.1).kd(0.2).ks(0.5).kr(0.1).kt(0.7).ior(1.5).fresnel(true).build();
        Scene s = scene(env, glass, 4);
        double[] one = Renderer.render(s, 1, ProgressListener.NONE).frame().data();
        double[] four = Renderer.render(s, 4, ProgressListener.NONE).frame().data();
        assertArrayEquals(one, four);
    }
}
