package lt.spindulys.render;

import java.util.ArrayDeque;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.accel.WideBvh;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.scene.TriangleMesh;

/**
 * Renders a small built-in scene (a torus of 1,024 quads on a ground quad, one point light, hard
 * shadows) again and again on a background thread while the caller's thread parses the scene
 * file; before the real scene is built the caller waits for it to finish or stops it
 * ({@link #finishFor}). For a program that starts a JVM to render one scene, as the command line
 * does: {@code try (JitWarmup warm = JitWarmup.start()) { ...parse...; warm.finishFor(builder,
 * accelerator); ...build and render... }}.
 *
 * <p>Why: a new JVM runs the first part of a render in interpreted and provisionally compiled
 * code. The warm-up was added while the parse left a core idle; a large OBJ is now parsed on
 * every core (ObjReader): the warm-up now slows that parse, but it speeds the cold build and
 * render more, a small net gain in alternated cold renders of the 1m torus (docs/performance.md,
 * OBJ parsing). The vector box test suffers most: its
 * vectors are real objects until the JIT compiles the traversal, so on a cold JVM a large mesh
 * renders slower with the wide tree than with the scalar one, and several times slower than warm
 * (docs/performance.md, the wide vector BVH). Warming up on this scene's rays compiles the
 * traversal, the triangle test, shading and shadow rays first.
 * The warm-up shares nothing with the real scene; the image is the same with or without it.
 */
public final class JitWarmup implements AutoCloseable {
    /**
     * Enough renders to compile the hot paths, few enough to end within a large scene's parse
     * (fewer left the render slower, many more slowed the parse; see docs/performance.md).
     */
    static final int MAX_RENDERS = 15;
    /** Meshes this large are walked with the wide tree (smaller ones are a few leaves). */
    private static final int MESH_TRIANGLES = 64;

    /** One warm-up render; a seam so that tests can see what the warm-up does without timing it. */
    @FunctionalInterface
    interface Work {
        void render() throws InterruptedException;

        /** From now on warm the grid path of adaptive surfaces rather than the mesh path. */
        default void wantGrids() {}
    }

    private final AtomicBoolean stop = new AtomicBoolean();
    private final AtomicInteger renders = new AtomicInteger();
    private final Work work;
    private final Thread thread;

    private JitWarmup(Work work) {
        this.work = work;
        thread = new Thread(this::run, "spindulys-warmup");
        thread.setDaemon(true);
        thread.setPriority(Thread.MIN_PRIORITY);
    }

    /**
     * Starts warming up on a new background thread.
     *
     * @return the warm-up, to be finished ({@link #finishFor}) or closed before the real scene is built
     */
    public static JitWarmup start() {
        return start(new SceneRenders());
    }

    /** Starts {@code work}, at most {@link #MAX_RENDERS} times, on a new background thread (tests give their own). */
    static JitWarmup start(Work work) {
        JitWarmup w = new JitWarmup(work);
        w.thread.start();
        return w;
    }

    private void run() {
        try {
            for (int i = 0; i < MAX_RENDERS && !stop.get(); i++) {
                work.render();
                renders.incrementAndGet();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            // Only speed depends on the warm-up; a failure here must not fail the real render.
        }
    }

    /**
     * The real work: the built-in scenes, each built on the warm-up thread at its first render,
     * rendered on one thread: the mesh scene until the real scene turns out to hold adaptive
     * surfaces, then the grid scene (their code: evaluation, pieces, the grid traversal).
     */
    private static final class SceneRenders implements Work {
        private Scene meshes;
        private volatile boolean wantGrids;

        @Override
        public void render() throws InterruptedException {
            if (wantGrids) {
                Renderer.render(gridScene(), 1, ProgressListener.NONE);
            } else {
                if (meshes == null) meshes = scene();
                Renderer.render(meshes, 1, ProgressListener.NONE);
            }
        }

        @Override
        public void wantGrids() { wantGrids = true; }
    }

    /**
     * Stops the warm-up without waiting for it: a render in progress is abandoned (its worker
     * finishes the tile it is on and exits), but building the small scene cannot be cut short,
     * and the command need not wait for that. Idempotent.
     */
    @Override
    public void close() {
        stop.set(true);
        thread.interrupt();
    }

    /**
     * Waits for the warm-up to finish its renders when the scene's meshes will be walked with the
     * wide vector tree, the code it compiles, and stops it otherwise. A short parse ends long
     * before the warm-up, and a small mesh scene then rendered on a cold JVM took several times
     * as long as after a finished warm-up, more than the wait; a scene of spheres, or one whose
     * structure is another ({@code accel}, the scene's or the command line's), would wait for
     * nothing (figures in docs/performance.md, the wide vector BVH).
     *
     * @param scene the scene as read, before it is built
     * @param accel the structure it will be built with
     * @throws InterruptedException when interrupted while waiting ({@link #close} then stops the warm-up)
     */
    public void finishFor(SceneBuilder scene, AcceleratorKind accel) throws InterruptedException {
        // The renders still to come warm what the scene will run: the grids of its adaptive surfaces.
        if (scene.objects().stream().anyMatch(JitWarmup::hasGrids)) work.wantGrids();
        if (waitsFor(scene, accel)) thread.join();
        close();
    }

    /** Whether {@link #finishFor} waits for the warm-up: the scene has a mesh walked with the wide vector tree. */
    static boolean waitsFor(SceneBuilder scene, AcceleratorKind accel) {
        return accel == AcceleratorKind.BVH && WideBvh.AVAILABLE && scene.objects().stream().anyMatch(JitWarmup::hasMesh);
    }

    /** Whether the warm-up thread has ended (for tests). */
    boolean ended() {
        return !thread.isAlive();
    }

    /** Waits until the warm-up thread has ended (for tests). */
    void join() throws InterruptedException {
        thread.join();
    }

    /** Renders finished so far (for tests). */
    int renders() {
        return renders.get();
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
            if (hasGrids(o)) return true;
            if (o instanceof Bool b) for (GObject operand : b.operands()) pending.push(operand);
        }
        return false;
    }

    /** Whether the scene holds an adaptive surface tessellated in grids (at any depth of CSG). */
    private static boolean hasGrids(GObject top) {
        ArrayDeque<GObject> pending = new ArrayDeque<>();
        pending.push(top);
        while (!pending.isEmpty()) {
            GObject o = pending.pop();
            if (o instanceof AdaptiveSubdivisionSurface a && a.levels() == AdaptiveSubdivisionSurface.Levels.RATE) return true;
            if (o instanceof Bool b) for (GObject operand : b.operands()) pending.push(operand);
        }
        return false;
    }

    /** The benchmark's view of a small torus; 96 x 54 pixels, so that the renders are short beside a large parse. */
    static Scene scene() {
        return view(new TriangleMesh(torus(32, 32, 0)).smooth(false));
    }

    /** The same view of a small cage as an adaptive surface (grids), for scenes that have them; built anew each time, so evaluation and piece building warm too. */
    static Scene gridScene() {
        MeshData cage = torus(8, 8, 0);
        return view(new AdaptiveSubdivisionSurface(ControlMesh.builder(cage.positions(), cage.faceSizes(), cage.vertexIndex()).build(),
                AdaptiveSubdivisionSurface.Method.LAZY, true));
    }

    /** {@code object} on the benchmark's ground, under its light, seen by its camera, all grey. */
    private static Scene view(GObject object) {
        Material grey = Material.builder().name("warmup").color(new Color(0.8, 0.8, 0.8)).ka(0).kd(1).ks(0).build();
        return new SceneBuilder()
                .settings(RenderSettings.builder().size(96, 54).ambient(Color.BLACK).srgb(true).build())
                .camera(new PinholeCamera(new Vec3(0, 2.5, 3.5), new Vec3(0, -0.2, 0), Vec3.Y, 40))
                .light(new PointLight(new Vec3(3, 5, 2), Color.WHITE, 25, PointLight.Falloff.INVERSE_SQUARE))
                .add(object.material(grey))
                .add(new TriangleMesh(new MeshData(new double[] {-20, -0.4, -20, 20, -0.4, -20, 20, -0.4, 20, -20, -0.4, 20}, null, null,
                        new int[] {4}, new int[] {0, 3, 2, 1}, null, null, "warm-up ground")).smooth(false).material(grey))
                .build();
    }

    /** A closed torus (R 1, r 0.4, axis +Y, centre at z = dz) of n x m quads. */
    private static MeshData torus(int n, int m, double dz) {
        double[] p = new double[3 * n * m];
        for (int i = 0; i < n; i++) {
            double a = 2 * Math.PI * i / n;
            for (int j = 0; j < m; j++) {
                double c = 2 * Math.PI * j / m, r = 1 + 0.4 * Math.cos(c);
                int o = 3 * (i * m + j);
                p[o] = r * Math.cos(a);
                p[o + 1] = 0.4 * Math.sin(c);
                p[o + 2] = r * Math.sin(a) + dz;
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
