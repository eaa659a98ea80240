package lt.spindulys.subdiv;

import static lt.spindulys.subdiv.Level.E_FWD;
import static lt.spindulys.subdiv.Level.E_PRIMARY;
import static lt.spindulys.subdiv.Level.T_BOUNDARY;
import static lt.spindulys.subdiv.Level.T_INF_SHARP;
import static lt.spindulys.subdiv.Level.T_NONMANIFOLD;
import static lt.spindulys.subdiv.Level.T_SEMI_EDGES;
import static lt.spindulys.subdiv.Level.T_SEMI_SHARP;

import java.util.Arrays;

/**
 * Makes level 0 of a {@link Level} from polygons, as Far's {@code TopologyRefinerFactory} does:
 * first the topology ({@code completeTopologyFromFaceVertices}: Far's edge numbering, twins, vertex
 * fans and the non-manifold side tables), then, once the caller has looked up its crease edges
 * with {@link #findEdge}, the tags ({@code prepareComponentTagsAndSharpness}). The edge table
 * that both steps need is Far's construction state, not part of a level, so it lives here and is
 * released by {@link #tag}. One builder makes one level: call {@link #tag} once, last.
 */
final class BaseLevelBuilder {
    /** The level being built: topology complete, tags and sharpness set by {@link #tag}. */
    final Level level;
    // Construction state, released by tag(): the caller may go on to build more (a UV value mesh).
    private EdgeTable edges;
    /** Corners per vertex (the faces at it, a face that repeats the vertex counted again). */
    private int[] vertexFaces;
    private boolean[] nonManifold;

    /**
     * Builds the topology of polygons the way Far's {@code completeTopologyFromFaceVertices}
     * does: edges numbered in order of first appearance; an edge used by more than two faces,
     * twice by one face, by two faces in the same direction, or joining a vertex to itself is
     * non-manifold (and its end vertices too), as is any vertex whose faces do not form a single
     * fan (unused vertices included).
     *
     * @param general keep per-face starts even when every face is a quad (a patch's one-ring cut
     *                from a mesh with other polygons: level 0 is then stored, and its values are
     *                computed, as the whole mesh's are)
     */
    BaseLevelBuilder(int nV, int[] faceSizes, int[] faceVerts, boolean general) {
        int nF = faceSizes.length;
        boolean quads = !general;
        for (int s : faceSizes) quads &= s == 4;
        int[] faceStart = null, hFace = null;
        int nH = faceVerts.length;
        if (!quads) {
            faceStart = new int[nF + 1];
            hFace = new int[nH];
            for (int f = 0; f < nF; f++) {
                faceStart[f + 1] = faceStart[f] + faceSizes[f];
                Arrays.fill(hFace, faceStart[f], faceStart[f + 1], f);
            }
        }
        int[] hOrig = faceVerts.clone();
        EdgeTable b = new EdgeTable(nV, nH);
        int[] hEdgeId = new int[nH];
        for (int f = 0, h = 0; f < nF; f++) {
            int s = h, n = faceSizes[f];
            for (int k = 0; k < n; k++, h++) {
                int v0 = hOrig[h], v1 = hOrig[k + 1 < n ? h + 1 : s];
                hEdgeId[h] = b.addHalf(h, f, v0, v1);
            }
        }
        int nE = b.nE;
        // Twins: only a manifold edge with exactly two opposite half-edges.
        int[] hTwin = new int[nH];
        Arrays.fill(hTwin, -1);
        for (int e = 0; e < nE; e++) {
            if (!b.eNm[e] && b.eSecond[e] >= 0) {
                hTwin[b.ePrimary[e]] = b.eSecond[e];
                hTwin[b.eSecond[e]] = b.ePrimary[e];
            }
        }
        int[] hEdge = new int[nH];
        for (int h = 0; h < nH; h++) {
            int e = hEdgeId[h];
            hEdge[h] = e << 2 | (b.ePrimary[e] == h ? E_PRIMARY : 0) | (hOrig[h] == b.eV0[e] ? E_FWD : 0);
        }
        int[] vOut = new int[nV];
        Arrays.fill(vOut, -1);
        Level lv = new Level(0, nV, nF, nE, faceStart, hFace, hOrig, hTwin, hEdge, vOut);

        // Corner counts and first corners; non-manifold edges mark their vertices.
        int[] fCount = new int[nV];
        for (int h = nH - 1; h >= 0; h--) {
            fCount[hOrig[h]]++;
            vOut[hOrig[h]] = h; // ends as the first corner in face order
        }
        boolean[] nmV = new boolean[nV];
        int nmEdges = 0;
        for (int e = 0; e < nE; e++) {
            if (b.eNm[e]) {
                nmV[b.eV0[e]] = nmV[b.eV1[e]] = true;
                nmEdges++;
            }
        }
        for (int v = 0; v < nV; v++) {
            if (nmV[v]) continue;
            int eCount = b.vertexEdgeCount(v);
            int fc = fCount[v];
            if (fc == 0 || eCount < 2 || eCount - fc > 1) {
                nmV[v] = true;
                continue;
            }
            int start;
            if (eCount == fc) {
                start = vOut[v];
            } else {
                start = -1;
                for (int slot = b.vHead[v]; slot >= 0; slot = b.slotNext[slot]) {
                    int e = slot >> 1;
                    if (b.eFaceCount[e] == 1 && hOrig[b.ePrimary[e]] == v) {
                        start = b.ePrimary[e];
                        break;
                    }
                }
                if (start < 0) {
                    nmV[v] = true;
                    continue;
                }
            }
            // Walk counter-clockwise; a manifold vertex visits all its corners in one fan.
            int h = start, visited = 0;
            boolean ok;
            while (true) {
                visited++;
                int t = hTwin[lv.prev(h)];
                if (t < 0) {
                    ok = eCount != fc && visited == fc;
                    break;
                }
                if (t == start) {
                    ok = eCount == fc && visited == fc;
                    break;
                }
                if (visited > fc) {
                    ok = false;
                    break;
                }
                h = t;
            }
            if (ok) vOut[v] = start;
            else nmV[v] = true;
        }

        // Side tables for non-manifold edges and vertices, in Far's orders.
        lv.nmEdge = new int[nmEdges];
        lv.nmEdgeStart = new int[nmEdges + 1];
        int[] nmEdgeSlot = new int[nE];
        for (int e = 0, i = 0; e < nE; e++) {
            if (b.eNm[e]) {
                nmEdgeSlot[e] = i;
                lv.nmEdge[i] = e;
                lv.nmEdgeStart[i + 1] = lv.nmEdgeStart[i] + b.eFaceCount[e];
                i++;
            }
        }
        lv.nmEdgeHalf = new int[lv.nmEdgeStart[nmEdges]];
        int[] fill = new int[nmEdges];
        for (int h = 0; h < nH; h++) {
            int e = hEdgeId[h];
            if (b.eNm[e]) {
                int i = nmEdgeSlot[e];
                lv.nmEdgeHalf[lv.nmEdgeStart[i] + fill[i]++] = h;
            }
        }
        int nmCount = 0, nmEntries = 0;
        for (int v = 0; v < nV; v++) {
            if (nmV[v]) {
                nmCount++;
                nmEntries += b.vertexEdgeCount(v);
            }
        }
        lv.nmVert = new int[nmCount];
        lv.nmVertStart = new int[nmCount + 1];
        lv.nmVertHalf = new int[nmEntries];
        lv.nmVertOther = new int[nmEntries];
        lv.nmVertEnd = new int[nmEntries];
        for (int v = 0, i = 0, k = 0; v < nV; v++) {
            if (!nmV[v]) continue;
            lv.nmVert[i] = v;
            int lastEdge = -1;
            for (int slot = b.vHead[v]; slot >= 0; slot = b.slotNext[slot]) {
                int e = slot >> 1;
                int end;
                if (b.eV0[e] != b.eV1[e]) end = b.eV1[e] == v ? 1 : 0;
                else end = lastEdge == e ? 1 : 0; // a loop edge is listed twice: ends 0 then 1
                lastEdge = e;
                lv.nmVertHalf[k] = b.ePrimary[e];
                lv.nmVertOther[k] = end == 0 ? b.eV1[e] : b.eV0[e];
                lv.nmVertEnd[k] = e << 1 | end;
                k++;
            }
            lv.nmVertStart[++i] = k;
        }
        lv.nmFaceStart = new int[nmCount + 1];
        for (int i = 0; i < nmCount; i++) lv.nmFaceStart[i + 1] = lv.nmFaceStart[i] + fCount[lv.nmVert[i]];
        lv.nmFaceHalf = new int[lv.nmFaceStart[nmCount]];
        int[] nmSlot = new int[nV];
        Arrays.fill(nmSlot, -1);
        for (int i = 0; i < nmCount; i++) nmSlot[lv.nmVert[i]] = i;
        int[] faceFill = new int[nmCount];
        for (int h = 0; h < nH; h++) {
            int i = nmSlot[hOrig[h]];
            if (i >= 0) lv.nmFaceHalf[lv.nmFaceStart[i] + faceFill[i]++] = h;
        }
        level = lv;
        edges = b;
        vertexFaces = fCount;
        nonManifold = nmV;
    }

    /** Edge construction state of level 0 (Far's dynamic relations, as linked lists). */
    private static final class EdgeTable {
        int nE;
        int[] eV0, eV1, ePrimary, eSecond, eFaceCount, eLastFace;
        boolean[] eNm;
        /** Per vertex, its edges in creation order: slot 2e is edge e at its v0, 2e+1 at v1. */
        final int[] vHead, vTail;
        int[] slotNext;

        EdgeTable(int nV, int nH) {
            int cap = Math.max(16, nH / 2 + 8);
            eV0 = new int[cap];
            eV1 = new int[cap];
            ePrimary = new int[cap];
            eSecond = new int[cap];
            eFaceCount = new int[cap];
            eLastFace = new int[cap];
            eNm = new boolean[cap];
            slotNext = new int[2 * cap];
            vHead = new int[nV];
            vTail = new int[nV];
            Arrays.fill(vHead, -1);
            Arrays.fill(vTail, -1);
        }

        int addHalf(int h, int f, int v0, int v1) {
            int e = v0 != v1 ? find(v0, v1) : -1;
            boolean newIsNm = v0 == v1; // a loop edge is always a new, non-manifold instance
            if (e >= 0) {
                if (eLastFace[e] == f) {
                    // The face uses this edge twice: Far makes a second, non-manifold instance.
                    eNm[e] = true;
                    newIsNm = true;
                    e = -1;
                } else if (eFaceCount[e] > 1 || v0 == eV0[e]) {
                    eNm[e] = true; // a third face, or two faces running the same way
                }
            }
            if (e < 0) {
                e = create(v0, v1, h);
                eNm[e] = newIsNm;
            } else if (eSecond[e] < 0) {
                eSecond[e] = h;
            }
            eFaceCount[e]++;
            eLastFace[e] = f;
            return e;
        }

        /** Far's findEdge: the first edge (in creation order) of v0 that also ends at v1. */
        int find(int v0, int v1) {
            for (int slot = vHead[v0]; slot >= 0; slot = slotNext[slot]) {
                int e = slot >> 1;
                if (eV0[e] == v1 || eV1[e] == v1) return e;
            }
            return -1;
        }

        int create(int v0, int v1, int h) {
            if (nE == eV0.length) grow();
            int e = nE++;
            eV0[e] = v0;
            eV1[e] = v1;
            ePrimary[e] = h;
            eSecond[e] = -1;
            eFaceCount[e] = 0;
            eLastFace[e] = -1;
            link(v0, 2 * e);
            link(v1, 2 * e + 1);
            return e;
        }

        private void link(int v, int slot) {
            slotNext[slot] = -1;
            if (vTail[v] < 0) vHead[v] = slot;
            else slotNext[vTail[v]] = slot;
            vTail[v] = slot;
        }

        int vertexEdgeCount(int v) {
            int n = 0;
            for (int slot = vHead[v]; slot >= 0; slot = slotNext[slot]) n++;
            return n;
        }

        private void grow() {
            int cap = eV0.length * 2;
            eV0 = Arrays.copyOf(eV0, cap);
            eV1 = Arrays.copyOf(eV1, cap);
            ePrimary = Arrays.copyOf(ePrimary, cap);
            eSecond = Arrays.copyOf(eSecond, cap);
            eFaceCount = Arrays.copyOf(eFaceCount, cap);
            eLastFace = Arrays.copyOf(eLastFace, cap);
            eNm = Arrays.copyOf(eNm, cap);
            slotNext = Arrays.copyOf(slotNext, 2 * cap);
        }
    }

    /**
     * Far's edge between a and b for a crease tag: the first edge of a (in creation order) that
     * ends at b, or -1. Only before {@link #tag}.
     */
    int findEdge(int a, int b) {
        if (a == b) {
            for (int slot = edges.vHead[a]; slot >= 0; slot = edges.slotNext[slot]) {
                int e = slot >> 1;
                if (edges.eV0[e] == edges.eV1[e]) return e;
            }
            return -1;
        }
        return edges.find(a, b);
    }

    /**
     * Far's {@code prepareComponentTagsAndSharpness}: sharpens boundary and non-manifold edges
     * (implicitly), EDGE_AND_CORNER corners and non-manifold vertices, and gives every vertex its
     * rule and flags. With boundary NONE the faces at boundary vertices become holes.
     *
     * @param eSharpIn tagged edge sharpness by edge index, or null
     * @param vSharpIn tagged vertex sharpness, or null
     * @param extraVertexSharp if not null, vertices flagged here are made infinitely sharp too
     *                         (face-varying corners)
     * @return the finished level
     */
    Level tag(SubdivOptions.Boundary boundary, float[] eSharpIn, float[] vSharpIn, boolean[] extraVertexSharp, boolean[] holesIn) {
        Level lv = level;
        lv.eSharp = eSharpIn;
        float[] vs = vSharpIn != null ? vSharpIn.clone() : new float[lv.nV];
        byte[] tags = new byte[lv.nV];
        int[] ringBuf = new int[lv.maxValence() + 2];
        boolean any = eSharpIn != null || vSharpIn != null;
        boolean sharpenCorners = boundary == SubdivOptions.Boundary.EDGE_AND_CORNER;
        boolean makeHoles = boundary == SubdivOptions.Boundary.NONE;
        boolean[] holes = holesIn != null ? holesIn.clone() : null;
        for (int v = 0; v < lv.nV; v++) {
            int boundaryEdges = 0, infEdges = 0, semiEdges = 0, nmEdges = 0, edgeCount, faceCount;
            boolean nm = nonManifold[v];
            if (!nm) {
                int n = lv.ring(v, ringBuf);
                boolean bnd = lv.hTwin[lv.vOut[v]] < 0;
                edgeCount = bnd ? n + 1 : n;
                faceCount = n;
                for (int i = 0; i < edgeCount; i++) {
                    int h = ringBuf[i];
                    float s = lv.edgeSharpness(h);
                    if (lv.hTwin[h] < 0) boundaryEdges++;
                    if (Crease.isInfinite(s)) infEdges++;
                    else if (Crease.isSharp(s)) semiEdges++;
                }
            } else {
                int i = lv.nmVertIndex(v);
                edgeCount = lv.nmVertStart[i + 1] - lv.nmVertStart[i];
                faceCount = vertexFaces[v];
                for (int k = lv.nmVertStart[i]; k < lv.nmVertStart[i + 1]; k++) {
                    int e = lv.nmVertEnd[k] >> 1;
                    int h = lv.nmVertHalf[k];
                    if (edges.eFaceCount[e] < 2) boundaryEdges++;
                    if (edges.eNm[e]) nmEdges++;
                    float s = lv.edgeSharpness(h);
                    if (Crease.isInfinite(s)) infEdges++;
                    else if (Crease.isSharp(s)) semiEdges++;
                }
            }
            boolean topologicalCorner = faceCount == 1 && edgeCount == 2;
            if (topologicalCorner && sharpenCorners) {
                vs[v] = Crease.INFINITE;
            } else if (nm) {
                // Far leaves a vertex on an interior non-manifold crease (two non-manifold edges
                // with extra "fins") unsharpened; every other non-manifold vertex is a corner.
                if (!(nmEdges == 2 && boundaryEdges == 0 && faceCount > edgeCount)) vs[v] = Crease.INFINITE;
            }
            if (extraVertexSharp != null && extraVertexSharp[v]) vs[v] = Crease.INFINITE;
            int t = Crease.vertexRule(vs[v], infEdges + semiEdges);
            if (semiEdges > 0) t |= T_SEMI_EDGES;
            if (nm) t |= T_NONMANIFOLD;
            if (boundaryEdges > 0) t |= T_BOUNDARY;
            if (Crease.isInfinite(vs[v])) t |= T_INF_SHARP;
            else if (Crease.isSharp(vs[v])) t |= T_SEMI_SHARP;
            tags[v] = (byte) t;
            if (t != 0 || vs[v] != 0f) any = true;
            // Far 3.5 with boundary NONE: the faces at a boundary vertex become holes unless all
            // its boundary edges were tagged infinitely sharp.
            if (makeHoles && boundaryEdges > 0 && hasUntaggedBoundaryEdge(lv, v, nm, ringBuf, eSharpIn)) {
                if (holes == null) holes = new boolean[lv.nF];
                if (!nm) {
                    for (int i = 0; i < faceCount; i++) holes[lv.face(ringBuf[i])] = true;
                } else {
                    for (int h = 0; h < lv.nH; h++) if (lv.hOrig[h] == v) holes[lv.face(h)] = true;
                }
            }
        }
        boolean anyVs = false;
        for (float s : vs) anyVs |= s != 0f;
        lv.vSharp = anyVs ? vs : null;
        lv.vTag = any ? tags : null;
        lv.hole = holes;
        edges = null;
        vertexFaces = null;
        nonManifold = null;
        return lv;
    }

    private boolean hasUntaggedBoundaryEdge(Level lv, int v, boolean nm, int[] ringBuf, float[] tagged) {
        if (!nm) {
            int n = lv.ring(v, ringBuf);
            for (int i = 0; i <= n; i++) {
                int h = ringBuf[i];
                if (lv.hTwin[h] < 0 && (tagged == null || !Crease.isInfinite(tagged[lv.edge(h)]))) return true;
            }
            return false;
        }
        int i = lv.nmVertIndex(v);
        for (int k = lv.nmVertStart[i]; k < lv.nmVertStart[i + 1]; k++) {
            int e = lv.nmVertEnd[k] >> 1;
            if (edges.eFaceCount[e] < 2 && (tagged == null || !Crease.isInfinite(tagged[e]))) return true;
        }
        return false;
    }
}
