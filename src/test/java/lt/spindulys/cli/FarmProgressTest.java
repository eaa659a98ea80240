package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;

import lt.spindulys.render.RenderJob;

/** The lines of {@link FarmProgress}, driven by a fake clock and job step. */
class FarmProgressTest {
    private static final long S = 1_000_000_000L;

    private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
    private final AtomicReference<RenderJob.Stage> stage = new AtomicReference<>(RenderJob.Stage.READY);

    private FarmProgress sink(FarmProgress.Mode mode) { return sink(mode, 0); }

    private FarmProgress sink(FarmProgress.Mode mode, long start) {
        return new FarmProgress(mode, new PrintStream(bytes, true, StandardCharsets.UTF_8), stage::get, "out.png", start);
    }

    private List<String> lines() {
        List<String> l = bytes.toString(StandardCharsets.UTF_8).lines().toList();
        bytes.reset();
        return l;
    }

    @Test
    void openjdReportsEachStepOnceProgressEachIntervalAndTheEnd() {
        FarmProgress p = sink(FarmProgress.Mode.OPENJD);
        p.tick(0);
        assertEquals(List.of("openjd_status: starting out.png"), lines());
        stage.set(RenderJob.Stage.CHECK);
        p.tick(S / 20);
        assertEquals(List.of(), lines(), "checking the output is still starting: no second status");
        stage.set(RenderJob.Stage.LOAD);
        p.tick(S / 10);
        assertEquals(List.of("openjd_status: loading the scene for out.png"), lines());
        p.tick(S);
        assertEquals(List.of(), lines(), "nothing new, and the interval has not passed");
        p.tick(S / 10 + FarmProgress.INTERVAL_SECONDS * S);
        assertEquals(List.of("openjd_status: loading the scene for out.png"), lines(), "a sign of life every interval");
        stage.set(RenderJob.Stage.RENDER);
        p.progress(1, 3);
        p.tick(5 * S);
        assertEquals(List.of("openjd_status: rendering out.png", "openjd_progress: 33.3"), lines());
        p.progress(2999, 3000);
        p.progress(5, 3000); // a late report from another thread does not go back
        p.tick(5 * S + FarmProgress.INTERVAL_SECONDS * S);
        assertEquals(List.of("openjd_progress: 99.9"), lines(), "never 100 before the files are written");
        stage.set(RenderJob.Stage.WRITE);
        p.wrote("wrote out.png (8x8, 1 spp) in 7.0 s");
        assertEquals(List.of("openjd_progress: 100.0", "openjd_status: wrote out.png (8x8, 1 spp) in 7.0 s"), lines());
        p.tick(60 * S);
        assertEquals(List.of(), lines(), "nothing after the end");
    }

    @Test
    void severalFramesAreOnePieceOfWork() {
        FarmProgress p = sink(FarmProgress.Mode.OPENJD);
        p.item("f_0001.png", 0, 4);
        stage.set(RenderJob.Stage.RENDER);
        p.progress(1, 2);
        p.tick(0);
        assertEquals(List.of("openjd_status: rendering f_0001.png", "openjd_progress: 12.5"), lines());
        p.wrote("wrote f_0001.png");
        assertEquals(List.of("openjd_progress: 25.0", "openjd_status: wrote f_0001.png"), lines());
        p.item("f_0002.png", 1, 4);
        stage.set(RenderJob.Stage.LOAD);
        p.tick(S);
        assertEquals(List.of("openjd_status: loading the scene for f_0002.png"), lines(), "a new item's step at once");
        p.item("f_0004.png", 3, 4);
        p.wrote("wrote f_0004.png");
        assertEquals(List.of("openjd_progress: 100.0", "openjd_status: wrote f_0004.png"), lines());
        p.tick(100 * S);
        assertEquals(List.of(), lines(), "the last item ends the reports");

        FarmProgress plain = sink(FarmProgress.Mode.PLAIN);
        plain.item("f_0003.png", 2, 4);
        stage.set(RenderJob.Stage.RENDER);
        plain.progress(1, 2);
        plain.tick(10 * S);
        assertEquals(List.of("render: rendering f_0003.png (3 of 4), 62% done, 0:10 elapsed, about 0:06 to go"), lines());
    }

    @Test
    void openjdFailureIsOneFailLine() {
        FarmProgress p = sink(FarmProgress.Mode.OPENJD);
        p.tick(0);
        lines();
        p.failed("scene.dat:3:5: expected a number\nnext");
        assertEquals(List.of("openjd_fail: scene.dat:3:5: expected a number\\nnext"), lines());
    }

    @Test
    void plainLinesSayTheStepTheShareAndTheTimes() {
        FarmProgress p = sink(FarmProgress.Mode.PLAIN);
        p.tick(0);
        assertEquals(List.of("render: starting out.png, 0:00 elapsed"), lines());
        stage.set(RenderJob.Stage.BUILD);
        p.tick(3 * S);
        assertEquals(List.of("render: building the scene for out.png, 0:03 elapsed"), lines());
        stage.set(RenderJob.Stage.RENDER);
        p.progress(1, 4);
        p.tick(10 * S);
        assertEquals(List.of("render: rendering out.png, 25% done, 0:10 elapsed, about 0:30 to go"), lines());
        p.tick(11 * S);
        assertEquals(List.of(), lines());
        p.tick(12 * S);
        assertEquals(1, lines().size(), "one line every " + FarmProgress.INTERVAL_SECONDS + " s");
        p.failed("boom");
        assertEquals(List.of(), lines(), "the command line prints the error itself");
    }

    @Test
    void theThreadPrintsWithoutBeingAsked() throws InterruptedException {
        FarmProgress p = sink(FarmProgress.Mode.PLAIN, System.nanoTime());
        p.start();
        assertEquals(1, lines().size(), "the first line at once");
        stage.set(RenderJob.Stage.LOAD);
        long until = System.nanoTime() + 5 * S;
        List<String> seen = List.of();
        while (seen.isEmpty() && System.nanoTime() < until) {
            Thread.sleep(20);
            seen = lines();
        }
        p.close();
        assertTrue(!seen.isEmpty() && seen.get(0).matches("render: loading the scene for out\\.png, 0:0\\d elapsed"), seen.toString());
    }
}
