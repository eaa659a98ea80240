package lt.spindulys.subdiv;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;

/**
 * Not a test: a micro benchmark of {@link AdaptiveFaceSurface} on irregular faces of corpus
 * shapes (valence-3 corners, a valence-8 pole, semi-sharp creases, Loop). For each shape: the
 * set-up per face (one-ring, refinement, evaluator, the mean of 10; patches it is cut into), and per evaluation of position and both
 * derivatives on a 17 x 17 grid of each face (a triangle's half for Loop), time and bytes
 * allocated. Run with {@code java -cp target/classes:target/test-classes
 * lt.spindulys.subdiv.AdaptiveFaceSurfaceBenchmark}.
 */
public final class AdaptiveFaceSurfaceBenchmark {
    private static final int SMOOTH = 2, SHARP = 6, GRID = 17, FACES = 3, SETUPS = 10;

    public static void main(String[] args) {
        String[] shapes = args.length > 0 ? args : new String[] {"catmark_cube", "catmark_pole8", "catmark_cube_creases1", "loop_cube", "loop_cube_creases1"};
        for (int pass = 0; pass < 4; pass++) { // the first three passes warm up
            for (String shape : shapes) run(shape, pass == 3);
        }
        String[] limitShapes = {"catmark_car", "catmark_pole8", "catmark_cube_creases1", "loop_cube", "bilinear_nonquads0"};
        for (int pass = 0; pass < 3; pass++) {
            for (String shape : limitShapes) for (int level = 2; level <= 4; level += 2) limitSurface(shape, level, pass == 2);
        }
        wholeMeshSetup("catmark_car");
    }

    /**
     * {@link LimitSurface} on every face (at most 200) of a shape: the evaluator's set-up, the
     * first evaluation of the face's grid at rate 2^level (which refines an irregular face where
     * the grid falls), then ns per evaluation of the warm grid, regular and irregular faces apart.
     */
    private static void limitSurface(String shape, int level, boolean print) {
        ControlMesh cm = Corpus.load(shape);
        long t0 = System.nanoTime();
        LimitSurface surface = new LimitSurface(cm);
        long constructNs = System.nanoTime() - t0;
        boolean loop = cm.options().scheme() == SubdivOptions.Scheme.LOOP;
        double[] p = new double[3], du = new double[3], dv = new double[3];
        long[] setup = new long[2], first = new long[2], eval = new long[2], faces = new long[2], evals = new long[2];
        double sink = 0;
        for (int f = 0; f < Math.min(cm.faceCount(), 200); f++) {
            if (!surface.hasSurface(f)) continue;
            double[] uv = LimitSurfaceTest.grid(cm.base.faceSize(f), loop, 1 << level);
            long a = System.nanoTime();
            LimitSurface.Evaluator e = surface.evaluator(f, level);
            long b = System.nanoTime();
            for (int i = 0; i < uv.length; i += 2) e.evaluate(uv[i], uv[i + 1], p, du, dv);
            long c = System.nanoTime();
            int reps = Math.max(1, 4000 / uv.length);
            for (int r = 0; r < reps; r++) {
                for (int i = 0; i < uv.length; i += 2) {
                    e.evaluate(uv[i], uv[i + 1], p, du, dv);
                    sink += p[0] + du[1] + dv[2];
                }
            }
            long d = System.nanoTime();
            int k = e.isRegular() ? 0 : 1;
            setup[k] += b - a;
            first[k] += c - b;
            eval[k] += d - c;
            faces[k]++;
            evals[k] += (long) reps * uv.length / 2;
        }
        if (!print) return;
        System.out.printf("LimitSurface %-20s L%d: constructor %.2f ms;", shape, level, constructNs / 1e6);
        for (int k = 0; k < 2; k++) {
            if (faces[k] == 0) continue;
            System.out.printf(" %s %d faces: set-up %.1f us, first grid %.1f us, evaluate %.0f ns;", k == 0 ? "single-patch" : "adaptive", faces[k],
                    setup[k] / 1e3 / faces[k], first[k] / 1e3 / faces[k], (double) eval[k] / evals[k]);
        }
        System.out.printf(" (%.1f)%n", sink == 0 ? 0.0 : 1.0);
    }

    /** An irregular face's evaluator made from the whole control mesh rather than its one-ring: what the one-ring saves. */
    private static void wholeMeshSetup(String shape) {
        ControlMesh cm = Corpus.load(shape);
        PatchRefiner refiner = new PatchRefiner(cm);
        double[] p = new double[3];
        for (int pass = 0; pass < 3; pass++) {
            long whole = 0, ring = 0;
            int count = 0;
            for (int f = 0; f < cm.faceCount() && count < 10; f++) {
                if (FaceSurface.isRegular(cm.base, cm.options(), f)) continue;
                long a = System.nanoTime();
                AdaptiveFaceSurface.of(cm, f, SMOOTH, SHARP).evaluate(0.5, 0.5, p, null, null);
                long b = System.nanoTime();
                build(refiner, f).evaluate(0.5, 0.5, p, null, null);
                long c = System.nanoTime();
                whole += b - a;
                ring += c - b;
                count++;
            }
            if (pass == 2) System.out.printf("%s: irregular face set-up and first evaluation from the whole mesh %.2f ms, from its one-ring %.3f ms%n", shape, whole / 1e6 / count, ring / 1e6 / count);
        }
    }

    private static void run(String shape, boolean print) {
        ControlMesh cm = Corpus.load(shape);
        boolean loop = cm.options().scheme() == SubdivOptions.Scheme.LOOP;
        PatchRefiner refiner = new PatchRefiner(cm);
        List<Integer> faces = new ArrayList<>();
        for (int f = 0; f < cm.faceCount() && faces.size() < FACES; f++) {
            if (cm.base.faceSize(f) == (loop ? 3 : 4) && AdaptiveFaceSurface.supported(cm.base, cm.options(), f)
                    && !FaceSurface.isRegular(cm.base, cm.options(), f, true)) faces.add(f);
        }
        double[] uv = grid(loop);
        int points = uv.length / 2;
        double[] p = new double[3], du = new double[3], dv = new double[3];
        double sink = 0;
        long setupNs = 0, firstNs = 0, evalNs = 0, evalBytes = 0, evals = 0, missed = 0, patches = 0;
        for (int f : faces) {
            AdaptiveFaceSurface s = null;
            for (int r = 0; r < SETUPS; r++) {
                long t0 = System.nanoTime();
                s = build(refiner, f);
                long t1 = System.nanoTime();
                int miss = 0;
                for (int i = 0; i < points; i++) if (!s.evaluate(uv[2 * i], uv[2 * i + 1], p, du, dv)) miss++;
                if (r == 0) missed += miss;
                setupNs += (t1 - t0) / SETUPS;
                firstNs += (System.nanoTime() - t0) / SETUPS;
            }
            patches += s.patchCount();
            long t0;
            int reps = Math.max(1, 20000 / points);
            long b0 = allocated();
            t0 = System.nanoTime();
            for (int r = 0; r < reps; r++) {
                for (int i = 0; i < points; i++) {
                    s.evaluate(uv[2 * i], uv[2 * i + 1], p, du, dv);
                    sink += p[0] + du[1] + dv[2];
                }
            }
            evalNs += System.nanoTime() - t0;
            evalBytes += allocated() - b0;
            evals += (long) reps * points;
        }
        if (print) {
            System.out.printf("%-22s %d faces: set-up %6.2f ms/face, with the first grid %6.2f ms (%4.0f patches), then evaluate %7.0f ns, %6.0f bytes allocated per evaluation%s (%.1f)%n",
                    shape, faces.size(), setupNs / 1e6 / faces.size(), firstNs / 1e6 / faces.size(), (double) patches / faces.size(), (double) evalNs / evals, (double) evalBytes / evals,
                    missed > 0 ? ", " + missed + " points not evaluated" : "", sink == 0 ? 0.0 : 1.0);
        }
    }

    private static AdaptiveFaceSurface build(PatchRefiner refiner, int f) {
        PatchRefiner.Local local = refiner.local(f);
        return AdaptiveFaceSurface.of(local.mesh(), local.face(), SMOOTH, SHARP);
    }

    /** The (u, v) of a GRID x GRID grid over the face (its lower-left half for a triangle), shared with the face-varying benchmark. */
    static double[] grid(boolean triangle) {
        double[] uv = new double[2 * GRID * GRID];
        int k = 0;
        for (int j = 0; j < GRID; j++) {
            for (int i = 0; i < GRID; i++) {
                double u = i / (GRID - 1.0), v = j / (GRID - 1.0);
                if (triangle && u + v > 1) continue;
                uv[k++] = u;
                uv[k++] = v;
            }
        }
        return java.util.Arrays.copyOf(uv, k);
    }

    static long allocated() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean()).getThreadAllocatedBytes(Thread.currentThread().getId());
    }
}
