package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.accel.WideBvh;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.scene.TriangleMesh;

/**
 * The warm-up's behaviour, seen through its state (renders done, thread ended) and a stand-in
 * render that blocks until the test lets it go; nothing here is timed. The timeout only keeps a
 * broken build (a close that waits on a render that never ends) from hanging the suite.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class JitWarmupTest {

    private static final SceneBuilder MESH_SCENE = new SceneBuilder().add(new TriangleMesh(TestMeshes.icosphere(2, 1)));
    private static final SceneBuilder SPHERE_SCENE = new SceneBuilder().add(new Sphere(Vec3.ZERO, 1));

    /** A render that waits, deaf to interrupts, until released; it records that it was interrupted. */
    private static final class HeldRender implements JitWarmup.Work {
        final CountDownLatch entered = new CountDownLatch(1);
        final CountDownLatch release = new CountDownLatch(1);
        final AtomicBoolean interrupted = new AtomicBoolean();

        @Override
        public void render() {
            entered.countDown();
            while (true) {
                try {
                    release.await();
                    // An interrupt that lands after await's own check but before the latch
                    // opens leaves only the flag (await then returns normally).
                    if (Thread.currentThread().isInterrupted()) interrupted.set(true);
                    return;
                } catch (InterruptedException e) {
                    interrupted.set(true);
                }
            }
        }
    }

    @Test
    void theWarmupSceneExercisesHitsMissesAndShadows() throws InterruptedException {
        // Its failures are swallowed at run time, so check here that it really renders a lit
        // torus, its shadow on the ground, and background above the horizon.
        FrameBuffer fb = Renderer.render(JitWarmup.scene(), 1, ProgressListener.NONE).frame();
        int lit = 0, dark = 0;
        for (int y = 0; y < 54; y++) {
            for (int x = 0; x < 96; x++) {
                double v = fb.get(x, y, 0);
                if (v > 0.05) lit++;
                else dark++;
            }
        }
        assertTrue(lit > 1000, "lit pixels: " + lit);
        assertTrue(dark > 100, "unlit pixels (shadow, background): " + dark);
    }

    @Test
    void theImageIsTheSameWhileTheWarmupRenders() throws InterruptedException {
        // The warm-up shares nothing with the real scene: rendered while it runs, on both cores,
        // the image is bit for bit the one rendered alone (what the command promises, untimed).
        Scene scene = new SceneBuilder()
                .settings(RenderSettings.builder().size(160, 90).ambient(Color.BLACK).build())
                .camera(new PinholeCamera(new Vec3(0, 1, 4), Vec3.ZERO, Vec3.Y, 40))
                .light(new PointLight(new Vec3(3, 5, 2), Color.WHITE, 25, PointLight.Falloff.INVERSE_SQUARE))
                .add(new TriangleMesh(TestMeshes.icosphere(4, 1)))
                .add(new Sphere(new Vec3(1.5, 0, 0), 0.5))
                .build();
        double[] alone = Renderer.render(scene, 2, ProgressListener.NONE).frame().data();
        JitWarmup w = JitWarmup.start();
        try {
            for (int i = 0; i < 3; i++) {
                assertArrayEquals(alone, Renderer.render(scene, 2, ProgressListener.NONE).frame().data(), "render " + i + " beside the warm-up");
            }
        } finally {
            w.close();
            w.join();
        }
        assertArrayEquals(alone, Renderer.render(scene, 2, ProgressListener.NONE).frame().data(), "after the warm-up");
    }

    @Test
    void theGridSceneRendersItsAdaptiveSurfaceInGrids() throws InterruptedException {
        // The grid warm-up must reach the grid path: an adaptive surface tessellated by rates, lit, with pieces built.
        Scene s = JitWarmup.gridScene();
        FrameBuffer fb = Renderer.render(s, 1, ProgressListener.NONE).frame();
        int lit = 0;
        for (int y = 0; y < 54; y++) for (int x = 0; x < 96; x++) if (fb.get(x, y, 0) > 0.05) lit++;
        assertTrue(lit > 500, "lit pixels: " + lit);
        String stats = String.join("\n", s.adaptiveStatistics());
        assertTrue(stats.contains("edge rates") && !stats.contains("patches 0 built"), stats);
    }

    @Test
    void aSceneWithGridsTurnsTheRemainingRendersToTheGridScene() throws InterruptedException {
        java.util.concurrent.atomic.AtomicInteger asked = new java.util.concurrent.atomic.AtomicInteger();
        JitWarmup.Work work = new JitWarmup.Work() {
            @Override public void render() {}
            @Override public void wantGrids() { asked.incrementAndGet(); }
        };
        JitWarmup w = JitWarmup.start(work);
        w.finishFor(MESH_SCENE, AcceleratorKind.BVH);
        assertEquals(0, asked.get(), "a mesh scene keeps the mesh warm-up");
        SceneBuilder grids = new SceneBuilder().add(new lt.spindulys.scene.AdaptiveSubdivisionSurface(
                lt.spindulys.subdiv.ControlMesh.builder(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, new int[] {4}, new int[] {0, 1, 2, 3}).build(),
                lt.spindulys.scene.AdaptiveSubdivisionSurface.Method.LAZY, true));
        JitWarmup w2 = JitWarmup.start(work);
        w2.finishFor(grids, AcceleratorKind.BVH);
        assertEquals(1, asked.get(), "a scene with grids asks for the grid warm-up");
    }

    @Test
    void leftAloneTheWarmupRendersItsBudgetAndEnds() throws InterruptedException {
        JitWarmup w = JitWarmup.start();
        w.join();
        assertEquals(JitWarmup.MAX_RENDERS, w.renders(), "renders of the built-in scene");
    }

    @Test
    void closingInterruptsTheRenderInProgressWithoutWaitingAndStartsNoOther() throws InterruptedException {
        HeldRender held = new HeldRender();
        JitWarmup w = JitWarmup.start(held);
        held.entered.await();
        w.close();
        // close has returned while the render it stopped is still held: it did not wait for it.
        assertFalse(w.ended(), "the warm-up ended before its render was released");
        held.release.countDown();
        w.join();
        // Read after the join: the warm-up thread may not have run between close and here.
        assertTrue(held.interrupted.get(), "close interrupts the render in progress");
        assertEquals(1, w.renders(), "renders after close");
    }

    @Test
    void onlyAMeshSceneOnTheWideTreeWaitsForTheWarmup() {
        // The wait is for the vector traversal; without it (no module, or a 256-bit-less machine) nothing waits.
        assertEquals(WideBvh.AVAILABLE, JitWarmup.waitsFor(MESH_SCENE, AcceleratorKind.BVH));
        assertFalse(JitWarmup.waitsFor(MESH_SCENE, AcceleratorKind.BVH2), "a binary-tree scene");
        assertFalse(JitWarmup.waitsFor(SPHERE_SCENE, AcceleratorKind.BVH), "a scene of spheres");
    }

    @Test
    void finishForStopsTheWarmupWithoutWaitingWhenTheSceneDoesNotNeedIt() throws InterruptedException {
        for (SceneBuilder scene : new SceneBuilder[] {SPHERE_SCENE, MESH_SCENE}) {
            AcceleratorKind accel = scene == MESH_SCENE ? AcceleratorKind.BVH2 : AcceleratorKind.BVH;
            HeldRender held = new HeldRender();
            JitWarmup w = JitWarmup.start(held);
            held.entered.await();
            w.finishFor(scene, accel);
            assertFalse(w.ended(), accel + ": finishFor waited for a render in progress");
            held.release.countDown();
            w.join();
            assertEquals(1, w.renders(), accel + ": renders after finishFor");
        }
    }

    @Test
    void finishForWaitsForEveryRenderWhenTheSceneNeedsIt() throws InterruptedException {
        assumeTrue(WideBvh.AVAILABLE, "the wide vector tree is not available here");
        HeldRender held = new HeldRender();
        JitWarmup w = JitWarmup.start(held);
        held.entered.await();
        Thread caller = new Thread(() -> {
            try {
                w.finishFor(MESH_SCENE, AcceleratorKind.BVH);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        caller.start();
        // The caller parks in a join on the warm-up thread (WAITING) or, if it did not wait, ends.
        Thread.State state;
        while ((state = caller.getState()) != Thread.State.WAITING && state != Thread.State.TERMINATED) Thread.onSpinWait();
        assertEquals(Thread.State.WAITING, state, "finishFor returned while the warm-up was rendering");
        held.release.countDown();
        caller.join();
        assertTrue(w.ended());
        assertEquals(JitWarmup.MAX_RENDERS, w.renders(), "the warm-up was stopped instead of finished");
        assertFalse(held.interrupted.get(), "the warm-up was interrupted");
    }
}
