package lt.spindulys.subdiv;

import java.util.Arrays;

import lt.spindulys.mesh.MeshData;

/**
 * Refines one coarse face of a control mesh at a time, from its one-ring only. Immutable,
 * thread-safe: every call works on its own arrays.
 *
 * <p><b>Why the one-ring gives the uniform path's values bit for bit.</b> A patch is made by
 * gathering the faces that share a vertex with the face (through a vertex-to-faces incidence
 * built once, which also copes with non-manifold vertices), building a small {@link ControlMesh}
 * of them that keeps faces, vertices and UVs in their original relative order with the creases,
 * corners, holes and options that apply, and refining it with the same code as the whole mesh.
 * Far's numbering depends only on relative order (edges by first appearance, a vertex's first
 * face, its edges in creation order), and every value of the face's descendants, and of the
 * vertices around them, depends only on that one-ring: so each is computed by the same
 * operations in the same order as in the whole-mesh refinement. The descendants of a face are
 * one contiguous range of each level (faces of level L are the children of level L-1's faces in
 * order), and their triangles come from {@link RefinedTriangles}, the code the uniform surface
 * uses. Only the vertices at the one-ring's outer rim get other values than in the whole mesh
 * (their own neighbourhood is cut), and no descendant of the face depends on them.
 *
 * <p><b>Pruning.</b> The same holds at every level: the descendants at level l and the faces
 * sharing a vertex with them are all that deeper levels need. So each refined level below the
 * last is cut down to those faces (order kept, the rim's vertices made corners so that no rule
 * walks around their cut rings) before it is refined again, and a patch costs about
 * (2^l + 2)^2 faces per level instead of the whole one-ring's 9 * 4^l. Levels with non-manifold
 * side tables (and level 0, which may hold other polygons) are refined whole.
 *
 * <p><b>Cost.</b> Per patch, arrays proportional to the pruned levels plus one int per control
 * face of the one-ring; no hash maps, nothing shared and mutable. A one-ring holds every face at
 * the face's corners, so a vertex may be shared by at most {@link #MAX_VERTEX_FACES} faces.
 */
public final class PatchRefiner {
    /** The deepest level a patch may be refined to (as the uniform surface's). */
    public static final int MAX_LEVEL = 8;

    private final ControlMesh control;
    private final Level base;
    /** First corner of each face (faceCount + 1 entries). */
    private final int[] cornerStart;
    /** Vertex to faces: the faces at vertex v, ascending and each once, are vfFace[vfStart[v] .. vfStart[v+1]-1]. */
    private final int[] vfStart, vfFace;
    /**
     * Per vertex, the box (minX, minY, minZ, maxX, maxY, maxZ) of the corners of every face at it:
     * a face's one-ring box is the union of its corners' boxes, so each face costs its own size
     * rather than the size of its one-ring (which around a vertex shared by many faces would make
     * the boxes of all faces cost the square of that number).
     */
    private final double[] vertexRingBox;

    /**
     * The most faces that may share one vertex. A patch is refined from every face at its corners,
     * so the work of the patches around a vertex grows with the square of its faces; OpenSubdiv's
     * reference shapes go up to 360 (a pole), and a limit well above that keeps any cage's
     * refinement within a constant factor of its size.
     */
    public static final int MAX_VERTEX_FACES = 1024;

    /**
     * Builds the vertex-to-face incidence of {@code control} (two int arrays as long as its
     * vertices and its corners) and the box of the faces at each vertex (six doubles a vertex).
     *
     * @param control the control mesh
     */
    public PatchRefiner(ControlMesh control) {
        this.control = control;
        this.base = control.base;
        int[] sizes = control.faceSizes(), fv = control.faceVertices();
        int nF = sizes.length, nV = control.vertexCount();
        cornerStart = new int[nF + 1];
        for (int f = 0; f < nF; f++) cornerStart[f + 1] = cornerStart[f] + sizes[f];
        // A face that repeats a vertex is listed once at it: lastFace marks the faces counted.
        int[] lastFace = new int[nV];
        Arrays.fill(lastFace, -1);
        int[] start = new int[nV + 1];
        for (int f = 0; f < nF; f++) {
            for (int c = cornerStart[f]; c < cornerStart[f + 1]; c++) {
                int v = fv[c];
                if (lastFace[v] != f) {
                    lastFace[v] = f;
                    start[v + 1]++;
                }
            }
        }
        for (int v = 0; v < nV; v++) start[v + 1] += start[v];
        int[] faces = new int[start[nV]], fill = Arrays.copyOf(start, nV);
        Arrays.fill(lastFace, -1);
        for (int f = 0; f < nF; f++) {
            for (int c = cornerStart[f]; c < cornerStart[f + 1]; c++) {
                int v = fv[c];
                if (lastFace[v] != f) {
                    lastFace[v] = f;
                    faces[fill[v]++] = f;
                }
            }
        }
        for (int v = 0; v < nV; v++) {
            int count = start[v + 1] - start[v];
            if (count > MAX_VERTEX_FACES) {
                String at = control.source() == null ? "" : control.source() + ": ";
                throw new IllegalArgumentException(at + "vertex " + v + " is shared by " + count + " faces (face " + faces[start[v]] + " is the first); adaptive "
                        + "subdivision supports at most " + MAX_VERTEX_FACES + " at a vertex (repeated faces? refine uniformly with method uniform)");
            }
        }
        vfStart = start;
        vfFace = faces;
        vertexRingBox = vertexRingBoxes(control, cornerStart, fv);
        base.edgeCodes();
    }

    /** {@link #vertexRingBox}: each face's box once, merged into the boxes of its corners. */
    private static double[] vertexRingBoxes(ControlMesh control, int[] cornerStart, int[] fv) {
        double[] p = control.positions();
        int nV = control.vertexCount();
        double[] out = new double[6 * nV];
        for (int v = 0; v < nV; v++) {
            Arrays.fill(out, 6 * v, 6 * v + 3, Double.POSITIVE_INFINITY);
            Arrays.fill(out, 6 * v + 3, 6 * v + 6, Double.NEGATIVE_INFINITY);
        }
        for (int g = 0; g + 1 < cornerStart.length; g++) {
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            for (int d = cornerStart[g]; d < cornerStart[g + 1]; d++) {
                int w = 3 * fv[d];
                x0 = Math.min(x0, p[w]); x1 = Math.max(x1, p[w]);
                y0 = Math.min(y0, p[w + 1]); y1 = Math.max(y1, p[w + 1]);
                z0 = Math.min(z0, p[w + 2]); z1 = Math.max(z1, p[w + 2]);
            }
            for (int d = cornerStart[g]; d < cornerStart[g + 1]; d++) {
                int b = 6 * fv[d];
                out[b] = Math.min(out[b], x0); out[b + 1] = Math.min(out[b + 1], y0); out[b + 2] = Math.min(out[b + 2], z0);
                out[b + 3] = Math.max(out[b + 3], x1); out[b + 4] = Math.max(out[b + 4], y1); out[b + 5] = Math.max(out[b + 5], z1);
            }
        }
        return out;
    }

    /** {@return the control mesh} */
    public ControlMesh control() { return control; }

    /** {@return the number of coarse faces} */
    public int faceCount() { return cornerStart.length - 1; }

    /**
     * Whether the face is a hole (its patches have no triangles): tagged so, or made so by
     * boundary interpolation NONE.
     *
     * @param face the face
     * @return true for a hole
     */
    public boolean isHole(int face) { return base.hole != null && base.hole[face]; }

    /**
     * Corners of a coarse face.
     *
     * @param face the face
     * @return its size
     */
    public int faceSize(int face) { return cornerStart[face + 1] - cornerStart[face]; }

    /** {@return the number of control edges, numbered as the base level numbers them (Far's order)} */
    public int edgeCount() { return base.nE; }

    /**
     * The control edge from corner k's vertex to corner k+1's.
     *
     * @param face the face
     * @param corner the corner k, 0 to faceSize - 1
     * @return the edge index
     */
    public int faceEdge(int face, int corner) {
        if (corner < 0 || corner >= faceSize(face)) throw new IllegalArgumentException("face " + face + " has no corner " + corner);
        return base.edge(cornerStart[face] + corner);
    }

    /**
     * The two vertices of every control edge, in Far's edge order and vertex order: a new array
     * each call (the caller may keep or change it).
     *
     * @return two vertex indices per edge
     */
    public int[] edgeVertices() {
        int[] ev = new int[2 * base.nE];
        for (int h = 0; h < base.nH; h++) {
            if (!base.primary(h)) continue;
            int e = base.edge(h);
            ev[2 * e] = base.edgeV0(h);
            ev[2 * e + 1] = base.edgeV1(h);
        }
        return ev;
    }

    /**
     * Box (minX, minY, minZ, maxX, maxY, maxZ) of the face's one-ring control points: contains
     * every refined level of the face and its limit patch, because every rule of the three schemes
     * (Catmull-Clark's smooth, crease, corner, semi-sharp blends and smooth triangles; Loop's,
     * whose smooth vertex weight 1 - n beta stays positive at every valence; bilinear's) has
     * non-negative weights.
     * Not padded.
     *
     * @param face the face
     * @param out receives the six numbers
     */
    public void oneRingBounds(int face, double[] out) {
        int[] fv = control.faceVertices();
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        double[] b = vertexRingBox;
        for (int c = cornerStart[face]; c < cornerStart[face + 1]; c++) {
            int w = 6 * fv[c];
            x0 = Math.min(x0, b[w]); y0 = Math.min(y0, b[w + 1]); z0 = Math.min(z0, b[w + 2]);
            x1 = Math.max(x1, b[w + 3]); y1 = Math.max(y1, b[w + 4]); z1 = Math.max(z1, b[w + 5]);
        }
        out[0] = x0; out[1] = y0; out[2] = z0; out[3] = x1; out[4] = y1; out[5] = z1;
    }

    /** Bytes of an array's header, and of the MeshData record, on a 64-bit JVM (uncompressed references: the larger). */
    private static final long ARRAY_HEADER = 16, RECORD_BYTES = 80;

    /**
     * Heap bytes a patch of this face at this level will hold (its MeshData and arrays; for cache
     * budgets), computed without building it: an upper bound. A patch has at most one normal
     * and one UV per vertex (no sharp edge or UV seam runs inside a coarse face), unless the face
     * repeats a vertex, when one per corner is counted.
     *
     * @param face the face
     * @param level the level, 0 to {@link #MAX_LEVEL}
     * @param smooth whether normals are made
     * @return the bytes
     */
    public long patchBytes(int face, int level, boolean smooth) {
        checkLevel(level);
        int n = faceSize(face);
        long verts, faces, corners;
        if (level == 0) {
            verts = n;
            faces = n == 4 ? 2 : 1;
            corners = n == 4 ? 6 : n;
        } else if (base.triangleSplit) {
            long m = 1L << level; // segments per edge: a triangle grid of m^2 triangles
            verts = (m + 1) * (m + 2) / 2;
            faces = m * m;
            corners = 3 * faces;
        } else {
            long m = 1L << (level - 1), quads = n * m * m;
            verts = quads + n * m + 1;
            faces = 2 * quads;
            corners = 6 * quads;
        }
        if (isHole(face)) {
            verts = faces = corners = 0;
        }
        long perVertex = repeatsVertex(face) ? corners : verts;
        boolean uv = control.uvs() != null;
        long b = RECORD_BYTES + array(verts, 24) + array(faces, 4) + array(corners, 4);
        if (smooth) b += array(perVertex, 24) + array(corners, 4);
        if (uv) b += array(perVertex, 16) + array(corners, 4);
        return b;
    }

    private static long array(long count, long bytesEach) {
        return ARRAY_HEADER + ((count * bytesEach + 7) & ~7L);
    }

    private boolean repeatsVertex(int face) {
        int[] fv = control.faceVertices();
        for (int c = cornerStart[face]; c < cornerStart[face + 1]; c++) {
            for (int d = cornerStart[face]; d < c; d++) if (fv[c] == fv[d]) return true;
        }
        return false;
    }

    private static void checkLevel(int level) {
        if (level < 0 || level > MAX_LEVEL) throw new IllegalArgumentException("patch level must be between 0 and " + MAX_LEVEL + ", found " + level);
    }

    /**
     * The triangles of {@code face} refined {@code level} times, from its one-ring alone: see
     * {@link #refine(int, int, int[], int[], boolean)}, with each corner vertex placed at the
     * lower level of its two edges.
     *
     * @param face the coarse face
     * @param level 0 to {@link #MAX_LEVEL}
     * @param edgeLevels per corner k, the level of edge k (each at most {@code level}), or null for all {@code level}
     * @param smooth per-corner normals (true) or none
     * @return the patch
     */
    public MeshData refine(int face, int level, int[] edgeLevels, boolean smooth) {
        return refine(face, level, edgeLevels, null, smooth);
    }

    /**
     * The triangles of {@code face} refined {@code level} times (0..8), from its one-ring alone,
     * as MeshData with triangles only (at level 0 an n-gon stays one polygon, as the uniform path
     * leaves it), vertex positions, for smooth shading per-corner normal indices and normals
     * exactly as the uniform path gives them (flat: none), and face-varying UVs when the mesh has
     * them. With no level lowered the result is bit for bit the uniform path's triangles of the
     * face's descendants, in the same order (the arrays are the patch's own, numbered in order of
     * first use).
     *
     * <p>An edge refined less than the face: the face's boundary vertices on that edge are
     * snapped, monotonically (each to the nearest, ties towards the edge's first vertex), to the
     * positions the edge's vertices have at the edge's own level, so that a neighbour refined at
     * that level shares exactly the same edge vertices and the stitched surface is watertight
     * (degenerate zero-area triangles are allowed). A corner vertex is placed at its corner level:
     * for a watertight surface every face at a vertex must place it at the same level, e.g. the
     * least level of all the control edges at it ({@link #vertexLevel}). Normals and UVs of
     * snapped vertices are not changed.
     *
     * @param face the coarse face
     * @param level 0 to {@link #MAX_LEVEL}
     * @param edgeLevels per corner k, the level of edge k (each at most {@code level}), or null for all {@code level}
     * @param cornerLevels per corner k, the level whose position corner k's vertex takes (each at
     *                     most {@code level}), or null for the lower level of the two edges at it
     * @param smooth per-corner normals (true) or none
     * @return the patch
     */
    public MeshData refine(int face, int level, int[] edgeLevels, int[] cornerLevels, boolean smooth) {
        if (face < 0 || face >= faceCount()) throw new IllegalArgumentException("face " + face + " is not in the mesh (" + faceCount() + " faces)");
        checkLevel(level);
        int n = faceSize(face);
        int[] el = new int[n], cl = new int[n];
        Arrays.fill(el, level);
        if (edgeLevels != null) {
            if (edgeLevels.length != n) throw new IllegalArgumentException("face " + face + " has " + n + " edges, but " + edgeLevels.length + " edge levels were given");
            for (int k = 0; k < n; k++) {
                if (edgeLevels[k] < 0 || edgeLevels[k] > level) {
                    throw new IllegalArgumentException("edge level " + edgeLevels[k] + " of face " + face + " corner " + k + " is not between 0 and the face's level " + level);
                }
                el[k] = edgeLevels[k];
            }
        }
        if (cornerLevels != null) {
            if (cornerLevels.length != n) throw new IllegalArgumentException("face " + face + " has " + n + " corners, but " + cornerLevels.length + " corner levels were given");
            for (int k = 0; k < n; k++) {
                if (cornerLevels[k] < 0 || cornerLevels[k] > level) {
                    throw new IllegalArgumentException("corner level " + cornerLevels[k] + " of face " + face + " corner " + k + " is not between 0 and the face's level " + level);
                }
                cl[k] = cornerLevels[k];
            }
        } else {
            for (int k = 0; k < n; k++) cl[k] = Math.min(el[k], el[(k + n - 1) % n]);
        }
        boolean snap = false;
        for (int k = 0; k < n; k++) snap |= el[k] < level || cl[k] < level;

        Local lm = local(face);
        RefinedMesh r = RefinedMesh.base(lm.mesh);
        int h0 = lm.mesh.base.firstHalf(lm.face);
        // For snapping: the face's edges as half-edges of the current level (from corner k's
        // vertex on), and their vertices at every level, numbered as that level numbers them.
        int[][] halves = null;
        int[][][] chains = null;
        double[][] positions = null;
        if (snap) {
            halves = new int[n][];
            chains = new int[n][level + 1][];
            positions = new double[level + 1][];
            for (int k = 0; k < n; k++) halves[k] = new int[] {h0 + k};
            record(r, halves, chains, positions, 0);
        }
        int f0 = lm.face, count = 1;
        for (int l = 1; l <= level; l++) {
            Level p = r.topo;
            // A face's children: one per corner, numbered like its half-edges (quad split), or
            // four in a row (triangle split).
            if (p.triangleSplit) {
                f0 = 4 * f0;
                count = 4 * count;
            } else {
                f0 = p.firstHalf(f0);
                count = l == 1 ? n : 4 * count;
            }
            r = r.refine();
            if (snap) {
                for (int k = 0; k < n; k++) halves[k] = childHalves(p, halves[k]);
            }
            // Below the last level, only the faces around the face's descendants are kept.
            if (l < level && prunable(r)) {
                int[] faceAt = keptFaces(r, f0, count);
                r = prune(r, faceAt);
                f0 = faceAt[f0];
                if (snap) {
                    int fs = r.topo.triangleSplit ? 3 : 4;
                    for (int[] hs : halves) for (int i = 0; i < hs.length; i++) hs[i] = fs * faceAt[hs[i] / fs] + hs[i] % fs;
                }
            }
            if (snap) record(r, halves, chains, positions, l);
        }
        int[] vmap = new int[r.vertexCount()];
        MeshData md = RefinedTriangles.triangles(r, f0, f0 + count, smooth, vmap);
        if (snap && md.vertexIndex().length > 0) snap(lm.mesh.base, h0, n, level, el, cl, chains, positions, vmap, md.positions());
        return md;
    }

    private static void record(RefinedMesh r, int[][] halves, int[][][] chains, double[][] positions, int l) {
        Level t = r.topo;
        positions[l] = r.positions();
        for (int k = 0; k < halves.length; k++) {
            int[] hs = halves[k], v = new int[hs.length + 1];
            for (int i = 0; i < hs.length; i++) v[i] = t.hOrig[hs[i]];
            v[hs.length] = t.dest(hs[hs.length - 1]);
            chains[k][l] = v;
        }
    }

    /**
     * The child half-edges along half-edges of p: a child of x runs from x's origin to x's edge
     * point, the next from there to x's end (see {@link Refinement}'s numbering).
     */
    private static int[] childHalves(Level p, int[] hs) {
        int[] next = new int[2 * hs.length];
        if (p.triangleSplit) {
            for (int i = 0; i < hs.length; i++) {
                next[2 * i] = TriangleSplit.originPiece(hs[i]);
                next[2 * i + 1] = TriangleSplit.destPiece(hs[i]);
            }
            return next;
        }
        for (int i = 0; i < hs.length; i++) {
            int x = hs[i], xn = p.next(x);
            next[2 * i] = 4 * x + (Refinement.rot(p, x) & 3);
            next[2 * i + 1] = 4 * xn + ((Refinement.rot(p, xn) + 3) & 3);
        }
        return next;
    }

    /** Moves the boundary vertices of edges and corners below the face's level (see {@link #refine}). */
    private static void snap(Level b, int h0, int n, int level, int[] el, int[] cl, int[][][] chains, double[][] positions, int[] vmap, double[] out) {
        for (int k = 0; k < n; k++) {
            int ka = k, kb = (k + 1) % n;
            if (el[k] == level && cl[ka] == level && cl[kb] == level) continue;
            int[] fine = chains[k][level], coarse = chains[k][el[k]];
            int d = level - el[k], last = 1 << el[k];
            boolean towardsLow = b.fwd(h0 + k); // the edge's first vertex is at this face's corner k
            double[] pa = positions[cl[ka]], pb = positions[cl[kb]], pe = positions[el[k]];
            int va = chains[k][cl[ka]][0], vb = chains[k][cl[kb]][chains[k][cl[kb]].length - 1];
            for (int j = 0; j < fine.length; j++) {
                int i;
                if (d == 0) {
                    i = j;
                } else {
                    int rem = j & ((1 << d) - 1), half = 1 << (d - 1);
                    i = j >> d;
                    if (rem > half || (rem == half && !towardsLow)) i++;
                }
                int m = vmap[fine[j]];
                if (m < 0) continue;
                if (i == 0) System.arraycopy(pa, 3 * va, out, 3 * m, 3);
                else if (i == last) System.arraycopy(pb, 3 * vb, out, 3 * m, 3);
                else System.arraycopy(pe, 3 * coarse[i], out, 3 * m, 3);
            }
        }
    }

    // ---------------------------------------------------------------- pruning

    /**
     * Whether a refined level can be cut down: quads only (or triangles only, from a triangle
     * split) and no non-manifold side tables (for them, and before the first refinement, the
     * whole one-ring is refined).
     */
    static boolean prunable(RefinedMesh r) {
        FaceVarying.Channel uv = r.uvChannel();
        return uniform(r.topo) && (uv == null || uniform(uv.level()));
    }

    private static boolean uniform(Level t) {
        return t.hFace == null && (t.faceStart == null || t.triangleSplit) && t.nmVert.length == 0 && t.nmEdge.length == 0;
    }

    /**
     * The faces to keep around the faces f0 .. f0+count-1: those sharing a vertex with them (their
     * one-ring, which is all that their refinements and the one-rings of those depend on). Old
     * face index to new (order kept), -1 for a face left out.
     */
    private static int[] keptFaces(RefinedMesh r, int f0, int count) {
        Level t = r.topo;
        int fs = t.triangleSplit ? 3 : 4;
        boolean[] want = new boolean[t.nV];
        for (int h = fs * f0, e = fs * (f0 + count); h < e; h++) want[t.hOrig[h]] = true;
        return keptFaces(t, want);
    }

    /** As {@link #keptFaces(RefinedMesh, int, int)}, around the faces listed (faces[0..count)). */
    static int[] keptFaces(RefinedMesh r, int[] faces, int count) {
        Level t = r.topo;
        int fs = t.triangleSplit ? 3 : 4;
        boolean[] want = new boolean[t.nV];
        for (int i = 0; i < count; i++) for (int h = fs * faces[i], e = h + fs; h < e; h++) want[t.hOrig[h]] = true;
        return keptFaces(t, want);
    }

    private static int[] keptFaces(Level t, boolean[] want) {
        int fs = t.triangleSplit ? 3 : 4;
        int[] faceAt = new int[t.nF];
        int m = 0;
        for (int f = 0; f < t.nF; f++) {
            int h = fs * f;
            faceAt[f] = want[t.hOrig[h]] || want[t.hOrig[h + 1]] || want[t.hOrig[h + 2]] || (fs == 4 && want[t.hOrig[h + 3]]) ? m++ : -1;
        }
        return faceAt;
    }

    /** The level with only the faces kept ({@code faceAt} not -1), its positions and UVs likewise. */
    static RefinedMesh prune(RefinedMesh r, int[] faceAt) {
        int[] vAt = new int[r.topo.nV];
        Level t = pruneLevel(r.topo, faceAt, vAt);
        double[] p = r.positions(), np = new double[3 * t.nV];
        for (int v = 0; v < vAt.length; v++) if (vAt[v] >= 0) System.arraycopy(p, 3 * v, np, 3 * vAt[v], 3);
        FaceVarying.Channel uv = r.uvChannel();
        if (uv != null) {
            int[] uAt = new int[uv.level().nV];
            Level ut = pruneLevel(uv.level(), faceAt, uAt);
            double[] u = uv.values(), nu = new double[2 * ut.nV];
            for (int v = 0; v < uAt.length; v++) if (uAt[v] >= 0) System.arraycopy(u, 2 * v, nu, 2 * uAt[v], 2);
            uv = new FaceVarying.Channel(ut, nu, uv.linear(), uv.linearBoundaries());
        }
        return r.with(t, np, uv);
    }

    /**
     * A quad (or triangle-split) level cut down to the faces kept, everything renumbered in its original order:
     * faces, their half-edges, vertices (written to {@code vAt}, -1 where dropped) and edges, with
     * twins, edge codes, first half-edges, tags, sharpness and holes. An edge whose primary
     * half-edge is dropped gets a kept one as primary; a twin dropped leaves a boundary there.
     * Only the ring's rim sees these changes, and no value of the kept faces' descendants
     * depends on the rim's own neighbourhood.
     */
    private static Level pruneLevel(Level c, int[] faceAt, int[] vAt) {
        int[] code = c.edgeCodes();
        int fs = c.triangleSplit ? 3 : 4;
        int m = 0;
        for (int a : faceAt) if (a >= 0) m++;
        Arrays.fill(vAt, -1);
        int[] eAt = new int[c.nE];
        Arrays.fill(eAt, -1);
        for (int f = 0; f < faceAt.length; f++) {
            if (faceAt[f] < 0) continue;
            for (int h = fs * f; h < fs * f + fs; h++) {
                vAt[c.hOrig[h]] = 0;
                eAt[code[h] >>> 2] = 0;
            }
        }
        int nv = 0, ne = 0;
        for (int v = 0; v < vAt.length; v++) if (vAt[v] == 0) vAt[v] = nv++;
        for (int e = 0; e < eAt.length; e++) if (eAt[e] == 0) eAt[e] = ne++;
        int nh = fs * m;
        int[] o = new int[nh], tw = c.hTwin == null ? null : new int[nh], ed = new int[nh];
        boolean[] hasPrimary = new boolean[ne];
        for (int f = 0; f < faceAt.length; f++) {
            int nf = faceAt[f];
            if (nf < 0) continue;
            for (int k = 0; k < fs; k++) {
                int h = fs * f + k, nh1 = fs * nf + k;
                o[nh1] = vAt[c.hOrig[h]];
                if (tw != null) {
                    int x = c.hTwin[h];
                    tw[nh1] = x < 0 || faceAt[x / fs] < 0 ? -1 : fs * faceAt[x / fs] + x % fs;
                }
                int e = eAt[code[h] >>> 2];
                ed[nh1] = e << 2 | (code[h] & (Level.E_FWD | Level.E_PRIMARY));
                if ((code[h] & Level.E_PRIMARY) != 0) hasPrimary[e] = true;
            }
        }
        for (int h = 0; h < nh; h++) {
            int e = ed[h] >>> 2;
            if (!hasPrimary[e]) {
                ed[h] |= Level.E_PRIMARY;
                hasPrimary[e] = true;
            }
        }
        int[] out = null;
        if (c.vOut != null) {
            out = new int[nv];
            Arrays.fill(out, -1);
            for (int v = 0; v < vAt.length; v++) {
                int x = vAt[v] < 0 ? -1 : c.vOut[v];
                if (x >= 0 && faceAt[x / fs] >= 0) out[vAt[v]] = fs * faceAt[x / fs] + x % fs;
            }
            // A rim vertex whose first face was dropped starts at any kept one: walks around
            // it end at the dropped twins.
            for (int h = 0; h < nh; h++) if (out[o[h]] < 0) out[o[h]] = h;
        }
        int[] faceStart = null;
        if (c.triangleSplit) {
            faceStart = new int[m + 1];
            for (int f = 0; f <= m; f++) faceStart[f] = 3 * f;
        }
        Level n = new Level(c.depth, nv, m, ne, faceStart, null, o, tw, ed, out);
        n.triangleSplit = c.triangleSplit;
        if (c.vTag != null) {
            n.vTag = new byte[nv];
            for (int v = 0; v < vAt.length; v++) if (vAt[v] >= 0) n.vTag[vAt[v]] = c.vTag[v];
        }
        if (c.depOn != null) {
            // A UV value that follows another keeps following it; where that one was cut away
            // the value is on the rim, whose values are not used.
            n.depOn = new int[nv];
            Arrays.fill(n.depOn, -1);
            for (int v = 0; v < vAt.length; v++) {
                int b = vAt[v] < 0 ? -1 : c.depOn[v];
                if (b >= 0 && vAt[b] >= 0) n.depOn[vAt[v]] = vAt[b];
            }
        }
        if (c.vSharp != null) {
            n.vSharp = new float[nv];
            for (int v = 0; v < vAt.length; v++) if (vAt[v] >= 0) n.vSharp[vAt[v]] = c.vSharp[v];
        }
        if (c.eSharp != null) {
            n.eSharp = new float[ne];
            for (int e = 0; e < eAt.length; e++) if (eAt[e] >= 0) n.eSharp[eAt[e]] = c.eSharp[e];
        }
        if (c.hole != null) {
            n.hole = new boolean[m];
            for (int f = 0; f < faceAt.length; f++) if (faceAt[f] >= 0) n.hole[faceAt[f]] = c.hole[f];
        }
        if (tw != null) {
            // Rim vertices (some of their faces dropped) become corners: their rings are cut, and
            // a corner's rules never walk around it. Their values are not used (see above).
            int[] lost = new int[nv];
            for (int h = 0; h < c.nH; h++) {
                if (faceAt[h / fs] < 0 && vAt[c.hOrig[h]] >= 0) lost[vAt[c.hOrig[h]]]++;
            }
            for (int v = 0; v < nv; v++) {
                if (lost[v] == 0) continue;
                if (n.vTag == null) n.vTag = new byte[nv];
                if (n.vSharp == null) n.vSharp = new float[nv];
                n.vSharp[v] = Crease.INFINITE;
                n.vTag[v] = (byte) ((n.vTag[v] & ~(Level.T_RULE | Level.T_SEMI_SHARP)) | Crease.RULE_CORNER | Level.T_INF_SHARP | Level.T_BOUNDARY);
            }
        }
        return n;
    }

    /**
     * The least level of the control edges at a face's corner vertex, given a level per control
     * edge: the corner level at which every face around the vertex places it alike.
     *
     * @param face the face
     * @param corner its corner
     * @param edgeLevel a level per control edge (indexed as {@link #faceEdge})
     * @return the least level of an edge at the vertex
     */
    public int vertexLevel(int face, int corner, int[] edgeLevel) {
        int v = control.faceVertices()[cornerStart[face] + corner];
        int min = Integer.MAX_VALUE;
        for (int i = vfStart[v]; i < vfStart[v + 1]; i++) {
            int g = vfFace[i];
            for (int c = cornerStart[g]; c < cornerStart[g + 1]; c++) {
                if (base.hOrig[c] == v || base.dest(c) == v) min = Math.min(min, edgeLevel[base.edge(c)]);
            }
        }
        return min;
    }

    /** The one-ring control mesh of a face and the face's index in it. */
    record Local(ControlMesh mesh, int face) {}

    /**
     * The faces sharing a vertex with {@code face}, with their vertices, UVs, creases, corners,
     * holes and the options, everything kept in its original relative order.
     */
    Local local(int face) {
        int[] sizes = control.faceSizes(), fv = control.faceVertices();
        int total = 0;
        for (int c = cornerStart[face]; c < cornerStart[face + 1]; c++) total += vfStart[fv[c] + 1] - vfStart[fv[c]];
        int[] ring = new int[total];
        int k = 0;
        for (int c = cornerStart[face]; c < cornerStart[face + 1]; c++) {
            int v = fv[c];
            for (int i = vfStart[v]; i < vfStart[v + 1]; i++) ring[k++] = vfFace[i];
        }
        int nr = sortedUnique(ring, k);
        int corners = 0;
        for (int i = 0; i < nr; i++) corners += sizes[ring[i]];
        int[] verts = new int[corners];
        int[] lsizes = new int[nr];
        k = 0;
        for (int i = 0; i < nr; i++) {
            int g = ring[i];
            lsizes[i] = sizes[g];
            for (int c = cornerStart[g]; c < cornerStart[g + 1]; c++) verts[k++] = fv[c];
        }
        int[] lfv = verts.clone();
        int nv = sortedUnique(verts, corners);
        for (int i = 0; i < corners; i++) lfv[i] = Arrays.binarySearch(verts, 0, nv, lfv[i]);
        double[] p = control.positions(), lp = new double[3 * nv];
        for (int i = 0; i < nv; i++) System.arraycopy(p, 3 * verts[i], lp, 3 * i, 3);
        ControlMesh.Builder mb = ControlMesh.builder(lp, lsizes, lfv).options(control.options());
        // Level 0 of a mesh with other polygons is stored (and refined) in the general form, even
        // where a one-ring has only quads: the quad-only code sums in another order.
        mb.generalFaces = base.faceStart != null;
        if (control.uvs() != null) {
            int[] fuv = control.faceUvIndices();
            int[] uvIds = new int[corners];
            k = 0;
            for (int i = 0; i < nr; i++) {
                int g = ring[i];
                for (int c = cornerStart[g]; c < cornerStart[g + 1]; c++) uvIds[k++] = fuv[c];
            }
            int[] luv = uvIds.clone();
            int nu = sortedUnique(uvIds, corners);
            for (int i = 0; i < corners; i++) luv[i] = Arrays.binarySearch(uvIds, 0, nu, luv[i]);
            double[] uv = control.uvs(), lu = new double[2 * nu];
            for (int i = 0; i < nu; i++) System.arraycopy(uv, 2 * uvIds[i], lu, 2 * i, 2);
            mb.uvs(lu, luv);
        }
        // Sharpness as tagged (base.eSharp is the input, by edge) and as the base level settled
        // it for vertices (given corners plus those sharpened by its own topology, which the
        // one-ring sharpens alike at every vertex that matters).
        if (base.eSharp != null) {
            for (int i = 0; i < nr; i++) {
                int g = ring[i];
                for (int c = cornerStart[g]; c < cornerStart[g + 1]; c++) {
                    float s = base.eSharp[base.edge(c)];
                    if (s != 0f) {
                        mb.crease(Arrays.binarySearch(verts, 0, nv, base.edgeV0(c)), Arrays.binarySearch(verts, 0, nv, base.edgeV1(c)), s);
                    }
                }
            }
        }
        if (base.vSharp != null) {
            for (int i = 0; i < nv; i++) {
                float s = base.vSharp[verts[i]];
                if (s != 0f) mb.corner(i, s);
            }
        }
        ControlMesh m = mb.build();
        // Holes as the whole mesh has them: boundary NONE would also make holes of faces at the
        // ring's own rim, where the whole mesh has none.
        boolean[] holes = null;
        if (base.hole != null) {
            for (int i = 0; i < nr; i++) {
                if (base.hole[ring[i]]) {
                    if (holes == null) holes = new boolean[nr];
                    holes[i] = true;
                }
            }
        }
        m.base.hole = holes;
        return new Local(m, Arrays.binarySearch(ring, 0, nr, face));
    }

    /** Sorts a[0..n) and removes repeats; returns the new length. */
    private static int sortedUnique(int[] a, int n) {
        Arrays.sort(a, 0, n);
        int u = 0;
        for (int i = 0; i < n; i++) if (u == 0 || a[i] != a[u - 1]) a[u++] = a[i];
        return u;
    }
}
