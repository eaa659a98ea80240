package lt.spindulys.subdiv;

import static lt.spindulys.subdiv.Level.E_PRIMARY;
import static lt.spindulys.subdiv.Level.T_BOUNDARY;
import static lt.spindulys.subdiv.Level.T_INF_SHARP;
import static lt.spindulys.subdiv.Level.T_NONMANIFOLD;
import static lt.spindulys.subdiv.Level.T_RULE;
import static lt.spindulys.subdiv.Level.T_SEMI_EDGES;
import static lt.spindulys.subdiv.Level.T_SEMI_SHARP;

/**
 * How sharpness and vertex tags pass from a {@link Level} to its child, as Far's
 * Vtr::Refinement does it after the topology: edge and vertex sharpness decay (uniform or
 * Chaikin, by {@link Crease}'s rules), the child's vertex tags are propagated from the parent's
 * and the semi-sharp ones reclassified. The rules themselves, pure functions of sharpness values,
 * are in {@link Crease}; this class applies them over a level's topology.
 */
final class SharpnessRefinement {
    private SharpnessRefinement() {}

    /**
     * Gives the child c of p (its topology complete) its edge and vertex sharpness and its
     * vertex tags.
     *
     * @param sharpSource if not null, c's edge sharpness is copied from this level instead of
     *                    decayed from p's (see {@link Refinement#refine})
     */
    static void refine(Level p, Level c, boolean chaikin, Level sharpSource) {
        refineSharpness(p, c, chaikin);
        if (sharpSource != null) c.eSharp = sharpnessFrom(c, sharpSource);
        refineTags(p, c);
    }

    private static void refineSharpness(Level p, Level c, boolean chaikin) {
        int faceEdges = p.nH;
        if (p.eSharp != null) {
            float[] cs = new float[c.nE];
            boolean any = false;
            float[] buf = chaikin ? new float[p.maxValence() + 2] : null;
            int[] ringBuf = chaikin ? new int[buf.length] : null;
            for (int h = 0; h < p.nH; h++) {
                if ((p.hEdge[h] & E_PRIMARY) == 0 || p.hTwin[h] < 0) continue; // implicit-infinite edges stay so
                int e = p.hEdge[h] >>> 2;
                float s = p.eSharp[e];
                if (!Crease.isSemiSharp(s)) {
                    if (Crease.isInfinite(s)) {
                        cs[faceEdges + 2 * e] = cs[faceEdges + 2 * e + 1] = Crease.INFINITE;
                        any = true;
                    }
                    continue;
                }
                for (int end = 0; end < 2; end++) {
                    float childS;
                    if (!chaikin) {
                        childS = Crease.decrement(s);
                    } else {
                        int v = end == 0 ? p.edgeV0(h) : p.edgeV1(h);
                        int n = incidentSharpness(p, v, buf, ringBuf);
                        childS = Crease.chaikin(s, n, buf, 0);
                    }
                    cs[faceEdges + 2 * e + end] = childS;
                    any |= childS != 0f;
                }
            }
            c.eSharp = any ? cs : null;
        }
        if (p.vSharp != null) {
            float[] cv = new float[c.nV];
            boolean any = false;
            for (int v = 0; v < p.nV; v++) {
                cv[v] = Crease.decrement(p.vSharp[v]);
                any |= cv[v] != 0f;
            }
            c.vSharp = any ? cv : null;
        }
    }

    /** Edge sharpness for level c copied from level src that shares its half-edge numbering. */
    private static float[] sharpnessFrom(Level c, Level src) {
        float[] cs = null;
        for (int h = 0; h < c.nH; h++) {
            if ((c.hEdge[h] & E_PRIMARY) == 0 || c.hTwin[h] < 0) continue;
            float s = src.edgeSharpness(h);
            if (s != 0f) {
                if (cs == null) cs = new float[c.nE];
                cs[c.hEdge[h] >>> 2] = s;
            }
        }
        return cs;
    }

    /** Sharpness of every edge at v in Far's order into buf; returns the count. */
    private static int incidentSharpness(Level p, int v, float[] buf, int[] ringBuf) {
        int i = p.nmVertIndex(v);
        if (i >= 0) {
            int n = 0;
            for (int k = p.nmVertStart[i]; k < p.nmVertStart[i + 1]; k++) buf[n++] = p.edgeSharpness(p.nmVertHalf[k]);
            return n;
        }
        int n = p.ring(v, ringBuf);
        int edges = p.hTwin[p.vOut[v]] < 0 ? n + 1 : n;
        for (int j = 0; j < edges; j++) buf[j] = p.edgeSharpness(ringBuf[j]);
        return edges;
    }

    /** Far's propagation of vertex tags to the child, then its reclassification of semi-sharp ones. */
    private static void refineTags(Level p, Level c) {
        if (p.vTag == null) return;
        byte[] ct = new byte[c.nV];
        System.arraycopy(p.vTag, 0, ct, 0, p.nV);
        int faceEdges = p.nH;
        int eBase = p.triangleSplit ? p.nV : p.nV + p.nF; // the first edge point (no face points in a triangle split)
        boolean[] nmE = new boolean[p.nE];
        for (int e : p.nmEdge) nmE[e] = true;
        for (int h = 0; h < p.nH; h++) {
            if ((p.hEdge[h] & E_PRIMARY) == 0) continue;
            int e = p.hEdge[h] >>> 2;
            float s = p.edgeSharpness(h);
            int t = Crease.isSharp(s) ? Crease.RULE_CREASE : Crease.RULE_SMOOTH;
            if (nmE[e]) t |= T_NONMANIFOLD;
            else if (p.hTwin[h] < 0) t |= T_BOUNDARY;
            if (Crease.isSemiSharp(s)) t |= T_SEMI_EDGES;
            ct[eBase + e] = (byte) t;
        }
        c.vTag = ct;
        // Semi-sharp edge points: the rule follows how many of the two child edges stay sharp.
        for (int h = 0; h < p.nH; h++) {
            if ((p.hEdge[h] & E_PRIMARY) == 0) continue;
            int e = p.hEdge[h] >>> 2;
            int v = eBase + e;
            if ((ct[v] & T_SEMI_EDGES) == 0) continue;
            int sharp = 0;
            if (c.eSharp != null) {
                if (Crease.isSemiSharp(c.eSharp[faceEdges + 2 * e])) sharp++;
                if (Crease.isSemiSharp(c.eSharp[faceEdges + 2 * e + 1])) sharp++;
            }
            int t = ct[v] & ~(T_RULE | T_SEMI_EDGES);
            if (sharp > 0) t |= T_SEMI_EDGES;
            t |= Crease.vertexRule(0f, sharp);
            ct[v] = (byte) t;
        }
        // Vertex points of semi-sharp vertices or vertices with semi-sharp edges.
        int[] ringBuf = new int[p.maxValence() + 2];
        for (int v = 0; v < p.nV; v++) {
            int pt = p.vTag[v];
            int t = ct[v];
            float cs = c.vertexSharpness(v);
            if ((t & T_SEMI_SHARP) != 0 && !Crease.isSharp(cs)) t &= ~T_SEMI_SHARP;
            if ((pt & (T_SEMI_SHARP | T_SEMI_EDGES)) != 0) {
                boolean decayed = (pt & T_SEMI_SHARP) != 0 && (t & T_SEMI_SHARP) == 0;
                if ((pt & T_SEMI_EDGES) != 0 || decayed) {
                    int inf = 0, semi = 0;
                    int i = p.nmVertIndex(v);
                    if (i >= 0) {
                        for (int k = p.nmVertStart[i]; k < p.nmVertStart[i + 1]; k++) {
                            float s = childEdgeSharpness(p, c, p.nmVertHalf[k], p.nmVertEnd[k]);
                            if (Crease.isInfinite(s)) inf++;
                            else if (Crease.isSharp(s)) semi++;
                        }
                    } else {
                        int n = p.ring(v, ringBuf);
                        int edges = p.hTwin[p.vOut[v]] < 0 ? n + 1 : n;
                        for (int j = 0; j < edges; j++) {
                            int x = ringBuf[j];
                            int end = j < n ? (p.fwd(x) ? 0 : 1) : (p.fwd(x) ? 1 : 0);
                            float s = childEdgeSharpness(p, c, x, (p.hEdge[x] >>> 2) << 1 | end);
                            if (Crease.isInfinite(s)) inf++;
                            else if (Crease.isSharp(s)) semi++;
                        }
                    }
                    t &= ~T_SEMI_EDGES;
                    if (semi > 0) t |= T_SEMI_EDGES;
                    if ((t & (T_SEMI_SHARP | T_INF_SHARP)) == 0) t = (t & ~T_RULE) | Crease.vertexRule(0f, inf + semi);
                }
            }
            ct[v] = (byte) t;
        }
    }

    /**
     * Sharpness in the child of the half of a parent edge at one end: x is a half-edge of the
     * parent edge, {@code edgeEnd} the parent edge index times 2 plus the end.
     */
    static float childEdgeSharpness(Level p, Level c, int x, int edgeEnd) {
        if (p.hTwin[x] < 0) return Crease.INFINITE;
        return c.eSharp == null ? 0f : c.eSharp[p.nH + edgeEnd];
    }
}
