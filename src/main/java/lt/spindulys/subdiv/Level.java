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
 * <p>Level 0 is made by {@link BaseLevelBuilder}; each next level by {@link #refine}.
 */
final class Level {
    // vTag bits
    static final int T_RULE = 3, T_SEMI_EDGES = 4, T_NONMANIFOLD = 8, T_BOUNDARY = 16, T_INF_SHARP = 32, T_SEMI_SHARP = 64;
    // hEdge bits
    static final int E_FWD = 1, E_PRIMARY = 2;

    final int depth;
    final int nV, nF, nE, nH;
    final int[] faceStart;
    /** Face of each half-edge, only when faces are not all quads. */
    final int[] hFace;
    final int[] hOrig, hTwin;
    /** Edge codes; null after {@link #dropEdgeCodes} until {@link #edgeCodes()} rebuilds them. */
    int[] hEdge;
    final int[] vOut;

    byte[] vTag;
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

    int face(int h) { return hFace == null ? h >> 2 : hFace[h]; }

    int faceSize(int f) { return faceStart == null ? 4 : faceStart[f + 1] - faceStart[f]; }

    int firstHalf(int f) { return faceStart == null ? f << 2 : faceStart[f]; }

    int next(int h) {
        if (faceStart == null) return (h & ~3) | ((h + 1) & 3);
        int f = hFace[h];
        return h + 1 == faceStart[f + 1] ? faceStart[f] : h + 1;
    }

    int prev(int h) {
        if (faceStart == null) return (h & ~3) | ((h + 3) & 3);
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

    // ---------------------------------------------------------------- refinement

    /**
     * Far's uniform Catmull-Clark split: the child topology, built straight from this level's
     * half-edges (no searching), followed by the sharpness decay and the child vertex tags.
     * Child vertices: those of the vertices (same index), then one per face, then one per edge.
     *
     * @param sharpSource if not null, the child's edge sharpness is taken from this level (the
     *                    geometry's child, for a face-varying value mesh with the same half-edges)
     */
    Level refine(boolean chaikin, Level sharpSource) {
        int cV = nV + nF + nE, cF = nH, cE = nH + 2 * nE, cH = 4 * nH;
        if (cH < 0 || (long) cE * 4 > Integer.MAX_VALUE) throw new IllegalStateException("refined mesh too large for int indices");
        edgeCodes();
        int[] o = new int[cH], tw = new int[cH], ed = new int[cH];
        if (faceStart == null) refineQuads(o, tw);
        else refineGeneral(o, tw);
        childEdgeCodes(hEdge, faceStart, nF, ed);
        int[] out = new int[cV];
        for (int v = 0; v < nV; v++) {
            int h = vOut[v];
            out[v] = h < 0 ? -1 : 4 * h + (rot(h) & 3);
        }
        for (int f = 0; f < nF; f++) {
            out[nV + f] = 4 * firstHalf(f) + 2;
        }
        int eBase = nV + nF;
        for (int h = 0; h < nH; h++) {
            if ((hEdge[h] & E_PRIMARY) != 0) {
                int x = next(h);
                out[eBase + (hEdge[h] >>> 2)] = 4 * x + ((rot(x) + 3) & 3);
            }
        }
        Level c = new Level(depth + 1, cV, cF, cE, null, null, o, tw, ed, out);
        copyHoles(c);
        refineNonManifold(c);
        refineNonManifoldFaces(c);
        refineSharpness(c, chaikin);
        if (sharpSource != null) c.eSharp = sharpnessFrom(c, sharpSource);
        refineTags(c);
        return c;
    }

    /**
     * The child's faces and edges only, without twins, vertex rings, sharpness or tags: all that
     * bilinear interpolation (linear face-varying data) needs, at under half the cost.
     */
    Level refineCornersAndEdges() {
        int cV = nV + nF + nE, cF = nH, cE = nH + 2 * nE, cH = 4 * nH;
        if (cH < 0 || (long) cE * 4 > Integer.MAX_VALUE) throw new IllegalStateException("refined mesh too large for int indices");
        edgeCodes();
        int[] o = new int[cH], ed = new int[cH];
        int vFace = nV, vEdge = nV + nF;
        for (int f = 0; f < nF; f++) {
            int s = firstHalf(f), n = faceSize(f);
            for (int k = 0; k < n; k++) {
                int h = s + k, hp = k > 0 ? h - 1 : s + n - 1, r = n == 4 ? k : 0, base = h << 2;
                o[base + (r & 3)] = hOrig[h];
                o[base + ((r + 1) & 3)] = vEdge + (hEdge[h] >>> 2);
                o[base + ((r + 2) & 3)] = vFace + f;
                o[base + ((r + 3) & 3)] = vEdge + (hEdge[hp] >>> 2);
            }
        }
        childEdgeCodes(hEdge, faceStart, nF, ed);
        Level c = new Level(depth + 1, cV, cF, cE, null, null, o, null, ed, null);
        copyHoles(c);
        return c;
    }

    private void copyHoles(Level c) {
        if (hole != null) {
            boolean[] ch = new boolean[c.nF];
            for (int h = 0; h < nH; h++) ch[h] = hole[face(h)];
            c.hole = ch;
        }
    }

    private int[] parentCodes, parentFaceStart;
    private int parentNF;

    /**
     * Frees this level's edge codes (a quarter of its topology): they follow from the parent's
     * codes, which are kept instead, and are rebuilt by {@link #edgeCodes()} when needed.
     */
    void dropEdgeCodes(Level parent) {
        parentCodes = parent.edgeCodes();
        parentFaceStart = parent.faceStart;
        parentNF = parent.nF;
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
            childEdgeCodes(parentCodes, parentFaceStart, parentNF, ed);
            hEdge = ed;
            parentCodes = parentFaceStart = null;
        }
        return hEdge;
    }

    /**
     * The edge codes of the child of a level with the given codes and faces. A child edge is
     * either inside a parent face (numbered like the parent's half-edge it meets, running from
     * the face point) or half of a parent edge (2e + end, running from the edge point), and its
     * primary half-edge lies in the child of the parent edge's first face.
     */
    static void childEdgeCodes(int[] code, int[] faceStart, int nF, int[] ed) {
        int faceEdges = code.length;
        if (faceStart == null) {
            for (int h = 0; h < faceEdges; h++) {
                int k = h & 3, hp = (h & ~3) | ((h + 3) & 3), base = h << 2;
                int ch = code[h], cp = code[hp];
                ed[base + k] = (faceEdges + 2 * (ch >>> 2) + (~ch & 1)) << 2 | (ch & E_PRIMARY);
                ed[base + ((k + 1) & 3)] = h << 2 | E_PRIMARY;
                ed[base + ((k + 2) & 3)] = hp << 2 | E_FWD;
                ed[base + ((k + 3) & 3)] = (faceEdges + 2 * (cp >>> 2) + (cp & 1)) << 2 | (cp & E_PRIMARY) | E_FWD;
            }
            return;
        }
        for (int f = 0; f < nF; f++) {
            int s = faceStart[f], n = faceStart[f + 1] - s;
            for (int k = 0; k < n; k++) {
                int h = s + k, hp = k > 0 ? h - 1 : s + n - 1, r = n == 4 ? k : 0, base = h << 2;
                int ch = code[h], cp = code[hp];
                ed[base + (r & 3)] = (faceEdges + 2 * (ch >>> 2) + (~ch & 1)) << 2 | (ch & E_PRIMARY);
                ed[base + ((r + 1) & 3)] = h << 2 | E_PRIMARY;
                ed[base + ((r + 2) & 3)] = hp << 2 | E_FWD;
                ed[base + ((r + 3) & 3)] = (faceEdges + 2 * (cp >>> 2) + (cp & 1)) << 2 | (cp & E_PRIMARY) | E_FWD;
            }
        }
    }

    /** The rotation of the child faces of h's face: quads keep the parent corner in place. */
    private int rot(int h) {
        if (faceStart == null) return h & 3;
        int f = hFace[h];
        return faceStart[f + 1] - faceStart[f] == 4 ? h - faceStart[f] : 0;
    }

    private void refineQuads(int[] o, int[] tw) {
        final int[] orig = hOrig, twin = hTwin, code = hEdge;
        final int vFace = nV, vEdge = nV + nF, faceEdges = nH;
        for (int f = 0, h0 = 0; f < nF; f++, h0 += 4) {
            int fv = vFace + f;
            for (int k = 0; k < 4; k++) {
                int h = h0 + k;
                int hn = h0 + ((k + 1) & 3), hp = h0 + ((k + 3) & 3);
                int base = h << 2;
                int c0 = base + k, c1 = base + ((k + 1) & 3), c2 = base + ((k + 2) & 3), c3 = base + ((k + 3) & 3);
                int ch = code[h], cp = code[hp];
                o[c0] = orig[h];
                o[c1] = vEdge + (ch >>> 2);
                o[c2] = fv;
                o[c3] = vEdge + (cp >>> 2);
                tw[c1] = (hn << 2) + ((k + 3) & 3);
                tw[c2] = (hp << 2) + k;
                int t = twin[h];
                if (t < 0) {
                    tw[c0] = -1;
                } else {
                    int tn = (t & ~3) | ((t + 1) & 3);
                    tw[c0] = (tn << 2) + (t & 3);
                }
                int tp = twin[hp];
                tw[c3] = tp < 0 ? -1 : (tp << 2) + (tp & 3);
            }
        }
    }

    private void refineGeneral(int[] o, int[] tw) {
        final int vFace = nV, vEdge = nV + nF, faceEdges = nH;
        for (int f = 0; f < nF; f++) {
            int s = faceStart[f], n = faceStart[f + 1] - s;
            boolean quad = n == 4;
            for (int k = 0; k < n; k++) {
                int h = s + k;
                int hn = k + 1 < n ? h + 1 : s, hp = k > 0 ? h - 1 : s + n - 1;
                int r = quad ? k : 0;
                int base = h << 2;
                int c0 = base + (r & 3), c1 = base + ((r + 1) & 3), c2 = base + ((r + 2) & 3), c3 = base + ((r + 3) & 3);
                int ch = hEdge[h], cp = hEdge[hp];
                o[c0] = hOrig[h];
                o[c1] = vEdge + (ch >>> 2);
                o[c2] = vFace + f;
                o[c3] = vEdge + (cp >>> 2);
                tw[c1] = (hn << 2) + ((rot(hn) + 2) & 3);
                tw[c2] = (hp << 2) + ((rot(hp) + 1) & 3);
                int t = hTwin[h];
                if (t < 0) {
                    tw[c0] = -1;
                } else {
                    int tn = next(t);
                    tw[c0] = (tn << 2) + ((rot(tn) + 3) & 3);
                }
                int tp = hTwin[hp];
                tw[c3] = tp < 0 ? -1 : (tp << 2) + (rot(tp) & 3);
            }
        }
    }

    /** The child half-edge along half-edge x that touches x's edge at the given end (0 = v0). */
    private int childPiece(int x, int end) {
        int atOrigin = fwd(x) ? 0 : 1; // the end x starts from
        if (end == atOrigin) return 4 * x + (rot(x) & 3);
        int xn = next(x);
        return 4 * xn + ((rot(xn) + 3) & 3);
    }

    private void refineNonManifold(Level c) {
        int faceEdges = nH;
        int nme = nmEdge.length;
        c.nmEdge = new int[2 * nme];
        c.nmEdgeStart = new int[2 * nme + 1];
        c.nmEdgeHalf = new int[2 * nmEdgeHalf.length];
        for (int i = 0, k = 0; i < nme; i++) {
            int e = nmEdge[i];
            for (int end = 0; end < 2; end++) {
                int ci = 2 * i + end;
                c.nmEdge[ci] = faceEdges + 2 * e + end;
                for (int j = nmEdgeStart[i]; j < nmEdgeStart[i + 1]; j++) c.nmEdgeHalf[k++] = childPiece(nmEdgeHalf[j], end);
                c.nmEdgeStart[ci + 1] = k;
            }
        }
        // Non-manifold vertices: children of such vertices, then the points of such edges.
        int nmv = nmVert.length;
        int entries = nmVertHalf.length;
        for (int i = 0; i < nme; i++) entries += 2 + (nmEdgeStart[i + 1] - nmEdgeStart[i]);
        c.nmVert = new int[nmv + nme];
        c.nmVertStart = new int[nmv + nme + 1];
        c.nmVertHalf = new int[entries];
        c.nmVertOther = new int[entries];
        c.nmVertEnd = new int[entries];
        int k = 0;
        for (int i = 0; i < nmv; i++) {
            int v = nmVert[i];
            c.nmVert[i] = v;
            for (int j = nmVertStart[i]; j < nmVertStart[i + 1]; j++) {
                int e = nmVertEnd[j] >> 1, end = nmVertEnd[j] & 1;
                int ce = faceEdges + 2 * e + end;
                c.nmVertHalf[k] = childPiece(nmVertHalf[j], end);
                c.nmVertOther[k] = nV + nF + e;
                c.nmVertEnd[k] = ce << 1 | 1;
                k++;
            }
            c.nmVertStart[i + 1] = k;
        }
        for (int i = 0; i < nme; i++) {
            int e = nmEdge[i];
            int ev = nV + nF + e;
            c.nmVert[nmv + i] = ev;
            int h0 = nmEdgeHalf[nmEdgeStart[i]];
            int v0 = edgeV0(h0), v1 = edgeV1(h0);
            // Far: [edge child, face edge of face 0, other edge child, face edges of the rest],
            // the first edge child being the one towards v1 if face 0 runs v0 to v1.
            int first = (v0 != v1 && fwd(h0)) ? 1 : 0;
            int[] order = {first, -1, 1 - first};
            for (int slot = 0; slot < 3; slot++) {
                if (order[slot] >= 0) {
                    int end = order[slot];
                    c.nmVertHalf[k] = childPiece(h0, end);
                    c.nmVertOther[k] = end == 0 ? v0 : v1;
                    c.nmVertEnd[k] = (faceEdges + 2 * e + end) << 1;
                } else {
                    addFaceEdgeEntry(c, k, h0);
                }
                k++;
            }
            for (int j = nmEdgeStart[i] + 1; j < nmEdgeStart[i + 1]; j++) {
                addFaceEdgeEntry(c, k, nmEdgeHalf[j]);
                k++;
            }
            c.nmVertStart[nmv + i + 1] = k;
        }
    }

    /** Far's vertex-face order for the child's non-manifold vertices (as corner half-edges). */
    private void refineNonManifoldFaces(Level c) {
        int nmv = nmVert.length, nme = nmEdge.length;
        c.nmFaceStart = new int[nmv + nme + 1];
        int total = nmFaceHalf.length;
        for (int i = 0; i < nme; i++) total += 2 * (nmEdgeStart[i + 1] - nmEdgeStart[i]);
        c.nmFaceHalf = new int[total];
        int k = 0;
        for (int i = 0; i < nmv; i++) {
            for (int j = nmFaceStart[i]; j < nmFaceStart[i + 1]; j++) {
                int h = nmFaceHalf[j];
                c.nmFaceHalf[k++] = 4 * h + (rot(h) & 3);
            }
            c.nmFaceStart[i + 1] = k;
        }
        for (int i = 0; i < nme; i++) {
            for (int j = nmEdgeStart[i]; j < nmEdgeStart[i + 1]; j++) {
                int x = nmEdgeHalf[j], xn = next(x);
                c.nmFaceHalf[k++] = 4 * xn + ((rot(xn) + 3) & 3);
                c.nmFaceHalf[k++] = 4 * x + ((rot(x) + 1) & 3);
            }
            c.nmFaceStart[nmv + i + 1] = k;
        }
    }

    /** The child edge from the point of h's edge to the point of h's face, as a vertex entry. */
    private void addFaceEdgeEntry(Level c, int k, int h) {
        c.nmVertHalf[k] = 4 * h + ((rot(h) + 1) & 3);
        c.nmVertOther[k] = nV + face(h);
        c.nmVertEnd[k] = h << 1 | 1;
    }

    private void refineSharpness(Level c, boolean chaikin) {
        int faceEdges = nH;
        if (eSharp != null) {
            float[] cs = new float[c.nE];
            boolean any = false;
            float[] buf = chaikin ? new float[maxValence() + 2] : null;
            int[] ringBuf = chaikin ? new int[buf.length] : null;
            for (int h = 0; h < nH; h++) {
                if ((hEdge[h] & E_PRIMARY) == 0 || hTwin[h] < 0) continue; // implicit-infinite edges stay so
                int e = hEdge[h] >>> 2;
                float s = eSharp[e];
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
                        int v = end == 0 ? edgeV0(h) : edgeV1(h);
                        int n = incidentSharpness(v, buf, ringBuf);
                        childS = Crease.chaikin(s, n, buf, 0);
                    }
                    cs[faceEdges + 2 * e + end] = childS;
                    any |= childS != 0f;
                }
            }
            c.eSharp = any ? cs : null;
        }
        if (vSharp != null) {
            float[] cv = new float[c.nV];
            boolean any = false;
            for (int v = 0; v < nV; v++) {
                cv[v] = Crease.decrement(vSharp[v]);
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
    int incidentSharpness(int v, float[] buf, int[] ringBuf) {
        int i = nmVertIndex(v);
        if (i >= 0) {
            int n = 0;
            for (int k = nmVertStart[i]; k < nmVertStart[i + 1]; k++) buf[n++] = edgeSharpness(nmVertHalf[k]);
            return n;
        }
        int n = ring(v, ringBuf);
        int edges = hTwin[vOut[v]] < 0 ? n + 1 : n;
        for (int j = 0; j < edges; j++) buf[j] = edgeSharpness(ringBuf[j]);
        return edges;
    }

    /** Far's propagation of vertex tags to the child, then its reclassification of semi-sharp ones. */
    private void refineTags(Level c) {
        if (vTag == null) return;
        byte[] ct = new byte[c.nV];
        System.arraycopy(vTag, 0, ct, 0, nV);
        int faceEdges = nH;
        int eBase = nV + nF;
        boolean[] nmE = new boolean[nE];
        for (int e : nmEdge) nmE[e] = true;
        for (int h = 0; h < nH; h++) {
            if ((hEdge[h] & E_PRIMARY) == 0) continue;
            int e = hEdge[h] >>> 2;
            float s = edgeSharpness(h);
            int t = Crease.isSharp(s) ? Crease.RULE_CREASE : Crease.RULE_SMOOTH;
            if (nmE[e]) t |= T_NONMANIFOLD;
            else if (hTwin[h] < 0) t |= T_BOUNDARY;
            if (Crease.isSemiSharp(s)) t |= T_SEMI_EDGES;
            ct[eBase + e] = (byte) t;
        }
        c.vTag = ct;
        // Semi-sharp edge points: the rule follows how many of the two child edges stay sharp.
        for (int h = 0; h < nH; h++) {
            if ((hEdge[h] & E_PRIMARY) == 0) continue;
            int e = hEdge[h] >>> 2;
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
        int[] ringBuf = new int[maxValence() + 2];
        for (int v = 0; v < nV; v++) {
            int pt = vTag[v];
            int t = ct[v];
            float cs = c.vertexSharpness(v);
            if ((t & T_SEMI_SHARP) != 0 && !Crease.isSharp(cs)) t &= ~T_SEMI_SHARP;
            if ((pt & (T_SEMI_SHARP | T_SEMI_EDGES)) != 0) {
                boolean decayed = (pt & T_SEMI_SHARP) != 0 && (t & T_SEMI_SHARP) == 0;
                if ((pt & T_SEMI_EDGES) != 0 || decayed) {
                    int inf = 0, semi = 0;
                    int i = nmVertIndex(v);
                    if (i >= 0) {
                        for (int k = nmVertStart[i]; k < nmVertStart[i + 1]; k++) {
                            float s = childEdgeSharpness(c, nmVertHalf[k], nmVertEnd[k]);
                            if (Crease.isInfinite(s)) inf++;
                            else if (Crease.isSharp(s)) semi++;
                        }
                    } else {
                        int n = ring(v, ringBuf);
                        int edges = hTwin[vOut[v]] < 0 ? n + 1 : n;
                        for (int j = 0; j < edges; j++) {
                            int x = ringBuf[j];
                            int end = j < n ? (fwd(x) ? 0 : 1) : (fwd(x) ? 1 : 0);
                            float s = childEdgeSharpness(c, x, (hEdge[x] >>> 2) << 1 | end);
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
    float childEdgeSharpness(Level c, int x, int edgeEnd) {
        if (hTwin[x] < 0) return Crease.INFINITE;
        return c.eSharp == null ? 0f : c.eSharp[nH + edgeEnd];
    }
}
