package lt.spindulys.subdiv;

import static lt.spindulys.subdiv.Level.E_FWD;
import static lt.spindulys.subdiv.Level.E_PRIMARY;

/**
 * The uniform split of a triangle {@link Level} into four triangles per face (Loop's topology,
 * OpenSubdiv's Vtr::TriRefinement), the counterpart of {@link Refinement}'s quad split. The
 * child's numbering follows Far's, so refined vertices get Far's indices:
 * <ul>
 * <li>vertices: the children of the parent's vertices (same indices), then one point per parent
 *     edge (no face points);</li>
 * <li>faces: four per parent triangle (v0, v1, v2) with edge points e0 (of v0-v1), e1, e2, in
 *     Far's order {@code (v0,e0,e2)}, {@code (e0,v1,e1)}, {@code (e2,e1,v2)} and the middle
 *     {@code (e1,e2,e0)}: child face 4f+j, its half-edges 12f+3j .. 12f+3j+2;</li>
 * <li>edges: as in the quad split, those inside parent faces first (numbered like the parent's
 *     half-edges: the one of corner k runs from e_k to e_{k-1}), then two per parent edge
 *     (2e + end, running from the edge point to the edge's end vertex).</li>
 * </ul>
 * Sharpness and vertex tags then pass to the child through {@link SharpnessRefinement}, the
 * same code as for the quad split; vertex data is refined separately ({@link PrimvarRefiner}).
 */
final class TriangleSplit {
    private TriangleSplit() {}

    /** First half-edge of child j of face f. */
    private static int child(int f, int j) { return 12 * f + 3 * j; }

    /** The child half-edge of parent half-edge h (corner k of face f) that starts at h's origin. */
    static int originPiece(int h) {
        int f = h / 3, k = h - 3 * f;
        return 12 * f + 4 * k;
    }

    /** The child half-edge of parent half-edge h that ends at h's destination. */
    static int destPiece(int h) {
        int f = h / 3, k = h - 3 * f;
        return 12 * f + 3 * (k == 2 ? 0 : k + 1) + k;
    }

    /**
     * Far's split of p (all triangles) into the child level: topology, then sharpness and tags.
     *
     * @param sharpSource see {@link Refinement#refine}
     */
    static Level refine(Level p, boolean chaikin, Level sharpSource) {
        int cV = p.nV + p.nE, cF = 4 * p.nF, cE = p.nH + 2 * p.nE, cH = 4 * p.nH;
        if (cH < 0 || (long) cE * 4 > Integer.MAX_VALUE) throw new IllegalStateException("refined mesh too large for int indices");
        p.edgeCodes();
        int[] o = new int[cH], tw = new int[cH], ed = new int[cH];
        corners(p, o);
        int[] twin = p.hTwin;
        for (int f = 0; f < p.nF; f++) {
            int c = 12 * f;
            // The middle triangle's three edges, inside the parent face.
            tw[c + 1] = c + 10;
            tw[c + 10] = c + 1;
            tw[c + 5] = c + 11;
            tw[c + 11] = c + 5;
            tw[c + 6] = c + 9;
            tw[c + 9] = c + 6;
            for (int k = 0; k < 3; k++) {
                int h = 3 * f + k, t = twin[h];
                int op = originPiece(h), dp = destPiece(h);
                if (t < 0) {
                    tw[op] = -1;
                    tw[dp] = -1;
                } else {
                    tw[op] = destPiece(t);
                    tw[dp] = originPiece(t);
                }
            }
        }
        childEdgeCodes(p.hEdge, p.nF, ed);
        int[] out = new int[cV];
        for (int v = 0; v < p.nV; v++) {
            int h = p.vOut[v];
            out[v] = h < 0 ? -1 : originPiece(h);
        }
        // An edge point's faces start in the child of its edge's first face that holds the
        // parent edge's second half (Far's "leading" child face).
        for (int h = 0; h < p.nH; h++) {
            if ((p.hEdge[h] & E_PRIMARY) != 0) out[p.nV + (p.hEdge[h] >>> 2)] = destPiece(h);
        }
        Level c = new Level(p.depth + 1, cV, cF, cE, faceStarts(cF), null, o, tw, ed, out);
        c.triangleSplit = true;
        copyHoles(p, c);
        refineNonManifold(p, c);
        SharpnessRefinement.refine(p, c, chaikin, sharpSource);
        return c;
    }

    /** The child of p with its faces and edges only (see {@link Refinement#refineCornersAndEdges}). */
    static Level refineCornersAndEdges(Level p) {
        int cV = p.nV + p.nE, cF = 4 * p.nF, cE = p.nH + 2 * p.nE, cH = 4 * p.nH;
        if (cH < 0 || (long) cE * 4 > Integer.MAX_VALUE) throw new IllegalStateException("refined mesh too large for int indices");
        p.edgeCodes();
        int[] o = new int[cH], ed = new int[cH];
        corners(p, o);
        childEdgeCodes(p.hEdge, p.nF, ed);
        Level c = new Level(p.depth + 1, cV, cF, cE, faceStarts(cF), null, o, null, ed, null);
        c.triangleSplit = true;
        copyHoles(p, c);
        return c;
    }

    private static int[] faceStarts(int nF) {
        int[] fs = new int[nF + 1];
        for (int f = 0; f <= nF; f++) fs[f] = 3 * f;
        return fs;
    }

    private static void corners(Level p, int[] o) {
        int[] orig = p.hOrig, code = p.hEdge;
        int vEdge = p.nV;
        for (int f = 0; f < p.nF; f++) {
            int s = 3 * f, c = 12 * f;
            int v0 = orig[s], v1 = orig[s + 1], v2 = orig[s + 2];
            int e0 = vEdge + (code[s] >>> 2), e1 = vEdge + (code[s + 1] >>> 2), e2 = vEdge + (code[s + 2] >>> 2);
            o[c] = v0;
            o[c + 1] = e0;
            o[c + 2] = e2;
            o[c + 3] = e0;
            o[c + 4] = v1;
            o[c + 5] = e1;
            o[c + 6] = e2;
            o[c + 7] = e1;
            o[c + 8] = v2;
            o[c + 9] = e1;
            o[c + 10] = e2;
            o[c + 11] = e0;
        }
    }

    private static void copyHoles(Level p, Level c) {
        if (p.hole != null) {
            boolean[] ch = new boolean[c.nF];
            for (int f = 0; f < p.nF; f++) {
                boolean b = p.hole[f];
                ch[4 * f] = ch[4 * f + 1] = ch[4 * f + 2] = ch[4 * f + 3] = b;
            }
            c.hole = ch;
        }
    }

    /**
     * The edge codes of the child of a triangle level with the given codes (see {@link Level}):
     * the pieces of a parent edge keep its primary flag and run towards the parent's vertices
     * (so only the piece leaving the edge point runs forward); an inner edge's primary half-edge
     * is in the corner child, its other half in the middle triangle.
     */
    static void childEdgeCodes(int[] code, int nF, int[] ed) {
        int faceEdges = code.length;
        for (int f = 0; f < nF; f++) {
            int s = 3 * f;
            for (int k = 0; k < 3; k++) {
                int h = s + k, ch = code[h];
                int base = (faceEdges + 2 * (ch >>> 2)) << 2;
                int prim = ch & E_PRIMARY;
                ed[originPiece(h)] = base + ((~ch & 1) << 2) | prim;
                ed[destPiece(h)] = base + ((ch & 1) << 2) | prim | E_FWD;
            }
            int c = 12 * f;
            ed[c + 1] = s << 2 | E_PRIMARY | E_FWD;
            ed[c + 10] = s << 2;
            ed[c + 5] = (s + 1) << 2 | E_PRIMARY | E_FWD;
            ed[c + 11] = (s + 1) << 2;
            ed[c + 6] = (s + 2) << 2 | E_PRIMARY | E_FWD;
            ed[c + 9] = (s + 2) << 2;
        }
    }

    /** The child piece of parent half-edge x that touches x's edge at the given end (0 = v0). */
    private static int childPiece(Level p, int x, int end) {
        int atOrigin = p.fwd(x) ? 0 : 1;
        return end == atOrigin ? originPiece(x) : destPiece(x);
    }

    /** Far's non-manifold side tables of the child (see {@link Level}), from TriRefinement's orders. */
    private static void refineNonManifold(Level p, Level c) {
        int faceEdges = p.nH, vEdge = p.nV;
        int nme = p.nmEdge.length;
        Refinement.childNonManifoldEdges(p, c, TriangleSplit::childPiece);
        int nmv = p.nmVert.length;
        int entries = p.nmVertHalf.length, faces = p.nmFaceHalf.length;
        for (int i = 0; i < nme; i++) {
            int n = p.nmEdgeStart[i + 1] - p.nmEdgeStart[i];
            entries += 2 + 2 * n;
            faces += 3 * n;
        }
        c.nmVert = new int[nmv + nme];
        c.nmVertStart = new int[nmv + nme + 1];
        c.nmVertHalf = new int[entries];
        c.nmVertOther = new int[entries];
        c.nmVertEnd = new int[entries];
        c.nmFaceStart = new int[nmv + nme + 1];
        c.nmFaceHalf = new int[faces];
        int k = 0, q = 0;
        // Children of non-manifold vertices: the child edges of their edges, their faces' corner children.
        for (int i = 0; i < nmv; i++) {
            c.nmVert[i] = p.nmVert[i];
            for (int j = p.nmVertStart[i]; j < p.nmVertStart[i + 1]; j++, k++) {
                int e = p.nmVertEnd[j] >> 1, end = p.nmVertEnd[j] & 1;
                c.nmVertHalf[k] = childPiece(p, p.nmVertHalf[j], end);
                c.nmVertOther[k] = vEdge + e;
                c.nmVertEnd[k] = (faceEdges + 2 * e + end) << 1 | 1;
            }
            c.nmVertStart[i + 1] = k;
            for (int j = p.nmFaceStart[i]; j < p.nmFaceStart[i + 1]; j++) c.nmFaceHalf[q++] = originPiece(p.nmFaceHalf[j]);
            c.nmFaceStart[i + 1] = q;
        }
        // Points of non-manifold edges. Far's edge order: one child of the parent edge (the one
        // towards the end face 0 runs to), the two inner edges of face 0, the other child, then
        // the two inner edges of every further face; faces: leading, middle, trailing child of
        // each parent face in the edge's face order.
        for (int i = 0; i < nme; i++) {
            int e = p.nmEdge[i];
            c.nmVert[nmv + i] = vEdge + e;
            int h0 = p.nmEdgeHalf[p.nmEdgeStart[i]];
            int v0 = p.edgeV0(h0), v1 = p.edgeV1(h0);
            int first = p.fwd(h0) ? 1 : 0;
            for (int j = p.nmEdgeStart[i]; j < p.nmEdgeStart[i + 1]; j++) {
                int x = p.nmEdgeHalf[j];
                if (j == p.nmEdgeStart[i]) k = edgeChildEntry(p, c, k, h0, first, first == 0 ? v0 : v1);
                int f = x / 3, kk = x - 3 * f, kn = kk == 2 ? 0 : kk + 1, kp = kk == 0 ? 2 : kk - 1;
                // Inner edge of corner kn (from e_{k+1} into this point), then of corner k (out of it).
                int xn = 3 * f + kn, xp = 3 * f + kp;
                c.nmVertHalf[k] = child(f, kn) + (kn == 2 ? 0 : kn + 1);
                c.nmVertOther[k] = vEdge + p.edge(xn);
                c.nmVertEnd[k] = xn << 1 | 1;
                k++;
                c.nmVertHalf[k] = child(f, kk) + kn;
                c.nmVertOther[k] = vEdge + p.edge(xp);
                c.nmVertEnd[k] = x << 1;
                k++;
                if (j == p.nmEdgeStart[i]) k = edgeChildEntry(p, c, k, h0, 1 - first, first == 0 ? v1 : v0);
                c.nmFaceHalf[q++] = child(f, kn) + kk;
                c.nmFaceHalf[q++] = child(f, 3) + (kk == 0 ? 2 : kk - 1);
                c.nmFaceHalf[q++] = child(f, kk) + kn;
            }
            c.nmVertStart[nmv + i + 1] = k;
            c.nmFaceStart[nmv + i + 1] = q;
        }
    }

    /** The entry of the child edge (edge point to the parent edge's end {@code end}) at the edge point. */
    private static int edgeChildEntry(Level p, Level c, int k, int h0, int end, int endVertex) {
        int e = p.edge(h0);
        c.nmVertHalf[k] = childPiece(p, h0, end);
        c.nmVertOther[k] = endVertex;
        c.nmVertEnd[k] = (p.nH + 2 * e + end) << 1;
        return k + 1;
    }
}
