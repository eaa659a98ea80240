package lt.spindulys.viewer;

import lt.spindulys.math.Bounds;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.RefinedTriangles;

/**
 * What the rasterizer draws of one surface, as flat arrays: positions, shading normals,
 * triangles with a normal index per corner, and edges as index pairs into the positions. Floats,
 * because the display needs no more and the arrays are half the size. Immutable by convention.
 *
 * @param positions x, y, z per vertex
 * @param normals x, y, z per shading normal (unit length)
 * @param triangles three vertex indices per triangle
 * @param cornerNormals a normal index per triangle corner, parallel to {@code triangles}
 * @param edges two vertex indices per edge
 */
public record DisplayGeometry(float[] positions, float[] normals, int[] triangles, int[] cornerNormals, int[] edges) {
    private static final int[] NONE = new int[0];
    private static final float[] NO_FLOATS = new float[0];

    /** {@return the number of vertices} */
    public int vertexCount() { return positions.length / 3; }
    /** {@return the number of triangles} */
    public int triangleCount() { return triangles.length / 3; }
    /** {@return the number of edges} */
    public int edgeCount() { return edges.length / 2; }

    /** {@return the bytes of the arrays, for keeping the cache's size in check} */
    public long bytes() {
        return 4L * (positions.length + normals.length + triangles.length + cornerNormals.length + edges.length);
    }

    /** {@return the box around the vertices (empty without any)} */
    public Bounds bounds() {
        Bounds b = Bounds.EMPTY;
        for (int i = 0; i < positions.length; i += 3) b = b.union(positions[i], positions[i + 1], positions[i + 2]);
        return b;
    }

    /**
     * The volume the triangles enclose, signed: the sum over triangles of det(p0, p1, p2) / 6,
     * positive when a closed surface's faces wind counter-clockwise seen from outside, negative
     * when they wind clockwise. Only meaningful for a closed surface.
     *
     * @return the signed volume
     */
    public double signedVolume() {
        float[] p = positions;
        double v = 0;
        for (int i = 0; i < triangles.length; i += 3) {
            int a = 3 * triangles[i], b = 3 * triangles[i + 1], c = 3 * triangles[i + 2];
            double ax = p[a], ay = p[a + 1], az = p[a + 2], bx = p[b], by = p[b + 1], bz = p[b + 2], cx = p[c], cy = p[c + 1], cz = p[c + 2];
            v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
        }
        return v / 6;
    }

    /**
     * This closed surface with every triangle wound counter-clockwise seen from outside: the
     * triangles are made to agree with their neighbours across each edge (a file may wind a few
     * faces the other way round, as gourd.obj's end caps are), and then all turned round if the
     * volume they enclose is negative (a file wound clockwise). A turned triangle gets its
     * normals negated, so it is lit as before from its new front. Only for a closed surface
     * (see {@link #closed}); a surface already wound so is returned as it is.
     *
     * @return the geometry wound outwards (this one if nothing needs turning)
     */
    public DisplayGeometry outward() {
        int t = triangleCount(), halves = 3 * t;
        if (t == 0) return this;
        // Half-edges matched across their edge by an open-addressing table over the edge's two vertex indices.
        int cap = Integer.highestOneBit(Math.max(4, 2 * halves - 1)) << 1;
        long[] keys = new long[cap];
        int[] slot = new int[cap];
        java.util.Arrays.fill(keys, -1);
        int[] twin = new int[halves];
        java.util.Arrays.fill(twin, -1);
        long nv = vertexCount();
        for (int h = 0; h < halves; h++) {
            int a = triangles[h], b = triangles[h - h % 3 + (h % 3 + 1) % 3];
            long key = Math.min(a, b) * nv + Math.max(a, b);
            int i = (int) (key * 0x9E3779B97F4A7C15L >>> 40) & (cap - 1);
            while (keys[i] != -1 && keys[i] != key) i = (i + 1) & (cap - 1);
            if (keys[i] == -1) {
                keys[i] = key;
                slot[i] = h;
            } else if (twin[slot[i]] == -1 && slot[i] / 3 != h / 3) {
                twin[slot[i]] = h;
                twin[h] = slot[i];
            } // a third triangle on an edge (non-manifold): left unmatched
        }
        // Flood each connected piece from its first triangle: a neighbour that runs the shared
        // edge the same way round is turned relative to the triangle it was reached from.
        boolean[] flip = new boolean[t], seen = new boolean[t];
        int[] queue = new int[t];
        for (int start = 0; start < t; start++) {
            if (seen[start]) continue;
            seen[start] = true;
            int head = 0, tail = 0;
            queue[tail++] = start;
            while (head < tail) {
                int u = queue[head++];
                for (int c = 0; c < 3; c++) {
                    int h = 3 * u + c, o = twin[h];
                    if (o < 0 || seen[o / 3]) continue;
                    boolean sameWay = triangles[o] == triangles[h];
                    flip[o / 3] = flip[u] ^ sameWay;
                    seen[o / 3] = true;
                    queue[tail++] = o / 3;
                }
            }
        }
        float[] p = positions;
        double v = 0;
        for (int i = 0; i < t; i++) {
            int a = 3 * triangles[3 * i], b = 3 * triangles[3 * i + 1], c = 3 * triangles[3 * i + 2];
            double d = p[a] * ((double) p[b + 1] * p[c + 2] - (double) p[b + 2] * p[c + 1])
                    - p[a + 1] * ((double) p[b] * p[c + 2] - (double) p[b + 2] * p[c])
                    + p[a + 2] * ((double) p[b] * p[c + 1] - (double) p[b + 1] * p[c]);
            v += flip[i] ? -d : d;
        }
        boolean all = v < 0;
        boolean any = false;
        for (int i = 0; i < t && !any; i++) any = flip[i] != all;
        if (!any) return this;
        int n = normals.length / 3;
        float[] nn = java.util.Arrays.copyOf(normals, 2 * normals.length);
        for (int i = 0; i < normals.length; i++) nn[normals.length + i] = -normals[i];
        int[] tt = triangles.clone(), cn = cornerNormals.clone();
        for (int i = 0; i < t; i++) {
            if (flip[i] == all) continue;
            int k = 3 * i;
            tt[k + 1] = triangles[k + 2];
            tt[k + 2] = triangles[k + 1];
            cn[k] = cornerNormals[k] + n;
            cn[k + 1] = cornerNormals[k + 2] + n;
            cn[k + 2] = cornerNormals[k + 1] + n;
        }
        return new DisplayGeometry(positions, nn, tt, cn, edges);
    }

    /**
     * Whether a mesh is closed, so that it has an inside: no holes, and every edge shared by
     * exactly two faces. The faces' winding need not agree across an edge (a file may wind a few
     * faces the other way round); what is closed still encloses a volume.
     *
     * @param r the mesh (the control mesh refined 0 times will do: refinement keeps it closed or open)
     * @return true if closed
     */
    public static boolean closed(RefinedMesh r) {
        int[] sizes = r.faceSizes(), fv = r.faceVertices();
        if (r.hasHoles() || fv.length == 0) return false;
        long[] edges = new long[fv.length];
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int j = 0; j < sizes[f]; j++) {
                long a = fv[c + j], b = fv[c + (j + 1) % sizes[f]];
                edges[c + j] = Math.min(a, b) << 32 | Math.max(a, b);
            }
        }
        java.util.Arrays.sort(edges);
        for (int i = 0; i < edges.length; i += 2) {
            if (i + 1 >= edges.length || edges[i] != edges[i + 1] || (i + 2 < edges.length && edges[i + 2] == edges[i])) return false;
        }
        return true;
    }

    /**
     * The polyhedron: every face of the refined mesh (the control mesh at level 0) flat shaded
     * with its own normal (Newell's, so a non-planar face still gets one normal), fanned into
     * triangles; holes left out.
     *
     * @param r the refined mesh
     * @return the geometry, without edges
     */
    public static DisplayGeometry polyhedron(RefinedMesh r) {
        double[] p = r.positions();
        int[] sizes = r.faceSizes(), fv = r.faceVertices();
        int tris = 0, faces = 0;
        for (int f = 0; f < sizes.length; f++) {
            if (r.isHole(f)) continue;
            tris += sizes[f] - 2;
            faces++;
        }
        int[] t = new int[3 * tris], cn = new int[3 * tris];
        float[] n = new float[3 * faces];
        int k = 0, nf = 0;
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            if (r.isHole(f)) continue;
            int s = sizes[f];
            double x = 0, y = 0, z = 0;
            for (int j = 0; j < s; j++) {
                int a = 3 * fv[c + j], b = 3 * fv[c + (j + 1) % s];
                x += (p[a + 1] - p[b + 1]) * (p[a + 2] + p[b + 2]);
                y += (p[a + 2] - p[b + 2]) * (p[a] + p[b]);
                z += (p[a] - p[b]) * (p[a + 1] + p[b + 1]);
            }
            putUnit(n, nf, x, y, z);
            for (int j = 1; j + 1 < s; j++) {
                t[k] = fv[c]; t[k + 1] = fv[c + j]; t[k + 2] = fv[c + j + 1];
                cn[k] = cn[k + 1] = cn[k + 2] = nf;
                k += 3;
            }
            nf++;
        }
        return new DisplayGeometry(toFloats(p), n, t, cn, NONE);
    }

    /**
     * The smoothed surface: the refined mesh's triangles as the ray tracer makes them
     * ({@link RefinedTriangles}: quads split along the shorter diagonal, holes left out), shaded
     * with the limit normals (split where sharp edges meet at a vertex).
     *
     * @param r the refined mesh
     * @return the geometry, without edges
     */
    public static DisplayGeometry smoothed(RefinedMesh r) {
        MeshData m = RefinedTriangles.triangles(r, true);
        int[] sizes = m.faceSizes(), vi = m.vertexIndex(), ni = m.normalIndex();
        int tris = 0;
        for (int s : sizes) tris += s - 2;
        int[] t = new int[3 * tris], cn = new int[3 * tris];
        int k = 0;
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int j = 1; j + 1 < sizes[f]; j++) {
                t[k] = vi[c]; t[k + 1] = vi[c + j]; t[k + 2] = vi[c + j + 1];
                cn[k] = ni[c]; cn[k + 1] = ni[c + j]; cn[k + 2] = ni[c + j + 1];
                k += 3;
            }
        }
        double[] nd = m.normals();
        float[] n = new float[nd.length];
        for (int i = 0; i < nd.length; i += 3) putUnit(n, i / 3, nd[i], nd[i + 1], nd[i + 2]);
        return new DisplayGeometry(toFloats(m.positions()), n, t, cn, NONE);
    }

    /**
     * The lattice: every edge of the control cage once (a non-manifold edge once per instance,
     * as the control mesh numbers it), holes' edges included.
     *
     * @param control the control mesh
     * @return the geometry, without triangles
     */
    public static DisplayGeometry lattice(ControlMesh control) {
        RefinedMesh base = Subdivision.refine(control, 0);
        return new DisplayGeometry(toFloats(control.positions()), NO_FLOATS, NONE, NONE, base.edgeVertices());
    }

    private static void putUnit(float[] n, int i, double x, double y, double z) {
        double len = Math.sqrt(x * x + y * y + z * z);
        // A degenerate face or normal shades as if facing the viewer's light at a right angle: dark, not NaN.
        if (!(len > 0) || !Double.isFinite(len)) return;
        n[3 * i] = (float) (x / len);
        n[3 * i + 1] = (float) (y / len);
        n[3 * i + 2] = (float) (z / len);
    }

    private static float[] toFloats(double[] d) {
        float[] f = new float[d.length];
        for (int i = 0; i < d.length; i++) f[i] = (float) d[i];
        return f;
    }
}
