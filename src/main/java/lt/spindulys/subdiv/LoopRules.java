package lt.spindulys.subdiv;

/**
 * Loop's rules as OpenSubdiv's Sdc has them ({@code LoopScheme}, after Hbr): four triangles from
 * every triangle, no face points; smooth edge points 3/8 on the ends and 1/8 on the vertex
 * opposite the edge in each triangle; smooth vertex points with Loop's original (1987) weights,
 * beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n per neighbour and 1 - n beta on the vertex (not
 * Warren's 3 / (8n)); limit positions (1 - n chi) v + chi sum(e) with chi = 1 / (n + 3 / (8 beta)),
 * the cubic B-spline's (1/6, 2/3, 1/6) along creases and boundaries; Sdc's tangents.
 */
final class LoopRules extends SchemeRules {
    static final LoopRules RULES = new LoopRules();

    private static final double ROOT3 = 1.73205080756887729352, ROOT3_BY_2 = ROOT3 * 0.5;
    /** The smooth tangent masks at valence 6. */
    private static final double[] REGULAR_T1 = {1.0, 0.5, -0.5, -1.0, -0.5, 0.5}, REGULAR_T2 = {0.0, ROOT3_BY_2, ROOT3_BY_2, 0.0, -ROOT3_BY_2, -ROOT3_BY_2};

    /** Smooth vertex weights by valence, computed once: the cosine is the costly part. */
    private static final int TABLE = 64;
    private static final double[] EDGE_WEIGHT = new double[TABLE], LIMIT_EDGE_WEIGHT = new double[TABLE];

    static {
        for (int n = 1; n < TABLE; n++) {
            EDGE_WEIGHT[n] = edgeWeight(n);
            LIMIT_EDGE_WEIGHT[n] = limitEdgeWeight(n);
        }
    }

    private LoopRules() {}

    @Override
    boolean splitsToTriangles() { return true; }

    @Override
    void smoothEdgeMask(int size0, int size1, double[] w) {
        w[0] = 0.375;
        w[1] = 0.125;
    }

    @Override
    double smoothVertexEdgeWeight(int n) { return n < TABLE ? EDGE_WEIGHT[n] : edgeWeight(n); }

    @Override
    double smoothVertexFaceWeight(int n) { return 0.0; }

    @Override
    double smoothVertexWeight(int n) { return n == 6 ? 0.625 : 1.0 - smoothVertexEdgeWeight(n) * n; }

    /** Sdc's arithmetic, step for step, so that results match OpenSubdiv's to the last bit. */
    private static double edgeWeight(int n) {
        if (n == 6) return 0.0625;
        double dValence = n, invValence = 1.0 / dValence;
        double cosTheta = Math.cos(Math.PI * 2.0 * invValence);
        double beta = 0.25 * cosTheta + 0.375;
        return (0.625 - beta * beta) * invValence;
    }

    private static double limitEdgeWeight(int n) {
        if (n == 6) return 1.0 / 12.0;
        double dValence = n, invValence = 1.0 / dValence;
        double cosTheta = Math.cos(Math.PI * 2.0 * invValence);
        double beta = 0.25 * cosTheta + 0.375;
        double gamma = (0.625 - beta * beta) * invValence;
        return 1.0 / (dValence + 3.0 / (8.0 * gamma));
    }

    @Override
    void limitMasks(int rule, int nEdges, int nFaces, boolean nonManifold, float[] sharp, LimitMasks m) {
        // Unlike Catmull-Clark, Loop's smooth masks hold at a vertex in two faces too.
        if (rule <= Crease.RULE_DART && !nonManifold) {
            smooth(nEdges, nFaces, m);
        } else if (rule == Crease.RULE_CREASE) {
            crease(nEdges, nFaces, sharp, m);
        } else {
            cornerLimitMasks(nEdges, 0, 3.0, m);
        }
    }

    private static void smooth(int n, int nFaces, LimitMasks m) {
        m.clear(n, 0);
        double ewt = n < TABLE ? LIMIT_EDGE_WEIGHT[n] : limitEdgeWeight(n);
        m.vw = n == 6 ? 0.5 : 1.0 - ewt * n;
        for (int j = 0; j < n; j++) m.ew[j] = ewt;
        if (n == 6) {
            System.arraycopy(REGULAR_T1, 0, m.t1e, 0, 6);
            System.arraycopy(REGULAR_T2, 0, m.t2e, 0, 6);
            return;
        }
        double alpha = 2.0 * Math.PI / n;
        for (int j = 0; j < n; j++) {
            double a = alpha * j;
            m.t1e[j] = Math.cos(a);
            m.t2e[j] = Math.sin(a);
        }
    }

    private static void crease(int nEdges, int nFaces, float[] sharp, LimitMasks m) {
        creaseEnds(nEdges, sharp, m.ends);
        int c0 = m.ends[0], c1 = m.ends[1];
        m.clear(nEdges, 0);
        m.vw = 4.0 / 6.0;
        m.ew[c0] = 1.0 / 6.0;
        m.ew[c1] = 1.0 / 6.0;
        m.t1e[c0] = 1.5;
        m.t1e[c1] = -1.5;
        // The second tangent points across the faces between the two sharp edges (inward).
        int interior = c1 - c0 - 1;
        if (interior == 2) {
            m.t2v = -ROOT3;
            m.t2e[c0] = -ROOT3_BY_2;
            m.t2e[c1] = -ROOT3_BY_2;
            m.t2e[c0 + 1] = ROOT3;
            m.t2e[c0 + 2] = ROOT3;
        } else if (interior > 2) {
            double theta = Math.PI / (interior + 1);
            double cWeight = -3.0 * Math.sin(theta);
            m.t2e[c0] = cWeight;
            m.t2e[c1] = cWeight;
            double eCoeff = -3.0 * 2.0 * (Math.cos(theta) - 1.0);
            for (int i = 1; i <= interior; i++) m.t2e[c0 + i] = eCoeff * Math.sin(i * theta);
        } else if (interior == 1) {
            m.t2v = -3.0;
            m.t2e[c0 + 1] = 3.0;
        } else {
            m.t2v = -6.0;
            m.t2e[c0] = 3.0;
            m.t2e[c1] = 3.0;
        }
    }
}
