package lt.spindulys.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The peers' render-only figures, read from lines as the installed versions print them. */
class PeerLogsTest {
    @Test
    void embreeMeanFrameTimeFromItsBenchmarkLines() {
        String log = """
                cannot open grey.mtl
                BENCHMARK SCENE: default
                frame [  0 /   6]:   5.0469 fps (skipped)
                frame [  1 -   6]:               min =   7.5518 fps, avg =   7.6077 fps, max =   7.6605 fps, sigma = 0.0213 (0.2793%)
                BENCHMARK_RENDER_MIN 7.5518
                BENCHMARK_RENDER_AVG 8.0000
                BENCHMARK_RENDER_MAX 7.6605
                BENCHMARK_RENDER_AVG_SIGMA 0.0213
                BENCHMARK_RENDER_MRAYPS_AVG 14.0226
                """;
        assertEquals(0.125, PeerLogs.embreeFrameSeconds(log), 1e-12);
        // BENCHMARK_RENDER_AVG_SIGMA and the MRAYPS lines are not the frame rate.
        assertTrue(Double.isNaN(PeerLogs.embreeFrameSeconds("BENCHMARK_RENDER_AVG_SIGMA 0.02\nBENCHMARK_RENDER_MRAYPS_AVG 14\n")));
        assertTrue(Double.isNaN(PeerLogs.embreeFrameSeconds("")));
    }

    @Test
    void povRayTraceTimeFromItsStatistics() {
        String log = """
                Parse Time:       0 hours  0 minutes  9 seconds (9.902 seconds)
                              using 1 thread(s) with 9.871 CPU-seconds total
                Bounding Time:    0 hours  0 minutes  0 seconds (0.512 seconds)
                              using 1 thread(s) with 0.511 CPU-seconds total
                Render Time:
                  Photon Time:      No photons
                  Radiosity Time:   No radiosity
                  Trace Time:       0 hours  0 minutes  0 seconds (0.608 seconds)
                              using 2 thread(s) with 1.188 CPU-seconds total
                """;
        assertEquals(0.608, PeerLogs.povTraceSeconds(log), 1e-12);
        assertTrue(Double.isNaN(PeerLogs.povTraceSeconds("Parse Time:       0 hours  0 minutes  9 seconds (9.902 seconds)\n")));
    }

    @Test
    void cyclesSamplingTimeFromItsStatusLines() {
        String log = """
                Fra:1 Mem:9.48M (Peak 9.49M) | Time:00:00.16 | Mem:0.00M, Peak:0.00M | Scene, ViewLayer | Updating Scene BVH | Building
                Fra:1 Mem:10.13M (Peak 10.38M) | Time:00:00.17 | Mem:1.07M, Peak:1.07M | Scene, ViewLayer | Sample 0/1
                Fra:1 Mem:38.26M (Peak 66.38M) | Time:00:02.19 | Mem:15.13M, Peak:15.13M | Scene, ViewLayer | Sample 1/1
                Fra:1 Mem:38.26M (Peak 66.38M) | Time:00:02.19 | Mem:15.13M, Peak:15.13M | Scene, ViewLayer | Finished
                Saved: '/tmp/x.tga'
                 Time: 00:02.58 (Saving: 00:00.36)
                """;
        assertEquals(2.02, PeerLogs.cyclesSamplingSeconds(log), 1e-9);
        // Carriage returns (a terminal's progress) separate lines as well.
        assertEquals(2.02, PeerLogs.cyclesSamplingSeconds(log.replace('\n', '\r')), 1e-9);
        assertTrue(Double.isNaN(PeerLogs.cyclesSamplingSeconds("Fra:1 Mem:1M (Peak 1M) | Time:00:00.17 | Mem:1M | Scene, ViewLayer | Sample 0/1\n")));
    }

    @Test
    void cyclesStatusTimesWithMinutesAndHours() {
        assertEquals(61.5, PeerLogs.statusTime("Fra:1 | Time:01:01.50 | Mem:1M"), 1e-9);
        assertEquals(3723.25, PeerLogs.statusTime("Fra:1 | Time:01:02:03.25 | Mem:1M"), 1e-9);
        assertTrue(Double.isNaN(PeerLogs.statusTime("no time here")));
    }
}
