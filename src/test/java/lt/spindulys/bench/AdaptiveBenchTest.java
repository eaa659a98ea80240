package lt.spindulys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.scene.TriangleMesh;

/** The adaptive bench rows' inputs and readings (the rows themselves are timed only by render bench). */
class AdaptiveBenchTest {
    @Test
    void cagesAreTheStatedSizesAndTheTorusIsClosed(@TempDir Path dir) throws IOException {
        StringBuilder torus = new StringBuilder(), hills = new StringBuilder();
        AdaptiveBench.writeTorusCage(torus, AdaptiveBench.CLOSE_RING, AdaptiveBench.CLOSE_TUBE);
        AdaptiveBench.writeHillsCage(hills, AdaptiveBench.HUGE_CELLS, AdaptiveBench.HUGE_HALF);
        Files.writeString(dir.resolve("t.obj"), torus);
        Files.writeString(dir.resolve("h.obj"), hills);
        TriangleMesh t = new TriangleMesh(ObjReader.read(dir.resolve("t.obj")));
        assertEquals(2 * AdaptiveBench.CLOSE_RING * AdaptiveBench.CLOSE_TUBE, t.triangleCount());
        assertTrue(t.isClosed());
        assertEquals(0, t.degenerateCount());
        TriangleMesh h = new TriangleMesh(ObjReader.read(dir.resolve("h.obj")));
        assertEquals(2 * AdaptiveBench.HUGE_CELLS * AdaptiveBench.HUGE_CELLS, h.triangleCount());
        // Deterministic: the same text every time.
        StringBuilder again = new StringBuilder();
        AdaptiveBench.writeTorusCage(again, AdaptiveBench.CLOSE_RING, AdaptiveBench.CLOSE_TUBE);
        assertEquals(torus.toString(), again.toString());
    }

    /** The scenes are what the rows claim: level 6 or more at full HD close up, and an eager tessellation beyond 2 GiB. */
    @Test
    void scenesNeedWhatTheTableClaims() throws IOException {
        AdaptiveBench a = new AdaptiveBench(1, 1, new PrintStream(PrintStream.nullOutputStream()), "lt.spindulys.cli.Main");
        try {
            AdaptiveBench.Need close = a.need("close", AdaptiveBench.CLOSE_FRONT, 1920, 1080);
            int deepest = 0;
            for (int l = 0; l < close.levelHistogram().length; l++) if (close.levelHistogram()[l] > 0) deepest = l;
            assertTrue(deepest >= 6, close.levels());
            assertEquals(AdaptiveBench.CLOSE_RING * AdaptiveBench.CLOSE_TUBE, close.faces());
            AdaptiveBench.Need small = a.need("close", AdaptiveBench.CLOSE_FRONT, 150, 100);
            assertTrue(small.quads() < close.quads() / 16, small.levels() + " against " + close.levels());
            AdaptiveBench.Need huge = a.need("huge", AdaptiveBench.HUGE_VIEW, 1920, 1080);
            assertTrue(huge.patchBytes() > 2L << 30, huge.patchBytes() + " bytes");
            assertTrue(a.need("close", AdaptiveBench.CLOSE_GRAZING, 640, 360).quads() > 0);
        } finally {
            a.close();
        }
    }

    @Test
    void liveHeapIsTheLargestOccupancyAfterACollection(@TempDir Path dir) throws IOException {
        Path log = dir.resolve("gc.log");
        Files.write(log, Arrays.asList(
                "[0.010s][info][gc] Using Parallel",
                "[0.512s][info][gc] GC(0) Pause Young (Allocation Failure) 64M->12M(245M) 5.123ms",
                "[1.020s][info][gc] GC(1) Pause Full (Ergonomics) 900M->1G(2048M) 80.0ms",
                "[1.500s][info][gc] GC(2) Pause Young (Allocation Failure) 1200M->512K(2048M) 1.0ms"));
        assertEquals(1024.0, AdaptiveBench.liveAfterGcMiB(log));
        assertTrue(Double.isNaN(AdaptiveBench.liveAfterGcMiB(dir.resolve("none.log"))));
    }
}
