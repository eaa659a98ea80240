package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.time.Duration;
import java.util.concurrent.CancellationException;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * The render threads' buffers sized by the samples are checked for all threads at once before
 * any starts, and a failure on one thread (an OutOfMemoryError included) stops the others within
 * the tile they are in and fails the render.
 */
class RendererMemoryTest {
    private static final long MIB = 1L << 20;

    /** Two 16-pixel tiles of sky under a disc light of 256 samples: cheap to trace, 16 MiB of strata a thread at 16384 pixel samples. */
    private static Scene sky(int spp) {
        return new SceneBuilder()
                .settings(RenderSettings.builder().size(32, 1).samplesPerPixel(spp).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 50))
                .areaLight(AreaLight.disc(new Vec3(0, 5, 0), new Vec3(0, -1, 0), 1, Color.WHITE, 1, false, 256))
                .build();
    }

    @Test
    void theThreadsSampleBuffersAreCheckedTogetherBeforeAnyStarts() throws InterruptedException {
        // One thread's buffers (16.7 MiB) fit in 24 MiB, two threads' do not. The cap is this
        // thread's: the check must be made here, for all threads at once, not by each worker
        // (which would see the whole heap, and, checking one after another, each the same free heap).
        Scene s = sky(16384);
        try (HeapBudget.Scope cap = HeapBudget.cap(24 * MIB)) {
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> Renderer.render(s, 2, ProgressListener.NONE));
            assertEquals("samples", e.key());
            assertTrue(e.getMessage().startsWith("buffering the samples of 2 render threads (samples 16384 of the settings x samples 256 of the disclight)"
                    + " needs 33 MiB of heap, but only 24 MiB is free"), e.getMessage());
            assertEquals(0, HeapBudget.reserved(), "nothing stays reserved");
            RenderResult one = Renderer.render(s, 1, ProgressListener.NONE);
            assertEquals(32L * 16384, one.stats().cameraRays());
        }
        assertEquals(0, HeapBudget.reserved(), "the reservation is released once the scratch is made");
    }

    /**
     * Tile 0 (the left half) is a sphere lit by 1024 light samples at 1024 pixel samples, a
     * million shadow rays a pixel, tens of seconds a tile; tile 1 is sky, done at once.
     */
    private static Scene heavyLeftTile() {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(32, 16).samplesPerPixel(1024).build())
                .camera(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 50))
                .areaLight(AreaLight.disc(new Vec3(-6, 8, -2), new Vec3(0, -1, 0), 1, Color.WHITE, 1, false, AreaLight.MAX_SAMPLES));
        b.add(new Sphere(new Vec3(-7, 0, 0), 6));
        return b.build();
    }

    @Test
    void aFailureOnOneThreadStopsTheOtherWithinItsTile() {
        Scene s = heavyLeftTile();
        // The sky tile's thread fails as it finishes; the other is then deep in the sphere's tile.
        TileListener failing = (fb, x0, y0, x1, y1) -> { throw new OutOfMemoryError("simulated"); };
        long t0 = System.nanoTime();
        OutOfMemoryError e = assertTimeoutPreemptively(Duration.ofSeconds(10),
                () -> assertThrows(OutOfMemoryError.class, () -> Renderer.render(s, 2, null, null, failing)));
        assertEquals("simulated", e.getMessage(), "the failure itself reaches the caller, never a finished image");
        assertTrue(System.nanoTime() - t0 < 5_000_000_000L, "the other thread stopped within its tile");
    }

    @Test
    void aCancelStopsATileMidway() {
        Scene s = heavyLeftTile();
        AtomicBoolean cancelled = new AtomicBoolean();
        Thread canceller = new Thread(() -> {
            try {
                Thread.sleep(300);
            } catch (InterruptedException e) {
                return;
            }
            cancelled.set(true);
        });
        canceller.start();
        assertTimeoutPreemptively(Duration.ofSeconds(10), () -> assertThrows(CancellationException.class, () -> Renderer.render(s, 2, null, cancelled)));
    }
}
