package lt.spindulys.subdiv;

/**
 * Applies Catmull-Clark weights (Sdc's masks) to data carried by the vertices of a level, giving
 * the data of the refined level: OpenSubdiv's {@code PrimvarRefiner::Interpolate}. The same
 * code refines positions (3 values per vertex) and face-varying UVs (2 per vertex of the UV
 * "value mesh"), so both follow one set of rules.
 *
 * <p>Weights and the order of summation follow Far (faces, then edges, then the vertex itself),
 * so results agree with OpenSubdiv to the last bits in the common cases.
 */
final class PrimvarRefiner {
    private PrimvarRefiner() {}

    /** Far's smooth-triangle edge weight (after Hbr). */
    private static final double TRI_EDGE_WEIGHT = 0.470;

    /**
     * @param src    {@code stride} values per vertex of {@code p}
     * @param dst    receives {@code stride} values per vertex of {@code c}
     * @param linear bilinear instead of Catmull-Clark (Far's linear face-varying
     *               interpolation): face centroids, edge midpoints, vertices kept
     */
    static void interpolate(Level p, Level c, SubdivOptions opt, int stride, double[] src, double[] dst, boolean linear) {
        p.edgeCodes();
        if (!p.triangleSplit) faces(p, stride, src, dst);
        if (linear || opt.scheme() == SubdivOptions.Scheme.BILINEAR) {
            linearEdgesAndVertices(p, stride, src, dst);
            return;
        }
        edges(p, c, opt, stride, src, dst);
        vertices(p, c, opt, stride, src, dst);
    }

    /** Index of the first edge point in the child: after the vertices, and the face points of a quad split. */
    static int firstEdgePoint(Level p) { return p.triangleSplit ? p.nV : p.nV + p.nF; }

    private static void linearEdgesAndVertices(Level p, int stride, double[] src, double[] dst) {
        int vEdge = firstEdgePoint(p);
        for (int h = 0; h < p.nH; h++) {
            if ((p.hEdge[h] & Level.E_PRIMARY) == 0) continue;
            int out = (vEdge + (p.hEdge[h] >>> 2)) * stride;
            int v0 = p.edgeV0(h) * stride, v1 = p.edgeV1(h) * stride;
            for (int d = 0; d < stride; d++) dst[out + d] = 0.5 * src[v0 + d] + 0.5 * src[v1 + d];
        }
        System.arraycopy(src, 0, dst, 0, p.nV * stride);
    }

    private static void faces(Level p, int stride, double[] src, double[] dst) {
        int[] orig = p.hOrig;
        int out = p.nV * stride;
        if (p.faceStart == null && stride == 3) {
            for (int f = 0, h = 0; f < p.nF; f++, h += 4, out += 3) {
                int a = orig[h] * 3, b = orig[h + 1] * 3, cc = orig[h + 2] * 3, d = orig[h + 3] * 3;
                dst[out] = 0.25 * src[a] + 0.25 * src[b] + 0.25 * src[cc] + 0.25 * src[d];
                dst[out + 1] = 0.25 * src[a + 1] + 0.25 * src[b + 1] + 0.25 * src[cc + 1] + 0.25 * src[d + 1];
                dst[out + 2] = 0.25 * src[a + 2] + 0.25 * src[b + 2] + 0.25 * src[cc + 2] + 0.25 * src[d + 2];
            }
            return;
        }
        for (int f = 0; f < p.nF; f++, out += stride) {
            int s = p.firstHalf(f), n = p.faceSize(f);
            double w = 1.0 / n;
            for (int d = 0; d < stride; d++) {
                double acc = 0.0;
                for (int k = 0; k < n; k++) acc += w * src[orig[s + k] * stride + d];
                dst[out + d] = acc;
            }
        }
    }

    private static void edges(Level p, Level c, SubdivOptions opt, int stride, double[] src, double[] dst) {
        boolean smoothTris = opt.triangles() == SubdivOptions.Triangles.SMOOTH;
        boolean loop = p.triangleSplit;
        int[] code = p.hEdge, twin = p.hTwin;
        int vFace = p.nV, vEdge = firstEdgePoint(p);
        for (int h = 0; h < p.nH; h++) {
            int ch = code[h];
            if ((ch & Level.E_PRIMARY) == 0) continue;
            int e = ch >>> 2;
            int out = (vEdge + e) * stride;
            int v0 = p.edgeV0(h) * stride, v1 = p.edgeV1(h) * stride;
            float sharp = p.edgeSharpness(h);
            // Sdc's edge mask: a crease if the child stays a crease; an infinitely sharp edge
            // always is one (a face-varying boundary edge's point may be pinned as a corner).
            if (Crease.isSharp(sharp) && (Crease.isInfinite(sharp) || c.rule(vEdge + e) == Crease.RULE_CREASE)) {
                for (int d = 0; d < stride; d++) dst[out + d] = 0.5 * src[v0 + d] + 0.5 * src[v1 + d];
                continue;
            }
            if (loop) {
                // Loop's smooth edge mask: 3/8 on the ends, 1/8 on the vertex opposite the edge
                // in each of its two triangles; a decaying crease blends in (1/2, 1/2).
                int o0 = p.hOrig[p.prev(h)] * stride, o1 = p.hOrig[p.prev(twin[h])] * stride;
                double vw = 0.375, fw = 0.125;
                if (Crease.isSharp(sharp)) {
                    double pw = sharp, cw = 1.0 - pw;
                    vw = pw * 0.5 + cw * vw;
                    fw = fw * cw;
                }
                for (int d = 0; d < stride; d++) {
                    dst[out + d] = vw * src[v0 + d] + vw * src[v1 + d] + fw * src[o0 + d] + fw * src[o1 + d];
                }
                continue;
            }
            int f0 = (vFace + p.face(h)) * stride, f1 = (vFace + p.face(twin[h])) * stride;
            double vw = 0.25, fw = 0.25;
            if (smoothTris) {
                boolean tri0 = p.faceSize(p.face(h)) == 3, tri1 = p.faceSize(p.face(twin[h])) == 3;
                if (tri0 || tri1) {
                    double w0 = tri0 ? TRI_EDGE_WEIGHT : 0.25, w1 = tri1 ? TRI_EDGE_WEIGHT : 0.25;
                    fw = 0.5 * (w0 + w1);
                    vw = 0.5 * (1.0 - 2.0 * fw);
                }
            }
            if (Crease.isSharp(sharp)) {
                // A crease decaying to smooth in the child: blend by the parent sharpness.
                double pw = sharp, cw = 1.0 - pw;
                vw = pw * 0.5 + cw * vw;
                fw = fw * cw;
            }
            for (int d = 0; d < stride; d++) {
                dst[out + d] = vw * src[v0 + d] + vw * src[v1 + d] + fw * dst[f0 + d] + fw * dst[f1 + d];
            }
        }
    }

    private static void vertices(Level p, Level c, SubdivOptions opt, int stride, double[] src, double[] dst) {
        int[] orig = p.hOrig, twin = p.hTwin;
        int vFace = p.nV;
        boolean quads = p.faceStart == null, loop = p.triangleSplit;
        VertexMask m = null;
        for (int v = 0; v < p.nV; v++) {
            int pRule = p.rule(v);
            int vs = v * stride;
            if (pRule <= Crease.RULE_DART && loop) {
                int n = p.valence(v);
                double ew = loopEdgeWeight(n), vw = loopVertexWeight(n, ew);
                int start = p.vOut[v];
                for (int d = 0; d < stride; d++) {
                    double acc = 0.0;
                    int h = start;
                    do {
                        acc += ew * src[p.dest(h) * stride + d];
                        h = twin[p.prev(h)];
                    } while (h != start);
                    dst[vs + d] = acc + vw * src[vs + d];
                }
                continue;
            }
            if (pRule <= Crease.RULE_DART) {
                int start = p.vOut[v];
                if (stride == 3 && quads) {
                    // The common case, unrolled: Far's smooth mask with weights 1/n^2 on the
                    // face and edge points and (n-2)/n on the vertex.
                    int n = p.valence(v);
                    double fw = 1.0 / (n * n), vw = (double) (n - 2) / (double) n;
                    double ax = 0, ay = 0, az = 0;
                    int h = start;
                    do {
                        int fp = (vFace + (h >> 2)) * 3;
                        ax += fw * dst[fp];
                        ay += fw * dst[fp + 1];
                        az += fw * dst[fp + 2];
                        h = twin[(h & ~3) | ((h + 3) & 3)];
                    } while (h != start);
                    do {
                        int op = orig[(h & ~3) | ((h + 1) & 3)] * 3;
                        ax += fw * src[op];
                        ay += fw * src[op + 1];
                        az += fw * src[op + 2];
                        h = twin[(h & ~3) | ((h + 3) & 3)];
                    } while (h != start);
                    int out = v * 3;
                    dst[out] = ax + vw * src[vs];
                    dst[out + 1] = ay + vw * src[vs + 1];
                    dst[out + 2] = az + vw * src[vs + 2];
                    continue;
                }
                int n = p.valence(v);
                double fw = 1.0 / (n * n), vw = (double) (n - 2) / (double) n;
                for (int d = 0; d < stride; d++) {
                    double acc = 0.0;
                    int h = start;
                    do {
                        acc += fw * dst[(vFace + p.face(h)) * stride + d];
                        h = twin[p.prev(h)];
                    } while (h != start);
                    do {
                        acc += fw * src[p.dest(h) * stride + d];
                        h = twin[p.prev(h)];
                    } while (h != start);
                    dst[vs + d] = acc + vw * src[vs + d];
                }
                continue;
            }
            if (m == null) m = new VertexMask(p.maxValence() + 2);
            m.gather(p, c, v);
            m.compute(p, c, v, opt.creasing() == SubdivOptions.Creasing.CHAIKIN, loop);
            for (int d = 0; d < stride; d++) {
                double acc = 0.0;
                if (m.hasFaces) for (int i = 0; i < m.nFaces; i++) acc += m.fw[i] * dst[(vFace + m.face[i]) * stride + d];
                if (m.hasEdges) for (int i = 0; i < m.nEdges; i++) acc += m.ew[i] * src[m.other[i] * stride + d];
                dst[vs + d] = acc + m.vw * src[vs + d];
            }
        }
    }

    /**
     * Loop's smooth vertex mask (Sdc's, after Hbr: Loop's original weights, not Warren's): the
     * weight of each of the n edge neighbours, (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n; 1/16 at
     * valence 6.
     */
    static double loopEdgeWeight(int n) {
        if (n == 6) return 0.0625;
        double dValence = n, invValence = 1.0 / dValence;
        double cosTheta = Math.cos(Math.PI * 2.0 * invValence);
        double beta = 0.25 * cosTheta + 0.375;
        return (0.625 - beta * beta) * invValence;
    }

    /** The vertex's own weight in Loop's smooth mask, given the edge weight. */
    static double loopVertexWeight(int n, double edgeWeight) {
        return n == 6 ? 0.625 : 1.0 - edgeWeight * n;
    }

    /**
     * A vertex's neighbourhood (in Far's order) and the weights of its refinement mask, for the
     * vertices that are not plain smooth: creases, corners and transitions between rules.
     */
    static final class VertexMask {
        final int[] other, face, ring;
        final float[] pSharp, cSharp;
        final double[] ew, fw, ewChild, fwChild;
        int nEdges, nFaces;
        double vw;
        boolean hasEdges, hasFaces;

        VertexMask(int cap) {
            other = new int[cap];
            face = new int[cap];
            ring = new int[cap + 1];
            pSharp = new float[cap];
            cSharp = new float[cap];
            ew = new double[cap];
            fw = new double[cap];
            ewChild = new double[cap];
            fwChild = new double[cap];
        }

        /** Edges (far ends, parent and child sharpness) and faces of v in Far's order. */
        void gather(Level p, Level c, int v) {
            int i = p.nmVertIndex(v);
            if (i >= 0) {
                nEdges = 0;
                for (int k = p.nmVertStart[i]; k < p.nmVertStart[i + 1]; k++, nEdges++) {
                    other[nEdges] = p.nmVertOther[k];
                    pSharp[nEdges] = p.edgeSharpness(p.nmVertHalf[k]);
                    cSharp[nEdges] = c == null ? 0f : SharpnessRefinement.childEdgeSharpness(p, c, p.nmVertHalf[k], p.nmVertEnd[k]);
                }
                nFaces = 0;
                return;
            }
            int n = p.ring(v, ring);
            boolean boundary = p.hTwin[p.vOut[v]] < 0;
            nFaces = n;
            nEdges = boundary ? n + 1 : n;
            for (int j = 0; j < nEdges; j++) {
                int x = ring[j];
                boolean out = j < n;
                other[j] = out ? p.dest(x) : p.hOrig[x];
                pSharp[j] = p.edgeSharpness(x);
                if (c != null) {
                    int end = out ? (p.fwd(x) ? 0 : 1) : (p.fwd(x) ? 1 : 0);
                    cSharp[j] = SharpnessRefinement.childEdgeSharpness(p, c, x, (p.hEdge[x] >>> 2) << 1 | end);
                }
                if (out) face[j] = p.face(x);
            }
        }

        /** Sdc's {@code ComputeVertexVertexMask} for vertex v of p with child rule from c (Loop's masks if {@code loop}). */
        void compute(Level p, Level c, int v, boolean chaikin, boolean loop) {
            this.loop = loop;
            int pRule = p.rule(v), cRule = c.rule(v);
            float pVs = p.vertexSharpness(v), cVs = c.vertexSharpness(v);
            vw = assign(pRule, pSharp, ew, fw);
            hasEdges = edgesSet;
            hasFaces = facesSet;
            if (cRule == pRule) return;
            // Sdc blends the parent's mask with the child's by the fractional weight.
            double cvw = assign(cRule, cSharp, ewChild, fwChild);
            boolean cEdges = edgesSet, cFaces = facesSet;
            double pw = Crease.fractionalWeight(pVs, cVs, nEdges, pSharp, chaikin ? cSharp : null);
            double cw = 1.0 - pw;
            vw = pw * vw + cw * cvw;
            if (cEdges) {
                for (int j = 0; j < nEdges; j++) ew[j] = hasEdges ? pw * ew[j] + cw * ewChild[j] : cw * ewChild[j];
                hasEdges = true;
            }
            if (cFaces) {
                for (int j = 0; j < nFaces; j++) fw[j] = hasFaces ? pw * fw[j] + cw * fwChild[j] : cw * fwChild[j];
                hasFaces = true;
            }
        }

        /** Whether the mask last assigned has edge and face weights. */
        private boolean edgesSet, facesSet;
        /** Loop's smooth mask instead of Catmull-Clark's. */
        private boolean loop;

        /**
         * Sdc's Catmark mask of one rule into e (edge ends) and f (face points); returns the
         * vertex's own weight. Smooth (and dart): (n-2)/n, 1/n^2 each; crease: 3/4 and 1/8 on
         * the first and last sharp edge; corner: the vertex alone.
         */
        private double assign(int rule, float[] sharp, double[] e, double[] f) {
            if (rule <= Crease.RULE_DART && loop) {
                int n = nFaces;
                double ewt = loopEdgeWeight(n);
                for (int j = 0; j < n; j++) e[j] = ewt;
                edgesSet = true;
                facesSet = false;
                return loopVertexWeight(n, ewt);
            }
            if (rule <= Crease.RULE_DART) {
                int n = nFaces;
                double fwt = 1.0 / (n * n);
                for (int j = 0; j < n; j++) {
                    e[j] = fwt;
                    f[j] = fwt;
                }
                edgesSet = facesSet = true;
                return (double) (n - 2) / (double) n;
            }
            if (rule == Crease.RULE_CREASE) {
                int c0 = 0, c1 = nEdges - 1;
                while (c0 < nEdges - 1 && !Crease.isSharp(sharp[c0])) c0++;
                while (c1 > 0 && !Crease.isSharp(sharp[c1])) c1--;
                for (int j = 0; j < nEdges; j++) e[j] = 0.0;
                e[c0] = 0.125;
                e[c1] = 0.125;
                edgesSet = true;
                facesSet = false;
                return 0.75;
            }
            edgesSet = facesSet = false;
            return 1.0;
        }
    }
}
