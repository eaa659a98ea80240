package lt.spindulys.subdiv;

/**
 * Limit positions and normals of the vertices of a level with Sdc's Catmull-Clark limit masks
 * (OpenSubdiv's {@code PrimvarRefiner::Limit}): smooth (and dart) vertices use the smooth
 * masks over their 1-ring, crease vertices (creases and boundaries) the crease masks along their
 * two sharp edges, corners stay where they are. The normal is the normalised cross product of
 * the two limit tangents; the first tangent points along the vertex's first edge and the second
 * turns counter-clockwise from it, so the normal is on the side where faces wind
 * counter-clockwise.
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
    static void evaluate(Level lv, SubdivOptions.Scheme scheme, double[] p, double[] pos, double[] nrm) {
        evaluate(lv, scheme, p, pos, nrm, null);
    }

    /**
     * As {@link #evaluate(Level, double[], double[], double[])} for the vertices flagged in
     * {@code only} (null: all); each vertex's values are computed alone, so they are the same.
     */
    static void evaluate(Level lv, SubdivOptions.Scheme scheme, double[] p, double[] pos, double[] nrm, boolean[] only) {
        boolean loop = scheme == SubdivOptions.Scheme.LOOP, bilinear = scheme == SubdivOptions.Scheme.BILINEAR;
        if (lv.eSharp != null) lv.edgeCodes(); // edge sharpness is looked up by edge index
        int cap = lv.maxValence() + 2;
        int[] ring = new int[cap + 1], other = new int[cap], opp = new int[cap];
        float[] sharp = new float[cap];
        double[] ew = new double[cap], fw = new double[cap], t1e = new double[cap], t1f = new double[cap],
                t2e = new double[cap], t2f = new double[cap];
        double[] t = new double[6];
        boolean quads = lv.faceStart == null && scheme == SubdivOptions.Scheme.CATMARK;
        boolean anyNm = lv.nmVert.length > 0;
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
            if (nmi >= 0) {
                nEdges = 0;
                for (int k = lv.nmVertStart[nmi]; k < lv.nmVertStart[nmi + 1]; k++, nEdges++) {
                    other[nEdges] = lv.nmVertOther[k];
                    sharp[nEdges] = lv.edgeSharpness(lv.nmVertHalf[k]);
                }
                // Far's vertex-face order of a non-manifold vertex, as its masks index it.
                nFaces = 0;
                for (int k = lv.nmFaceStart[nmi]; k < lv.nmFaceStart[nmi + 1]; k++, nFaces++) {
                    opp[nFaces] = lv.hOrig[lv.next(lv.next(lv.nmFaceHalf[k]))];
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
                        opp[j] = lv.hOrig[lv.next(lv.next(x))];
                    } else {
                        other[j] = lv.hOrig[x];
                    }
                    sharp[j] = lv.edgeSharpness(x);
                }
            }
            int vp = 3 * v;
            if (nEdges == 0) {
                if (pos != null) System.arraycopy(p, vp, pos, vp, 3);
                if (nrm != null) fallbackNormal(lv, p, v, nrm);
                continue;
            }
            int rule = lv.rule(v);
            double vw, t1v, t2v;
            int nE1 = nEdges, nF1 = nFaces; // weights in use
            // Bilinear: every vertex is a corner (the limit surface is the refined mesh itself);
            // Catmull-Clark treats a smooth valence-2 vertex as a corner, Loop does not.
            boolean smooth = !bilinear && rule <= Crease.RULE_DART && (loop || nFaces != 2) && nmi < 0;
            if (loop && (smooth || rule == Crease.RULE_CREASE)) {
                vw = loopMasks(smooth, nEdges, sharp, ew, t1e, t2e, t);
                t1v = t[0];
                t2v = t[1];
                nF1 = 0;
                for (int j = 0; j < nFaces; j++) {
                    t1f[j] = 0.0;
                    t2f[j] = 0.0;
                }
            } else if (smooth) {
                int n = nFaces;
                double fwt, ewt;
                if (n == 4) {
                    fwt = 1.0 / 36.0;
                    ewt = 1.0 / 9.0;
                    vw = 4.0 / 9.0;
                } else {
                    double valence = n;
                    fwt = 1.0 / (valence * (valence + 5.0));
                    ewt = 4.0 * fwt;
                    vw = 1.0 - valence * (ewt + fwt);
                }
                for (int j = 0; j < n; j++) {
                    ew[j] = ewt;
                    fw[j] = fwt;
                }
                t1v = t2v = 0.0;
                if (n == 4) {
                    double[] e1 = {4, 0, -4, 0}, f1 = {1, -1, -1, 1}, e2 = {0, 4, 0, -4}, f2 = {1, 1, -1, -1};
                    for (int j = 0; j < 4; j++) {
                        t1e[j] = e1[j];
                        t1f[j] = f1[j];
                        t2e[j] = e2[j];
                        t2f[j] = f2[j];
                    }
                } else {
                    double theta = 2.0 * Math.PI / n;
                    double cosTheta = Math.cos(theta), cosHalfTheta = Math.cos(theta * 0.5);
                    double lambda = (5.0 / 16.0) + (1.0 / 16.0) * (cosTheta + cosHalfTheta * Math.sqrt(2.0 * (9.0 + cosTheta)));
                    double faceScale = 1.0 / (4.0 * lambda - 1.0);
                    for (int j = 0; j < n; j++) {
                        double ci = Math.cos(j * theta), ci1 = Math.cos((j + 1) * theta);
                        t1e[j] = 4.0 * ci;
                        t1f[j] = faceScale * (ci + ci1);
                    }
                    t2e[0] = t1e[n - 1];
                    t2f[0] = t1f[n - 1];
                    for (int j = 1; j < n; j++) {
                        t2e[j] = t1e[j - 1];
                        t2f[j] = t1f[j - 1];
                    }
                }
            } else if (rule == Crease.RULE_CREASE && !bilinear) {
                int c0 = 0, c1 = nEdges - 1;
                while (c0 < nEdges - 1 && !Crease.isSharp(sharp[c0])) c0++;
                while (c1 > 0 && !Crease.isSharp(sharp[c1])) c1--;
                vw = 2.0 / 3.0;
                for (int j = 0; j < nEdges; j++) ew[j] = 0.0;
                ew[c0] = 1.0 / 6.0;
                ew[c1] = 1.0 / 6.0;
                nF1 = 0;
                for (int j = 0; j < nEdges; j++) {
                    t1e[j] = 0.0;
                    t2e[j] = 0.0;
                }
                for (int j = 0; j < nFaces; j++) {
                    t1f[j] = 0.0;
                    t2f[j] = 0.0;
                }
                t1v = 0.0;
                t1e[c0] = 0.5;
                t1e[c1] = -0.5;
                int interior = c1 - c0 - 1;
                if (interior == 1) {
                    t2v = -4.0 / 6.0;
                    t2e[c0] = -1.0 / 6.0;
                    t2e[c0 + 1] = 4.0 / 6.0;
                    t2e[c1] = -1.0 / 6.0;
                    t2f[c0] = 1.0 / 6.0;
                    t2f[c0 + 1] = 1.0 / 6.0;
                } else if (interior > 1) {
                    double k = interior + 1;
                    double theta = Math.PI / k;
                    double cosTheta = Math.cos(theta), sinTheta = Math.sin(theta);
                    double commonDenom = 1.0 / (k * (3.0 + cosTheta));
                    double r = (cosTheta + 1.0) / sinTheta;
                    double vertexWeight = 4.0 * r * (cosTheta - 1.0);
                    double creaseWeight = -r * (1.0 + 2.0 * cosTheta);
                    t2v = vertexWeight * commonDenom;
                    t2e[c0] = creaseWeight * commonDenom;
                    t2e[c1] = creaseWeight * commonDenom;
                    t2f[c0] = sinTheta * commonDenom;
                    double sinI, sinI1 = sinTheta;
                    for (int i = 1; i < k; i++) {
                        sinI = sinI1;
                        sinI1 = Math.sin((i + 1) * theta);
                        t2e[c0 + i] = (4.0 * sinI) * commonDenom;
                        t2f[c0 + i] = (sinI + sinI1) * commonDenom;
                    }
                } else {
                    t2v = -6.0;
                    t2e[c0] = 3.0;
                    t2e[c1] = 3.0;
                    t2f[c0] = 0.0;
                }
            } else {
                // Corner (and valence-2 smooth vertices, as in Sdc): the vertex itself, with
                // tangents along the first two edges.
                vw = 1.0;
                nE1 = 0;
                nF1 = 0;
                for (int j = 0; j < nEdges; j++) {
                    t1e[j] = 0.0;
                    t2e[j] = 0.0;
                }
                for (int j = 0; j < nFaces; j++) {
                    t1f[j] = 0.0;
                    t2f[j] = 0.0;
                }
                // Loop's corner tangents are scaled by 3 (Sdc's convention); the direction is the same.
                double scale = loop ? 3.0 : 1.0;
                t1v = -scale;
                t2v = -scale;
                t1e[0] = scale;
                if (nEdges > 1) t2e[1] = scale;
            }
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
                    for (int j = 0; j < nFaces; j++) {
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

    private static final double ROOT3 = 1.73205080756887729352, ROOT3_BY_2 = ROOT3 * 0.5;

    /**
     * Sdc's Loop limit masks of a smooth (or dart) vertex over its n edges, or of a crease vertex
     * along its two sharp edges: position edge weights into {@code ew}, tangent edge weights into
     * {@code t1e} and {@code t2e}, the tangents' vertex weights into {@code tv[0]} and
     * {@code tv[1]}; returns the position's vertex weight. No face weights. Smooth: the limit
     * (1 - n chi) v + chi sum(e) with chi = 1 / (n + 3 / (8 gamma)), tangents the cosine and sine
     * masks; crease: the cubic B-spline's (1/6, 2/3, 1/6) along the crease, Far's tangent across
     * the faces between the two sharp edges (counter-clockwise from the first).
     */
    private static double loopMasks(boolean smooth, int nEdges, float[] sharp, double[] ew, double[] t1e, double[] t2e, double[] tv) {
        if (smooth) {
            int n = nEdges;
            double ewt, vw;
            if (n == 6) {
                ewt = 1.0 / 12.0;
                vw = 0.5;
            } else {
                double dValence = n, invValence = 1.0 / dValence;
                double cosTheta = Math.cos(Math.PI * 2.0 * invValence);
                double beta = 0.25 * cosTheta + 0.375;
                double gamma = (0.625 - beta * beta) * invValence;
                ewt = 1.0 / (dValence + 3.0 / (8.0 * gamma));
                vw = 1.0 - ewt * dValence;
            }
            for (int j = 0; j < n; j++) ew[j] = ewt;
            tv[0] = tv[1] = 0.0;
            if (n == 6) {
                double[] c1 = {1.0, 0.5, -0.5, -1.0, -0.5, 0.5}, c2 = {0.0, ROOT3_BY_2, ROOT3_BY_2, 0.0, -ROOT3_BY_2, -ROOT3_BY_2};
                for (int j = 0; j < 6; j++) {
                    t1e[j] = c1[j];
                    t2e[j] = c2[j];
                }
            } else {
                double alpha = 2.0 * Math.PI / n;
                for (int j = 0; j < n; j++) {
                    double a = alpha * j;
                    t1e[j] = Math.cos(a);
                    t2e[j] = Math.sin(a);
                }
            }
            return vw;
        }
        int c0 = 0, c1 = nEdges - 1;
        while (c0 < nEdges - 1 && !Crease.isSharp(sharp[c0])) c0++;
        while (c1 > 0 && !Crease.isSharp(sharp[c1])) c1--;
        for (int j = 0; j < nEdges; j++) {
            ew[j] = 0.0;
            t1e[j] = 0.0;
            t2e[j] = 0.0;
        }
        ew[c0] = 1.0 / 6.0;
        ew[c1] = 1.0 / 6.0;
        tv[0] = 0.0;
        t1e[c0] = 1.5;
        t1e[c1] = -1.5;
        int interior = c1 - c0 - 1;
        if (interior == 2) {
            tv[1] = -ROOT3;
            t2e[c0] = -ROOT3_BY_2;
            t2e[c1] = -ROOT3_BY_2;
            t2e[c0 + 1] = ROOT3;
            t2e[c0 + 2] = ROOT3;
        } else if (interior > 2) {
            double theta = Math.PI / (interior + 1);
            tv[1] = 0.0;
            double cWeight = -3.0 * Math.sin(theta);
            t2e[c0] = cWeight;
            t2e[c1] = cWeight;
            double eCoeff = -3.0 * 2.0 * (Math.cos(theta) - 1.0);
            for (int i = 1; i <= interior; i++) t2e[c0 + i] = eCoeff * Math.sin(i * theta);
        } else if (interior == 1) {
            tv[1] = -3.0;
            t2e[c0 + 1] = 3.0;
        } else {
            tv[1] = -6.0;
            t2e[c0] = 3.0;
            t2e[c1] = 3.0;
        }
        return 4.0 / 6.0;
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
            final double fw = 1.0 / 36.0, ew = 1.0 / 9.0, vw = 4.0 / 9.0;
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
