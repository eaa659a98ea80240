package lt.spindulys.subdiv;

import static lt.spindulys.subdiv.Level.E_FWD;
import static lt.spindulys.subdiv.Level.E_PRIMARY;

/**
 * The uniform split of one {@link Level} into the next: quads from any face (Catmull-Clark and
 * bilinear), or, for a level marked {@link Level#triangleSplit}, triangles from triangles through
 * {@link TriangleSplit} (Loop). OpenSubdiv's Vtr::Refinement, without its parent-to-child maps: the child's numbering follows from the
 * parent's, see {@link Level}). Builds the child's topology straight from the parent's half-edges,
 * with no searching, then hands over to {@link SharpnessRefinement} for the child's sharpness and
 * tags. Vertex data is refined separately, by {@link PrimvarRefiner}.
 */
final class Refinement {
    private Refinement() {}

    /**
     * Far's uniform split of p (quads, or triangles for a triangle-split level): the child topology, built straight from p's
     * half-edges (no searching), followed by the sharpness decay and the child vertex tags.
     * Child vertices: those of the vertices (same index), then one per face, then one per edge.
     *
     * @param sharpSource if not null, the child's edge sharpness is taken from this level (the
     *                    geometry's child, for a face-varying value mesh with the same half-edges)
     */
    static Level refine(Level p, boolean chaikin, Level sharpSource) {
        if (p.triangleSplit) return TriangleSplit.refine(p, chaikin, sharpSource);
        int cV = p.nV + p.nF + p.nE, cF = p.nH, cE = p.nH + 2 * p.nE, cH = 4 * p.nH;
        if (cH < 0 || (long) cE * 4 > Integer.MAX_VALUE) throw new IllegalStateException("refined mesh too large for int indices");
        p.edgeCodes();
        int[] o = new int[cH], tw = new int[cH], ed = new int[cH];
        if (p.faceStart == null) refineQuads(p, o, tw);
        else refineGeneral(p, o, tw);
        childEdgeCodes(p.hEdge, p.faceStart, p.nF, ed);
        int[] out = new int[cV];
        for (int v = 0; v < p.nV; v++) {
            int h = p.vOut[v];
            out[v] = h < 0 ? -1 : 4 * h + (rot(p, h) & 3);
        }
        for (int f = 0; f < p.nF; f++) {
            out[p.nV + f] = 4 * p.firstHalf(f) + 2;
        }
        int eBase = p.nV + p.nF;
        for (int h = 0; h < p.nH; h++) {
            if ((p.hEdge[h] & E_PRIMARY) != 0) {
                int x = p.next(h);
                out[eBase + (p.hEdge[h] >>> 2)] = 4 * x + ((rot(p, x) + 3) & 3);
            }
        }
        Level c = new Level(p.depth + 1, cV, cF, cE, null, null, o, tw, ed, out);
        copyHoles(p, c);
        refineNonManifold(p, c);
        refineNonManifoldFaces(p, c);
        SharpnessRefinement.refine(p, c, chaikin, sharpSource);
        return c;
    }

    /**
     * The child of p with its faces and edges only, without twins, vertex rings, sharpness or
     * tags: all that bilinear interpolation (linear face-varying data) needs, at under half the
     * cost.
     */
    static Level refineCornersAndEdges(Level p) {
        if (p.triangleSplit) return TriangleSplit.refineCornersAndEdges(p);
        int cV = p.nV + p.nF + p.nE, cF = p.nH, cE = p.nH + 2 * p.nE, cH = 4 * p.nH;
        if (cH < 0 || (long) cE * 4 > Integer.MAX_VALUE) throw new IllegalStateException("refined mesh too large for int indices");
        p.edgeCodes();
        int[] o = new int[cH], ed = new int[cH];
        int vFace = p.nV, vEdge = p.nV + p.nF;
        for (int f = 0; f < p.nF; f++) {
            int s = p.firstHalf(f), n = p.faceSize(f);
            for (int k = 0; k < n; k++) {
                int h = s + k, hp = k > 0 ? h - 1 : s + n - 1, r = n == 4 ? k : 0, base = h << 2;
                o[base + (r & 3)] = p.hOrig[h];
                o[base + ((r + 1) & 3)] = vEdge + (p.hEdge[h] >>> 2);
                o[base + ((r + 2) & 3)] = vFace + f;
                o[base + ((r + 3) & 3)] = vEdge + (p.hEdge[hp] >>> 2);
            }
        }
        childEdgeCodes(p.hEdge, p.faceStart, p.nF, ed);
        Level c = new Level(p.depth + 1, cV, cF, cE, null, null, o, null, ed, null);
        copyHoles(p, c);
        return c;
    }

    private static void copyHoles(Level p, Level c) {
        if (p.hole != null) {
            boolean[] ch = new boolean[c.nF];
            for (int h = 0; h < p.nH; h++) ch[h] = p.hole[p.face(h)];
            c.hole = ch;
        }
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
    static int rot(Level p, int h) {
        if (p.faceStart == null) return h & 3;
        int f = p.face(h);
        return p.faceStart[f + 1] - p.faceStart[f] == 4 ? h - p.faceStart[f] : 0;
    }

    private static void refineQuads(Level p, int[] o, int[] tw) {
        final int[] orig = p.hOrig, twin = p.hTwin, code = p.hEdge;
        final int vFace = p.nV, vEdge = p.nV + p.nF, faceEdges = p.nH;
        for (int f = 0, h0 = 0; f < p.nF; f++, h0 += 4) {
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

    private static void refineGeneral(Level p, int[] o, int[] tw) {
        final int vFace = p.nV, vEdge = p.nV + p.nF, faceEdges = p.nH;
        for (int f = 0; f < p.nF; f++) {
            int s = p.faceStart[f], n = p.faceStart[f + 1] - s;
            boolean quad = n == 4;
            for (int k = 0; k < n; k++) {
                int h = s + k;
                int hn = k + 1 < n ? h + 1 : s, hp = k > 0 ? h - 1 : s + n - 1;
                int r = quad ? k : 0;
                int base = h << 2;
                int c0 = base + (r & 3), c1 = base + ((r + 1) & 3), c2 = base + ((r + 2) & 3), c3 = base + ((r + 3) & 3);
                int ch = p.hEdge[h], cp = p.hEdge[hp];
                o[c0] = p.hOrig[h];
                o[c1] = vEdge + (ch >>> 2);
                o[c2] = vFace + f;
                o[c3] = vEdge + (cp >>> 2);
                tw[c1] = (hn << 2) + ((rot(p, hn) + 2) & 3);
                tw[c2] = (hp << 2) + ((rot(p, hp) + 1) & 3);
                int t = p.hTwin[h];
                if (t < 0) {
                    tw[c0] = -1;
                } else {
                    int tn = p.next(t);
                    tw[c0] = (tn << 2) + ((rot(p, tn) + 3) & 3);
                }
                int tp = p.hTwin[hp];
                tw[c3] = tp < 0 ? -1 : (tp << 2) + (rot(p, tp) & 3);
            }
        }
    }

    /** The child half-edge along half-edge x that touches x's edge at the given end (0 = v0). */
    private static int childPiece(Level p, int x, int end) {
        int atOrigin = p.fwd(x) ? 0 : 1; // the end x starts from
        if (end == atOrigin) return 4 * x + (rot(p, x) & 3);
        int xn = p.next(x);
        return 4 * xn + ((rot(p, xn) + 3) & 3);
    }

    /** The child half-edge along parent half-edge x that touches x's edge at the given end (0 = v0), in one split. */
    interface ChildPiece {
        int of(Level p, int x, int end);
    }

    /**
     * The child's non-manifold edges, the same for both splits: each non-manifold parent edge
     * gives two (2e + end, numbered as in {@link Level}), each with the pieces of the parent's
     * half-edges at that end, in the parent's edge-face order.
     */
    static void childNonManifoldEdges(Level p, Level c, ChildPiece piece) {
        int faceEdges = p.nH;
        int nme = p.nmEdge.length;
        c.nmEdge = new int[2 * nme];
        c.nmEdgeStart = new int[2 * nme + 1];
        c.nmEdgeHalf = new int[2 * p.nmEdgeHalf.length];
        for (int i = 0, k = 0; i < nme; i++) {
            int e = p.nmEdge[i];
            for (int end = 0; end < 2; end++) {
                int ci = 2 * i + end;
                c.nmEdge[ci] = faceEdges + 2 * e + end;
                for (int j = p.nmEdgeStart[i]; j < p.nmEdgeStart[i + 1]; j++) c.nmEdgeHalf[k++] = piece.of(p, p.nmEdgeHalf[j], end);
                c.nmEdgeStart[ci + 1] = k;
            }
        }
    }

    private static void refineNonManifold(Level p, Level c) {
        int faceEdges = p.nH;
        int nme = p.nmEdge.length;
        childNonManifoldEdges(p, c, Refinement::childPiece);
        // Non-manifold vertices: children of such vertices, then the points of such edges.
        int nmv = p.nmVert.length;
        int entries = p.nmVertHalf.length;
        for (int i = 0; i < nme; i++) entries += 2 + (p.nmEdgeStart[i + 1] - p.nmEdgeStart[i]);
        c.nmVert = new int[nmv + nme];
        c.nmVertStart = new int[nmv + nme + 1];
        c.nmVertHalf = new int[entries];
        c.nmVertOther = new int[entries];
        c.nmVertEnd = new int[entries];
        int k = 0;
        for (int i = 0; i < nmv; i++) {
            int v = p.nmVert[i];
            c.nmVert[i] = v;
            for (int j = p.nmVertStart[i]; j < p.nmVertStart[i + 1]; j++) {
                int e = p.nmVertEnd[j] >> 1, end = p.nmVertEnd[j] & 1;
                int ce = faceEdges + 2 * e + end;
                c.nmVertHalf[k] = childPiece(p, p.nmVertHalf[j], end);
                c.nmVertOther[k] = p.nV + p.nF + e;
                c.nmVertEnd[k] = ce << 1 | 1;
                k++;
            }
            c.nmVertStart[i + 1] = k;
        }
        for (int i = 0; i < nme; i++) {
            int e = p.nmEdge[i];
            int ev = p.nV + p.nF + e;
            c.nmVert[nmv + i] = ev;
            int h0 = p.nmEdgeHalf[p.nmEdgeStart[i]];
            int v0 = p.edgeV0(h0), v1 = p.edgeV1(h0);
            // Far: [edge child, face edge of face 0, other edge child, face edges of the rest],
            // the first edge child being the one towards v1 if face 0 runs v0 to v1.
            int first = (v0 != v1 && p.fwd(h0)) ? 1 : 0;
            int[] order = {first, -1, 1 - first};
            for (int slot = 0; slot < 3; slot++) {
                if (order[slot] >= 0) {
                    int end = order[slot];
                    c.nmVertHalf[k] = childPiece(p, h0, end);
                    c.nmVertOther[k] = end == 0 ? v0 : v1;
                    c.nmVertEnd[k] = (faceEdges + 2 * e + end) << 1;
                } else {
                    addFaceEdgeEntry(p, c, k, h0);
                }
                k++;
            }
            for (int j = p.nmEdgeStart[i] + 1; j < p.nmEdgeStart[i + 1]; j++) {
                addFaceEdgeEntry(p, c, k, p.nmEdgeHalf[j]);
                k++;
            }
            c.nmVertStart[nmv + i + 1] = k;
        }
    }

    /** Far's vertex-face order for the child's non-manifold vertices (as corner half-edges). */
    private static void refineNonManifoldFaces(Level p, Level c) {
        int nmv = p.nmVert.length, nme = p.nmEdge.length;
        c.nmFaceStart = new int[nmv + nme + 1];
        int total = p.nmFaceHalf.length;
        for (int i = 0; i < nme; i++) total += 2 * (p.nmEdgeStart[i + 1] - p.nmEdgeStart[i]);
        c.nmFaceHalf = new int[total];
        int k = 0;
        for (int i = 0; i < nmv; i++) {
            for (int j = p.nmFaceStart[i]; j < p.nmFaceStart[i + 1]; j++) {
                int h = p.nmFaceHalf[j];
                c.nmFaceHalf[k++] = 4 * h + (rot(p, h) & 3);
            }
            c.nmFaceStart[i + 1] = k;
        }
        for (int i = 0; i < nme; i++) {
            for (int j = p.nmEdgeStart[i]; j < p.nmEdgeStart[i + 1]; j++) {
                int x = p.nmEdgeHalf[j], xn = p.next(x);
                c.nmFaceHalf[k++] = 4 * xn + ((rot(p, xn) + 3) & 3);
                c.nmFaceHalf[k++] = 4 * x + ((rot(p, x) + 1) & 3);
            }
            c.nmFaceStart[nmv + i + 1] = k;
        }
    }

    /** The child edge from the point of h's edge to the point of h's face, as a vertex entry. */
    private static void addFaceEdgeEntry(Level p, Level c, int k, int h) {
        c.nmVertHalf[k] = 4 * h + ((rot(p, h) + 1) & 3);
        c.nmVertOther[k] = p.nV + p.face(h);
        c.nmVertEnd[k] = h << 1 | 1;
    }
}
