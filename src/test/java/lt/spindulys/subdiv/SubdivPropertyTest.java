package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Seeded properties of refinement that hold for any input of the kind generated. */
class SubdivPropertyTest {

    /** A closed mesh: a torus of nu x nv quads (some split into triangles), jittered. */
    static ControlMesh randomTorus(Random rnd, boolean creases) {
        int nu = 3 + rnd.nextInt(6), nv = 3 + rnd.nextInt(6);
        double[] p = new double[3 * nu * nv];
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                double a = 2 * Math.PI * i / nu, b = 2 * Math.PI * j / nv, r = 2 + Math.cos(b);
                int v = 3 * (i * nv + j);
                p[v] = r * Math.cos(a) + 0.2 * rnd.nextGaussian();
                p[v + 1] = r * Math.sin(a) + 0.2 * rnd.nextGaussian();
                p[v + 2] = Math.sin(b) + 0.2 * rnd.nextGaussian();
            }
        }
        int[] sizes = new int[2 * nu * nv];
        int[] fv = new int[4 * nu * nv * 2];
        int nf = 0, nc = 0;
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                int a = i * nv + j, b = ((i + 1) % nu) * nv + j, c = ((i + 1) % nu) * nv + (j + 1) % nv, d = i * nv + (j + 1) % nv;
                if (rnd.nextInt(4) == 0) {
                    sizes[nf++] = 3;
                    fv[nc++] = a; fv[nc++] = b; fv[nc++] = c;
                    sizes[nf++] = 3;
                    fv[nc++] = a; fv[nc++] = c; fv[nc++] = d;
                } else {
                    sizes[nf++] = 4;
                    fv[nc++] = a; fv[nc++] = b; fv[nc++] = c; fv[nc++] = d;
                }
            }
        }
        ControlMesh.Builder bld = ControlMesh.builder(p, java.util.Arrays.copyOf(sizes, nf), java.util.Arrays.copyOf(fv, nc));
        if (creases) {
            for (int k = 0; k < 4; k++) {
                int i = rnd.nextInt(nu), j = rnd.nextInt(nv);
                bld.crease(i * nv + j, ((i + 1) % nu) * nv + j, ControlMesh.INFINITELY_SHARP);
            }
        }
        return bld.build();
    }

    @ParameterizedTest
    @ValueSource(longs = {1, 2, 3, 4, 5, 6})
    void closedMeshesStayClosed(long seed) {
        ControlMesh m = randomTorus(new Random(seed), seed % 2 == 0);
        RefinedMesh r = CatmullClark.refine(m, 0);
        int euler = r.vertexCount() - r.edgeCount() + r.faceCount();
        assertEquals(0, euler, "a torus has Euler characteristic 0");
        for (int level = 1; level <= 3; level++) {
            r = r.refine();
            Level t = r.topo;
            for (int h = 0; h < t.nH; h++) {
                assertTrue(t.hTwin[h] >= 0, "level " + level + ": half-edge " + h + " has no twin");
                assertEquals(h, t.hTwin[t.hTwin[h]]);
                assertEquals(t.hOrig[h], t.dest(t.hTwin[h]), "twins run opposite ways");
                assertEquals(t.edge(h), t.edge(t.hTwin[h]));
            }
            assertEquals(t.nH / 2, r.edgeCount());
            assertEquals(euler, r.vertexCount() - r.edgeCount() + r.faceCount(), "Euler characteristic at level " + level);
            assertEquals(4 * r.faceCount(), r.faceVertices().length);
        }
    }

    @ParameterizedTest
    @ValueSource(longs = {11, 12, 13, 14})
    void planarGridRefinesToPlanarGrid(long seed) {
        Random rnd = new Random(seed);
        int nx = 2 + rnd.nextInt(5), ny = 2 + rnd.nextInt(5);
        // A random plane through a random origin, spanned by orthonormal u and w.
        double[] o = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        double[] u = unit(new double[] {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()});
        double[] w = unit(cross(u, new double[] {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()}));
        double[] n = cross(u, w);
        double[] p = new double[3 * (nx + 1) * (ny + 1)];
        for (int i = 0; i <= nx; i++) {
            for (int j = 0; j <= ny; j++) {
                double s = i + 0.3 * (rnd.nextDouble() - 0.5), t = j + 0.3 * (rnd.nextDouble() - 0.5);
                for (int d = 0; d < 3; d++) p[3 * (i * (ny + 1) + j) + d] = o[d] + s * u[d] + t * w[d];
            }
        }
        int[] sizes = new int[nx * ny], fv = new int[4 * nx * ny];
        for (int i = 0, f = 0; i < nx; i++) {
            for (int j = 0; j < ny; j++, f++) {
                sizes[f] = 4;
                fv[4 * f] = i * (ny + 1) + j;
                fv[4 * f + 1] = (i + 1) * (ny + 1) + j;
                fv[4 * f + 2] = (i + 1) * (ny + 1) + j + 1;
                fv[4 * f + 3] = i * (ny + 1) + j + 1;
            }
        }
        SubdivOptions.Boundary[] modes = SubdivOptions.Boundary.values();
        ControlMesh m = ControlMesh.builder(p, sizes, fv)
                .options(SubdivOptions.DEFAULT.withBoundary(modes[rnd.nextInt(modes.length)])).build();
        RefinedMesh r = CatmullClark.refine(m, 3);
        assertEquals(16 * nx * ny * 4, r.faceCount());
        double[] q = r.positions(), lp = r.limitPositions(), ln = r.limitNormals();
        // Faces wind counter-clockwise seen from +n, so every normal is n.
        for (int v = 0; v < r.vertexCount(); v++) {
            assertEquals(0, dot(n, sub(q, v, o)), 1e-12, "refined vertex " + v + " off the plane");
            assertEquals(0, dot(n, sub(lp, v, o)), 1e-12, "limit of vertex " + v + " off the plane");
            assertArrayEquals(n, new double[] {ln[3 * v], ln[3 * v + 1], ln[3 * v + 2]}, 1e-9, "normal of vertex " + v);
        }
    }

    /**
     * The limit of a vertex does not depend on the level it is computed from, and refined
     * positions approach it: the exact-limit property of Sdc's masks, checked on smooth closed
     * meshes (all vertices smooth, valence 3 and more).
     */
    @ParameterizedTest
    @ValueSource(longs = {21, 22, 23, 24})
    void refinedVerticesConvergeToTheirLimit(long seed) {
        ControlMesh m = randomTorus(new Random(seed), false);
        RefinedMesh r0 = CatmullClark.refine(m, 1); // level 1: quads only, every vertex smooth
        double[] limit = r0.limitPositions(), normal = r0.limitNormals();
        double size = 0;
        for (double x : m.positions()) size = Math.max(size, Math.abs(x));
        double prevDist = Double.MAX_VALUE;
        RefinedMesh r = r0;
        for (int level = 2; level <= 5; level++) {
            r = r.refine();
            double[] q = r.positions(), lq = r.limitPositions(), nq = r.limitNormals();
            double dist = 0;
            for (int v = 0; v < r0.vertexCount(); v++) {
                for (int d = 0; d < 3; d++) {
                    dist = Math.max(dist, Math.abs(q[3 * v + d] - limit[3 * v + d]));
                    assertEquals(limit[3 * v + d], lq[3 * v + d], 1e-12 * size, "limit of vertex " + v + " at level " + level);
                    assertEquals(normal[3 * v + d], nq[3 * v + d], 1e-9, "normal of vertex " + v + " at level " + level);
                }
            }
            assertTrue(dist < prevDist * 0.6, "level " + level + ": distance to the limit " + dist + " after " + prevDist);
            prevDist = dist;
        }
        assertTrue(prevDist < 1e-2 * size);
    }

    private static double[] unit(double[] a) {
        double l = Math.sqrt(dot(a, a));
        return new double[] {a[0] / l, a[1] / l, a[2] / l};
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

    private static double[] sub(double[] p, int v, double[] o) {
        return new double[] {p[3 * v] - o[0], p[3 * v + 1] - o[1], p[3 * v + 2] - o[2]};
    }
}
