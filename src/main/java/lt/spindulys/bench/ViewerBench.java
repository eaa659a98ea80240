package lt.spindulys.bench;

import static lt.spindulys.bench.BenchTable.fmt;
import static lt.spindulys.bench.BenchTable.median;

import java.io.PrintStream;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.viewer.DisplayGeometry;
import lt.spindulys.viewer.OrbitCamera;
import lt.spindulys.viewer.Rasterizer;
import lt.spindulys.math.Vec3;

/**
 * The {@code viewer} bench row: the viewer's rasterizer drawing offscreen frames of a 102,400-quad
 * surface (a 400-quad torus cage refined 4 times) at 1280x720 while the camera orbits, as the
 * viewport does while the mouse drags. Reports the median frames per second over the timed runs
 * for the smoothed surface, the polyhedron, and the smoothed surface with its cage over it.
 */
final class ViewerBench {
    private ViewerBench() {}

    static final int WIDTH = 1280, HEIGHT = 720, LEVEL = 4, RINGS = 25, SIDES = 16;
    /** Frames per timed run: a full turn around the surface in 10 degree steps, tilted as it goes. */
    static final int FRAMES = 36;

    /** A torus cage of RINGS x SIDES quads, major radius 1, minor 0.4, around the y axis. */
    static ControlMesh torusCage() {
        double[] p = new double[3 * RINGS * SIDES];
        int[] sizes = new int[RINGS * SIDES], fv = new int[4 * RINGS * SIDES];
        for (int i = 0; i < RINGS; i++) {
            double u = 2 * Math.PI * i / RINGS;
            for (int j = 0; j < SIDES; j++) {
                double v = 2 * Math.PI * j / SIDES, r = 1 + 0.4 * Math.cos(v);
                int k = i * SIDES + j;
                p[3 * k] = r * Math.cos(u);
                p[3 * k + 1] = 0.4 * Math.sin(v);
                p[3 * k + 2] = r * Math.sin(u);
                int i1 = (i + 1) % RINGS, j1 = (j + 1) % SIDES;
                sizes[k] = 4;
                // Counter-clockwise seen from outside.
                fv[4 * k] = k;
                fv[4 * k + 1] = i * SIDES + j1;
                fv[4 * k + 2] = i1 * SIDES + j1;
                fv[4 * k + 3] = i1 * SIDES + j;
            }
        }
        return ControlMesh.builder(p, sizes, fv).build();
    }

    static void run(PrintStream out, int runs, int threads) {
        ControlMesh cage = torusCage();
        RefinedMesh r = Subdivision.refine(cage, LEVEL);
        DisplayGeometry smooth = DisplayGeometry.smoothed(r), poly = DisplayGeometry.polyhedron(r), lattice = DisplayGeometry.lattice(cage);
        int[] frame = new int[WIDTH * HEIGHT];
        out.printf(Locale.ROOT, "  surface: %,d quads (%,d triangles, %,d vertices), %dx%d, %d threads, %d frames per run orbiting the surface%n",
                r.faceCount(), smooth.triangleCount(), smooth.vertexCount(), WIDTH, HEIGHT, threads, FRAMES);
        BenchTable t = new BenchTable("display", "frames/s (median)", "ms/frame", "slowest run frames/s");
        try (Rasterizer ras = new Rasterizer(threads)) {
            Object[][] cases = {
                    {"smoothed", List.of(Rasterizer.Item.faces(smooth, 0xd9a441, 0x9a7a80))},
                    {"polyhedron", List.of(Rasterizer.Item.faces(poly, 0xd9a441, 0x9a7a80))},
                    {"smoothed + cage", List.of(Rasterizer.Item.faces(smooth, 0xd9a441, 0x9a7a80), Rasterizer.Item.edges(lattice, 0x1c1c1c))}};
            // Warm-up: every case, so the raster loops are compiled for all before any is timed.
            for (int i = 0; i < 5; i++) for (Object[] c : cases) orbit(ras, items(c), frame);
            // Cases alternate within each run, so drift on a shared machine hits them alike.
            double[][] fps = new double[cases.length][runs];
            for (int i = 0; i < runs; i++) {
                for (int k = 0; k < cases.length; k++) {
                    long t0 = System.nanoTime();
                    orbit(ras, items(cases[k]), frame);
                    fps[k][i] = FRAMES / ((System.nanoTime() - t0) / 1e9);
                }
            }
            for (int k = 0; k < cases.length; k++) {
                double[] s = fps[k].clone();
                Arrays.sort(s);
                double med = median(s);
                t.add((String) cases[k][0], String.format(Locale.ROOT, "%.1f", med), String.format(Locale.ROOT, "%.1f", 1000 / med),
                        String.format(Locale.ROOT, "%.1f", s[0]));
            }
        }
        t.print(out);
        out.println("  target: at least 30 frames/s for a 100,000-quad surface at 1280x720 on 2 cores");
        levelChange(out, cage, runs);
    }

    /**
     * How long the viewer takes to show the surface at a new level (its background work before the
     * first frame): refining the cage, making the smoothed triangles, and winding them outwards
     * (the torus is closed). Medians over the runs, after one untimed warm-up.
     */
    private static void levelChange(PrintStream out, ControlMesh cage, int runs) {
        double[][] ms = new double[3][runs];
        for (int i = -1; i < runs; i++) {
            long t0 = System.nanoTime();
            RefinedMesh r = Subdivision.refine(cage, LEVEL);
            long t1 = System.nanoTime();
            DisplayGeometry g = DisplayGeometry.smoothed(r);
            long t2 = System.nanoTime();
            g.outward();
            long t3 = System.nanoTime();
            if (i < 0) continue;
            ms[0][i] = (t1 - t0) / 1e6;
            ms[1][i] = (t2 - t1) / 1e6;
            ms[2][i] = (t3 - t2) / 1e6;
        }
        double refine = median(ms[0]), geometry = median(ms[1]), outward = median(ms[2]);
        out.printf(Locale.ROOT, "  a level change to this surface (off the event thread): refine %.0f ms + smoothed triangles %.0f ms"
                + " + outward winding %.0f ms = %.0f ms (median)%n", refine, geometry, outward, refine + geometry + outward);
    }

    @SuppressWarnings("unchecked")
    private static List<Rasterizer.Item> items(Object[] c) { return (List<Rasterizer.Item>) c[1]; }

    /** One run: FRAMES frames from around the surface, fitted as the viewer's F key fits it. */
    private static void orbit(Rasterizer ras, List<Rasterizer.Item> items, int[] frame) {
        OrbitCamera cam = new OrbitCamera();
        cam.fit(new lt.spindulys.math.Bounds(-1.4, -0.4, -1.4, 1.4, 0.4, 1.4), WIDTH / (double) HEIGHT);
        Vec3 target = cam.target();
        double distance = cam.distance();
        for (int f = 0; f < FRAMES; f++) {
            cam.set(target, distance, Math.toRadians(10 * f), Math.toRadians(35 * Math.sin(2 * Math.PI * f / FRAMES)));
            ras.render(items, cam, frame, WIDTH, HEIGHT);
        }
    }
}
