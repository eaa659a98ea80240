package lt.spindulys.subdiv;

/**
 * Limit positions and normals of the vertices of a level (OpenSubdiv's
 * {@code PrimvarRefiner::Limit}): each vertex's 1-ring is gathered in Far's order and weighed by
 * its scheme's limit masks ({@link SchemeRules#limitMasks}: smooth, crease or corner by the
 * vertex's rule). The normal is the normalised cross product of the two limit tangents; the
 * first tangent points along the vertex's first edge and the second turns counter-clockwise
 * from it, so the normal is on the side where faces wind counter-clockwise.
 *
 * <p>Where the masks leave the tangents degenerate (for example a corner whose first two edges
 * are collinear) the normal falls back to the sum of the face normals around the vertex.
 */
final class Limit {
    private Limit() {}

    /**
     * @param pos receives the limit position of every vertex (3 per vertex), or null
     * @param nrm receives the unit limit normal of every vertex (3 per vertex), or null
     */
    static void evaluate(Level lv, SchemeRules rules, double[] p, double[] pos, double[] nrm) {
        evaluate(lv, rules, p, pos, nrm, null);
    }

    /**
     * As {@link #evaluate(Level, SchemeRules, double[], double[], double[])} for the vertices flagged in
     * {@code only} (null: all); each vertex's values are computed alone, so they are the same.
     */
    static void evaluate(Level lv, SchemeRules rules, double[] p, double[] pos, double[] nrm, boolean[] only) {
        if (lv.eSharp != null) lv.edgeCodes(); // edge sharpness is looked up by edge index
        int cap = lv.maxValence() + 2;
        int[] ring = new int[cap + 1], other = new int[cap], opp = new int[cap];
        float[] sharp = new float[cap];
        SchemeRules.LimitMasks m = new SchemeRules.LimitMasks(cap);
        double[] t = new double[6];
        // Catmull-Clark's regular vertices take an unrolled path.
        boolean quads = lv.faceStart == null && rules instanceof CatmarkRules;
        boolean anyNm = lv.nmVert.length > 0, faceWeights = rules.limitUsesFaces();
        // Regular vertices first, visited in half-edge order (each at its leading half-edge),
        // which keeps the 1-ring lookups close in memory; the rest vertex by vertex.
        boolean[] done = null;
        if (quads) {
            done = new boolean[lv.nV];
            int[] orig = lv.hOrig, out = lv.vOut;
            for (int h = 0; h < lv.nH; h++) {
                int v = orig[h];
                if (only != null && !only[v]) continue;
                if (out[v] == h && lv.rule(v) <= Crease.RULE_DART && !(anyNm && lv.isNonManifold(v))) {
                    done[v] = regular(lv, p, v, pos, nrm);
                }
            }
        }
        for (int v = 0; v < lv.nV; v++) {
            if (done != null && done[v]) continue;
            if (only != null && !only[v]) continue;
            int nEdges, nFaces;
            int nmi = lv.nmVertIndex(v);
            // Sharpness matters to the crease masks only; the opposite vertices to masks with face weights.
            int rule = lv.rule(v);
            boolean wantSharp = rule == Crease.RULE_CREASE;
            if (nmi >= 0) {
                nEdges = 0;
                for (int k = lv.nmVertStart[nmi]; k < lv.nmVertStart[nmi + 1]; k++, nEdges++) {
                    other[nEdges] = lv.nmVertOther[k];
                    if (wantSharp) sharp[nEdges] = lv.edgeSharpness(lv.nmVertHalf[k]);
                }
                // Far's vertex-face order of a non-manifold vertex, as its masks index it.
                nFaces = 0;
                for (int k = lv.nmFaceStart[nmi]; k < lv.nmFaceStart[nmi + 1]; k++, nFaces++) {
                    if (faceWeights) opp[nFaces] = lv.hOrig[lv.next(lv.next(lv.nmFaceHalf[k]))];
                }
            } else {
                int n = lv.ring(v, ring);
                boolean boundary = lv.hTwin[lv.vOut[v]] < 0;
                nFaces = n;
                nEdges = boundary ? n + 1 : n;
                for (int j = 0; j < nEdges; j++) {
                    int x = ring[j];
                    if (j < n) {
                        other[j] = lv.dest(x);
                        if (faceWeights) opp[j] = lv.hOrig[lv.next(lv.next(x))];
                    } else {
                        other[j] = lv.hOrig[x];
                    }
                    if (wantSharp) sharp[j] = lv.edgeSharpness(x);
                }
            }
            int vp = 3 * v;
            if (nEdges == 0) {
                if (pos != null) System.arraycopy(p, vp, pos, vp, 3);
                if (nrm != null) fallbackNormal(lv, p, v, nrm);
                continue;
            }
            rules.limitMasks(rule, nEdges, nFaces, nmi >= 0, sharp, m);
            double[] ew = m.ew, fw = m.fw, t1e = m.t1e, t1f = m.t1f, t2e = m.t2e, t2f = m.t2f;
            double vw = m.vw, t1v = m.t1v, t2v = m.t2v;
            int nE1 = m.posEdges, nF1 = m.posFaces; // weights the position uses
            if (pos != null) {
                for (int d = 0; d < 3; d++) {
                    double acc = 0.0;
                    for (int j = 0; j < nF1; j++) acc += fw[j] * p[3 * opp[j] + d];
                    for (int j = 0; j < nE1; j++) acc += ew[j] * p[3 * other[j] + d];
                    pos[vp + d] = acc + vw * p[vp + d];
                }
            }
            if (nrm != null) {
                for (int d = 0; d < 3; d++) {
                    double a = 0.0, b = 0.0;
                    for (int j = 0; j < m.tanFaces; j++) {
                        double q = p[3 * opp[j] + d];
                        a += t1f[j] * q;
                        b += t2f[j] * q;
                    }
                    for (int j = 0; j < nEdges; j++) {
                        double q = p[3 * other[j] + d];
                        a += t1e[j] * q;
                        b += t2e[j] * q;
                    }
                    t[d] = a + t1v * p[vp + d];
                    t[3 + d] = b + t2v * p[vp + d];
                }
                double nx = t[1] * t[5] - t[2] * t[4];
                double ny = t[2] * t[3] - t[0] * t[5];
                double nz = t[0] * t[4] - t[1] * t[3];
                double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
                double scale = Math.max(Math.sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2])
                        * Math.sqrt(t[3] * t[3] + t[4] * t[4] + t[5] * t[5]), Double.MIN_NORMAL);
                if (len > 1e-12 * scale && len > 0) {
                    nrm[vp] = nx / len;
                    nrm[vp + 1] = ny / len;
                    nrm[vp + 2] = nz / len;
                } else {
                    fallbackNormal(lv, p, v, nrm);
                }
            }
        }
    }

    /**
     * The smooth masks at an interior vertex of valence 4 in a quad level, unrolled. Returns
     * false (having written nothing) for any other vertex.
     */
    private static boolean regular(Level lv, double[] p, int v, double[] pos, double[] nrm) {
        int[] orig = lv.hOrig, twin = lv.hTwin;
        int h0 = lv.vOut[v];
        int h1 = twin[(h0 & ~3) | ((h0 + 3) & 3)];
        if (h1 < 0) return false;
        int h2 = twin[(h1 & ~3) | ((h1 + 3) & 3)];
        if (h2 < 0 || h2 == h0) return false; // valence 1 or 2 closes early
        int h3 = twin[(h2 & ~3) | ((h2 + 3) & 3)];
        if (h3 < 0 || twin[(h3 & ~3) | ((h3 + 3) & 3)] != h0) return false;
        int e0 = 3 * orig[(h0 & ~3) | ((h0 + 1) & 3)], e1 = 3 * orig[(h1 & ~3) | ((h1 + 1) & 3)];
        int e2 = 3 * orig[(h2 & ~3) | ((h2 + 1) & 3)], e3 = 3 * orig[(h3 & ~3) | ((h3 + 1) & 3)];
        int o0 = 3 * orig[(h0 & ~3) | ((h0 + 2) & 3)], o1 = 3 * orig[(h1 & ~3) | ((h1 + 2) & 3)];
        int o2 = 3 * orig[(h2 & ~3) | ((h2 + 2) & 3)], o3 = 3 * orig[(h3 & ~3) | ((h3 + 2) & 3)];
        int vp = 3 * v;
        if (pos != null) {
            final double fw = CatmarkRules.REGULAR_LIMIT_FACE, ew = CatmarkRules.REGULAR_LIMIT_EDGE, vw = CatmarkRules.REGULAR_LIMIT_VERTEX;
            for (int d = 0; d < 3; d++) {
                pos[vp + d] = fw * p[o0 + d] + fw * p[o1 + d] + fw * p[o2 + d] + fw * p[o3 + d]
                        + ew * p[e0 + d] + ew * p[e1 + d] + ew * p[e2 + d] + ew * p[e3 + d] + vw * p[vp + d];
            }
        }
        if (nrm != null) {
            double ax = 4 * (p[e0] - p[e2]) + (p[o0] - p[o1] - p[o2] + p[o3]);
            double ay = 4 * (p[e0 + 1] - p[e2 + 1]) + (p[o0 + 1] - p[o1 + 1] - p[o2 + 1] + p[o3 + 1]);
            double az = 4 * (p[e0 + 2] - p[e2 + 2]) + (p[o0 + 2] - p[o1 + 2] - p[o2 + 2] + p[o3 + 2]);
            double bx = 4 * (p[e1] - p[e3]) + (p[o0] + p[o1] - p[o2] - p[o3]);
            double by = 4 * (p[e1 + 1] - p[e3 + 1]) + (p[o0 + 1] + p[o1 + 1] - p[o2 + 1] - p[o3 + 1]);
            double bz = 4 * (p[e1 + 2] - p[e3 + 2]) + (p[o0 + 2] + p[o1 + 2] - p[o2 + 2] - p[o3 + 2]);
            double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;
            double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
            double scale = Math.sqrt(ax * ax + ay * ay + az * az) * Math.sqrt(bx * bx + by * by + bz * bz);
            if (!(len > 1e-12 * scale && len > 0)) {
                fallbackNormal(lv, p, v, nrm);
            } else {
                nrm[vp] = nx / len;
                nrm[vp + 1] = ny / len;
                nrm[vp + 2] = nz / len;
            }
        }
        return true;
    }

    /** The normalised sum of the (area-weighted) normals of the faces at v; zero if none. */
    private static void fallbackNormal(Level lv, double[] p, int v, double[] nrm) {
        double[] n = new double[3];
        if (lv.vOut[v] >= 0 && !lv.isNonManifold(v)) {
            int start = lv.vOut[v], x = start;
            do {
                addCornerNormal(lv, p, x, n);
                x = lv.hTwin[lv.prev(x)];
            } while (x >= 0 && x != start);
        } else {
            int i = lv.nmVertIndex(v);
            if (i >= 0) for (int k = lv.nmFaceStart[i]; k < lv.nmFaceStart[i + 1]; k++) addCornerNormal(lv, p, lv.nmFaceHalf[k], n);
        }
        double len = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        int vp = 3 * v;
        for (int d = 0; d < 3; d++) nrm[vp + d] = len > 0 ? n[d] / len : 0.0;
    }

    private static void addCornerNormal(Level lv, double[] p, int h, double[] n) {
        int o = 3 * lv.hOrig[h], a = 3 * lv.dest(h), b = 3 * lv.hOrig[lv.prev(h)];
        double ux = p[a] - p[o], uy = p[a + 1] - p[o + 1], uz = p[a + 2] - p[o + 2];
        double wx = p[b] - p[o], wy = p[b + 1] - p[o + 1], wz = p[b + 2] - p[o + 2];
        n[0] += uy * wz - uz * wy;
        n[1] += uz * wx - ux * wz;
        n[2] += ux * wy - uy * wx;
    }
}
