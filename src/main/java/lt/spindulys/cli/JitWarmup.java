package lt.spindulys.cli;

import java.util.ArrayDeque;
import java.util.concurrent.atomic.AtomicBoolean;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.accel.WideBvh;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.scene.TriangleMesh;

/**
 * Renders a small built-in scene (a torus of 1,024 quads on a ground quad, one point light, hard
 * shadows) again and again on a background thread while the command's thread parses the scene
 * file; before the real scene is built the command waits for it to finish or stops it
 * ({@link #finishFor}).
 *
 * <p>Why: parsing is single-threaded, so one core is idle, and a new JVM runs the first part of
 * a render in interpreted and provisionally compiled code. The vector box test suffers most: its
 * vectors are real objects until the JIT compiles the traversal, and a 2M-triangle render on a
 * cold JVM took 0.74-0.78 s instead of 0.54 s for the scalar tree (0.22 s warm). Warming up on
 * this scene's rays compiles the traversal, the triangle test, shading and shadow rays first.
 * The warm-up shares nothing with the real scene; the image is the same with or without it.
 */
final class JitWarmup implements AutoCloseable {
    /** Enough renders to compile the hot paths (measured on the 1m torus: 6 left the render slower, 40 slowed the parse). */
    private static final int MAX_RENDERS = 15;
    /** Meshes this large are walked with the wide tree (smaller ones are a few leaves). */
    private static final int MESH_TRIANGLES = 64;

    private final AtomicBoolean stop = new AtomicBoolean();
    private final Thread thread;

    private JitWarmup() {
        thread = new Thread(this::run, "spindulys-warmup");
        thread.setDaemon(true);
        thread.setPriority(Thread.MIN_PRIORITY);
    }

    /** Starts warming up on a new background thread. */
    static JitWarmup start() {
        JitWarmup w = new JitWarmup();
        w.thread.start();
        return w;
    }

    private void run() {
        try {
            Scene scene = scene();
            for (int i = 0; i < MAX_RENDERS && !stop.get(); i++) Renderer.render(scene, 1, ProgressListener.NONE);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            // Only speed depends on the warm-up; a failure here must not fail the real render.
        }
    }

    /**
     * Stops the warm-up without waiting for it: a render in progress is abandoned (its worker
     * finishes the tile it is on and exits), but building the small scene cannot be cut short
     * (about 0.1 s on a cold JVM), and the command need not wait for that. Idempotent.
     */
    @Override
    public void close() {
        stop.set(true);
        thread.interrupt();
    }

    /**
     * Waits for the warm-up to finish its renders (at most a few tenths of a second) when the
     * scene's meshes will be walked with the wide vector tree, the code it compiles, and stops it
     * otherwise. A short parse ends long before the warm-up, and a small mesh scene then rendered
     * on a cold JVM: the 2k-triangle benchmark frame in 0.72-0.78 s instead of 0.17-0.21 s after a
     * finished warm-up (whole process 1.0-1.1 s against 0.64-0.85 s); a scene of spheres, or one
     * whose structure is another ({@code accel}, the scene's or the command line's), would pay
     * up to 0.25 s for nothing.
     */
    void finishFor(SceneBuilder scene, AcceleratorKind accel) throws InterruptedException {
        if (scene.objects().stream().noneMatch(JitWarmup::hasMesh) || accel != AcceleratorKind.BVH || !WideBvh.AVAILABLE) {
            close();
            return;
        }
        thread.join();
        close();
    }

    /** Whether the warm-up thread has ended within {@code millis}, 0 for now (for tests). */
    boolean ended(long millis) throws InterruptedException {
        if (millis > 0) thread.join(millis);
        return !thread.isAlive();
    }

    private static boolean hasMesh(GObject top) {
        // A walk with its own stack: CSG nests up to Bool.MAX_NESTING levels, too deep for a
        // recursion through streams on the caller's stack.
        ArrayDeque<GObject> pending = new ArrayDeque<>();
        pending.push(top);
        while (!pending.isEmpty()) {
            GObject o = pending.pop();
            if (o instanceof TriangleMesh m && m.triangleCount() >= MESH_TRIANGLES) return true;
            if (o instanceof SubdivisionSurface) return true;
            if (o instanceof Bool b) for (GObject operand : b.operands()) pending.push(operand);
        }
        return false;
    }

    /** The benchmark's view of a small torus; 96 x 54 pixels, so one render takes a few milliseconds. */
    static Scene scene() {
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(96, 54).ambient(Color.BLACK).srgb(true).build())
                .camera(new PinholeCamera(new Vec3(0, 2.5, 3.5), new Vec3(0, -0.2, 0), Vec3.Y, 40))
                .light(new PointLight(new Vec3(3, 5, 2), Color.WHITE, 25, PointLight.Falloff.INVERSE_SQUARE));
        Material grey = Material.builder().name("warmup").color(new Color(0.8, 0.8, 0.8)).ka(0).kd(1).ks(0).build();
        b.add(new TriangleMesh(torus(32, 32)).smooth(false).material(grey));
        b.add(new TriangleMesh(new MeshData(new double[] {-20, -0.4, -20, 20, -0.4, -20, 20, -0.4, 20, -20, -0.4, 20}, null, null,
                new int[] {4}, new int[] {0, 3, 2, 1}, null, null, "warm-up ground")).smooth(false).material(grey));
        return b.build();
    }

    /** A closed torus (R 1, r 0.4, axis +Y) of n x m quads. */
    private static MeshData torus(int n, int m) {
        double[] p = new double[3 * n * m];
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n;
            for (int j = 0; j < m; j++) {
                double c = 2 * Math.PI * j / m, r = 1 + 0.4 * Math.cos(c);
                int o = 3 * (i * m + j);
                p[o] = r * Math.cos(a);
                p[o + 1] = 0.4 * Math.sin(c);
                p[o + 2] = r * Math.sin(a);
            }
        }
        int[] sizes = new int[n * m], idx = new int[4 * n * m];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < m; j++) {
                int f = i * m + j, i1 = (i + 1) % n, j1 = (j + 1) % m;
                sizes[f] = 4;
                idx[4 * f] = i * m + j;
                idx[4 * f + 1] = i * m + j1;
                idx[4 * f + 2] = i1 * m + j1;
                idx[4 * f + 3] = i1 * m + j;
            }
        }
        return new MeshData(p, null, null, sizes, idx, null, null, "warm-up torus");
    }
}
