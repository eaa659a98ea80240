package lt.spindulys.subdiv;

/**
 * The creasing rules of OpenSubdiv's Sdc: how sharpness decays from level to level, which rule
 * (smooth, dart, crease, corner) a vertex follows, and the weight that blends two rules when
 * sharpness decays to zero between a parent vertex and its child. Pure functions of sharpness
 * values; no topology and no vertex data.
 *
 * <p>Everything here is computed in {@code float}, in the same order as Sdc, because
 * OpenSubdiv stores sharpness as float and semi-sharp blend weights derive from those float
 * values: doing the arithmetic in double would move semi-sharp results by about 1e-8.
 */
final class Crease {
    private Crease() {}

    static final float SMOOTH = 0f;
    static final float INFINITE = ControlMesh.INFINITELY_SHARP;

    /** Vertex rules, numbered so that a vertex with 0, 1 or 2 sharp edges has that rule. */
    static final int RULE_SMOOTH = 0, RULE_DART = 1, RULE_CREASE = 2, RULE_CORNER = 3;

    static boolean isSmooth(float s) { return s <= SMOOTH; }
    static boolean isSharp(float s) { return s > SMOOTH; }
    static boolean isInfinite(float s) { return s >= INFINITE; }
    static boolean isSemiSharp(float s) { return SMOOTH < s && s < INFINITE; }

    /** Uniform decay: semi-sharp values lose 1 per level, infinite ones stay. */
    static float decrement(float s) {
        if (s <= SMOOTH) return SMOOTH;
        if (s >= INFINITE) return INFINITE;
        if (s > 1f) return s - 1f;
        return SMOOTH;
    }

    /** Sdc's rule for a vertex of the given sharpness with that many sharp incident edges. */
    static int vertexRule(float vertexSharpness, int sharpEdgeCount) {
        if (isSharp(vertexSharpness)) return RULE_CORNER;
        return sharpEdgeCount > 2 ? RULE_CORNER : sharpEdgeCount;
    }

    /**
     * Chaikin decay of one edge's sharpness at one end vertex: 3/4 of its own sharpness plus 1/4
     * of the average of the other semi-sharp edges at that vertex, minus 1.
     *
     * @param incident sharpness of every edge at the vertex (the edge itself included), in the
     *                 vertex's edge order, {@code count} values from {@code offset}
     */
    static float chaikin(float edgeSharpness, int count, float[] incident, int offset) {
        if (count < 2) return decrement(edgeSharpness);
        if (isSmooth(edgeSharpness)) return SMOOTH;
        if (isInfinite(edgeSharpness)) return INFINITE;
        float sharpSum = 0f;
        int sharpCount = 0;
        for (int i = 0; i < count; i++) {
            float s = incident[offset + i];
            if (isSemiSharp(s)) {
                sharpCount++;
                sharpSum += s;
            }
        }
        float e = edgeSharpness;
        if (sharpCount > 1) {
            float avgOthers = (sharpSum - e) / (float) (sharpCount - 1);
            e = 0.75f * e + 0.25f * avgOthers;
        }
        e -= 1f;
        return isSharp(e) ? e : SMOOTH;
    }

    /**
     * The weight of the parent's (sharper) rule when a vertex's rule changes between parent and
     * child; the child's rule gets 1 minus it. Sdc averages the sharpness that decays to zero
     * over the vertex and its edges, clamped to 1.
     *
     * @param childEdges child edge sharpness parallel to {@code parentEdges}, or null for uniform
     *                   creasing (then an edge is in transition when its sharpness is at most 1)
     */
    static float fractionalWeight(float parentVertex, float childVertex, int count,
                                  float[] parentEdges, float[] childEdges) {
        int transitions = 0;
        float sum = 0f;
        if (isSharp(parentVertex) && isSmooth(childVertex)) {
            transitions = 1;
            sum = parentVertex;
        }
        if (childEdges == null) {
            for (int i = 0; i < count; i++) {
                float s = parentEdges[i];
                if (isSharp(s) && s <= 1f) {
                    sum += s;
                    transitions++;
                }
            }
        } else {
            for (int i = 0; i < count; i++) {
                if (isSharp(parentEdges[i]) && isSmooth(childEdges[i])) {
                    sum += parentEdges[i];
                    transitions++;
                }
            }
        }
        if (transitions == 0) return 0f;
        float w = sum / (float) transitions;
        return w > 1f ? 1f : w;
    }
}
