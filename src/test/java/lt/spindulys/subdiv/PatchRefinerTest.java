package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.mesh.MeshData;

/**
 * Per-face patches against the uniform path, for the three schemes: bit identity, watertight
 * stitching, bounds, size bound.
 */
class PatchRefinerTest {
    /** Most faces checked per shape and level: every face of small shapes, an even spread of large ones. */
    private static final int FACES_PER_LEVEL = 40;

    @Test
    void patchesAreBitIdenticalToTheUniformPathOnEveryReferenceShape() {
        for (String shape : Corpus.shapes().keySet()) {
            ControlMesh m = Corpus.load(shape);
            checkExact(shape, m, m.faceCount() <= 120 ? 4 : 3);
        }
    }

    @Test
    void patchesAreExactWithEveryFaceVaryingModeAndBoundaryRule() {
        for (String shape : new String[] {"catmark_fvar_bound0", "catmark_fvar_bound1", "catmark_fvar_bound2", "catmark_fvar_bound3",
                "catmark_fvar_bound4", "catmark_fvar_project0"}) {
            for (SubdivOptions.FaceVarying mode : SubdivOptions.FaceVarying.values()) {
                checkExact(shape + " " + mode, Corpus.load(shape, o -> o.withFaceVarying(mode)), 3);
            }
        }
        for (SubdivOptions.Boundary b : SubdivOptions.Boundary.values()) {
            for (String shape : new String[] {"catmark_edgecorner", "catmark_hole_test1", "catmark_nonquads", "catmark_nonman_edges"}) {
                checkExact(shape + " " + b, Corpus.load(shape, o -> o.withBoundary(b)), 3);
            }
        }
        for (String shape : new String[] {"catmark_smoothtris0", "catmark_nonquads", "catmark_pyramid"}) {
            checkExact(shape + " smooth triangles", Corpus.load(shape, o -> o.withTriangles(SubdivOptions.Triangles.SMOOTH)), 4);
        }
        checkExact("catmark_cube_creases2 level 5", Corpus.load("catmark_cube_creases2"), 5);
        checkExact("loop_cube_creases1 level 5", Corpus.load("loop_cube_creases1"), 5);
        for (SubdivOptions.Boundary b : SubdivOptions.Boundary.values()) {
            for (String shape : new String[] {"loop_triangle_edgecorner", "loop_xord_boundary", "loop_nonman_edges"}) {
                checkExact(shape + " " + b, Corpus.load(shape, o -> o.withBoundary(b)), 3);
            }
        }
        // UV values that follow another's semi-sharp decay (Far's dependent sharpness).
        checkExact("loop_cube_creases1_uvwarp CORNERS_PLUS1", Corpus.load("loop_cube_creases1_uvwarp",
                o -> o.withFaceVarying(SubdivOptions.FaceVarying.CORNERS_PLUS1)), 4);
        for (SubdivOptions.FaceVarying mode : SubdivOptions.FaceVarying.values()) {
            checkExact("loop_fvar_bound1 " + mode, Corpus.load("loop_fvar_bound1", o -> o.withFaceVarying(mode)), 3);
            checkExact("bilinear_nonquads1 " + mode, Corpus.load("bilinear_nonquads1", o -> o.withFaceVarying(mode)), 3);
        }
    }

    private static void checkExact(String name, ControlMesh m, int maxLevel) {
        PatchRefiner pr = new PatchRefiner(m);
        RefinedMesh r = RefinedMesh.base(m);
        for (int level = 0; level <= maxLevel; level++) {
            if (level > 0) r = r.refine();
            for (boolean smooth : new boolean[] {true, false}) {
                MeshData uniform = RefinedTriangles.triangles(r, smooth);
                int step = Math.max(1, m.faceCount() / FACES_PER_LEVEL);
                for (int face = 0; face < m.faceCount(); face += step) {
                    MeshData patch = pr.refine(face, level, null, smooth);
                    compare(name + " L" + level + (smooth ? " smooth" : " flat") + " face " + face, r, uniform, descendants(m, face, level), patch);
                }
            }
        }
    }

    /** The range of level-L faces descending from a base face. */
    private static int[] descendants(ControlMesh m, int face, int level) {
        if (level == 0) return new int[] {face, face + 1};
        if (m.options().scheme() == SubdivOptions.Scheme.LOOP) {
            int span = 1 << (2 * level); // four triangles per triangle, numbered in a row
            return new int[] {face * span, (face + 1) * span};
        }
        int start = 0;
        for (int f = 0; f < face; f++) start += m.faceSizes()[f];
        int count = m.faceSizes()[face];
        for (int l = 2; l <= level; l++) {
            start *= 4;
            count *= 4;
        }
        return new int[] {start, start + count};
    }

    private static void compare(String at, RefinedMesh r, MeshData u, int[] range, MeshData p) {
        int[] sizes = r.faceSizes();
        int tri = 0, corner = 0;
        for (int f = 0; f < range[0]; f++) {
            if (r.isHole(f)) continue;
            tri += sizes[f] == 4 ? 2 : 1;
            corner += sizes[f] == 4 ? 6 : sizes[f];
        }
        assertEquals((p.uvs() == null), (u.uvs() == null), at + ": uvs present");
        assertEquals((p.normals() == null), (u.normals() == null), at + ": normals present");
        for (int t = 0; t < p.faceSizes().length; t++) {
            assertEquals(u.faceSizes()[tri + t], p.faceSizes()[t], at + ": size of triangle " + t);
        }
        int end = corner + p.vertexIndex().length;
        if (range[1] < sizes.length || true) {
            int expected = 0;
            for (int f = range[0]; f < range[1]; f++) if (!r.isHole(f)) expected += sizes[f] == 4 ? 6 : sizes[f];
            assertEquals(expected, p.vertexIndex().length, at + ": corners");
        }
        for (int c = corner, k = 0; c < end; c++, k++) {
            same(at + " corner " + k + " position", u.positions(), 3 * u.vertexIndex()[c], p.positions(), 3 * p.vertexIndex()[k], 3);
            if (u.normals() != null) {
                same(at + " corner " + k + " normal", u.normals(), 3 * u.normalIndex()[c], p.normals(), 3 * p.normalIndex()[k], 3);
            }
            if (u.uvs() != null) same(at + " corner " + k + " uv", u.uvs(), 2 * u.uvIndex()[c], p.uvs(), 2 * p.uvIndex()[k], 2);
        }
    }

    private static void same(String at, double[] a, int i, double[] b, int j, int n) {
        for (int d = 0; d < n; d++) {
            if (!(a[i + d] == b[j + d]) && !(Double.isNaN(a[i + d]) && Double.isNaN(b[j + d]))) {
                fail(at + ": uniform " + a[i + d] + ", patch " + b[j + d]);
            }
        }
    }

    // ---------------------------------------------------------------- stitching

    @Test
    void stitchingWithRandomEdgeLevelsIsWatertight() {
        for (String shape : new String[] {"catmark_torus", "catmark_cube_creases1", "catmark_pyramid_creases0", "catmark_toroidal_tet", "catmark_smoothtris0", "catmark_cubes_semisharp", "catmark_chaikin1",
                "loop_icosahedron", "loop_cube_creases1", "loop_chaikin1", "loop_icos_semisharp", "loop_toroidal_tet", "loop_cubes_semisharp", "bilinear_cube"}) {
            ControlMesh m = Corpus.load(shape);
            PatchRefiner pr = new PatchRefiner(m);
            for (int s = 1; s <= 4; s++) {
                long seed = s;
                Random rnd = new Random(seed * 7919 + shape.hashCode());
                int[] edgeLevel = new int[pr.edgeCount()];
                for (int e = 0; e < edgeLevel.length; e++) edgeLevel[e] = rnd.nextInt(5);
                Map<String, Integer> open = new HashMap<>();
                int segments = 0;
                for (int f = 0; f < pr.faceCount(); f++) {
                    int n = pr.faceSize(f), level = 0;
                    int[] el = new int[n], cl = new int[n];
                    for (int k = 0; k < n; k++) {
                        el[k] = edgeLevel[pr.faceEdge(f, k)];
                        level = Math.max(level, el[k]);
                        cl[k] = pr.vertexLevel(f, k, edgeLevel);
                    }
                    level = Math.min(PatchRefiner.MAX_LEVEL, level + rnd.nextInt(2));
                    MeshData p = pr.refine(f, level, el, cl, rnd.nextBoolean());
                    for (String[] seg : boundarySegments(p)) {
                        segments++;
                        String back = seg[1] + "|" + seg[0];
                        Integer c = open.get(back);
                        if (c != null) {
                            if (c == 1) open.remove(back);
                            else open.put(back, c - 1);
                        } else {
                            open.merge(seg[0] + "|" + seg[1], 1, Integer::sum);
                        }
                    }
                }
                assertTrue(segments > 0);
                int total = segments;
                assertTrue(open.isEmpty(), () -> shape + " seed " + seed + ": " + open.size() + " of " + total + " boundary segments unmatched, e.g. "
                        + open.keySet().iterator().next());
            }
        }
    }

    /** The patch's boundary edges (used by one triangle, by vertex index) that have length, as position keys, in winding order. */
    private static List<String[]> boundarySegments(MeshData p) {
        Map<Long, Integer> count = new HashMap<>();
        int[] vi = p.vertexIndex(), sizes = p.faceSizes();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int k = 0; k < sizes[f]; k++) {
                int a = vi[c + k], b = vi[c + (k + 1) % sizes[f]];
                count.merge(key(a, b), 1, Integer::sum);
            }
        }
        List<String[]> out = new ArrayList<>();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int k = 0; k < sizes[f]; k++) {
                int a = vi[c + k], b = vi[c + (k + 1) % sizes[f]];
                if (count.get(key(a, b)) != 1) continue;
                String pa = pos(p, a), pb = pos(p, b);
                if (!pa.equals(pb)) out.add(new String[] {pa, pb});
            }
        }
        return out;
    }

    private static long key(int a, int b) { return (long) Math.min(a, b) << 32 | Math.max(a, b); }

    private static String pos(MeshData p, int v) {
        double[] x = p.positions();
        return Double.doubleToLongBits(x[3 * v]) + "," + Double.doubleToLongBits(x[3 * v + 1]) + "," + Double.doubleToLongBits(x[3 * v + 2]);
    }

    @Test
    void equalEdgeLevelsChangeNothing() {
        ControlMesh m = Corpus.load("catmark_cube_creases1");
        PatchRefiner pr = new PatchRefiner(m);
        for (int f = 0; f < pr.faceCount(); f++) {
            int[] el = new int[pr.faceSize(f)];
            java.util.Arrays.fill(el, 3);
            MeshData a = pr.refine(f, 3, null, true), b = pr.refine(f, 3, el, true);
            assertTrue(java.util.Arrays.equals(a.positions(), b.positions()));
            assertTrue(java.util.Arrays.equals(a.vertexIndex(), b.vertexIndex()));
        }
    }

    @Test
    void faceEdgesJoinTheFacesCorners() {
        for (String shape : new String[] {"catmark_nonquads", "catmark_nonman_edges", "catmark_torus"}) {
            ControlMesh m = Corpus.load(shape);
            PatchRefiner pr = new PatchRefiner(m);
            int[] ev = pr.edgeVertices(), fv = m.faceVertices();
            assertEquals(2 * pr.edgeCount(), ev.length);
            for (int f = 0, c = 0; f < pr.faceCount(); c += pr.faceSize(f), f++) {
                for (int k = 0; k < pr.faceSize(f); k++) {
                    int e = pr.faceEdge(f, k), a = fv[c + k], b = fv[c + (k + 1) % pr.faceSize(f)];
                    assertTrue(ev[2 * e] == a && ev[2 * e + 1] == b || ev[2 * e] == b && ev[2 * e + 1] == a, shape + " face " + f + " edge " + k);
                }
            }
        }
    }

    @Test
    void patchesFromManyThreadsEqualOnesMadeAlone() throws Exception {
        ControlMesh m = Corpus.load("catmark_fvar_bound2", o -> o.withFaceVarying(SubdivOptions.FaceVarying.CORNERS_ONLY));
        PatchRefiner pr = new PatchRefiner(m);
        MeshData[] alone = new MeshData[pr.faceCount()];
        for (int f = 0; f < alone.length; f++) alone[f] = pr.refine(f, 3, null, true);
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(4);
        try {
            List<java.util.concurrent.Future<Boolean>> results = new ArrayList<>();
            for (int rep = 0; rep < 8; rep++) {
                for (int f = 0; f < alone.length; f++) {
                    int face = f;
                    results.add(pool.submit(() -> {
                        MeshData p = pr.refine(face, 3, null, true);
                        return java.util.Arrays.equals(p.positions(), alone[face].positions()) && java.util.Arrays.equals(p.normals(), alone[face].normals())
                                && java.util.Arrays.equals(p.uvs(), alone[face].uvs()) && java.util.Arrays.equals(p.vertexIndex(), alone[face].vertexIndex());
                    }));
                }
            }
            for (java.util.concurrent.Future<Boolean> r : results) assertTrue(r.get());
        } finally {
            pool.shutdown();
        }
    }

    @Test
    void badArgumentsAreRefused() {
        PatchRefiner pr = new PatchRefiner(Corpus.load("catmark_cube"));
        assertThrows(IllegalArgumentException.class, () -> pr.refine(0, 9, null, true));
        assertThrows(IllegalArgumentException.class, () -> pr.refine(0, 2, new int[] {3, 2, 2, 2}, true));
        assertThrows(IllegalArgumentException.class, () -> pr.refine(0, 2, new int[] {2, 2}, true));
        assertThrows(IllegalArgumentException.class, () -> pr.refine(6, 2, null, true));
    }

    // ---------------------------------------------------------------- bounds and size

    @Test
    void oneRingBoundsContainEveryPatchVertex() {
        double[] box = new double[6];
        for (String shape : new String[] {"catmark_torus", "catmark_cubes_semisharp", "catmark_chaikin1", "catmark_nonquads", "catmark_smoothtris1",
                "catmark_fan", "catmark_nonman_edges", "catmark_xord_boundary", "catmark_val2_interior",
                "loop_pole8", "loop_cubes_semisharp", "loop_chaikin1", "loop_nonman_edges", "loop_val2_interior", "bilinear_nonplanar"}) {
            ControlMesh m = Corpus.load(shape);
            PatchRefiner pr = new PatchRefiner(m);
            for (int f = 0; f < pr.faceCount(); f++) {
                pr.oneRingBounds(f, box);
                for (int level = 0; level <= 4; level++) {
                    double[] p = pr.refine(f, level, null, false).positions();
                    for (int i = 0; i < p.length; i++) {
                        int a = i % 3;
                        assertTrue(p[i] >= box[a] && p[i] <= box[a + 3], shape + " face " + f + " L" + level + ": coordinate " + p[i] + " outside " + box[a] + ".." + box[a + 3]);
                    }
                }
            }
        }
    }

    @Test
    void patchBytesBoundTheArraysHeld() {
        for (String shape : new String[] {"catmark_torus", "catmark_nonquads", "catmark_fvar_bound1", "catmark_hole_test2", "catmark_nonman_verts", "catmark_cube_creases0",
                "loop_fvar_bound1", "loop_nonman_verts", "loop_triangle_edgenone", "bilinear_nonquads0"}) {
            PatchRefiner pr = new PatchRefiner(Corpus.load(shape));
            double worst = 0;
            for (int f = 0; f < pr.faceCount(); f++) {
                for (int level = 0; level <= 4; level++) {
                    for (boolean smooth : new boolean[] {true, false}) {
                        MeshData p = pr.refine(f, level, null, smooth);
                        long held = 80 + bytes(p.positions(), 8) + bytes(p.normals(), 8) + bytes(p.uvs(), 8) + bytes(p.faceSizes(), 4)
                                + bytes(p.vertexIndex(), 4) + bytes(p.normalIndex(), 4) + bytes(p.uvIndex(), 4);
                        long bound = pr.patchBytes(f, level, smooth);
                        assertTrue(bound >= held, shape + " face " + f + " L" + level + ": patchBytes " + bound + " < " + held);
                        if (level == 4) worst = Math.max(worst, (double) bound / held);
                    }
                }
            }
            System.out.printf("patchBytes/held at level 4, %s: at most %.3f%n", shape, worst);
        }
    }

    private static long bytes(Object a, int each) {
        if (a == null) return 0;
        int n = java.lang.reflect.Array.getLength(a);
        return 16 + ((n * (long) each + 7) & ~7L);
    }

    // ---------------------------------------------------------------- shapes

    /** A u x v torus of quads (major radius R, minor r). */
    static ControlMesh torusCage(int nu, int nv, double big, double small) {
        double[] p = new double[3 * nu * nv];
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                double a = 2 * Math.PI * i / nu, b = 2 * Math.PI * j / nv, rr = big + small * Math.cos(b);
                int k = 3 * (i * nv + j);
                p[k] = rr * Math.cos(a);
                p[k + 1] = rr * Math.sin(a);
                p[k + 2] = small * Math.sin(b);
            }
        }
        int[] sizes = new int[nu * nv], fv = new int[4 * nu * nv];
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                int f = i * nv + j, i1 = (i + 1) % nu, j1 = (j + 1) % nv;
                sizes[f] = 4;
                fv[4 * f] = i * nv + j;
                fv[4 * f + 1] = i1 * nv + j;
                fv[4 * f + 2] = i1 * nv + j1;
                fv[4 * f + 3] = i * nv + j1;
            }
        }
        return ControlMesh.builder(p, sizes, fv).build();
    }

    @Test
    void oneRingBoundsAreTheBoxOfEveryFaceAtTheFacesCorners() {
        for (String shape : Corpus.shapes().keySet()) {
            ControlMesh m = Corpus.load(shape);
            PatchRefiner pr = new PatchRefiner(m);
            int[] sizes = m.faceSizes(), fv = m.faceVertices(), start = new int[sizes.length + 1];
            for (int f = 0; f < sizes.length; f++) start[f + 1] = start[f] + sizes[f];
            double[] p = m.positions(), got = new double[6];
            for (int f = 0; f < sizes.length; f++) {
                double[] want = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                        Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
                for (int c = start[f]; c < start[f + 1]; c++) {
                    for (int g = 0; g < sizes.length; g++) {
                        boolean touches = false;
                        for (int d = start[g]; d < start[g + 1]; d++) touches |= fv[d] == fv[c];
                        if (!touches) continue;
                        for (int d = start[g]; d < start[g + 1]; d++) {
                            for (int k = 0; k < 3; k++) {
                                want[k] = Math.min(want[k], p[3 * fv[d] + k]);
                                want[k + 3] = Math.max(want[k + 3], p[3 * fv[d] + k]);
                            }
                        }
                    }
                }
                pr.oneRingBounds(f, got);
                assertTrue(java.util.Arrays.equals(want, got), shape + " face " + f);
            }
        }
    }

    /** A tetrahedron with {@code extra} more copies of its second face (vertices 0, 3, 1, counted from 0). */
    private static ControlMesh tetrahedronWithRepeatedFace(int extra) {
        double[] p = {1, 1, 1, -1, -1, 1, -1, 1, -1, 1, -1, -1};
        int[] sizes = new int[4 + extra], fv = new int[3 * (4 + extra)];
        int[] tet = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
        System.arraycopy(tet, 0, fv, 0, 12);
        for (int i = 0; i < extra; i++) System.arraycopy(tet, 3, fv, 12 + 3 * i, 3);
        java.util.Arrays.fill(sizes, 3);
        return ControlMesh.builder(p, sizes, fv).source("t.obj").build();
    }

    @Test
    void aVertexSharedByMoreFacesThanTheLimitIsRefusedNamingIt() {
        // Vertex 0 is in 3 faces of the tetrahedron and in every copy: 1024 faces are accepted,
        // and the patches of a face there stay exact.
        PatchRefiner at = new PatchRefiner(tetrahedronWithRepeatedFace(PatchRefiner.MAX_VERTEX_FACES - 3));
        assertEquals(PatchRefiner.MAX_VERTEX_FACES + 1, at.faceCount());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new PatchRefiner(tetrahedronWithRepeatedFace(PatchRefiner.MAX_VERTEX_FACES - 2)));
        assertEquals("t.obj: vertex 0 is shared by 1025 faces (face 0 is the first); adaptive subdivision supports at most 1024 at a vertex"
                + " (repeated faces? refine uniformly with method uniform)", e.getMessage());
        // 20,000 copies (the gathering of every face's one-ring took minutes, then ran out of
        // memory): refused at once.
        assertThrows(IllegalArgumentException.class, () -> new PatchRefiner(tetrahedronWithRepeatedFace(20_000)));
    }
}
