package lt.spindulys.accel;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.cli.Main;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.trace.TraceContext;

/**
 * The traversal counters ({@link TraversalScratch#COUNTING}): off in this JVM, where they must stay
 * zero; exact on traversals small enough to predict, and equal for one and two render threads, in
 * child JVMs started with {@code -Dspindulys.counters=true} (the switch is a constant read once).
 */
class TraversalCountersTest {

    /** Two unit triangles in the plane z = 0, one at x in [0, 1], one at x in [10, 11]; y in [0, 1]. */
    private static TriangleMesh twoTriangles() {
        return new TriangleMesh(TestMeshes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 10, 0, 0, 11, 0, 0, 10, 1, 0}));
    }

    private static TriangleMesh oneTriangle() {
        return new TriangleMesh(TestMeshes.soup(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0}));
    }

    /** A ray straight down -z from (x, y, 5). */
    private static Ray down(double x, double y) {
        return new Ray().set(x, y, 5, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
    }

    /** The counts a query adds, as "nodes leaves tests" of {@code kind}. */
    private static String counts(TraversalScratch ctx, int kind, Runnable query) {
        long n = ctx.nodesVisited[kind], l = ctx.leavesEntered[kind], t = ctx.triangleTests[kind];
        query.run();
        return (ctx.nodesVisited[kind] - n) + " " + (ctx.leavesEntered[kind] - l) + " " + (ctx.triangleTests[kind] - t);
    }

    /**
     * Run in a child JVM with the counters on: prints one line per case, its name and the counts
     * it added. The cases: a one-triangle binary tree (its root is a leaf), a two-leaf binary tree
     * and its wide collapse (one node whose children are the two leaves), rays that hit a
     * triangle, pass between the two, or miss the root's box, and an any-hit query as a shadow ray.
     */
    public static void main(String[] args) {
        TraceContext ctx = new TraceContext();
        PrimitiveHit hit = new PrimitiveHit();
        Bvh one = new Bvh(oneTriangle(), 1, false), two = new Bvh(twoTriangles(), 1, false);
        System.out.println("counting " + TraversalScratch.COUNTING);
        System.out.println("one-hit " + counts(ctx, TraversalScratch.CAMERA, () -> one.intersect(down(0.25, 0.25), hit, ctx)));
        System.out.println("one-miss " + counts(ctx, TraversalScratch.CAMERA, () -> one.intersect(down(0.25, 50), hit, ctx)));
        System.out.println("two-hit " + counts(ctx, TraversalScratch.CAMERA, () -> two.intersect(down(0.25, 0.25), hit, ctx)));
        System.out.println("two-between " + counts(ctx, TraversalScratch.CAMERA, () -> two.intersect(down(5, 0.5), hit, ctx)));
        System.out.println("two-miss " + counts(ctx, TraversalScratch.CAMERA, () -> two.intersect(down(0.25, 50), hit, ctx)));
        ctx.rayKind = TraversalScratch.SHADOW;
        System.out.println("two-occluded " + counts(ctx, TraversalScratch.SHADOW, () -> two.occluded(down(10.25, 0.25), ctx)));
        if (WideBvh.AVAILABLE) {
            WideBvh wide = new WideBvh(two);
            ctx.rayKind = TraversalScratch.CAMERA;
            System.out.println("wide-hit " + counts(ctx, TraversalScratch.CAMERA, () -> wide.intersect(down(10.25, 0.25), hit, ctx)));
            System.out.println("wide-between " + counts(ctx, TraversalScratch.CAMERA, () -> wide.intersect(down(5, 0.5), hit, ctx)));
            System.out.println("wide-miss " + counts(ctx, TraversalScratch.CAMERA, () -> wide.intersect(down(0.25, 50), hit, ctx)));
            ctx.rayKind = TraversalScratch.SHADOW;
            System.out.println("wide-occluded " + counts(ctx, TraversalScratch.SHADOW, () -> wide.occluded(down(0.25, 0.25), ctx)));
        }
        // Nothing is charged to a kind other than the one set.
        System.out.println("secondary " + ctx.nodesVisited[TraversalScratch.SECONDARY] + " " + ctx.leavesEntered[TraversalScratch.SECONDARY]
                + " " + ctx.triangleTests[TraversalScratch.SECONDARY]);
    }

    /** Runs {@code mainClass} with {@code args} in a JVM with the counters on; its output lines. */
    private static List<String> child(Path dir, String mainClass, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "--add-modules", "jdk.incubator.vector", "-Dspindulys.counters=true", "-cp", System.getProperty("java.class.path"), mainClass));
        cmd.addAll(List.of(args));
        Path log = dir.resolve("out-" + System.nanoTime() + ".txt");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        assertTrue(p.waitFor(2, TimeUnit.MINUTES), "child JVM timed out");
        String out = Files.readString(log, StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), out);
        return out.lines().toList();
    }

    private static String line(List<String> lines, String start) {
        return lines.stream().filter(l -> l.startsWith(start)).findFirst().orElseThrow(() -> new AssertionError("no " + start + " in " + lines));
    }

    @Test
    void countsAreExactOnTinyTrees(@TempDir Path dir) throws Exception {
        List<String> out = child(dir, TraversalCountersTest.class.getName());
        assertEquals("counting true", line(out, "counting"));
        // One triangle: the root is a leaf (its box is tested before the walk, not counted as a node).
        assertEquals("one-hit 0 1 1", line(out, "one-hit"));
        assertEquals("one-miss 0 0 0", line(out, "one-miss"));
        // Two leaves under one inner node: the root's visit tests both children's boxes.
        assertEquals("two-hit 1 1 1", line(out, "two-hit"));
        assertEquals("two-between 1 0 0", line(out, "two-between"));
        assertEquals("two-miss 0 0 0", line(out, "two-miss"));
        assertEquals("two-occluded 1 1 1", line(out, "two-occluded"));
        if (out.stream().anyMatch(l -> l.startsWith("wide-"))) {
            // The wide tree has no box test of its own root: a ray that misses it still visits it.
            assertEquals("wide-hit 1 1 1", line(out, "wide-hit"));
            assertEquals("wide-between 1 0 0", line(out, "wide-between"));
            assertEquals("wide-miss 1 0 0", line(out, "wide-miss"));
            assertEquals("wide-occluded 1 1 1", line(out, "wide-occluded"));
        }
        assertEquals("secondary 0 0 0", line(out, "secondary"));
    }

    @Test
    void countersStayZeroWhenOff() {
        assertFalse(TraversalScratch.COUNTING, "this JVM was started with -Dspindulys.counters=true");
        TraceContext ctx = new TraceContext();
        PrimitiveHit hit = new PrimitiveHit();
        Bvh two = new Bvh(twoTriangles(), 1, false);
        Accelerator wide = WideBvh.widen(two);
        for (Accelerator a : List.of(two, wide)) {
            assertTrue(a.intersect(down(0.25, 0.25), hit, ctx));
            assertTrue(a.occluded(down(10.25, 0.25), ctx));
        }
        for (int k = 0; k < TraversalScratch.KINDS; k++) {
            assertEquals(0, ctx.nodesVisited[k] + ctx.leavesEntered[k] + ctx.triangleTests[k]);
        }
    }

    /**
     * A render's counts do not depend on how its tiles are shared out. The scene has no light: a
     * shadow ray may first try the triangle that last blocked one on its thread (the scene's
     * occluder cache), so with shadows the counts would depend on which tiles a thread rendered
     * before; reflection gives the secondary rays instead.
     */
    @Test
    void renderCountsAreTheSameForOneAndTwoThreads(@TempDir Path dir) throws Exception {
        Files.copy(Path.of("scenes/bench/meshes/torus_1k.obj"), dir.resolve("torus.obj"));
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, """
                settings { width 64 height 48 samples 1 ambient 1 1 1 }
                camera { eye 0 2 3  lookat 0 0 0  up 0 1 0  fov 50 }
                material mirror { color 0.8 0.8 0.8  ka 0.5 kd 0 ks 0 kr 0.5 }
                mesh { file "torus.obj"  shading flat  material mirror }
                """);
        List<String> one = child(dir, Main.class.getName(), scene.toString(), "-o", dir.resolve("a.png").toString(), "--threads", "1", "--stats", "--quiet");
        List<String> two = child(dir, Main.class.getName(), scene.toString(), "-o", dir.resolve("b.png").toString(), "--threads", "2", "--stats", "--quiet");
        for (String kind : List.of("traversal camera:", "traversal secondary:", "traversal shadow:")) {
            assertEquals(line(one, kind), line(two, kind));
        }
        assertEquals("traversal camera: 3072 rays", line(one, "traversal camera:").replaceAll(", [0-9.]+ nodes.*", ""));
        assertFalse(line(one, "traversal camera:").contains(" 0.000 nodes"), line(one, "traversal camera:"));
        assertFalse(line(one, "traversal secondary:").startsWith("traversal secondary: 0 rays"), line(one, "traversal secondary:"));
    }
}
