package lt.spindulys.subdiv;

import java.util.HashMap;
import java.util.Map;

/**
 * Uniform Catmull-Clark refinement with OpenSubdiv's rules. Stateless.
 *
 * <p>TEMPORARY body for the renderer branch: textbook smooth, crease and corner rules with
 * uniform sharpness decay, boundaries as infinitely sharp creases, linear UVs; manifold meshes
 * only. Replaced by the core's version.
 */
public final class CatmullClark {
    private CatmullClark() {}

    /** The mesh refined {@code level} times (0 gives the control mesh itself as a RefinedMesh). */
    public static RefinedMesh refine(ControlMesh mesh, int level) {
        if (level < 0) throw new IllegalArgumentException("level must be >= 0, found " + level);
        double[] pos = mesh.positions;
        int[] sizes = mesh.faceSizes, fv = mesh.faceVertices;
        boolean[] holes = mesh.holes;
        double[] uvs = mesh.uvs;
        int[] fuv = mesh.faceUvs;
        Map<Long, Float> creases = mesh.creases;
        float[] corners = mesh.corners;
        boolean cornersAtBoundary = mesh.options.boundary() == SubdivOptions.Boundary.EDGE_AND_CORNER;
        for (int l = 0; l < level; l++) {
            int nv = pos.length / 3, nf = sizes.length;
            int[] starts = new int[nf];
            for (int f = 1; f < nf; f++) starts[f] = starts[f - 1] + sizes[f - 1];
            // Edges with their first two faces.
            Map<Long, Integer> edgeIndex = new HashMap<>();
            int[] ea = new int[fv.length], eb = new int[fv.length], ef0 = new int[fv.length], ef1 = new int[fv.length], efc = new int[fv.length];
            int ne = 0;
            for (int f = 0; f < nf; f++) {
                for (int j = 0; j < sizes[f]; j++) {
                    int a = fv[starts[f] + j], b = fv[starts[f] + (j + 1) % sizes[f]];
                    long k = ControlMesh.edgeKey(a, b);
                    Integer e = edgeIndex.get(k);
                    if (e == null) {
                        e = ne++;
                        edgeIndex.put(k, e);
                        ea[e] = a; eb[e] = b; ef0[e] = f;
                    } else if (efc[e] == 1) {
                        ef1[e] = f;
                    }
                    efc[e]++;
                }
            }
            double[] np = new double[3 * (nv + nf + ne)];
            // Face points.
            for (int f = 0; f < nf; f++) {
                for (int j = 0; j < sizes[f]; j++) {
                    int v = 3 * fv[starts[f] + j];
                    for (int k = 0; k < 3; k++) np[3 * (nv + f) + k] += pos[v + k] / sizes[f];
                }
            }
            float[] es = new float[ne];
            for (Map.Entry<Long, Integer> en : edgeIndex.entrySet()) {
                int e = en.getValue();
                es[e] = efc[e] != 2 ? ControlMesh.INFINITELY_SHARP : creases.getOrDefault(en.getKey(), 0f);
            }
            // Edge points.
            for (int e = 0; e < ne; e++) {
                int o = 3 * (nv + nf + e);
                for (int k = 0; k < 3; k++) {
                    double mid = 0.5 * (pos[3 * ea[e] + k] + pos[3 * eb[e] + k]);
                    double smooth = efc[e] == 2 ? 0.25 * (pos[3 * ea[e] + k] + pos[3 * eb[e] + k] + np[3 * (nv + ef0[e]) + k] + np[3 * (nv + ef1[e]) + k]) : mid;
                    double s = Math.min(1, es[e]);
                    np[o + k] = s * mid + (1 - s) * smooth;
                }
            }
            // Vertex points.
            double[] q = new double[3 * nv], r = new double[3 * nv];
            int[] faceCount = new int[nv], edgeCount = new int[nv], sharpCount = new int[nv];
            int[] sharpA = new int[nv], sharpB = new int[nv];
            double[] sharpSum = new double[nv];
            for (int f = 0; f < nf; f++) {
                for (int j = 0; j < sizes[f]; j++) {
                    int v = fv[starts[f] + j];
                    faceCount[v]++;
                    for (int k = 0; k < 3; k++) q[3 * v + k] += np[3 * (nv + f) + k];
                }
            }
            for (int e = 0; e < ne; e++) {
                int[] ends = {ea[e], eb[e]};
                for (int m = 0; m < 2; m++) {
                    int v = ends[m], other = ends[1 - m];
                    edgeCount[v]++;
                    for (int k = 0; k < 3; k++) r[3 * v + k] += 0.5 * (pos[3 * ea[e] + k] + pos[3 * eb[e] + k]);
                    if (es[e] > 0) {
                        if (sharpCount[v] == 0) sharpA[v] = other; else sharpB[v] = other;
                        sharpCount[v]++;
                        sharpSum[v] += Math.min(1, es[e]);
                    }
                }
            }
            for (int v = 0; v < nv; v++) {
                int n = edgeCount[v];
                double[] smooth = new double[3];
                for (int k = 0; k < 3; k++) {
                    double pv = pos[3 * v + k];
                    smooth[k] = n < 3 || faceCount[v] == 0 ? pv
                            : (q[3 * v + k] / faceCount[v] + 2 * r[3 * v + k] / n + (n - 3) * pv) / n;
                }
                double cornerWeight = Math.min(1, corners[v]);
                if (sharpCount[v] >= 3 || cornersAtBoundary && faceCount[v] == 1 && n == 2) cornerWeight = 1;
                for (int k = 0; k < 3; k++) {
                    double pv = pos[3 * v + k], value = smooth[k];
                    if (sharpCount[v] == 2) {
                        double crease = (6 * pv + pos[3 * sharpA[v] + k] + pos[3 * sharpB[v] + k]) / 8;
                        double w = sharpSum[v] / 2;
                        value = w * crease + (1 - w) * value;
                    }
                    np[3 * v + k] = cornerWeight * pv + (1 - cornerWeight) * value;
                }
            }
            // Child sharpness, decaying by one per level.
            Map<Long, Float> childCreases = new HashMap<>();
            for (Map.Entry<Long, Integer> en : edgeIndex.entrySet()) {
                int e = en.getValue();
                float s = creases.getOrDefault(en.getKey(), 0f);
                float cs = s >= ControlMesh.INFINITELY_SHARP ? s : s - 1;
                if (cs > 0) {
                    childCreases.put(ControlMesh.edgeKey(ea[e], nv + nf + e), cs);
                    childCreases.put(ControlMesh.edgeKey(eb[e], nv + nf + e), cs);
                }
            }
            float[] childCorners = new float[nv + nf + ne];
            for (int v = 0; v < nv; v++) childCorners[v] = corners[v] >= ControlMesh.INFINITELY_SHARP ? corners[v] : Math.max(0, corners[v] - 1);
            // Child faces: (v_j, e(j, j+1), f, e(j-1, j)), and linear UVs alongside.
            int corners4 = fv.length;
            int[] cfv = new int[4 * corners4], csizes = new int[corners4], cfuv = fuv != null ? new int[4 * corners4] : null;
            boolean[] choles = new boolean[corners4];
            int nuv = uvs != null ? uvs.length / 2 : 0;
            Map<Long, Integer> uvEdge = new HashMap<>();
            double[] cuv = uvs != null ? new double[2 * (nuv + nf + corners4)] : null;
            int cuvCount = nuv;
            if (cuv != null) System.arraycopy(uvs, 0, cuv, 0, uvs.length);
            int c = 0;
            for (int f = 0; f < nf; f++) {
                int s = sizes[f], st = starts[f];
                int faceUv = -1;
                if (cuv != null) {
                    faceUv = cuvCount++;
                    for (int j = 0; j < s; j++) {
                        cuv[2 * faceUv] += uvs[2 * fuv[st + j]] / s;
                        cuv[2 * faceUv + 1] += uvs[2 * fuv[st + j] + 1] / s;
                    }
                }
                for (int j = 0; j < s; j++) {
                    int prev = (j + s - 1) % s, next = (j + 1) % s;
                    int vj = fv[st + j];
                    int eNext = nv + nf + edgeIndex.get(ControlMesh.edgeKey(vj, fv[st + next]));
                    int ePrev = nv + nf + edgeIndex.get(ControlMesh.edgeKey(fv[st + prev], vj));
                    cfv[4 * c] = vj; cfv[4 * c + 1] = eNext; cfv[4 * c + 2] = nv + f; cfv[4 * c + 3] = ePrev;
                    if (cuv != null) {
                        int uj = fuv[st + j];
                        int[] mids = new int[2];
                        int[][] pairs = {{uj, fuv[st + next]}, {fuv[st + prev], uj}};
                        for (int m = 0; m < 2; m++) {
                            long key = ((long) Math.min(pairs[m][0], pairs[m][1]) << 32) | Math.max(pairs[m][0], pairs[m][1]);
                            Integer id = uvEdge.get(key);
                            if (id == null) {
                                id = cuvCount++;
                                uvEdge.put(key, id);
                                cuv[2 * id] = 0.5 * (uvs[2 * pairs[m][0]] + uvs[2 * pairs[m][1]]);
                                cuv[2 * id + 1] = 0.5 * (uvs[2 * pairs[m][0] + 1] + uvs[2 * pairs[m][1] + 1]);
                            }
                            mids[m] = id;
                        }
                        cfuv[4 * c] = uj; cfuv[4 * c + 1] = mids[0]; cfuv[4 * c + 2] = faceUv; cfuv[4 * c + 3] = mids[1];
                    }
                    csizes[c] = 4;
                    choles[c] = holes[f];
                    c++;
                }
            }
            pos = np;
            sizes = csizes;
            fv = cfv;
            holes = choles;
            if (cuv != null) {
                uvs = java.util.Arrays.copyOf(cuv, 2 * cuvCount);
                fuv = cfuv;
            }
            creases = childCreases;
            corners = childCorners;
        }
        return new RefinedMesh(level, pos, sizes, fv, holes, uvs, fuv);
    }
}
