package lt.spindulys.subdiv;

import java.util.Arrays;

import lt.spindulys.mesh.MeshData;

/**
 * The triangles of a refined mesh, the one implementation the uniform surface and the per-face
 * patches ({@link PatchRefiner}) share: positions of the refined vertices, face-varying UVs and,
 * for smooth shading, a normal per corner (the limit normal, or the sector's where sharp edges split a vertex); quads split along the
 * shorter diagonal, other polygons (at level 0) left whole for the triangle mesh's fans, holes
 * dropped. Stateless.
 */
public final class RefinedTriangles {
    private RefinedTriangles() {}

    /**
     * The triangles of every face of a refined mesh. The MeshData shares the mesh's positions and
     * UVs (its vertex and UV indices are the mesh's own).
     *
     * @param r the refined mesh
     * @param smooth a normal per corner (true) or none (flat shading)
     * @return the triangles
     */
    public static MeshData triangles(RefinedMesh r, boolean smooth) {
        return build(r, r.positions(), 0, r.faceCount(), smooth, null);
    }

    /**
     * The triangles of every face of a refined mesh with its vertices at other positions, such as
     * {@link RefinedMesh#limitPositions()} (the corners then lie on the limit surface). The quads'
     * diagonals and the sector normals at sharp edges are taken from these positions, as
     * {@link #triangles(RefinedMesh, boolean)} takes them from the refined ones; the MeshData
     * shares {@code positions} and the mesh's UVs.
     *
     * @param r the refined mesh
     * @param positions x, y, z of every vertex of {@code r}
     * @param smooth a normal per corner (true) or none (flat shading)
     * @return the triangles
     * @throws IllegalArgumentException if {@code positions} does not hold three numbers per vertex
     */
    public static MeshData triangles(RefinedMesh r, double[] positions, boolean smooth) {
        if (positions.length != 3 * r.vertexCount()) {
            throw new IllegalArgumentException(positions.length + " position numbers for " + r.vertexCount() + " vertices (three each)");
        }
        return build(r, positions, 0, r.faceCount(), smooth, null);
    }

    /**
     * The triangles of the faces {@code f0 .. f1-1} only, with their own compact vertex, UV and
     * normal arrays (numbered in order of first use) but every value computed exactly as
     * {@link #triangles(RefinedMesh, boolean)} computes it for the whole mesh.
     *
     * @param vertexMap receives, per vertex of {@code r}, its index in the result or -1 (length
     *                  {@code r.vertexCount()})
     */
    static MeshData triangles(RefinedMesh r, int f0, int f1, boolean smooth, int[] vertexMap) {
        return build(r, r.positions(), f0, f1, smooth, vertexMap);
    }

    /** Compact when {@code vmap} is given, else the whole mesh sharing its arrays; vertices at {@code p}. */
    private static MeshData build(RefinedMesh r, double[] p, int f0, int f1, boolean smooth, int[] vmap) {
        int[] sizes = r.faceSizes(), fv = r.faceVertices(), fuv = r.faceUvs();
        double[] uvs = r.uvs();
        boolean withUv = uvs != null && fuv != null;
        int c0 = 0;
        if (r.level() > 0) c0 = r.topo.triangleSplit ? 3 * f0 : 4 * f0;
        else for (int f = 0; f < f0; f++) c0 += sizes[f];
        int faces = 0, corners = 0;
        for (int f = f0; f < f1; f++) {
            if (r.isHole(f)) continue;
            faces += sizes[f] == 4 ? 2 : 1;
            corners += sizes[f] == 4 ? 6 : sizes[f];
        }
        int[] outSizes = new int[faces], outV = new int[corners], outUv = withUv ? new int[corners] : null;
        int o = 0, k = 0;
        for (int f = f0, c = c0; f < f1; c += sizes[f], f++) {
            if (r.isHole(f)) continue;
            if (sizes[f] == 4) {
                int[] order = split(p, fv, c);
                for (int j : order) {
                    outV[k] = fv[c + j];
                    if (withUv) outUv[k] = fuv[c + j];
                    k++;
                }
                outSizes[o++] = 3;
                outSizes[o++] = 3;
            } else {
                for (int j = 0; j < sizes[f]; j++) {
                    outV[k] = fv[c + j];
                    if (withUv) outUv[k] = fuv[c + j];
                    k++;
                }
                outSizes[o++] = sizes[f];
            }
        }
        int[] outN = smooth ? new int[corners] : null;
        double[] normals = !smooth ? null : vmap != null ? rangeNormals(r, f0, f1, outN) : cornerNormals(r, p, f0, f1, outN, false);
        if (vmap == null) {
            ControlMesh control = r.controlMesh();
            int[] groups = control.faceGroups() == null ? null : groups(r, f0, f1, faces);
            return new MeshData(p, normals, withUv ? uvs : null, outSizes, outV, outN, outUv, null, groups, control.groupNames());
        }
        // Compact: vertices and UVs renumbered in order of first use, values copied unchanged.
        Arrays.fill(vmap, -1);
        int nv = 0;
        for (int i = 0; i < corners; i++) {
            int v = outV[i];
            if (vmap[v] < 0) vmap[v] = nv++;
            outV[i] = vmap[v];
        }
        double[] pos = new double[3 * nv];
        for (int v = 0; v < vmap.length; v++) {
            int m = vmap[v];
            if (m >= 0) System.arraycopy(p, 3 * v, pos, 3 * m, 3);
        }
        double[] outUvs = null;
        if (withUv) {
            int[] umap = new int[uvs.length / 2];
            Arrays.fill(umap, -1);
            int nu = 0;
            double[] u = new double[2 * corners];
            for (int i = 0; i < corners; i++) {
                int t = outUv[i];
                if (umap[t] < 0) {
                    umap[t] = nu;
                    u[2 * nu] = uvs[2 * t];
                    u[2 * nu + 1] = uvs[2 * t + 1];
                    nu++;
                }
                outUv[i] = umap[t];
            }
            outUvs = Arrays.copyOf(u, 2 * nu);
        }
        return new MeshData(pos, normals, outUvs, outSizes, outV, outN, outUv, null);
    }

    /**
     * The face group of every output face of faces {@code f0 .. f1-1} (in the order {@link #build}
     * emits them): the group of the control face each refined face comes from.
     */
    private static int[] groups(RefinedMesh r, int f0, int f1, int faces) {
        int[] control = r.controlMesh().faceGroups(), sizes = r.faceSizes();
        int[] out = new int[faces];
        int[] cornerFace = r.level() > 0 && !r.topo.triangleSplit ? cornerFaces(r.controlMesh().faceSizes()) : null;
        for (int f = f0, o = 0; f < f1; f++) {
            if (r.isHole(f)) continue;
            int g = control[baseFace(r, f, cornerFace)];
            out[o++] = g;
            if (sizes[f] == 4) out[o++] = g;
        }
        return out;
    }

    /**
     * The control face that refined face {@code f} comes from, by Far's numbering: a triangle
     * split makes child faces 4f..4f+3 of face f at every level; a quad split makes one child per
     * parent corner (half-edge) at the first level, numbered as the corners, then 4f..4f+3 of quad
     * f at every further level.
     *
     * @param cornerFace the control face of each control corner (quad split, level above 0), else null
     */
    static int baseFace(RefinedMesh r, int f, int[] cornerFace) {
        int level = r.level();
        if (level == 0) return f;
        if (r.topo.triangleSplit) return f >>> (2 * level);
        return cornerFace[f >>> (2 * (level - 1))];
    }

    /** The face of every corner of faces of the given sizes, in order. */
    static int[] cornerFaces(int[] sizes) {
        int n = 0;
        for (int s : sizes) n += s;
        int[] out = new int[n];
        for (int f = 0, c = 0; f < sizes.length; f++) for (int k = 0; k < sizes[f]; k++) out[c++] = f;
        return out;
    }

    /**
     * The shading normal of every output corner of faces {@code f0 .. f1-1}, written as an index
     * into the returned array to {@code outN} (in the order {@link #build} emits corners): the
     * vertex's limit normal, except where infinitely sharp edges (creases, boundaries, corners)
     * cut the faces around a vertex into several sectors. The limit surface has a tangent plane
     * per sector there and no single normal is right for all, so each corner gets the
     * area-weighted normal of the faces in its own sector and the crease stays crisp in shading.
     * Sectors are summed over every face of the mesh, in face order, whatever the range, so a
     * range gets the values the whole mesh gets. Compact: only the normals the range uses, in
     * order of first use; otherwise every limit normal first (index = vertex), then the sectors'.
     */
    private static double[] cornerNormals(RefinedMesh r, double[] p, int f0, int f1, int[] outN, boolean compact) {
        double[] limit = r.limitNormals();
        int[] sizes = r.faceSizes(), fv = r.faceVertices(), twin = r.cornerTwins();
        boolean[] sharp = r.sharpEdges();
        int nv = p.length / 3, nf = sizes.length, nc = fv.length;
        int[] start = new int[nf + 1], faceOf = new int[nc];
        for (int f = 0; f < nf; f++) {
            start[f + 1] = start[f] + sizes[f];
            for (int c = start[f]; c < start[f + 1]; c++) faceOf[c] = f;
        }
        // Sectors: corners at the same vertex joined across every edge that is neither sharp nor
        // next to a hole (union-find over corners).
        int[] parent = new int[nc];
        for (int c = 0; c < nc; c++) parent[c] = c;
        for (int c = 0; c < nc; c++) {
            int t = twin[c];
            if (t < c || sharp[c] || r.isHole(faceOf[c]) || r.isHole(faceOf[t])) continue;
            // c runs a -> b in its face, t runs b -> a in the neighbour.
            union(parent, c, next(t, faceOf, start));
            union(parent, next(c, faceOf, start), t);
        }
        // Area-weighted face normals (Newell's method) summed per sector.
        double[] sector = new double[3 * nc];
        int[] vertexRoot = new int[nv];
        boolean[] split = new boolean[nv];
        Arrays.fill(vertexRoot, -1);
        for (int f = 0; f < nf; f++) {
            if (r.isHole(f)) continue;
            double x = 0, y = 0, z = 0;
            for (int c = start[f]; c < start[f + 1]; c++) {
                int a = 3 * fv[c], b = 3 * fv[next(c, faceOf, start)];
                x += (p[a + 1] - p[b + 1]) * (p[a + 2] + p[b + 2]);
                y += (p[a + 2] - p[b + 2]) * (p[a] + p[b]);
                z += (p[a] - p[b]) * (p[a + 1] + p[b + 1]);
            }
            for (int c = start[f]; c < start[f + 1]; c++) {
                int root = find(parent, c), v = fv[c];
                sector[3 * root] += x; sector[3 * root + 1] += y; sector[3 * root + 2] += z;
                if (vertexRoot[v] < 0) vertexRoot[v] = root;
                else if (vertexRoot[v] != root) split[v] = true;
            }
        }
        double[] normals;
        int count;
        int[] vertexNormal = null;
        if (compact) {
            normals = new double[3 * outN.length];
            count = 0;
            vertexNormal = new int[nv];
            Arrays.fill(vertexNormal, -1);
        } else {
            normals = Arrays.copyOf(limit, limit.length + 3 * nc);
            count = nv;
        }
        int[] sectorNormal = new int[nc];
        Arrays.fill(sectorNormal, -1);
        int k = 0;
        for (int f = f0; f < f1; f++) {
            if (r.isHole(f)) continue;
            int[] order = sizes[f] == 4 ? split(p, fv, start[f]) : null;
            int n = order != null ? 6 : sizes[f];
            for (int m = 0; m < n; m++) {
                int c = start[f] + (order != null ? order[m] : m), v = fv[c];
                int root = find(parent, c);
                double x = sector[3 * root], y = sector[3 * root + 1], z = sector[3 * root + 2];
                double len = Math.sqrt(x * x + y * y + z * z);
                if (!split[v] || !(len > 0) || !Double.isFinite(len)) {
                    if (!compact) {
                        outN[k++] = v;
                    } else {
                        if (vertexNormal[v] < 0) {
                            System.arraycopy(limit, 3 * v, normals, 3 * count, 3);
                            vertexNormal[v] = count++;
                        }
                        outN[k++] = vertexNormal[v];
                    }
                    continue;
                }
                if (sectorNormal[root] < 0) {
                    // Unit length like the limit normals, so that interpolation weighs them alike.
                    normals[3 * count] = x / len;
                    normals[3 * count + 1] = y / len;
                    normals[3 * count + 2] = z / len;
                    sectorNormal[root] = count++;
                }
                outN[k++] = sectorNormal[root];
            }
        }
        return Arrays.copyOf(normals, 3 * count);
    }

    /**
     * {@link #cornerNormals} for a compact range: the same values, but only the faces that touch
     * a vertex of the range are visited (in face order, so every sector sums in the same order)
     * and only those vertices' limit normals are evaluated.
     */
    private static double[] rangeNormals(RefinedMesh r, int f0, int f1, int[] outN) {
        Level lv = r.topo;
        double[] p = r.positions();
        int[] sizes = r.faceSizes(), fv = r.faceVertices(), twin = r.cornerTwins();
        int nv = p.length / 3, nf = sizes.length;
        boolean quads = lv.faceStart == null;
        if (lv.eSharp != null) lv.edgeCodes();
        boolean[] want = new boolean[nv];
        for (int c = lv.firstHalf(f0), e = f1 < nf ? lv.firstHalf(f1) : lv.nH; c < e; c++) want[fv[c]] = true;
        double[] limit = new double[3 * nv];
        Limit.evaluate(lv, SchemeRules.of(r.controlMesh().options()), p, null, limit, want);
        // The faces that touch the range's vertices, and their corners numbered compactly.
        int[] faceAt = new int[nf], faces = new int[nf], cornerAt = new int[nf + 1];
        int m = 0;
        for (int f = 0; f < nf; f++) {
            faceAt[f] = -1;
            int s = lv.firstHalf(f), n = quads ? 4 : sizes[f];
            boolean any = false;
            for (int c = s; c < s + n && !any; c++) any = want[fv[c]];
            if (!any) continue;
            faceAt[f] = m;
            faces[m] = f;
            cornerAt[m + 1] = cornerAt[m] + n;
            m++;
        }
        int nc = cornerAt[m];
        int[] parent = new int[nc];
        for (int c = 0; c < nc; c++) parent[c] = c;
        for (int i = 0; i < m; i++) {
            int f = faces[i], s = lv.firstHalf(f), n = cornerAt[i + 1] - cornerAt[i];
            if (r.isHole(f)) continue;
            for (int k = 0; k < n; k++) {
                int c = s + k, t = twin[c];
                if (t < c || Crease.isInfinite(lv.edgeSharpness(c))) continue;
                int cn = s + (k + 1 == n ? 0 : k + 1);
                if (!want[fv[c]] && !want[fv[cn]]) continue; // the neighbour may not be listed
                int g = lv.face(t), j = faceAt[g];
                if (r.isHole(g)) continue;
                int gs = lv.firstHalf(g), gn = cornerAt[j + 1] - cornerAt[j], tk = t - gs, tn = gs + (tk + 1 == gn ? 0 : tk + 1);
                // c runs a -> b in its face, t runs b -> a in the neighbour.
                if (want[fv[c]]) union(parent, cornerAt[i] + k, cornerAt[j] + (tn - gs));
                if (want[fv[cn]]) union(parent, cornerAt[i] + (cn - s), cornerAt[j] + tk);
            }
        }
        double[] sector = new double[3 * nc];
        int[] vertexRoot = new int[nv];
        boolean[] split = new boolean[nv];
        Arrays.fill(vertexRoot, -1);
        for (int i = 0; i < m; i++) {
            int f = faces[i];
            if (r.isHole(f)) continue;
            int s = lv.firstHalf(f), n = cornerAt[i + 1] - cornerAt[i];
            double x = 0, y = 0, z = 0;
            for (int k = 0; k < n; k++) {
                int a = 3 * fv[s + k], b = 3 * fv[s + (k + 1 == n ? 0 : k + 1)];
                x += (p[a + 1] - p[b + 1]) * (p[a + 2] + p[b + 2]);
                y += (p[a + 2] - p[b + 2]) * (p[a] + p[b]);
                z += (p[a] - p[b]) * (p[a + 1] + p[b + 1]);
            }
            for (int k = 0; k < n; k++) {
                int root = find(parent, cornerAt[i] + k), v = fv[s + k];
                sector[3 * root] += x; sector[3 * root + 1] += y; sector[3 * root + 2] += z;
                if (vertexRoot[v] < 0) vertexRoot[v] = root;
                else if (vertexRoot[v] != root) split[v] = true;
            }
        }
        double[] normals = new double[3 * outN.length];
        int count = 0;
        int[] vertexNormal = new int[nv];
        Arrays.fill(vertexNormal, -1);
        int[] sectorNormal = new int[nc];
        Arrays.fill(sectorNormal, -1);
        int k = 0;
        for (int f = f0; f < f1; f++) {
            if (r.isHole(f)) continue;
            int s = lv.firstHalf(f), i = faceAt[f];
            int[] order = sizes[f] == 4 ? split(p, fv, s) : null;
            int n = order != null ? 6 : sizes[f];
            for (int q = 0; q < n; q++) {
                int j = order != null ? order[q] : q, v = fv[s + j];
                int root = find(parent, cornerAt[i] + j);
                double x = sector[3 * root], y = sector[3 * root + 1], z = sector[3 * root + 2];
                double len = Math.sqrt(x * x + y * y + z * z);
                if (!split[v] || !(len > 0) || !Double.isFinite(len)) {
                    if (vertexNormal[v] < 0) {
                        System.arraycopy(limit, 3 * v, normals, 3 * count, 3);
                        vertexNormal[v] = count++;
                    }
                    outN[k++] = vertexNormal[v];
                    continue;
                }
                if (sectorNormal[root] < 0) {
                    // Unit length like the limit normals, so that interpolation weighs them alike.
                    normals[3 * count] = x / len;
                    normals[3 * count + 1] = y / len;
                    normals[3 * count + 2] = z / len;
                    sectorNormal[root] = count++;
                }
                outN[k++] = sectorNormal[root];
            }
        }
        return Arrays.copyOf(normals, 3 * count);
    }

    private static int next(int c, int[] faceOf, int[] start) {
        int f = faceOf[c];
        return c + 1 == start[f + 1] ? start[f] : c + 1;
    }

    private static int find(int[] parent, int c) {
        while (parent[c] != c) c = parent[c] = parent[parent[c]];
        return c;
    }

    private static void union(int[] parent, int a, int b) {
        a = find(parent, a);
        b = find(parent, b);
        if (a != b) parent[Math.max(a, b)] = Math.min(a, b);
    }

    /** Corners of the two triangles of a quad abcd cut along ac, or along bd; both keep the winding. */
    private static final int[] SPLIT_AC = {0, 1, 2, 0, 2, 3}, SPLIT_BD = {0, 1, 3, 1, 2, 3};

    /**
     * How the quad whose corners start at {@code c} is cut: along the shorter diagonal, which keeps
     * the two triangles closest to the (curved) quad.
     */
    private static int[] split(double[] p, int[] fv, int c) {
        return dist2(p, fv[c], fv[c + 2]) <= dist2(p, fv[c + 1], fv[c + 3]) ? SPLIT_AC : SPLIT_BD;
    }

    private static double dist2(double[] p, int a, int b) {
        double dx = p[3 * a] - p[3 * b], dy = p[3 * a + 1] - p[3 * b + 1], dz = p[3 * a + 2] - p[3 * b + 2];
        return dx * dx + dy * dy + dz * dz;
    }
}
