package lt.spindulys.cli;

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
        FrameBuffer fb = Renderer.render(JitWarmup.scene(), 1, ProgressListener.NONE).image();
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
    void closingStopsItPromptly() throws InterruptedException {
        long t0 = System.nanoTime();
        JitWarmup w = JitWarmup.start();
        w.close();
        double seconds = (System.nanoTime() - t0) / 1e9;
        // Generous: a cold JVM's first tile of the warm-up may run interpreted.
        assertTrue(seconds < 5, "close took " + seconds + " s");
    }
}
