package lt.spindulys.accel;

import java.util.Random;

import lt.spindulys.math.Ray;

/**
 * A micro benchmark, not a test (run by hand): ns per leaf of four triangles, today's scalar double
 * {@link WatertightTriangles#test} against one {@link TriangleBlocks} block (vector and scalar
 * kernels), closest and any hit, rays hitting a triangle of the leaf or passing beside it. 4096
 * leaves of small triangles (in cache), one thread, CPU time, best of several runs.
 *
 * <pre>
 * mvn -q -o test-compile
 * java --add-modules jdk.incubator.vector -cp target/classes:target/test-classes lt.spindulys.accel.TriangleBlocksBenchmark
 * </pre>
 */
public final class TriangleBlocksBenchmark {
    private TriangleBlocksBenchmark() {}

    private static final int LEAVES = 4096;

    private interface Leaf { boolean run(int leaf, Ray r, PrimitiveHit h, TraversalScratch c); }

    public static void main(String[] args) {
        Random rnd = new Random(1);
        double[] pos = new double[3 * 3 * 4 * LEAVES];
        int[] tri = new int[3 * 4 * LEAVES];
        for (int l = 0; l < LEAVES; l++) {
            // four triangles around a random centre, each about 0.1 across
            double cx = rnd.nextDouble(), cy = rnd.nextDouble(), cz = rnd.nextDouble();
            for (int k = 0; k < 12; k++) {
                int p = 12 * l + k;
                pos[3 * p] = cx + 0.1 * rnd.nextDouble();
                pos[3 * p + 1] = cy + 0.1 * rnd.nextDouble();
                pos[3 * p + 2] = cz + 0.02 * rnd.nextDouble();
                tri[p] = p;
            }
        }
        int[] bounds = new int[LEAVES + 1];
        for (int l = 0; l <= LEAVES; l++) bounds[l] = 4 * l;
        TriangleBlocks blocks = new TriangleBlocks(tri, pos, null, bounds);
        System.out.printf("blocks: %.1f B/tri (full blocks)%n", (double) blocks.bytes() / (4 * LEAVES));
        for (boolean hitting : new boolean[] {true, false}) {
            double[] rays = new double[6 * LEAVES];
            for (int l = 0; l < LEAVES; l++) {
                int p = 12 * l + 3 * rnd.nextInt(4);
                double u = rnd.nextDouble(), v = rnd.nextDouble();
                if (u + v > 1) { u = 1 - u; v = 1 - v; }
                double[] q = new double[3];
                for (int a = 0; a < 3; a++) q[a] = (1 - u - v) * pos[3 * p + a] + u * pos[3 * p + 3 + a] + v * pos[3 * p + 6 + a];
                if (!hitting) q[0] += 0.2;  // beside the leaf's triangles
                double ox = q[0] + 0.3 * rnd.nextGaussian(), oy = q[1] + 0.3 * rnd.nextGaussian(), oz = q[2] + 2;
                double[] r = {ox, oy, oz, q[0] - ox, q[1] - oy, q[2] - oz};
                System.arraycopy(r, 0, rays, 6 * l, 6);
            }
            String name = hitting ? "hitting" : "missing";
            report(name + " double x4, closest", rays, (l, r, h, c) -> WatertightTriangles.test(tri, pos, null, 4 * l, 4 * l + 4, r, h, c));
            report(name + " block (auto), closest", rays, (l, r, h, c) -> blocks.intersect(l, l + 1, r, h, c));
            report(name + " block scalar, closest", rays, (l, r, h, c) -> blocks.test(l, l + 1, r, h, c, false));
            report(name + " double x4, any", rays, (l, r, h, c) -> WatertightTriangles.test(tri, pos, null, 4 * l, 4 * l + 4, r, null, c));
            report(name + " block (auto), any", rays, (l, r, h, c) -> blocks.occluded(l, l + 1, r, c));
        }
    }

    private static void report(String name, double[] rays, Leaf leaf) {
        Ray r = new Ray();
        PrimitiveHit h = new PrimitiveHit();
        TraversalScratch c = new TraversalScratch();
        int[] hits = new int[1];
        Runnable run = () -> {
            for (int rep = 0; rep < 20; rep++) {
                for (int l = 0; l < LEAVES; l++) {
                    r.set(rays[6 * l], rays[6 * l + 1], rays[6 * l + 2], rays[6 * l + 3], rays[6 * l + 4], rays[6 * l + 5], 0, Double.POSITIVE_INFINITY);
                    if (leaf.run(l, r, h, c)) hits[0]++;
                }
            }
        };
        long best = best(15, run);
        hits[0] = 0;
        run.run();
        System.out.printf("%-34s %6.1f ns/leaf  (%d of %d leaves hit)%n", name, best / (20.0 * LEAVES), hits[0] / 20, LEAVES);
    }

    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory.getThreadMXBean();

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
