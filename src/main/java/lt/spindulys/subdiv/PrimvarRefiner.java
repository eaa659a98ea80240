package lt.spindulys.subdiv;

/**
 * Applies a scheme's weights (its {@link SchemeRules}) to data carried by the vertices of a
 * level, giving the data of the refined level: OpenSubdiv's {@code PrimvarRefiner::Interpolate}
 * with Sdc's generic mask logic (creases, corners, and the blend where sharpness decays between a
 * level and its child). The same code refines positions (3 values per vertex) and face-varying
 * UVs (2 per vertex of the UV "value mesh"), so both follow one set of rules, and the same code
 * serves every scheme: only the smooth masks differ between them.
 *
 * <p>Weights and the order of summation follow Far (faces, then edges, then the vertex itself),
 * so results agree with OpenSubdiv to the last bits in the common cases.
 */
final class PrimvarRefiner {
    private PrimvarRefiner() {}

    /**
     * @param src    {@code stride} values per vertex of {@code p}
     * @param dst    receives {@code stride} values per vertex of {@code c}
     * @param linear linear interpolation whatever the scheme (Far's linear face-varying
     *               interpolation): face centroids, edge midpoints, vertices kept
     */
    static void interpolate(Level p, Level c, SubdivOptions opt, int stride, double[] src, double[] dst, boolean linear) {
        SchemeRules rules = SchemeRules.of(opt);
        p.edgeCodes();
        if (!p.triangleSplit) faces(p, stride, src, dst);
        if (linear || rules.linear()) {
            linearEdgesAndVertices(p, stride, src, dst);
            return;
        }
        edges(p, c, rules, stride, src, dst);
        vertices(p, c, rules, opt.creasing() == SubdivOptions.Creasing.CHAIKIN, stride, src, dst);
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

    /**
     * Edge points: Sdc's {@code ComputeEdgeVertexMask}. A crease (1/2, 1/2) where the child
     * stays a crease, the scheme's smooth mask where the edge is smooth, and between them, where
     * a semi-sharp edge decays to smooth in the child, the smooth mask blended with the crease by
     * the parent sharpness. The smooth mask's face weights apply to the face points (quad split)
     * or to the vertices opposite the edge (triangle split).
     */
    private static void edges(Level p, Level c, SchemeRules rules, int stride, double[] src, double[] dst) {
        boolean opposite = p.triangleSplit;
        int[] code = p.hEdge, twin = p.hTwin;
        int vFace = p.nV, vEdge = firstEdgePoint(p);
        double[] w = new double[2];
        for (int h = 0; h < p.nH; h++) {
            int ch = code[h];
            if ((ch & Level.E_PRIMARY) == 0) continue;
            int e = ch >>> 2;
            int out = (vEdge + e) * stride;
            int v0 = p.edgeV0(h) * stride, v1 = p.edgeV1(h) * stride;
            float sharp = p.edgeSharpness(h);
            // An infinitely sharp edge is always a crease (a face-varying boundary edge's point
            // may be pinned as a corner).
            if (Crease.isSharp(sharp) && (Crease.isInfinite(sharp) || c.rule(vEdge + e) == Crease.RULE_CREASE)) {
                for (int d = 0; d < stride; d++) dst[out + d] = 0.5 * src[v0 + d] + 0.5 * src[v1 + d];
                continue;
            }
            int t = twin[h];
            rules.smoothEdgeMask(p.faceSize(p.face(h)), p.faceSize(p.face(t)), w);
            double vw = w[0], fw = w[1];
            if (Crease.isSharp(sharp)) {
                // A crease decaying to smooth in the child: blend by the parent sharpness.
                double pw = sharp, cw = 1.0 - pw;
                vw = pw * 0.5 + cw * vw;
                fw = fw * cw;
            }
            if (opposite) {
                int o0 = p.hOrig[p.prev(h)] * stride, o1 = p.hOrig[p.prev(t)] * stride;
                for (int d = 0; d < stride; d++) {
                    dst[out + d] = vw * src[v0 + d] + vw * src[v1 + d] + fw * src[o0 + d] + fw * src[o1 + d];
                }
            } else {
                int f0 = (vFace + p.face(h)) * stride, f1 = (vFace + p.face(t)) * stride;
                for (int d = 0; d < stride; d++) {
                    dst[out + d] = vw * src[v0 + d] + vw * src[v1 + d] + fw * dst[f0 + d] + fw * dst[f1 + d];
                }
            }
        }
    }

    /**
     * Vertex points: Sdc's {@code ComputeVertexVertexMask}. Smooth and dart vertices take the
     * scheme's smooth mask; the others go through {@link VertexMask} (crease, corner, blends).
     */
    private static void vertices(Level p, Level c, SchemeRules rules, boolean chaikin, int stride, double[] src, double[] dst) {
        int[] orig = p.hOrig, twin = p.hTwin;
        int vFace = p.nV;
        boolean quads = p.faceStart == null, facePoints = !p.triangleSplit;
        VertexMask m = null;
        for (int v = 0; v < p.nV; v++) {
            int pRule = p.rule(v);
            int vs = v * stride;
            if (pRule <= Crease.RULE_DART) {
                int start = p.vOut[v];
                int n = p.valence(v);
                double fw = rules.smoothVertexFaceWeight(n), ew = rules.smoothVertexEdgeWeight(n), vw = rules.smoothVertexWeight(n);
                if (stride == 3 && quads) {
                    // The common case, unrolled: positions on a level of quads.
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
                        ax += ew * src[op];
                        ay += ew * src[op + 1];
                        az += ew * src[op + 2];
                        h = twin[(h & ~3) | ((h + 3) & 3)];
                    } while (h != start);
                    int out = v * 3;
                    dst[out] = ax + vw * src[vs];
                    dst[out + 1] = ay + vw * src[vs + 1];
                    dst[out + 2] = az + vw * src[vs + 2];
                    continue;
                }
                if (stride == 3 && p.hFace == null) {
                    // Positions on a level of triangles (Loop), in one walk around the vertex.
                    double ax = 0, ay = 0, az = 0;
                    int h = start;
                    do {
                        int k = h % 3;
                        int op = orig[k == 2 ? h - 2 : h + 1] * 3;
                        ax += ew * src[op];
                        ay += ew * src[op + 1];
                        az += ew * src[op + 2];
                        h = twin[k == 0 ? h + 2 : h - 1];
                    } while (h != start);
                    dst[vs] = ax + vw * src[vs];
                    dst[vs + 1] = ay + vw * src[vs + 1];
                    dst[vs + 2] = az + vw * src[vs + 2];
                    continue;
                }
                for (int d = 0; d < stride; d++) {
                    double acc = 0.0;
                    int h = start;
                    if (facePoints) {
                        do {
                            acc += fw * dst[(vFace + p.face(h)) * stride + d];
                            h = twin[p.prev(h)];
                        } while (h != start);
                    }
                    do {
                        acc += ew * src[p.dest(h) * stride + d];
                        h = twin[p.prev(h)];
                    } while (h != start);
                    dst[vs + d] = acc + vw * src[vs + d];
                }
                continue;
            }
            if (m == null) m = new VertexMask(p.maxValence() + 2);
            m.gather(p, c, v);
            m.compute(p, c, v, chaikin, rules, facePoints);
            for (int d = 0; d < stride; d++) {
                double acc = 0.0;
                if (m.hasFaces) for (int i = 0; i < m.nFaces; i++) acc += m.fw[i] * dst[(vFace + m.face[i]) * stride + d];
                if (m.hasEdges) for (int i = 0; i < m.nEdges; i++) acc += m.ew[i] * src[m.other[i] * stride + d];
                dst[vs + d] = acc + m.vw * src[vs + d];
            }
        }
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

        /** Sdc's {@code ComputeVertexVertexMask} for vertex v of p with child rule from c, with the scheme's masks. */
        void compute(Level p, Level c, int v, boolean chaikin, SchemeRules rules, boolean facePoints) {
            this.rules = rules;
            this.facePoints = facePoints;
            int pRule = p.rule(v), cRule = c.rule(v);
            float pVs = p.vertexSharpness(v), cVs = c.vertexSharpness(v);
            vw = assign(pRule, pSharp, ew, fw);
            hasEdges = edgesSet;
            hasFaces = facesSet;
            if (cRule == pRule) return;
            // Sdc blends the parent's mask with the child's by the fractional weight.
            double cvw = assign(cRule, cSharp, ewChild, fwChild);
            boolean cEdges = edgesSet, cFaces = facesSet;
            double pw;
            int b = p.depOn == null ? -1 : p.depOn[v];
            if (b < 0) {
                pw = Crease.fractionalWeight(pVs, cVs, nEdges, pSharp, chaikin ? cSharp : null);
            } else {
                // A dependent UV value blends with the weight of the value it depends on.
                if (followed == null) followed = new VertexMask(pSharp.length);
                followed.gather(p, c, b);
                pw = Crease.fractionalWeight(p.vertexSharpness(b), c.vertexSharpness(b), followed.nEdges, followed.pSharp, chaikin ? followed.cSharp : null);
            }
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
        private final int[] ends = new int[2];
        /** The neighbourhood of the value a dependent UV value follows (made when first needed). */
        private VertexMask followed;
        /** The scheme's masks, and whether it makes face points. */
        private SchemeRules rules;
        private boolean facePoints;

        /**
         * The scheme's mask of one rule into e (edge ends) and f (face points); returns the
         * vertex's own weight. Smooth (and dart): the scheme's smooth mask; crease: 3/4 and 1/8
         * on the first and last sharp edge; corner: the vertex alone (Sdc's, in every scheme).
         */
        private double assign(int rule, float[] sharp, double[] e, double[] f) {
            if (rule <= Crease.RULE_DART) {
                int n = nFaces;
                double ewt = rules.smoothVertexEdgeWeight(n), fwt = rules.smoothVertexFaceWeight(n);
                for (int j = 0; j < n; j++) e[j] = ewt;
                if (facePoints) for (int j = 0; j < n; j++) f[j] = fwt;
                edgesSet = true;
                facesSet = facePoints;
                return rules.smoothVertexWeight(n);
            }
            if (rule == Crease.RULE_CREASE) {
                SchemeRules.creaseEnds(nEdges, sharp, ends);
                int c0 = ends[0], c1 = ends[1];
                for (int j = 0; j < nEdges; j++) e[j] = 0.0;
                e[c0] = SchemeRules.CREASE_EDGE;
                e[c1] = SchemeRules.CREASE_EDGE;
                edgesSet = true;
                facesSet = false;
                return SchemeRules.CREASE_VERTEX;
            }
            edgesSet = facesSet = false;
            return 1.0;
        }
    }
}
