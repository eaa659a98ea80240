package lt.spindulys.accel;

import java.util.Random;

import lt.spindulys.accel.GridTestSurfaces.Reference;
import lt.spindulys.math.Ray;

/**
 * A micro benchmark, not a test (run by hand): build time, rays per second and bytes per triangle of a
 * {@link GridPatch} (for several leaf sizes) against today's per-patch route, a binary SAH {@link Bvh} over the same
 * triangles collapsed into a {@link WideBvh}, on bumpy grids of 17 x 17 (one cache piece), 65 x 65 and 257 x 257 vertices. One thread.
 *
 * <pre>
 * mvn -q -o test-compile
 * java --add-modules jdk.incubator.vector -cp target/classes:target/test-classes lt.spindulys.accel.GridPatchBenchmark
 * </pre>
 */
public final class GridPatchBenchmark {
    private GridPatchBenchmark() {}

    private static final int RAYS = 1 << 14;
    private static final int[] LEAVES = {2, 3, 5, 9, 17};

    public static void main(String[] args) {
        // the builders compiled first, so that the first build timed is not the interpreter's
        double[] small = GridTestSurfaces.bumpy(33, 33);
        for (int leaf : LEAVES) for (int i = 0; i < 500; i++) new GridPatch(33, 33, small, null, null, leaf);
        PrimitiveSet smallSet = new Reference(new GridPatch(33, 33, small, null, null, 3)).set();
        for (int i = 0; i < 100; i++) WideBvh.widen(new Bvh(smallSet, Bvh.DEFAULT_LEAF_SIZE, false));
        for (int n : new int[] {17, 65, 257}) {
            bench(n);
        }
    }

    private static void bench(int n) {
        double[] xyz = GridTestSurfaces.bumpy(n, n);
        float[] f = new float[xyz.length];
        for (int k = 0; k < f.length; k++) f[k] = (float) xyz[k];
        int tris = 2 * (n - 1) * (n - 1);
        System.out.printf("%n%d x %d vertices, %d triangles%n", n, n, tris);
        double[][] rays = {rays(new Random(1), false, n), rays(new Random(2), true, n)};
        String[] rayNames = {"down", "grazing"};

        Reference ref = new Reference(new GridPatch(n, n, f, null, null, 0, 0, 1, 1, 5));
        PrimitiveSet set = ref.set();
        int reps = n > 100 ? 30 : n > 20 ? 100 : 1000;
        Accelerator[] bvh = new Accelerator[1];
        long bvhBuild = best(reps, () -> bvh[0] = WideBvh.widen(new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, false)));
        Accelerator bin = new Bvh(set, Bvh.DEFAULT_LEAF_SIZE, false);
        // today's PatchTriangles: 96 + 12 B of position indices per triangle + 24 B per double vertex + the structure
        long bvhBytes = 96 + 12L * tris + 24L * n * n + bvh[0].memoryBytes();
        System.out.printf("%-22s build %8.1f us  %6.1f B/tri (positions, indices, structure; +%.1f B/tri with per-vertex normals)%n",
                "wide BVH (today)", bvhBuild / 1e3, (double) bvhBytes / tris, (12.0 * tris + 24.0 * n * n) / tris);
        report("wide BVH (today)", rays, rayNames, (r, h, c) -> bvh[0].intersect(r, h, c), (r, c) -> bvh[0].occluded(r, c));
        report("binary BVH (fallback)", rays, rayNames, (r, h, c) -> bin.intersect(r, h, c), (r, c) -> bin.occluded(r, c));

        for (int leaf : LEAVES) {
            GridPatch[] g = new GridPatch[1];
            long build = best(reps, () -> g[0] = new GridPatch(n, n, f, null, null, 0, 0, 1, 1, leaf));
            long buildFromDouble = best(reps, () -> new GridPatch(n, n, xyz, null, null, leaf));
            String name = "grid, leaves " + leaf + "x" + leaf;
            System.out.printf("%-22s build %8.1f us (%.1f from doubles)  %6.1f B/tri (+%.1f B/tri with float normals), %d nodes%n",
                    name, build / 1e3, buildFromDouble / 1e3, (double) g[0].bytes() / tris, 12.0 * n * n / tris, g[0].nodeCount());
            report(name, rays, rayNames, (r, h, c) -> g[0].intersect(r, h, c), (r, c) -> g[0].occluded(r, c));
        }
    }

    private interface Closest { boolean run(Ray r, PrimitiveHit h, TraversalScratch c); }
    private interface Any { boolean run(Ray r, TraversalScratch c); }

    private static void report(String name, double[][] rays, String[] rayNames, Closest closest, Any any) {
        StringBuilder sb = new StringBuilder(String.format("%-22s", name));
        for (int s = 0; s < rays.length; s++) {
            double[] set = rays[s];
            Ray r = new Ray();
            PrimitiveHit h = new PrimitiveHit();
            TraversalScratch ctx = new TraversalScratch();
            int[] hits = new int[1];
            long tc = best(9, () -> {
                for (int k = 0; k < set.length; k += 6) {
                    r.set(set[k], set[k + 1], set[k + 2], set[k + 3], set[k + 4], set[k + 5], 0, Double.POSITIVE_INFINITY);
                    if (closest.run(r, h, ctx)) hits[0]++;
                }
            });
            long ta = best(9, () -> {
                for (int k = 0; k < set.length; k += 6) {
                    r.set(set[k], set[k + 1], set[k + 2], set[k + 3], set[k + 4], set[k + 5], 0, Double.POSITIVE_INFINITY);
                    if (any.run(r, ctx)) hits[0]++;
                }
            });
            int count = set.length / 6;
            sb.append(String.format("  %s: closest %5.2f Mrays/s, any %5.2f Mrays/s", rayNames[s], count * 1e3 / tc, count * 1e3 / ta));
        }
        System.out.println(sb);
    }

    /** Rays at the grid: from above at random points of it, or from the side at grazing angles. */
    private static double[] rays(Random rnd, boolean grazing, int n) {
        double[] r = new double[6 * RAYS];
        for (int k = 0; k < r.length; k += 6) {
            double tx = rnd.nextDouble(), ty = rnd.nextDouble(), tz = GridTestSurfaces.bump(tx, ty);
            double ox, oy, oz;
            if (grazing) { double a = 2 * Math.PI * rnd.nextDouble(); ox = tx + 2 * Math.cos(a); oy = ty + 2 * Math.sin(a); oz = tz + 0.3 * rnd.nextDouble(); }
            else { ox = tx + 0.3 * rnd.nextGaussian(); oy = ty + 0.3 * rnd.nextGaussian(); oz = 2; }
            r[k] = ox; r[k + 1] = oy; r[k + 2] = oz; r[k + 3] = tx - ox; r[k + 4] = ty - oy; r[k + 5] = tz - oz;
        }
        return r;
    }

    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory.getThreadMXBean();

    /**
     * The least time of {@code reps} runs, in nanoseconds of this thread's CPU time (so that other processes on a
     * shared machine count less), after as many warm-up runs.
     */
    private static long best(int reps, Runnable run) {
        for (int i = 0; i < reps; i++) run.run();
        long best = Long.MAX_VALUE;
        for (int i = 0; i < reps; i++) {
            long t0 = THREADS.getCurrentThreadCpuTime();
            run.run();
            best = Math.min(best, THREADS.getCurrentThreadCpuTime() - t0);
        }
        return best;
    }
}
