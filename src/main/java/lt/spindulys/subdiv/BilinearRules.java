package lt.spindulys.subdiv;

/**
 * Bilinear rules as OpenSubdiv's Sdc has them ({@code BilinearScheme}): quads from every face,
 * every new point linear (face centroids, edge midpoints, vertices kept) whatever the sharpness,
 * and a limit surface that is the refined mesh itself: a vertex's limit is the vertex, its
 * tangents run along its first two edges (the normal of its first face's bilinear patch there).
 * Useful to show a cage refined without smoothing.
 */
final class BilinearRules extends SchemeRules {
    static final BilinearRules RULES = new BilinearRules();

    private BilinearRules() {}

    @Override
    boolean splitsToTriangles() { return false; }

    @Override
    boolean linear() { return true; }

    @Override
    void smoothEdgeMask(int size0, int size1, double[] w) {
        w[0] = 0.5;
        w[1] = 0.0;
    }

    @Override
    double smoothVertexEdgeWeight(int n) { return 0.0; }

    @Override
    double smoothVertexFaceWeight(int n) { return 0.0; }

    @Override
    double smoothVertexWeight(int n) { return 1.0; }

    @Override
    void limitMasks(int rule, int nEdges, int nFaces, boolean nonManifold, float[] sharp, LimitMasks m) {
        cornerLimitMasks(nEdges, 0, 1.0, m);
    }
}
