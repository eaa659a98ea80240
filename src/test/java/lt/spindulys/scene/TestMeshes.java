package lt.spindulys.scene;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import lt.spindulys.mesh.MeshData;

/** Meshes generated for tests: closed solids with shared vertices, and triangle soups. */
public final class TestMeshes {
    /** An octahedron: eight triangles, closed (every subdivision scheme refines it). */
    public static final String OCTAHEDRON_OBJ = """
            v 1 0 0
            v -1 0 0
            v 0 1 0
            v 0 -1 0
            v 0 0 1
            v 0 0 -1
            f 1 3 5
            f 3 2 5
            f 2 4 5
            f 4 1 5
            f 3 1 6
            f 2 3 6
            f 4 2 6
            f 1 4 6
            """;

    /** The cube [-1, 1]^3 as OBJ text, outward quads; vertices 0..7 as in scenes/models/crease-cube.obj. */
    public static final String CUBE_OBJ = """
            v -1 -1 -1
            v  1 -1 -1
            v  1  1 -1
            v -1  1 -1
            v -1 -1  1
            v  1 -1  1
            v  1  1  1
            v -1  1  1
            f 1 4 3 2
            f 5 6 7 8
            f 1 2 6 5
            f 3 4 8 7
            f 2 3 7 6
            f 1 5 8 4
            """;

    private TestMeshes() {}

    /** Triangles given as nine coordinates each (a soup: no shared vertices). */
    public static MeshData soup(double[] coords) {
        int n = coords.length / 9;
        int[] sizes = new int[n], idx = new int[3 * n];
        java.util.Arrays.fill(sizes, 3);
        for (int i = 0; i < 3 * n; i++) idx[i] = i;
        return new MeshData(coords.clone(), null, null, sizes, idx, null, null, "soup");
    }

    /** The cube [-1, 1]^3 as eight vertices and six counter-clockwise (outward) quads. */
    public static MeshData cube() {
        return gridCube(1);
    }

    /**
     * The cube [-1, 1]^3 with each face an n x n grid of quads sharing vertices with their
     * neighbours and across the cube's edges (many shared edges and vertices).
     */
    public static MeshData gridCube(int n) {
        Map<Long, Integer> index = new HashMap<>();
        List<Double> pos = new ArrayList<>();
        List<Integer> faces = new ArrayList<>();
        for (int axis = 0; axis < 3; axis++) {
            int ua = (axis + 1) % 3, va = (axis + 2) % 3;
            for (int sign = -1; sign <= 1; sign += 2) {
                for (int i = 0; i < n; i++) {
                    for (int j = 0; j < n; j++) {
                        int[][] corners = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                        int[] q = new int[4];
                        for (int c = 0; c < 4; c++) {
                            int[] g = new int[3];
                            g[axis] = sign < 0 ? 0 : n;
                            g[ua] = corners[c][0];
                            g[va] = corners[c][1];
                            long key = ((long) g[0] * (n + 1) + g[1]) * (n + 1) + g[2];
                            q[c] = index.computeIfAbsent(key, k -> {
                                for (int a = 0; a < 3; a++) pos.add(-1 + 2.0 * g[a] / n);
                                return pos.size() / 3 - 1;
                            });
                        }
                        // e_u x e_v = e_axis, so this order faces +axis; reverse it on the - side.
                        if (sign > 0) for (int c = 0; c < 4; c++) faces.add(q[c]);
                        else for (int c = 3; c >= 0; c--) faces.add(q[c]);
                    }
                }
            }
        }
        return quads(pos, faces, "gridCube" + n);
    }

    /** The cube [-1, 1]^3 as in {@link #cube()} but every face with its own four vertices (24 in all). */
    public static MeshData splitCube() {
        MeshData c = cube();
        int[] vi = c.vertexIndex();
        double[] p = new double[3 * vi.length];
        int[] idx = new int[vi.length];
        for (int k = 0; k < vi.length; k++) {
            System.arraycopy(c.positions(), 3 * vi[k], p, 3 * k, 3);
            idx[k] = k;
        }
        return new MeshData(p, null, null, c.faceSizes(), idx, null, null, "splitCube");
    }

    private static MeshData quads(List<Double> pos, List<Integer> faces, String name) {
        double[] p = pos.stream().mapToDouble(Double::doubleValue).toArray();
        int[] idx = faces.stream().mapToInt(Integer::intValue).toArray();
        int[] sizes = new int[idx.length / 4];
        java.util.Arrays.fill(sizes, 4);
        return new MeshData(p, null, null, sizes, idx, null, null, name);
    }

    /** A subdivided icosahedron on the sphere of the given radius, outward winding, shared vertices. */
    public static MeshData icosphere(int subdivisions, double radius) {
        double t = (1 + Math.sqrt(5)) / 2;
        List<double[]> v = new ArrayList<>();
        double[][] base = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
        for (double[] b : base) v.add(unit(b));
        int[][] f = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6},
                {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        List<int[]> tris = new ArrayList<>(List.of(f));
        for (int s = 0; s < subdivisions; s++) {
            Map<Long, Integer> mid = new HashMap<>();
            List<int[]> next = new ArrayList<>();
            for (int[] tr : tris) {
                int ab = midpoint(v, mid, tr[0], tr[1]), bc = midpoint(v, mid, tr[1], tr[2]), ca = midpoint(v, mid, tr[2], tr[0]);
                next.add(new int[] {tr[0], ab, ca});
                next.add(new int[] {tr[1], bc, ab});
                next.add(new int[] {tr[2], ca, bc});
                next.add(new int[] {ab, bc, ca});
            }
            tris = next;
        }
        double[] p = new double[3 * v.size()];
        for (int i = 0; i < v.size(); i++) for (int a = 0; a < 3; a++) p[3 * i + a] = radius * v.get(i)[a];
        int[] idx = new int[3 * tris.size()];
        for (int i = 0; i < tris.size(); i++) {
            int[] tr = tris.get(i);
            double[] a = v.get(tr[0]), b = v.get(tr[1]), c = v.get(tr[2]);
            double[] n = cross(sub(b, a), sub(c, a));
            boolean outward = n[0] * a[0] + n[1] * a[1] + n[2] * a[2] > 0;
            idx[3 * i] = tr[0];
            idx[3 * i + 1] = outward ? tr[1] : tr[2];
            idx[3 * i + 2] = outward ? tr[2] : tr[1];
        }
        int[] sizes = new int[tris.size()];
        java.util.Arrays.fill(sizes, 3);
        return new MeshData(p, null, null, sizes, idx, null, null, "icosphere" + subdivisions);
    }

    private static int midpoint(List<double[]> v, Map<Long, Integer> cache, int a, int b) {
        long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
        return cache.computeIfAbsent(key, k -> {
            double[] p = v.get(a), q = v.get(b);
            v.add(unit(new double[] {p[0] + q[0], p[1] + q[1], p[2] + q[2]}));
            return v.size() - 1;
        });
    }

    private static double[] unit(double[] p) {
        double l = Math.sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        return new double[] {p[0] / l, p[1] / l, p[2] / l};
    }

    private static double[] sub(double[] a, double[] b) { return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
