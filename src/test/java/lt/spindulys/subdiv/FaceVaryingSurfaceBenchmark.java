package lt.spindulys.subdiv;


/**
 * Not a test: a micro benchmark of {@link FaceVaryingSurface} on corpus shapes with UV seams,
 * under a few face-varying options. For each: the set-up per face (one-ring, evaluator and the
 * descent made by a first 17 x 17 grid, the mean over the shape's quads, or Loop triangles), then
 * per evaluation of the UV on that grid, time and bytes allocated. Run with
 * {@code java -cp target/classes:target/test-classes lt.spindulys.subdiv.FaceVaryingSurfaceBenchmark}.
 */
public final class FaceVaryingSurfaceBenchmark {
    private static final int SMOOTH = 2, SHARP = 6;

    public static void main(String[] args) {
        String[] shapes = args.length > 0 ? args : new String[] {"catmark_fvar_bound1", "catmark_cubes_semisharp", "loop_fvar_bound1"};
        SubdivOptions.FaceVarying[] modes = {SubdivOptions.FaceVarying.CORNERS_PLUS1, SubdivOptions.FaceVarying.BOUNDARIES, SubdivOptions.FaceVarying.ALL};
        for (int pass = 0; pass < 4; pass++) { // the first three passes warm up
            for (String shape : shapes) for (SubdivOptions.FaceVarying m : modes) run(shape, m, pass == 3);
        }
    }

    private static void run(String shape, SubdivOptions.FaceVarying mode, boolean print) {
        ControlMesh cm = Corpus.load(shape, o -> o.withFaceVarying(mode));
        boolean loop = cm.options().scheme() == SubdivOptions.Scheme.LOOP;
        PatchRefiner refiner = new PatchRefiner(cm);
        double[] grid = AdaptiveFaceSurfaceBenchmark.grid(loop), uv = new double[2];
        int points = grid.length / 2, faces = 0;
        double sink = 0;
        long setupNs = 0, evalNs = 0, evalBytes = 0, evals = 0;
        for (int f = 0; f < cm.faceCount(); f++) {
            if (cm.base.faceSize(f) != (loop ? 3 : 4)) continue;
            faces++;
            long t0 = System.nanoTime();
            FaceVaryingSurface s = FaceVaryingSurface.of(refiner, f, SMOOTH, SHARP);
            for (int i = 0; i < points; i++) s.evaluate(grid[2 * i], grid[2 * i + 1], uv);
            setupNs += System.nanoTime() - t0;
            int reps = Math.max(1, 20000 / points);
            long b0 = AdaptiveFaceSurfaceBenchmark.allocated();
            t0 = System.nanoTime();
            for (int r = 0; r < reps; r++) {
                for (int i = 0; i < points; i++) {
                    s.evaluate(grid[2 * i], grid[2 * i + 1], uv);
                    sink += uv[0] + uv[1];
                }
            }
            evalNs += System.nanoTime() - t0;
            evalBytes += AdaptiveFaceSurfaceBenchmark.allocated() - b0;
            evals += (long) reps * points;
        }
        if (print) {
            System.out.printf("%-24s %-13s %3d faces: set-up with the first grid %6.3f ms/face, then evaluate %5.0f ns, %4.1f bytes allocated per evaluation (%.1f)%n",
                    shape, mode, faces, setupNs / 1e6 / faces, (double) evalNs / evals, (double) evalBytes / evals, sink == 0 ? 0.0 : 1.0);
        }
    }
}
