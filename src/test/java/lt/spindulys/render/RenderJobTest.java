package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.concurrent.CancellationException;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

class RenderJobTest {
    @TempDir Path dir;

    private static SceneBuilder builder(boolean srgb) {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(40, 24).samplesPerPixel(2).seed(3).srgb(srgb).build())
                .camera(new PinholeCamera(new Vec3(0, 1, -4), new Vec3(0, 0.5, 0), Vec3.Y, 50))
                .light(new PointLight(new Vec3(2, 5, -3), Color.WHITE));
        b.add(new Plane(Vec3.Y, 0).material(Material.builder().kr(0.3).build()));
        b.add(new Sphere(new Vec3(0, 0.8, 0), 0.8));
        return b;
    }

    @Test
    void aJobRendersWhatTheRendererRendersAndWritesItsImageWithTheScenesEncoding() throws Exception {
        double[] direct = Renderer.render(builder(true).build(), 1, null).frame().data();
        Path out = dir.resolve("out.png");
        RenderResult r = RenderJob.of(builder(true)).output(out).run();
        assertArrayEquals(direct, r.frame().data(), 0.0);
        BufferedImage written = ImageIO.read(out.toFile());
        BufferedImage shown = r.image();
        assertEquals(40, written.getWidth());
        assertEquals(24, shown.getHeight());
        for (int y = 0; y < 24; y++) {
            for (int x = 0; x < 40; x++) assertEquals(written.getRGB(x, y), shown.getRGB(x, y), x + "," + y);
        }
        // Linear output when the scene says so: the same frame gives darker 8-bit mid-tones.
        RenderResult linear = RenderJob.of(builder(false)).run();
        assertNotEquals(shown.getRGB(20, 20), linear.image().getRGB(20, 20));
        assertEquals(r.frame().toBufferedImage(false).getRGB(20, 20), linear.image().getRGB(20, 20));
    }

    @Test
    void overridesApplyWithoutChangingTheCallersBuilder() throws Exception {
        SceneBuilder b = builder(true);
        RenderSettings before = b.settings();
        var cameraBefore = b.camera();
        RenderResult r = RenderJob.of(b).settings(s -> s.toBuilder().size(20, 12).build()).threads(1)
                .camera(c -> new PinholeCamera(new Vec3(0, 2, -4), Vec3.ZERO, Vec3.Y, 40)).run();
        assertEquals(20, r.width());
        assertEquals(12, r.height());
        assertSame(before, b.settings());
        assertSame(cameraBefore, b.camera());
    }

    @Test
    void passesAreWrittenBesideTheImageInOneGroup() throws Exception {
        Path out = dir.resolve("p.png");
        RenderResult r = RenderJob.of(builder(true)).settings(s -> s.toBuilder().aovs(EnumSet.of(Aov.DEPTH, Aov.OBJECT)).build()).output(out).run();
        assertTrue(r.passes().isPresent());
        assertTrue(Files.exists(out));
        assertTrue(Files.exists(Aov.DEPTH.fileBeside(out)));
        assertTrue(Files.exists(Aov.OBJECT.fileBeside(out)));
        assertTrue(RenderJob.of(builder(true)).run().passes().isEmpty());
    }

    @Test
    void aCancelledJobStopsAndWritesNothing() throws Exception {
        Path out = dir.resolve("c.png");
        RenderJob before = RenderJob.of(builder(true)).output(out);
        before.cancel();
        assertThrows(CancellationException.class, before::run);
        assertFalse(Files.exists(out));

        // Cancelled from its own progress report, on a thread of its own: the render stops between tiles.
        AtomicInteger reports = new AtomicInteger();
        RenderJob[] job = new RenderJob[1];
        job[0] = RenderJob.of(builder(true)).settings(s -> s.toBuilder().size(400, 240).build()).output(out).threads(1)
                .progress((done, total) -> { if (reports.incrementAndGet() == 1) job[0].cancel(); });
        Future<RenderResult> f = job[0].start();
        ExecutionException e = assertThrows(ExecutionException.class, f::get);
        assertInstanceOf(CancellationException.class, e.getCause());
        assertEquals(RenderJob.Stage.RENDER, job[0].stage());
        assertTrue(reports.get() < (400 / 16) * (240 / 16), "stopped early: " + reports.get() + " tiles");
        assertFalse(Files.exists(out));
    }

    @Test
    void anUnwritableOutputFailsBeforeTheSceneIsRead() {
        Path out = dir.resolve("missing-dir").resolve("x.png");
        RenderJob job = RenderJob.of(dir.resolve("no-such-scene.dat")).output(out);
        IOException e = assertThrows(IOException.class, job::run);
        assertEquals(RenderJob.Stage.CHECK, job.stage());
        assertTrue(e.getMessage().contains("missing-dir"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> RenderJob.of(builder(true)).output(dir.resolve("x.bmp")));
    }

    @Test
    void aJobReadsASceneFile() throws Exception {
        Path scene = dir.resolve("s.dat");
        Files.writeString(scene, """
                settings { width 16 height 10 samples 1 }
                camera { eye 0 0 -5 lookat 0 0 0 up 0 1 0 fov 40 }
                light { position 0 5 -5 color 1 1 1 }
                sphere { center 0 0 0 radius 1 }
                """);
        RenderResult r = RenderJob.of(scene).run();
        assertEquals(16, r.width());
        assertTrue(r.loadSeconds() > 0);
        assertTrue(r.buildSeconds() >= 0);
    }

    @Test
    void aJobRunsOnceAndABuiltSceneTakesNoOverrides() throws Exception {
        RenderJob job = RenderJob.of(builder(true)).threads(1);
        job.run();
        assertThrows(IllegalStateException.class, job::run);
        assertThrows(IllegalStateException.class, () -> job.threads(2));
        RenderJob built = RenderJob.of(builder(true).build());
        assertThrows(IllegalStateException.class, () -> built.settings(s -> s));
        assertEquals(40, built.progress(null).run().width());
    }

    @Test
    void checkRefusesBeforeTheBuildAndTheRunGoesOnFromIt() throws Exception {
        Path out = dir.resolve("checked.png");
        RenderJob job = RenderJob.of(builder(true)).settings(s -> s.toBuilder().size(20, 12).build()).output(out).threads(1);
        assertEquals(20, job.check().width());
        assertEquals(RenderJob.Stage.SETTINGS, job.stage());
        assertFalse(Files.exists(out), "nothing built, rendered or written");
        assertEquals(12, job.run().height());
        assertTrue(Files.exists(out));
        assertThrows(IllegalStateException.class, job::run);
        RenderJob twice = RenderJob.of(builder(true));
        twice.check();
        assertThrows(IllegalStateException.class, twice::check);
        // A region the frame has no room for is refused by the check, before anything is built.
        RenderJob outside = RenderJob.of(builder(true)).region(new lt.spindulys.image.PixelRegion(0, 400, 0, 1));
        assertThrows(IllegalArgumentException.class, outside::check);
        assertEquals(RenderJob.Stage.SETTINGS, outside.stage());
    }
}
