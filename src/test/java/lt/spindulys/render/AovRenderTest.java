package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.image.AovFrame;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.image.Images;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * The render passes of a scene with known geometry: a sphere above a floor, seen by a pinhole
 * camera looking along +z, with sky above the horizon. Every pixel is checked against the
 * analytic first hit of the ray through its centre.
 */
class AovRenderTest {
    private static final int W = 40, H = 30;
    private static final double FOV = 40, CX = 0.3, CY = 0.1, CZ = 0, R = 1, FLOOR = -1;

    @TempDir Path dir;

    private static Scene scene(int spp, Set<Aov> aovs) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(W, H).samplesPerPixel(spp).seed(3).aovs(aovs).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, FOV))
                .light(new PointLight(new Vec3(2, 5, -3), Color.WHITE));
        // A mirror sphere: the passes must show the sphere itself, not what it reflects.
        b.add(new Sphere(new Vec3(CX, CY, CZ), R).material(Material.builder().kr(0.9).build()));  // id 0
        b.add(new Plane(Vec3.Y, FLOOR));                                                           // id 1
        return b.build();
    }

    /** What the ray through the centre of pixel (x, y) hits: {t, nx, ny, nz, id}, or null for the sky or a grazing ray. */
    private static double[] analytic(int x, int y) {
        // Camera frame for eye (0, 0, -5) looking at the origin with up +y: forward +z, right -x, up +y.
        double tanHalf = Math.tan(Math.toRadians(FOV) / 2), aspect = (double) W / H;
        double sx = (2 * (x + 0.5) / W - 1) * tanHalf * aspect, sy = (1 - 2 * (y + 0.5) / H) * tanHalf;
        double dx = -sx, dy = sy, dz = 1, len = Math.sqrt(dx * dx + dy * dy + dz * dz);
        dx /= len; dy /= len; dz /= len;
        double ox = 0, oy = 0, oz = -5;
        // Sphere: |o + t d - c|^2 = R^2 with |d| = 1.
        double lx = ox - CX, ly = oy - CY, lz = oz - CZ;
        double b = lx * dx + ly * dy + lz * dz, disc = b * b - (lx * lx + ly * ly + lz * lz - R * R);
        if (Math.abs(disc) < 1e-6) return null; // silhouette: either answer is right
        if (disc > 0) {
            double t = -b - Math.sqrt(disc);
            return new double[] {t, (ox + t * dx - CX) / R, (oy + t * dy - CY) / R, (oz + t * dz - CZ) / R, 0};
        }
        if (dy < -1e-9) return new double[] {(FLOOR - oy) / dy, 0, 1, 0, 1};
        return dy > 1e-9 ? new double[] {Double.POSITIVE_INFINITY, 0, 0, 0, -1} : null;
    }

    @Test
    void passesMatchTheAnalyticFirstHitAtEveryPixel() throws Exception {
        RenderResult r = Renderer.render(scene(1, EnumSet.allOf(Aov.class)), 2, ProgressListener.NONE);
        AovFrame f = r.passes().orElse(null);
        int sphere = 0, floor = 0, sky = 0;
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                double[] e = analytic(x, y);
                if (e == null) continue;
                String at = "pixel " + x + "," + y;
                assertEquals((int) e[4], f.objectId(x, y), at);
                if (e[4] < 0) {
                    sky++;
                    assertEquals(Double.POSITIVE_INFINITY, f.depth(x, y), at);
                    for (int c = 0; c < 3; c++) assertEquals(0.0, f.normal(x, y, c), at);
                    continue;
                }
                if (e[4] == 0) sphere++; else floor++;
                assertEquals(e[0], f.depth(x, y), 1e-9 * e[0], at);
                for (int c = 0; c < 3; c++) assertEquals(e[1 + c], f.normal(x, y, c), 1e-9, at);
            }
        }
        assertTrue(sphere > 100 && floor > 100 && sky > 100, sphere + " sphere, " + floor + " floor, " + sky + " sky pixels");

        // The files carry the same values (PFM stores 32-bit floats) and the ids + 1.
        Path out = dir.resolve("frame.png");
        ImageWriter.write(r.frame(), out, ImageOptions.DEFAULT, f);
        FrameBuffer depth = Images.read(dir.resolve("frame.depth.pfm"));
        FrameBuffer normal = Images.read(dir.resolve("frame.normal.pfm"));
        int[] ids = Images.read(dir.resolve("frame.object.png"), false).toRgb8(false);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                String at = "pixel " + x + "," + y;
                assertEquals((float) f.depth(x, y), (float) depth.get(x, y, 0), at);
                for (int c = 0; c < 3; c++) assertEquals((float) f.normal(x, y, c), (float) normal.get(x, y, c), at);
                assertEquals(f.objectId(x, y) + 1, ids[y * W + x], at);
                double[] e = analytic(x, y);
                if (e != null && e[4] >= 0) assertEquals(e[0], depth.get(x, y, 0), 1e-6 * e[0], at);
            }
        }
    }

    @Test
    void theFloorSeenFromBelowHasItsNormalTurnedToTheCamera() throws InterruptedException {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(3, 3).aovs(EnumSet.of(Aov.NORMAL, Aov.DEPTH)).build())
                .camera(new PinholeCamera(new Vec3(0, -4, 0), new Vec3(0, 0, 0), Vec3.Z, 30));
        b.add(new Plane(Vec3.Y, 0));
        AovFrame f = Renderer.render(b.build(), 1, ProgressListener.NONE).passes().orElse(null);
        assertEquals(-1.0, f.normal(1, 1, 1));
        assertEquals(4.0, f.depth(1, 1), 1e-12);
    }

    @Test
    void passesAreByteIdenticalForAnyThreadCountAndSampleCount() throws Exception {
        Path one = dir.resolve("one.png"), three = dir.resolve("three.png"), many = dir.resolve("many.png");
        RenderResult r1 = Renderer.render(scene(1, EnumSet.allOf(Aov.class)), 1, ProgressListener.NONE);
        RenderResult r3 = Renderer.render(scene(1, EnumSet.allOf(Aov.class)), 3, ProgressListener.NONE);
        RenderResult r9 = Renderer.render(scene(9, EnumSet.allOf(Aov.class)), 3, ProgressListener.NONE);
        ImageWriter.write(r1.frame(), one, ImageOptions.DEFAULT, r1.passes().orElse(null));
        ImageWriter.write(r3.frame(), three, ImageOptions.DEFAULT, r3.passes().orElse(null));
        ImageWriter.write(r9.frame(), many, ImageOptions.DEFAULT, r9.passes().orElse(null));
        for (Aov a : Aov.values()) {
            byte[] base = Files.readAllBytes(a.fileBeside(one));
            assertArrayEquals(base, Files.readAllBytes(a.fileBeside(three)), a + ": 1 vs 3 threads");
            // The noise pass records the samples themselves, and the albedo is their average, antialiased
            // like the image: both change with them; the others see the pixel centre only.
            if (a != Aov.NOISE && a != Aov.ALBEDO) assertArrayEquals(base, Files.readAllBytes(a.fileBeside(many)), a + ": 1 vs 9 samples per pixel");
        }
    }

    @Test
    void noPassesMeansNoFrameAndNoExtraRays() throws InterruptedException {
        RenderResult none = Renderer.render(scene(2, Set.of()), 2, ProgressListener.NONE);
        assertNull(none.passes().orElse(null));
        assertEquals((long) W * H * 2, none.stats().cameraRays());
        RenderResult with = Renderer.render(scene(2, EnumSet.of(Aov.OBJECT)), 2, ProgressListener.NONE);
        assertEquals((long) W * H * 3, with.stats().cameraRays(), "one more camera ray per pixel");
        assertEquals(EnumSet.of(Aov.OBJECT), with.passes().orElse(null).passes());
        // The main image does not change when passes are asked for.
        assertArrayEquals(none.frame().data(), with.frame().data(), 0.0);
    }
}
