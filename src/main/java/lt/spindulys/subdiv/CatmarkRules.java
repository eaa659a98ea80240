package lt.spindulys.subdiv;

/**
 * Catmull-Clark's rules as OpenSubdiv's Sdc has them ({@code CatmarkScheme}): quads from every
 * face; face points at centroids; smooth edge points (v0 + v1 + f0 + f1) / 4, or Hbr's smooth
 * triangle weights next to triangles when asked; smooth vertex points ((n-2) v + sum(e) / n +
 * sum(f) / n) / n; the limit masks of Halstead et al. with Sdc's tangents.
 */
final class CatmarkRules extends SchemeRules {
    /** Catmull-Clark's own weights at triangles. */
    static final CatmarkRules PLAIN = new CatmarkRules(false);
    /** Hbr's smooth-triangle edge weights ({@link SubdivOptions.Triangles#SMOOTH}). */
    static final CatmarkRules SMOOTH_TRIANGLES = new CatmarkRules(true);

    /** Far's smooth-triangle edge weight (after Hbr). */
    private static final double TRI_EDGE_WEIGHT = 0.470;

    /** The limit masks at a regular interior vertex (valence 4), unrolled by {@link Limit}. */
    static final double REGULAR_LIMIT_FACE = 1.0 / 36.0, REGULAR_LIMIT_EDGE = 1.0 / 9.0, REGULAR_LIMIT_VERTEX = 4.0 / 9.0;

    /** The smooth tangent masks at valence 4 (edges, faces). */
    private static final double[] REGULAR_T1E = {4, 0, -4, 0}, REGULAR_T1F = {1, -1, -1, 1}, REGULAR_T2E = {0, 4, 0, -4}, REGULAR_T2F = {1, 1, -1, -1};

    private final boolean smoothTriangles;

    private CatmarkRules(boolean smoothTriangles) { this.smoothTriangles = smoothTriangles; }

    @Override
    boolean splitsToTriangles() { return false; }

    @Override
    void smoothEdgeMask(int size0, int size1, double[] w) {
        double vw = 0.25, fw = 0.25;
        if (smoothTriangles) {
            boolean tri0 = size0 == 3, tri1 = size1 == 3;
            if (tri0 || tri1) {
                double w0 = tri0 ? TRI_EDGE_WEIGHT : 0.25, w1 = tri1 ? TRI_EDGE_WEIGHT : 0.25;
                fw = 0.5 * (w0 + w1);
                vw = 0.5 * (1.0 - 2.0 * fw);
            }
        }
        w[0] = vw;
        w[1] = fw;
    }

    @Override
    double smoothVertexEdgeWeight(int n) { return 1.0 / (n * n); }

    @Override
    double smoothVertexFaceWeight(int n) { return 1.0 / (n * n); }

    @Override
    double smoothVertexWeight(int n) { return (double) (n - 2) / (double) n; }

    @Override
    void limitMasks(int rule, int nEdges, int nFaces, boolean nonManifold, float[] sharp, LimitMasks m) {
        // Sdc treats a smooth vertex in two faces as a corner (its smooth masks degenerate).
        if (rule <= Crease.RULE_DART && nFaces != 2 && !nonManifold) {
            smooth(nFaces, m);
        } else if (rule == Crease.RULE_CREASE) {
            crease(nEdges, nFaces, sharp, m);
        } else {
            cornerLimitMasks(nEdges, nFaces, 1.0, m);
        }
    }

    private static void smooth(int n, LimitMasks m) {
        m.clear(n, n);
        double fwt, ewt;
        if (n == 4) {
            fwt = REGULAR_LIMIT_FACE;
            ewt = REGULAR_LIMIT_EDGE;
            m.vw = REGULAR_LIMIT_VERTEX;
        } else {
            double valence = n;
            fwt = 1.0 / (valence * (valence + 5.0));
            ewt = 4.0 * fwt;
            m.vw = 1.0 - valence * (ewt + fwt);
        }
        for (int j = 0; j < n; j++) {
            m.ew[j] = ewt;
            m.fw[j] = fwt;
        }
        if (n == 4) {
            System.arraycopy(REGULAR_T1E, 0, m.t1e, 0, 4);
            System.arraycopy(REGULAR_T1F, 0, m.t1f, 0, 4);
            System.arraycopy(REGULAR_T2E, 0, m.t2e, 0, 4);
            System.arraycopy(REGULAR_T2F, 0, m.t2f, 0, 4);
            return;
        }
        double theta = 2.0 * Math.PI / n;
        double cosTheta = Math.cos(theta), cosHalfTheta = Math.cos(theta * 0.5);
        double lambda = (5.0 / 16.0) + (1.0 / 16.0) * (cosTheta + cosHalfTheta * Math.sqrt(2.0 * (9.0 + cosTheta)));
        double faceScale = 1.0 / (4.0 * lambda - 1.0);
        for (int j = 0; j < n; j++) {
            double ci = Math.cos(j * theta), ci1 = Math.cos((j + 1) * theta);
            m.t1e[j] = 4.0 * ci;
            m.t1f[j] = faceScale * (ci + ci1);
        }
        m.t2e[0] = m.t1e[n - 1];
        m.t2f[0] = m.t1f[n - 1];
        for (int j = 1; j < n; j++) {
            m.t2e[j] = m.t1e[j - 1];
            m.t2f[j] = m.t1f[j - 1];
        }
    }

    private static void crease(int nEdges, int nFaces, float[] sharp, LimitMasks m) {
        creaseEnds(nEdges, sharp, m.ends);
        int c0 = m.ends[0], c1 = m.ends[1];
        m.clear(nEdges, nFaces);
        m.vw = 2.0 / 3.0;
        m.ew[c0] = 1.0 / 6.0;
        m.ew[c1] = 1.0 / 6.0;
        m.posFaces = 0;
        m.t1e[c0] = 0.5;
        m.t1e[c1] = -0.5;
        int interior = c1 - c0 - 1;
        if (interior == 1) {
            m.t2v = -4.0 / 6.0;
            m.t2e[c0] = -1.0 / 6.0;
            m.t2e[c0 + 1] = 4.0 / 6.0;
            m.t2e[c1] = -1.0 / 6.0;
            m.t2f[c0] = 1.0 / 6.0;
            m.t2f[c0 + 1] = 1.0 / 6.0;
        } else if (interior > 1) {
            double k = interior + 1;
            double theta = Math.PI / k;
            double cosTheta = Math.cos(theta), sinTheta = Math.sin(theta);
            double commonDenom = 1.0 / (k * (3.0 + cosTheta));
            double r = (cosTheta + 1.0) / sinTheta;
            double vertexWeight = 4.0 * r * (cosTheta - 1.0);
            double creaseWeight = -r * (1.0 + 2.0 * cosTheta);
            m.t2v = vertexWeight * commonDenom;
            m.t2e[c0] = creaseWeight * commonDenom;
            m.t2e[c1] = creaseWeight * commonDenom;
            m.t2f[c0] = sinTheta * commonDenom;
            double sinI, sinI1 = sinTheta;
            for (int i = 1; i < k; i++) {
                sinI = sinI1;
                sinI1 = Math.sin((i + 1) * theta);
                m.t2e[c0 + i] = (4.0 * sinI) * commonDenom;
                m.t2f[c0 + i] = (sinI + sinI1) * commonDenom;
            }
        } else {
            m.t2v = -6.0;
            m.t2e[c0] = 3.0;
            m.t2e[c1] = 3.0;
            m.t2f[c0] = 0.0;
        }
    }
}
