package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

class RendererTest {
    private static Scene scene(int spp) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(37, 23).samplesPerPixel(spp).seed(5).build())
                .camera(new PinholeCamera(new Vec3(0, 1, -4), new Vec3(0, 0.5, 0), Vec3.Y, 50))
                .light(new PointLight(new Vec3(2, 5, -3), Color.WHITE));
        b.add(new Plane(Vec3.Y, 0).material(Material.builder().kr(0.3).build()));
        b.add(new Sphere(new Vec3(0, 0.8, 0), 0.8).material(Material.builder().kt(0.8).ior(1.5).fresnel(true).ks(0.5).build()));
        b.add(new Sphere(new Vec3(1.2, 0.4, 0.5), 0.4));
        return b.build();
    }

    @Test
    void imageIsIdenticalForAnyThreadCount() throws InterruptedException {
        double[] one = Renderer.render(scene(5), 1, ProgressListener.NONE).frame().data();
        double[] three = Renderer.render(scene(5), 3, ProgressListener.NONE).frame().data();
        assertArrayEquals(one, three, 0.0, "bit-identical output for 1 and 3 threads");
    }

    @Test
    void countsRaysAndReportsProgressToTheEnd() throws InterruptedException {
        AtomicLong last = new AtomicLong();
        RenderResult r = Renderer.render(scene(4), 2, (done, total) -> last.accumulateAndGet(done, Math::max));
        assertEquals(37L * 23, last.get());
        RenderStats s = r.stats();
        assertEquals(37L * 23 * 4, s.cameraRays());
        assertTrue(s.shadowRays() > 0 && s.reflectionRays() > 0 && s.refractionRays() > 0, s.toString());
        assertTrue(s.seconds() > 0);
    }

    @Test
    void rejectsZeroThreads() {
        assertThrows(IllegalArgumentException.class, () -> Renderer.render(scene(1), 0, ProgressListener.NONE));
    }

    @Test
    void nearerHitKeepsItsOwnMaterialWhateverTheTestOrder() throws InterruptedException {
        for (int far = 0; far < 8; far++) { // enough objects for a BVH too; the far one comes first
            SceneBuilder b = new SceneBuilder()
                    .settings(RenderSettings.builder().size(1, 1).ambient(Color.WHITE).build())
                    .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 10));
            Material blue = Material.builder().color(new Color(0, 0, 1)).ka(1).kd(0).build();
            Material red = Material.builder().color(new Color(1, 0, 0)).ka(1).kd(0).build();
            b.add(new Sphere(new Vec3(0, 0, 3), 1).material(blue));
            for (int i = 0; i < far; i++) b.add(new Sphere(new Vec3(10 + 3 * i, 0, 0), 1).material(blue));
            b.add(new Sphere(new Vec3(0, 0, 0), 1).material(red));
            var img = Renderer.render(b.build(), 1, ProgressListener.NONE).frame();
            assertEquals(1, img.get(0, 0, 0), 1e-12, "red sphere in front");
            assertEquals(0, img.get(0, 0, 2), 1e-12);
        }
    }
}
