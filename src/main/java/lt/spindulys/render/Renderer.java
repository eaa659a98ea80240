package lt.spindulys.render;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;

import lt.spindulys.camera.Camera;
import lt.spindulys.image.AovFrame;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.math.Ray;
import lt.spindulys.sampling.PixelSampler;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.shading.TracerScratch;
import lt.spindulys.shading.WhittedIntegrator;

/**
 * Renders a frozen scene on several threads. The image is cut into square tiles handed out from
 * an atomic counter; each thread has its own sampler and scratch, and every sample is seeded from
 * its pixel, so the result is the same for any thread count. When the settings ask for render
 * passes ({@link RenderSettings#aovs()}), each pixel gets one more camera ray for them; otherwise
 * nothing is traced or stored for them.
 */
public final class Renderer {
    /** Tile side in pixels: small enough to balance two cores, large enough to keep counters cheap. */
    static final int TILE = 16;

    private Renderer() {}

    /**
     * The finished frame and what it cost.
     *
     * @param aovs the render passes the scene's settings ask for, or null when they ask for none
     */
    public record Result(FrameBuffer image, RenderStats stats, AovFrame aovs) {}

    /**
     * Renders {@code scene} with {@code threads} threads (at least 1), reporting progress.
     * Interrupting the calling thread stops the workers and throws InterruptedException.
     */
    public static Result render(Scene scene, int threads, ProgressListener progress) throws InterruptedException {
        if (threads < 1) throw new IllegalArgumentException("threads must be at least 1, found " + threads);
        RenderSettings st = scene.settings();
        int w = st.width(), h = st.height();
        FrameBuffer fb = new FrameBuffer(w, h);
        AovFrame aovs = st.aovs().isEmpty() ? null : new AovFrame(w, h, st.aovs());
        int tilesX = (w + TILE - 1) / TILE, tilesY = (h + TILE - 1) / TILE, tiles = tilesX * tilesY;
        WhittedIntegrator integrator = new WhittedIntegrator(scene);
        AtomicInteger nextTile = new AtomicInteger();
        AtomicLong donePixels = new AtomicLong();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        long[][] counters = new long[threads][];
        long start = System.nanoTime();

        Thread[] workers = new Thread[Math.min(threads, tiles)];
        for (int k = 0; k < workers.length; k++) {
            int index = k;
            workers[k] = new Thread(() -> {
                TracerScratch scratch = integrator.newScratch();
                PixelSampler sampler = new PixelSampler(st.samplesPerPixel(), scene.camera().lensPattern());
                Ray ray = new Ray();
                double[] colour = new double[4];
                try {
                    for (int t; (t = nextTile.getAndIncrement()) < tiles && failure.get() == null; ) {
                        if (Thread.currentThread().isInterrupted()) return;
                        int x0 = (t % tilesX) * TILE, y0 = (t / tilesX) * TILE;
                        int x1 = Math.min(x0 + TILE, w), y1 = Math.min(y0 + TILE, h);
                        renderTile(scene.camera(), integrator, st, sampler, scratch, ray, colour, fb, aovs, x0, y0, x1, y1);
                        progress.progress(donePixels.addAndGet((long) (x1 - x0) * (y1 - y0)), (long) w * h);
                    }
                } catch (Throwable e) {
                    failure.compareAndSet(null, e);
                } finally {
                    counters[index] = new long[] {scratch.cameraRays, scratch.shadowRays, scratch.reflectionRays, scratch.refractionRays};
                }
            }, "spindulys-render-" + k);
            workers[k].start();
        }
        try {
            for (Thread worker : workers) worker.join();
        } catch (InterruptedException e) {
            for (Thread worker : workers) worker.interrupt();
            throw e;
        }
        Throwable f = failure.get();
        if (f instanceof RuntimeException re) throw re;
        if (f instanceof Error err) throw err;
        if (f != null) throw new IllegalStateException(f);
        double seconds = (System.nanoTime() - start) / 1e9;
        long[] sum = new long[4];
        for (long[] c : counters) if (c != null) for (int i = 0; i < 4; i++) sum[i] += c[i];
        return new Result(fb, new RenderStats(sum[0], sum[1], sum[2], sum[3], seconds), aovs);
    }

    private static void renderTile(Camera camera, WhittedIntegrator integrator, RenderSettings st, PixelSampler sampler,
                                   TracerScratch scratch, Ray ray, double[] colour, FrameBuffer fb, AovFrame aovs,
                                   int x0, int y0, int x1, int y1) {
        int w = st.width(), h = st.height(), n = sampler.samplesPerPixel();
        double aspect = st.aspect();
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                sampler.startPixel(st.seed(), x, y);
                double r = 0, g = 0, b = 0;
                for (int i = 0; i < n; i++) {
                    camera.generateRay(sampler.filmX(i) / w, sampler.filmY(i) / h, aspect,
                            sampler.lensU(i), sampler.lensV(i), sampler.time(i), ray);
                    integrator.traceCamera(ray, scratch, colour);
                    r += colour[0]; g += colour[1]; b += colour[2];
                }
                fb.set(x, y, r / n, g / n, b / n);
                if (aovs != null) {
                    // One more ray, through the exact pixel centre from the lens centre at time 0,
                    // so the passes do not depend on the sample pattern.
                    camera.generateRay((x + 0.5) / w, (y + 0.5) / h, aspect, 0, 0, 0, ray);
                    int id = integrator.traceFirstHit(ray, scratch, colour);
                    if (id < 0) aovs.setBackground(x, y);
                    else aovs.setHit(x, y, colour[0], colour[1], colour[2], colour[3], id);
                }
            }
        }
    }
}
