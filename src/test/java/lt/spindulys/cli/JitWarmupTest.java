package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;

class JitWarmupTest {

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
    void closingReturnsAtOnceAndTheThreadEndsSoonAfter() throws InterruptedException {
        long t0 = System.nanoTime();
        JitWarmup w = JitWarmup.start();
        w.close();
        double seconds = (System.nanoTime() - t0) / 1e9;
        assertTrue(seconds < 0.5, "close took " + seconds + " s");
        // Generous: on a cold JVM the small scene's build and first tile run interpreted.
        assertTrue(w.ended(10_000), "the warm-up thread is still running 10 s after close");
    }

    @Test
    void aMeshSceneOnTheWideTreeWaitsForTheWarmupAndOthersDoNot() throws InterruptedException {
        JitWarmup withMesh = JitWarmup.start();
        lt.spindulys.scene.SceneBuilder meshScene = new lt.spindulys.scene.SceneBuilder().add(
                new lt.spindulys.scene.TriangleMesh(lt.spindulys.scene.TestMeshes.icosphere(2, 1)));
        withMesh.finishFor(meshScene, lt.spindulys.scene.AcceleratorKind.BVH);
        // The wait is for the vector traversal; without it (no module, or a 256-bit-less machine) nothing waits.
        assertEquals(lt.spindulys.accel.WideBvh.AVAILABLE, withMesh.ended(0), "finishFor waits exactly when the wide tree is used");

        JitWarmup otherStructure = JitWarmup.start();
        long t1 = System.nanoTime();
        otherStructure.finishFor(meshScene, lt.spindulys.scene.AcceleratorKind.BVH2);
        assertTrue((System.nanoTime() - t1) / 1e9 < 0.5, "a binary-tree scene waited for the warm-up");
        assertTrue(otherStructure.ended(10_000));

        JitWarmup withoutMesh = JitWarmup.start();
        long t0 = System.nanoTime();
        withoutMesh.finishFor(new lt.spindulys.scene.SceneBuilder().add(new lt.spindulys.scene.Sphere(lt.spindulys.math.Vec3.ZERO, 1)),
                lt.spindulys.scene.AcceleratorKind.BVH);
        double seconds = (System.nanoTime() - t0) / 1e9;
        assertTrue(seconds < 0.5, "a scene of spheres waited " + seconds + " s");
        assertTrue(withoutMesh.ended(10_000));
    }
}
