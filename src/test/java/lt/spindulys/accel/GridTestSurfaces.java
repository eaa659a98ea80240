package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * Grids for the grid patch tests and benchmark: a bumpy height field (smooth or jittered), a closed cube-sphere of six grids whose
 * shared edges hold bit-identical vertices, and the brute-force reference (every triangle through
 * {@link WatertightTriangles}, on the same float values widened to double).
 */
final class GridTestSurfaces {
    private GridTestSurfaces() {}

    /** A bumpy height field over [0, 1]^2, vertex (i, j) at (i / (nu - 1), j / (nv - 1), z), |z| <= 0.1. */
    static double[] bumpy(int nu, int nv) {
        double[] p = new double[3 * nu * nv];
        for (int j = 0; j < nv; j++) {
            for (int i = 0; i < nu; i++) {
                double x = (double) i / (nu - 1), y = (double) j / (nv - 1);
                int q = 3 * (j * nu + i);
                p[q] = x;
                p[q + 1] = y;
                p[q + 2] = bump(x, y);
            }
        }
        return p;
    }

    /**
     * {@link #bumpy} with every vertex moved by up to a fifth of a cell in x and y and by up to 0.02 in z, by a hash
     * of its face indices (i, j) alone (so that pieces of one face agree on their shared vertices): cells of every
     * shape, cut along either diagonal about equally often.
     */
    static double[] jittered(int nu, int nv) {
        double[] p = new double[3 * nu * nv];
        for (int j = 0; j < nv; j++) {
            for (int i = 0; i < nu; i++) jitteredVertex(i, j, nu, nv, p, 3 * (j * nu + i));
        }
        return p;
    }

    /** Vertex (i, j) of {@link #jittered}(nu, nv) into out[o..o+2]. */
    static void jitteredVertex(int i, int j, int nu, int nv, double[] out, int o) {
        double x = (double) i / (nu - 1), y = (double) j / (nv - 1);
        out[o] = x + 0.2 * jitter(i, j, 0) / (nu - 1);
        out[o + 1] = y + 0.2 * jitter(i, j, 1) / (nv - 1);
        out[o + 2] = bump(x, y) + 0.02 * jitter(i, j, 2);
    }

    /** A number in [-1, 1) from a hash of (i, j, axis). */
    private static double jitter(int i, int j, int axis) {
        long h = (i * 0x9E3779B97F4A7C15L) ^ (j * 0xC2B2AE3D27D4EB4FL) ^ (axis * 0x165667B19E3779F9L);
        h = (h ^ (h >>> 31)) * 0xBF58476D1CE4E5B9L;
        h ^= h >>> 29;
        return (h >>> 11) * 0x1p-52 - 1;
    }

    static double bump(double x, double y) {
        return 0.06 * Math.sin(7.3 * x + 1) * Math.cos(5.1 * y) + 0.04 * Math.sin(17 * x * y);
    }

    /**
     * Face f (0..5) of a bumpy sphere made from the cube [-1, 1]^3 with n x n vertices per face. A vertex is a
     * function of its integer lattice point alone, so two faces compute the same doubles (and floats) on their
     * shared edge.
     */
    static float[] cubeSphereFace(int f, int n) {
        float[] p = new float[3 * n * n];
        int axis = f >> 1, side = (f & 1) == 0 ? 0 : n - 1;
        int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        int[] lattice = new int[3];
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                lattice[axis] = side;
                // mirror one index on the far side so both windings are exercised
                lattice[a1] = (f & 1) == 0 ? i : n - 1 - i;
                lattice[a2] = j;
                double x = 2.0 * lattice[0] / (n - 1) - 1, y = 2.0 * lattice[1] / (n - 1) - 1, z = 2.0 * lattice[2] / (n - 1) - 1;
                double len = Math.sqrt(x * x + y * y + z * z);
                x /= len; y /= len; z /= len;
                double r = 1 + 0.15 * Math.sin(3 * x + 1) * Math.sin(2 * y) * Math.cos(4 * z);
                int q = 3 * (j * n + i);
                p[q] = (float) (r * x);
                p[q + 1] = (float) (r * y);
                p[q + 2] = (float) (r * z);
            }
        }
        return p;
    }

    /** The grid's triangles in {@code sub} order as index arrays for {@link WatertightTriangles}. */
    static final class Reference {
        final int[] tri;
        final double[] pos;

        Reference(GridPatch g) {
            int n = g.nu() * g.nv();
            pos = new double[3 * n];
            for (int j = 0; j < g.nv(); j++) {
                for (int i = 0; i < g.nu(); i++) {
                    for (int a = 0; a < 3; a++) pos[3 * (j * g.nu() + i) + a] = g.x(i, j, a);
                }
            }
            tri = new int[3 * g.triangleCount()];
            for (int s = 0; s < g.triangleCount(); s++) {
                for (int c = 0; c < 3; c++) tri[3 * s + c] = g.triangleVertex(s, c);
            }
        }

        /** The nearest hit of every triangle; the ray is left alone. */
        boolean intersect(Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
            double saved = ray.tMax;
            boolean any = WatertightTriangles.test(tri, pos, null, 0, tri.length / 3, ray, hit, ctx);
            ray.tMax = saved;
            return any;
        }

        /** Whether triangle {@code s} alone is hit at exactly {@code t}. */
        boolean hitsAt(int s, double t, Ray ray, TraversalScratch ctx) {
            PrimitiveHit h = new PrimitiveHit();
            double saved = ray.tMax;
            boolean any = WatertightTriangles.test(tri, pos, null, s, s + 1, ray, h, ctx);
            ray.tMax = saved;
            return any && h.t == t;
        }

        /** The triangles as a primitive set, for the general BVH the grid is compared with. */
        PrimitiveSet set() {
            return new PrimitiveSet() {
                @Override public int size() { return tri.length / 3; }
                @Override public void bounds(int i, double[] out) { WatertightTriangles.bounds(tri, pos, i, out); }
                @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
                    return WatertightTriangles.test(tri, pos, null, i, i + 1, ray, hit, ctx);
                }
                @Override public boolean occluded(int i, Ray ray, TraversalScratch ctx) {
                    return WatertightTriangles.test(tri, pos, null, i, i + 1, ray, null, ctx);
                }
                @Override public boolean intersectRange(int[] prims, int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
                    return WatertightTriangles.test(tri, pos, prims, from, to, ray, hit, ctx);
                }
                @Override public boolean occludedRange(int[] prims, int from, int to, Ray ray, TraversalScratch ctx) {
                    return WatertightTriangles.test(tri, pos, prims, from, to, ray, null, ctx);
                }
            };
        }
    }
}
