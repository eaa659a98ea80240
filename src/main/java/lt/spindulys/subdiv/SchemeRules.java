package lt.spindulys.subdiv;

/**
 * The rules of one subdivision scheme, apart from topology and from the data they weigh (as
 * OpenSubdiv keeps its {@code sdc} apart from {@code vtr} and {@code far}): how the scheme splits
 * faces, its smooth masks for new edge and vertex points, and its limit masks. The code that
 * walks a level and applies the masks is shared by every scheme: {@link PrimvarRefiner} (with the
 * crease blending of Sdc's {@code ComputeEdgeVertexMask} and {@code ComputeVertexVertexMask}),
 * {@link Limit}, and the splits {@link Refinement} and {@link TriangleSplit}. The sharpness rules
 * are common to all schemes and live in {@link Crease}.
 *
 * <p>Implementations: {@link CatmarkRules} (Catmull-Clark), {@link LoopRules},
 * {@link BilinearRules}. Immutable and stateless.
 */
abstract class SchemeRules {
    /**
     * The rules of the options' scheme (for Catmull-Clark, with their triangle weights).
     *
     * @param o the options
     * @return the rules
     */
    static SchemeRules of(SubdivOptions o) {
        return switch (o.scheme()) {
            case CATMARK -> o.triangles() == SubdivOptions.Triangles.SMOOTH ? CatmarkRules.SMOOTH_TRIANGLES : CatmarkRules.PLAIN;
            case LOOP -> LoopRules.RULES;
            case BILINEAR -> BilinearRules.RULES;
        };
    }

    /** Whether faces split into triangles (Loop: four per triangle, no face points) rather than quads (one per corner). */
    abstract boolean splitsToTriangles();

    /** Whether any limit mask weighs the vertices opposite a vertex in its faces (Catmull-Clark's do). */
    boolean limitUsesFaces() { return !splitsToTriangles() && !linear(); }

    /** Whether every rule is linear (bilinear): face centroids, edge midpoints, vertices kept, whatever the sharpness. */
    boolean linear() { return false; }

    // ---------------------------------------------------------------- refinement masks

    /**
     * The smooth mask of an edge point (Sdc's {@code assignSmoothMaskForEdge}) into {@code w}:
     * {@code w[0]} the weight of each end vertex, {@code w[1]} the weight of each of the edge's
     * two faces' values: its face point in a quad split, the vertex opposite the edge in a
     * triangle split.
     *
     * @param size0 corners of the edge's first face
     * @param size1 corners of its second face
     */
    abstract void smoothEdgeMask(int size0, int size1, double[] w);

    /** The weight of each edge neighbour in the smooth vertex mask of a vertex in n faces. */
    abstract double smoothVertexEdgeWeight(int n);

    /** The weight of each face point in the smooth vertex mask of a vertex in n faces (0 without face points). */
    abstract double smoothVertexFaceWeight(int n);

    /** The vertex's own weight in its smooth mask, given n faces. */
    abstract double smoothVertexWeight(int n);

    /** Sdc's crease vertex mask, the same in every scheme: 3/4 the vertex, 1/8 each sharp neighbour. */
    static final double CREASE_VERTEX = 0.75, CREASE_EDGE = 0.125;

    // ---------------------------------------------------------------- limit masks

    /**
     * Sdc's limit masks of one vertex (position and two tangents) over its neighbourhood: edge
     * neighbours in the vertex's edge order, faces in its face order (the face weights apply to
     * the vertex opposite in each face). Filled by {@link #limitMasks}; arrays sized for the
     * level's largest valence.
     */
    static final class LimitMasks {
        final double[] ew, fw, t1e, t1f, t2e, t2f;
        /** The position's vertex weight and the tangents' vertex weights. */
        double vw, t1v, t2v;
        /** Edge and face weights the position uses (the first ones; the tangents use all edges). */
        int posEdges, posFaces;
        /** Face weights the tangents use: all faces, or none where the scheme has no face weights. */
        int tanFaces;
        /** Scratch: a crease's first and last sharp edge. */
        final int[] ends = new int[2];

        LimitMasks(int cap) {
            ew = new double[cap];
            fw = new double[cap];
            t1e = new double[cap];
            t1f = new double[cap];
            t2e = new double[cap];
            t2f = new double[cap];
        }

        /** Zeroes every weight for a vertex with these counts. */
        void clear(int nEdges, int nFaces) {
            for (int j = 0; j < nEdges; j++) ew[j] = t1e[j] = t2e[j] = 0.0;
            for (int j = 0; j < nFaces; j++) fw[j] = t1f[j] = t2f[j] = 0.0;
            vw = t1v = t2v = 0.0;
            posEdges = nEdges;
            posFaces = nFaces;
            tanFaces = nFaces;
        }
    }

    /**
     * The limit masks of a vertex following {@code rule} (Sdc's {@code ComputeVertexLimitMask}),
     * with tangents: the first along the vertex's first edge (or its first sharp edge), the
     * second turning counter-clockwise, so that their cross product is the normal on the side
     * where faces wind counter-clockwise. Magnitudes are arbitrary, as in Sdc.
     *
     * @param rule        the vertex's rule ({@link Crease#RULE_SMOOTH} ... {@link Crease#RULE_CORNER})
     * @param nEdges      its edges
     * @param nFaces      its faces
     * @param nonManifold whether it is a non-manifold vertex (whose neighbourhood is no disc or half-disc)
     * @param sharp       sharpness of its edges, in its edge order
     * @param m           receives the masks
     */
    abstract void limitMasks(int rule, int nEdges, int nFaces, boolean nonManifold, float[] sharp, LimitMasks m);

    /** The first and last sharp edge of a crease vertex (Sdc's {@code GetSharpEdgePairOfCrease}) into {@code ends}. */
    static void creaseEnds(int nEdges, float[] sharp, int[] ends) {
        int c0 = 0, c1 = nEdges - 1;
        while (c0 < nEdges - 1 && !Crease.isSharp(sharp[c0])) c0++;
        while (c1 > 0 && !Crease.isSharp(sharp[c1])) c1--;
        ends[0] = c0;
        ends[1] = c1;
    }

    /**
     * Sdc's corner masks: the vertex itself, tangents along its first two edges scaled by
     * {@code scale} (each scheme has its own scale; only the direction matters).
     */
    static void cornerLimitMasks(int nEdges, int nFaces, double scale, LimitMasks m) {
        m.clear(nEdges, nFaces);
        m.vw = 1.0;
        m.posEdges = 0;
        m.posFaces = 0;
        m.t1v = -scale;
        m.t2v = -scale;
        m.t1e[0] = scale;
        if (nEdges > 1) m.t2e[1] = scale;
    }
}
