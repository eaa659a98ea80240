package lt.spindulys.subdiv;

import java.util.Locale;

/**
 * Refinement speed and memory on a corpus shape, single thread (not a unit test; run with
 * {@code java -cp target/classes:target/test-classes lt.spindulys.subdiv.RefineBenchmark
 * [shape] [level] [uv|nouv] [repeats]}). Prints quads per second for the topology and positions
 * of the last level, and the bytes per final quad the result holds (topology + positions, and
 * with limit normals).
 */
public final class RefineBenchmark {
    private RefineBenchmark() {}

    public static void main(String[] args) {
        String shape = args.length > 0 ? args[0] : "catmark_cube";
        int level = args.length > 1 ? Integer.parseInt(args[1]) : 10;
        boolean uv = args.length > 2 && args[2].equals("uv");
        int repeats = args.length > 3 ? Integer.parseInt(args[3]) : 5;
        ControlMesh full = Corpus.load(shape);
        ControlMesh cm = full;
        if (!uv && full.uvs() != null) {
            ControlMesh.Builder b = ControlMesh.builder(full.positions(), full.faceSizes(), full.faceVertices()).options(full.options());
            for (String line : Corpus.text(shape + ".obj").split("\n")) if (line.startsWith("t ")) SubdivTags.apply(line, b);
            cm = b.build();
        }
        double best = Double.MAX_VALUE, bestNormals = Double.MAX_VALUE;
        RefinedMesh r = null;
        for (int i = 0; i < repeats; i++) {
            r = null;
            System.gc();
            long t0 = System.nanoTime();
            r = CatmullClark.refine(cm, level);
            long t1 = System.nanoTime();
            r.limitNormals();
            long t2 = System.nanoTime();
            best = Math.min(best, (t1 - t0) * 1e-9);
            bestNormals = Math.min(bestNormals, (t2 - t1) * 1e-9);
        }
        int quads = r.faceCount();
        Level t = r.topo;
        long topo = 4L * (t.hOrig.length + t.hTwin.length + t.vOut.length) + 4L * t.retainedEdgeCodeInts()
                + (t.vTag == null ? 0 : t.vTag.length) + (t.vSharp == null ? 0 : 4L * t.vSharp.length)
                + (t.eSharp == null ? 0 : 4L * t.eSharp.length) + (t.hole == null ? 0 : t.hole.length);
        long pos = 8L * r.positions().length, nrm = 8L * r.limitNormals().length;
        long uvBytes = 0;
        if (r.uvs() != null) {
            Level u = r.uvTopology();
            uvBytes = 4L * (u.hOrig.length + (u.hTwin == null ? 0 : u.hTwin.length) + (u.vOut == null ? 0 : u.vOut.length))
                    + 4L * u.retainedEdgeCodeInts() + 8L * r.uvs().length;
        }
        System.out.printf(Locale.ROOT, "%s level %d%s: %d quads, refine %.3f s = %.2f M quads/s; limit normals %.3f s%n",
                shape, level, uv ? " with UVs" : "", quads, best, quads / best / 1e6, bestNormals);
        System.out.printf(Locale.ROOT, "bytes per quad: topology %.1f + positions %.1f + normals %.1f = %.1f%n",
                (double) topo / quads, (double) pos / quads, (double) nrm / quads, (double) (topo + pos + nrm) / quads);
        if (uvBytes > 0) System.out.printf(Locale.ROOT, "UVs (value mesh and values): %.1f bytes per quad%n", (double) uvBytes / quads);
    }
}
