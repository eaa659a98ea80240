package lt.spindulys.subdiv;

import java.util.Arrays;

/**
 * One level of subdivision topology as flat arrays (OpenSubdiv's Vtr::Level in half-edge form),
 * with the sharpness and vertex tags that refinement needs. No vertex data lives here.
 *
 * <p><b>Half-edges.</b> Face f owns the half-edges {@code faceStart[f] .. faceStart[f+1]-1}, one
 * per corner, in winding order; when every face is a quad {@code faceStart} is null and face f
 * owns {@code 4f .. 4f+3}. Half-edge h runs from {@code hOrig[h]} (so {@code hOrig} is also the
 * face-vertex list) to the next corner's vertex. {@code hTwin[h]} is the opposite half-edge in
 * the neighbouring face, or -1 on a boundary and on every non-manifold edge.
 * {@code hEdge[h]} packs the edge index ({@code >>> 2}), whether h is the edge's
 * <i>primary</i> half-edge (the one in its first face, bit 1) and whether h runs from the
 * edge's first vertex to its second (bit 0).
 *
 * <p><b>Far's numbering.</b> Edges, their vertex order and each vertex's first face follow Far
 * exactly, so refined vertices get Far's indices: at level 0 edges are numbered as they first
 * appear face by face; a refined level lists the edges inside parent faces first (one per
 * parent corner, numbered like the parent's half-edges), then two per parent edge. A vertex's
 * faces run counter-clockwise from {@code vOut[v]}, its leading outgoing half-edge in its first
 * face (on a boundary: the outgoing boundary half-edge).
 *
 * <p><b>Sharpness.</b> An edge whose half-edges have no twin (boundary or non-manifold) is
 * infinitely sharp, as in Far; other edges take {@code eSharp} (null: all smooth). Vertex
 * sharpness is {@code vSharp} (null: all smooth). {@code vTag} holds per vertex the subdivision
 * rule and a few flags (null: every vertex is smooth, manifold and interior).
 *
 * <p><b>Non-manifold features</b> keep Far's incidence lists in small side tables: for each
 * non-manifold edge its half-edges in Far's edge-face order, and for each non-manifold vertex
 * its edges in Far's vertex-edge order.
 *
 * <p>A level holds the arrays and the navigation over them. Level 0 is made by
 * {@link BaseLevelBuilder}, each next level by {@link Refinement} or {@link TriangleSplit}
 * (topology) with {@link SharpnessRefinement} (sharpness and tags); the creasing rules are
 * {@link Crease}'s, the weights each scheme's {@link SchemeRules}.
 */
final class Level {
    // vTag bits
    static final int T_RULE = 3, T_SEMI_EDGES = 4, T_NONMANIFOLD = 8, T_BOUNDARY = 16, T_INF_SHARP = 32, T_SEMI_SHARP = 64;
    // hEdge bits
    static final int E_FWD = 1, E_PRIMARY = 2;

    final int depth;
    final int nV, nF, nE, nH;
    final int[] faceStart;
    /**
     * Face of each half-edge, only when faces are not all quads; null too in a level made by the
     * triangle split (all triangles: face f owns {@code 3f .. 3f+2}).
     */
    final int[] hFace;
    /**
     * Whether this level is split into triangles (Loop: every face a triangle, split in four)
     * rather than into quads (Catmull-Clark and bilinear: one quad per face corner).
     */
    boolean triangleSplit;
    final int[] hOrig, hTwin;
    /** Edge codes; null after {@link #dropEdgeCodes} until {@link #edgeCodes()} rebuilds them. */
    int[] hEdge;
    final int[] vOut;

    byte[] vTag;
    /**
     * Only in a UV value mesh with Far's dependent sharpness (CORNERS_PLUS1/PLUS2), else null: per
     * value vertex, the other value of the same vertex whose semi-sharp decay it follows, or -1.
     */
    int[] depOn;
    float[] vSharp;
    float[] eSharp;
    boolean[] hole;

    /** Bytes held by this level's arrays (topology, tags, sharpness), for the benchmark's memory figure. */
    long memoryBytes() {
        long b = 4L * (len(faceStart) + len(hFace) + len(hOrig) + len(hTwin) + retainedEdgeCodeInts() + len(vOut)
                + len(nmEdge) + len(nmEdgeStart) + len(nmEdgeHalf) + len(nmVert) + len(nmVertStart) + len(nmVertHalf) + len(nmVertOther) + len(nmVertEnd));
        b += (vTag == null ? 0 : vTag.length) + 4L * (len(vSharp) + len(eSharp)) + (hole == null ? 0 : hole.length);
        return b;
    }

    private static int len(int[] a) { return a == null ? 0 : a.length; }
    private static int len(float[] a) { return a == null ? 0 : a.length; }

    /** Non-manifold edges (sorted) and, per such edge, its half-edges in Far's edge-face order. */
    int[] nmEdge = new int[0], nmEdgeStart = {0}, nmEdgeHalf = new int[0];
    /**
     * Non-manifold vertices (sorted) and, per such vertex, its edges in Far's order: a half-edge
     * of the edge, the vertex at the other end and the edge's index times 2 plus which end
     * (0 or 1) the vertex is.
     */
    int[] nmVert = new int[0], nmVertStart = {0}, nmVertHalf = new int[0], nmVertOther = new int[0], nmVertEnd = new int[0];
    /** Per non-manifold vertex (parallel to {@link #nmVert}), its corners in Far's vertex-face order. */
    int[] nmFaceStart = {0}, nmFaceHalf = new int[0];

    Level(int depth, int nV, int nF, int nE, int[] faceStart, int[] hFace, int[] hOrig, int[] hTwin, int[] hEdge, int[] vOut) {
        this.depth = depth;
        this.nV = nV;
        this.nF = nF;
        this.nE = nE;
        this.nH = hOrig.length;
        this.faceStart = faceStart;
        this.hFace = hFace;
        this.hOrig = hOrig;
        this.hTwin = hTwin;
        this.hEdge = hEdge;
        this.vOut = vOut;
    }

    // ---------------------------------------------------------------- navigation

    int face(int h) {
        if (hFace != null) return hFace[h];
        return faceStart == null ? h >> 2 : h / 3; // all quads, or all triangles (a Loop level after the first)
    }

    int faceSize(int f) { return faceStart == null ? 4 : faceStart[f + 1] - faceStart[f]; }

    int firstHalf(int f) { return faceStart == null ? f << 2 : faceStart[f]; }

    int next(int h) {
        if (faceStart == null) return (h & ~3) | ((h + 1) & 3);
        if (hFace == null) return h % 3 == 2 ? h - 2 : h + 1; // all triangles
        int f = hFace[h];
        return h + 1 == faceStart[f + 1] ? faceStart[f] : h + 1;
    }

    int prev(int h) {
        if (faceStart == null) return (h & ~3) | ((h + 3) & 3);
        if (hFace == null) return h % 3 == 0 ? h + 2 : h - 1; // all triangles
        int f = hFace[h];
        return h == faceStart[f] ? faceStart[f + 1] - 1 : h - 1;
    }

    int dest(int h) { return hOrig[next(h)]; }

    int edge(int h) { return hEdge[h] >>> 2; }

    boolean fwd(int h) { return (hEdge[h] & E_FWD) != 0; }

    boolean primary(int h) { return (hEdge[h] & E_PRIMARY) != 0; }

    /** The edge's first vertex (Far's edge-vertex 0), from any of its half-edges. */
    int edgeV0(int h) { return fwd(h) ? hOrig[h] : dest(h); }

    int edgeV1(int h) { return fwd(h) ? dest(h) : hOrig[h]; }

    /** Sharpness of the edge of half-edge h: infinite without a twin, else the tagged value. */
    float edgeSharpness(int h) {
        if (hTwin[h] < 0) return Crease.INFINITE;
        return eSharp == null ? 0f : eSharp[hEdge[h] >>> 2];
    }

    float vertexSharpness(int v) { return vSharp == null ? 0f : vSharp[v]; }

    int tag(int v) { return vTag == null ? 0 : vTag[v]; }

    int rule(int v) { return vTag == null ? Crease.RULE_SMOOTH : vTag[v] & T_RULE; }

    boolean isNonManifold(int v) { return vTag != null && (vTag[v] & T_NONMANIFOLD) != 0; }

    /** Index of v in {@link #nmVert}, or a negative number. */
    int nmVertIndex(int v) { return Arrays.binarySearch(nmVert, v); }

    /**
     * Collects the 1-ring of a manifold vertex in Far's order into {@code out}: the outgoing
     * half-edge of each incident face, counter-clockwise from the vertex's first face, and, for a
     * boundary vertex, last the incoming boundary half-edge. Returns the number of faces; the
     * number of edges is that plus 1 on a boundary ({@code out[faces]} is then the incoming
     * half-edge), else equal. {@code out} must hold at least faces + 1 entries.
     */
    int ring(int v, int[] out) {
        int start = vOut[v];
        int h = start, n = 0;
        while (true) {
            out[n++] = h;
            int hp = prev(h);
            int t = hTwin[hp];
            if (t < 0) {
                out[n] = hp;
                return n;
            }
            if (t == start) return n;
            h = t;
        }
    }

    /** Number of faces around a manifold vertex (its valence when interior). */
    int valence(int v) {
        int start = vOut[v], h = start, n = 0;
        while (true) {
            n++;
            int t = hTwin[prev(h)];
            if (t < 0 || t == start) return n;
            h = t;
        }
    }

    private int maxValence = -1;

    /** Largest number of edges at any vertex (at least 4), for scratch sizing. */
    int maxValence() {
        if (maxValence >= 0) return maxValence;
        int max = 4;
        int[] count = new int[nV];
        for (int h = 0; h < nH; h++) count[hOrig[h]]++;
        for (int c : count) max = Math.max(max, c + 1);
        for (int i = 0; i + 1 < nmVertStart.length; i++) max = Math.max(max, nmVertStart[i + 1] - nmVertStart[i]);
        return maxValence = max;
    }

    // ---------------------------------------------------------------- edge codes of the last level

    private int[] parentCodes, parentFaceStart;
    private int parentNF;
    private boolean parentTriangleSplit;

    /**
     * Frees this level's edge codes (a quarter of its topology): they follow from the parent's
     * codes, which are kept instead, and are rebuilt by {@link #edgeCodes()} when needed.
     */
    void dropEdgeCodes(Level parent) {
        parentCodes = parent.edgeCodes();
        parentFaceStart = parent.faceStart;
        parentNF = parent.nF;
        parentTriangleSplit = parent.triangleSplit;
        hEdge = null;
    }

    /** Ints held for edge codes: this level's, or the parent's they are rebuilt from. */
    synchronized long retainedEdgeCodeInts() {
        return hEdge != null ? hEdge.length : parentCodes.length + (parentFaceStart == null ? 0 : parentFaceStart.length);
    }

    /** The edge codes, rebuilt from the parent's if they were dropped. */
    synchronized int[] edgeCodes() {
        if (hEdge == null) {
            int[] ed = new int[nH];
            if (parentTriangleSplit) TriangleSplit.childEdgeCodes(parentCodes, parentNF, ed);
            else Refinement.childEdgeCodes(parentCodes, parentFaceStart, parentNF, ed);
            hEdge = ed;
            parentCodes = parentFaceStart = null;
        }
        return hEdge;
    }
}
