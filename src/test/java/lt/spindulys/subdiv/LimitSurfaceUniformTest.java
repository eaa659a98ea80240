package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

/**
 * Power-of-two grids against uniform refinement: on every regression shape, at level L = 1 to 3
 * (4 on small shapes), the grid of every face at rate 2^L evaluated by {@link LimitSurface#evaluator
 * evaluator(f, L)} gives the limit positions of the uniform level L ({@link RefinedMesh#limitPositions()},
 * what {@code method uniform level L positions limit} renders) to 1e-9 of the shape's bounding-box
 * diagonal, and the grid is exactly the vertex set of the face's level-L descendants.
 *
 * <p>The grid point of each vertex is found exactly: a face's level-L descendants are followed
 * down the child-face order ({@link RefinedMesh}'s numbering) with their corners' parameters, so
 * every corner of a descendant has its lattice point (u 2^L, v 2^L). The face's grid, enumerated
 * on its own (quads: k/2^L; Loop triangles: the triangular grid; N-gons: each sub-face's grid of
 * 2^(L-1) per side), must be that set of lattice points.
 *
 * <p>Not compared: vertices where semi-sharp features have not decayed by level L. There the
 * uniform path's limit masks take the sharp rule as if infinitely sharp (Far's
 * {@code PrimvarRefiner::Limit}), an approximation; the evaluator refines on (as Bfr does, to the
 * sharp approximation level) and gives the exact limit. Larger shapes are checked on a seeded
 * sample of their faces. {@code -Dlimit.shapes=<regex>} checks only the matching shapes (all
 * their sampled faces) and prints each one's time.
 */
class LimitSurfaceUniformTest {
    static final double TOL = 1e-9;
    /** Shapes this small (faces) are also checked at level 4. */
    static final int LEVEL4_FACES = 12;
    /** Faces checked on a larger shape. */
    static final int SAMPLED_FACES = 12;
    /**
     * Faces checked on the non-manifold poles: a face at the pole refines its whole one-ring
     * (hundreds of faces) to the sharp level, as non-manifold levels are not pruned.
     */
    static final int POLE_FACES = 2;
    /**
     * Shapes with end patches {@link AdaptiveFaceSurface} does not make (Far's Gregory patches of
     * non-manifold corners and a few inf-sharp configurations; Bfr makes them), where points
     * are not evaluated (and are not compared).
     */
    static final java.util.Set<String> UNSUPPORTED_END_PATCHES = java.util.Set.of("catmark_fan", "catmark_nonman_edges",
            "catmark_nonman_quadpole360", "catmark_nonman_quadpole64", "catmark_nonman_quadpole8", "catmark_nonman_verts",
            "catmark_val2_nonman", "loop_nonman_edges", "loop_nonman_verts", "loop_val2_interior");

    @Test
    void powerOfTwoGridsAreTheUniformLimitPoints() {
        List<String> bad = new ArrayList<>();
        long[] counts = new long[3];
        long start = System.nanoTime();
        String only = System.getProperty("limit.shapes");
        FaceSurfaceTest.shapes().filter(x -> only == null || x.matches(only)).forEach(shape -> {
            long t0 = System.nanoTime();
            check(shape, bad, counts);
            if (only != null) System.out.printf("%s %.0f ms%n", shape, (System.nanoTime() - t0) / 1e6);
        });
        System.out.printf("LimitSurfaceUniformTest: %d grid points compared, %d at semi-sharp vertices skipped, %d in end patches not made%n", counts[0], counts[1], counts[2]);
        System.out.printf("LimitSurfaceUniformTest: %.1f s%n", (System.nanoTime() - start) / 1e9);
        assertTrue(bad.isEmpty(), () -> bad.size() + " mismatches:\n  " + String.join("\n  ", bad.subList(0, Math.min(30, bad.size()))));
    }

    private static void check(String shape, List<String> bad, long[] counts) {
        ControlMesh cm = Corpus.load(shape);
        LimitSurface surface = new LimitSurface(cm);
        boolean loop = cm.options().scheme() == SubdivOptions.Scheme.LOOP;
        double tol = TOL * diagonal(cm.positions());
        int maxLevel = cm.faceCount() <= LEVEL4_FACES ? 4 : 3;
        RefinedMesh r = RefinedMesh.base(cm);
        List<RefinedMesh> levels = new ArrayList<>();
        levels.add(r);
        for (int l = 1; l <= maxLevel; l++) levels.add(r = r.refine());
        double[] p = new double[3];
        for (int level = 1; level <= maxLevel; level++) {
            RefinedMesh uniform = levels.get(level);
            double[] limit = uniform.limitPositions();
            Level top = uniform.topo;
            int side = 1 << level;
            for (int f : sampledFaces(shape, cm.faceCount(), shape.contains("nonman_quadpole") ? POLE_FACES : SAMPLED_FACES)) {
                if (!surface.hasSurface(f)) continue;
                Map<Long, Integer> vertexAt = descendants(levels, f, level, loop);
                List<long[]> grid = grid(cm.base.faceSize(f), level, loop);
                if (grid.size() != vertexAt.size()) {
                    bad.add(shape + " L" + level + " face " + f + ": " + grid.size() + " grid points, " + vertexAt.size() + " vertices");
                    continue;
                }
                LimitSurface.Evaluator e = surface.evaluator(f, level);
                for (long[] g : grid) {
                    Integer v = vertexAt.get(key(g[0], g[1]));
                    if (v == null) {
                        bad.add(shape + " L" + level + " face " + f + ": grid point " + g[0] + "," + g[1] + " is no vertex");
                        continue;
                    }
                    if ((top.tag(v) & (Level.T_SEMI_SHARP | Level.T_SEMI_EDGES)) != 0) {
                        counts[1]++;
                        continue;
                    }
                    double u = (double) g[0] / side, w = (double) g[1] / side;
                    if (!e.evaluate(u, w, p, null, null)) {
                        if (UNSUPPORTED_END_PATCHES.contains(shape)) {
                            counts[2]++;
                            continue;
                        }
                        bad.add(shape + " L" + level + " face " + f + " (" + u + ", " + w + "): not evaluated");
                        continue;
                    }
                    counts[0]++;
                    double err = 0;
                    for (int d = 0; d < 3; d++) err = Math.max(err, Math.abs(p[d] - limit[3 * v + d]));
                    if (!(err <= tol)) bad.add(shape + " L" + level + " face " + f + " (" + u + ", " + w + ") vertex " + v + ": error " + err / tol * TOL + " of the diagonal; got " + java.util.Arrays.toString(p) + " uniform "
                            + limit[3 * v] + ", " + limit[3 * v + 1] + ", " + limit[3 * v + 2] + " tag " + top.tag(v) + " nm " + top.isNonManifold(v));
                }
            }
        }
    }

    /** Every face of a small shape; a seeded sample of {@code count} faces of a larger one. */
    static int[] sampledFaces(String shape, int faces, int count) {
        if (faces <= count) return java.util.stream.IntStream.range(0, faces).toArray();
        java.util.Random random = new java.util.Random(shape.hashCode());
        return random.ints(0, faces).distinct().limit(count).sorted().toArray();
    }

    /**
     * The level-L vertex at each lattice point (u 2^L, v 2^L) of face f: its descendants followed
     * down the levels with their corners' lattice points.
     */
    private static Map<Long, Integer> descendants(List<RefinedMesh> levels, int f, int level, boolean loop) {
        // Corner locations in units of 2^-level: faces[i] with loc[i] (x, y per corner).
        Level base = levels.get(0).topo;
        int n = base.faceSize(f), unit = 1 << level;
        List<Integer> faces = new ArrayList<>();
        List<long[]> locs = new ArrayList<>();
        int[] fs = {f};
        long[][] ls;
        if (loop) {
            ls = new long[][] {{0, 0, unit, 0, 0, unit}};
        } else if (n == 4) {
            ls = new long[][] {{0, 0, unit, 0, unit, unit, 0, unit}};
        } else {
            // Level 1: Bfr's sub-faces, one child quad per corner (child of half-edge h is face h).
            int columns = FaceSurface.subFaceColumns(n), h0 = base.firstHalf(f);
            fs = new int[n];
            ls = new long[n][];
            for (int k = 0; k < n; k++) {
                long x = (long) (k % columns) * unit, y = (long) (k / columns) * unit, hf = unit / 2;
                fs[k] = h0 + k;
                ls[k] = new long[] {x, y, x + hf, y, x + hf, y + hf, x, y + hf};
            }
        }
        int start = loop || n == 4 ? 0 : 1;
        for (int i = 0; i < fs.length; i++) { faces.add(fs[i]); locs.add(ls[i]); }
        for (int l = start; l < level; l++) {
            Level p = levels.get(l).topo;
            List<Integer> nf = new ArrayList<>();
            List<long[]> nl = new ArrayList<>();
            for (int i = 0; i < faces.size(); i++) {
                int g = faces.get(i);
                long[] c = locs.get(i);
                if (loop) {
                    long[] m01 = mid(c, 0, 1), m12 = mid(c, 1, 2), m20 = mid(c, 2, 0);
                    long[][] kids = {
                        {c[0], c[1], m01[0], m01[1], m20[0], m20[1]},
                        {m01[0], m01[1], c[2], c[3], m12[0], m12[1]},
                        {m20[0], m20[1], m12[0], m12[1], c[4], c[5]},
                        {m12[0], m12[1], m20[0], m20[1], m01[0], m01[1]}};
                    for (int k = 0; k < 4; k++) { nf.add(4 * g + k); nl.add(kids[k]); }
                } else {
                    // Quad child j keeps corner j at position j: (v_j, edge j, centre, edge j-1) turned by j.
                    long[] centre = {(c[0] + c[2] + c[4] + c[6]) / 4, (c[1] + c[3] + c[5] + c[7]) / 4};
                    int h0 = p.firstHalf(g);
                    for (int j = 0; j < 4; j++) {
                        long[] kid = new long[8];
                        long[] e = mid(c, j, (j + 1) & 3), ePrev = mid(c, (j + 3) & 3, j);
                        long[][] ring = {{c[2 * j], c[2 * j + 1]}, e, centre, ePrev};
                        for (int k = 0; k < 4; k++) {
                            int at = (j + k) & 3;
                            kid[2 * at] = ring[k][0];
                            kid[2 * at + 1] = ring[k][1];
                        }
                        nf.add(h0 + j);
                        nl.add(kid);
                    }
                }
            }
            faces = nf;
            locs = nl;
        }
        Level top = levels.get(level).topo;
        Map<Long, Integer> out = new HashMap<>();
        for (int i = 0; i < faces.size(); i++) {
            int g = faces.get(i), h0 = top.firstHalf(g);
            long[] c = locs.get(i);
            for (int k = 0; k < top.faceSize(g); k++) {
                Integer old = out.put(key(c[2 * k], c[2 * k + 1]), top.hOrig[h0 + k]);
                if (old != null && old != top.hOrig[h0 + k]) throw new IllegalStateException("two vertices at one lattice point");
            }
        }
        return out;
    }

    /** The face's grid at rate 2^level, in units of 2^-level. */
    static List<long[]> grid(int n, int level, boolean loop) {
        int side = 1 << level;
        List<long[]> out = new ArrayList<>();
        java.util.Set<Long> seen = new java.util.HashSet<>();
        if (loop || n == 4) {
            for (int j = 0; j <= side; j++) for (int i = 0; i <= side; i++) if (!loop || i + j <= side) add(out, seen, i, j);
        } else {
            int columns = FaceSurface.subFaceColumns(n), half = side / 2;
            for (int q = 0; q < n; q++) {
                for (int j = 0; j <= half; j++) for (int i = 0; i <= half; i++) add(out, seen, (long) (q % columns) * side + i, (long) (q / columns) * side + j);
            }
        }
        return out;
    }

    private static void add(List<long[]> out, java.util.Set<Long> seen, long x, long y) {
        if (seen.add(key(x, y))) out.add(new long[] {x, y});
    }

    private static long[] mid(long[] c, int a, int b) {
        return new long[] {(c[2 * a] + c[2 * b]) / 2, (c[2 * a + 1] + c[2 * b + 1]) / 2};
    }

    private static long key(long x, long y) { return x << 32 | y; }

    static double diagonal(double[] pos) {
        double s = 0;
        for (int d = 0; d < 3; d++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int i = d; i < pos.length; i += 3) {
                lo = Math.min(lo, pos[i]);
                hi = Math.max(hi, pos[i]);
            }
            s += (hi - lo) * (hi - lo);
        }
        return Math.sqrt(s);
    }
}
