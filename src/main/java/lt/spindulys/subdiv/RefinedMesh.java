package lt.spindulys.subdiv;

import java.util.Arrays;

/**
 * One level of a subdivided mesh: positions, faces (after the first level quads, or triangles
 * with the Loop scheme), which faces are holes, face-varying UVs, and, on request, limit
 * positions and normals of its vertices. Arrays returned are the mesh's own, not copies (except
 * {@link #edgeVertices()} and {@link #sharpEdges()}, made on each call): a deep level's arrays are
 * the largest the renderer holds, read once by whatever builds from them (the scene's triangles,
 * the OBJ writer, the viewer), and a copy would double the memory they take. Do not modify them.
 *
 * <p><b>Numbering</b> (OpenSubdiv Far's, with {@code orderVerticesFromFacesFirst=false}): the
 * vertices of level L are, in order, the children of the vertices of level L-1 (same indices),
 * one point per face of level L-1 (in face order; none with Loop), and one point per edge of
 * level L-1 (in the order of {@link #edgeVertices()} of level L-1). The faces of level L are the
 * children of the faces of level L-1 in order. Catmull-Clark and bilinear: one per parent corner
 * j; for a quad parent (v0..v3) child j keeps v_j at position j, for other parents child j is
 * (v_j, point of edge j, face point, point of edge j-1). Loop: four per parent triangle (v0, v1,
 * v2) with edge points e0 (of v0-v1), e1, e2: (v0,e0,e2), (e0,v1,e1), (e2,e1,v2), (e1,e2,e0).
 */
public final class RefinedMesh {
    private final ControlMesh control;
    private final int level;
    final Level topo;
    private final double[] positions;
    private final FaceVarying.Channel uv;
    private int[] faceSizes;
    private double[] limitPositions, limitNormals;

    private RefinedMesh(ControlMesh control, int level, Level topo, double[] positions, FaceVarying.Channel uv) {
        this.control = control;
        this.level = level;
        this.topo = topo;
        this.positions = positions;
        this.uv = uv;
    }

    /** Level 0: the control mesh itself. */
    static RefinedMesh base(ControlMesh m) {
        return new RefinedMesh(m, 0, m.base, m.positions(), m.uvChannel);
    }

    /**
     * Frees memory the last level does not need until it is refined again or asked for its
     * edges: see {@link Level#dropEdgeCodes}.
     */
    void compactAfter(RefinedMesh parent) {
        topo.dropEdgeCodes(parent.topo);
        if (uv != null) uv.level().dropEdgeCodes(parent.uv.level());
    }

    /**
     * The next level: this mesh refined once.
     *
     * @return the next level
     */
    public RefinedMesh refine() {
        SubdivOptions opt = control.options();
        Level c = Refinement.refine(topo, opt.creasing() == SubdivOptions.Creasing.CHAIKIN, null);
        double[] p = new double[3 * c.nV];
        PrimvarRefiner.interpolate(topo, c, opt, 3, positions, p, false);
        FaceVarying.Channel cuv = uv == null ? null : uv.refine(c, opt);
        return new RefinedMesh(control, level + 1, c, p, cuv);
    }

    /** The same level cut down to other topology and data (a patch's pruned level, see {@link PatchRefiner}). */
    RefinedMesh with(Level topo, double[] positions, FaceVarying.Channel uv) {
        return new RefinedMesh(control, level, topo, positions, uv);
    }

    /** The UV channel, or null. */
    FaceVarying.Channel uvChannel() { return uv; }

    /** {@return the control mesh this level was refined from} */
    public ControlMesh controlMesh() { return control; }

    /** {@return the level: 0 for the control mesh, then 1, 2, ...} */
    public int level() { return level; }

    /** {@return the number of vertices} */
    public int vertexCount() { return topo.nV; }

    /**
     * x, y, z per vertex.
     *
     * @return the positions
     */
    public double[] positions() { return positions; }

    /** {@return the number of faces} */
    public int faceCount() { return topo.nF; }

    /**
     * Corners per face (after level 0 all 4, or all 3 with Loop).
     *
     * @return the face sizes
     */
    public synchronized int[] faceSizes() {
        if (faceSizes == null) {
            if (level == 0) {
                faceSizes = control.faceSizes();
            } else {
                faceSizes = new int[topo.nF];
                Arrays.fill(faceSizes, topo.triangleSplit ? 3 : 4);
            }
        }
        return faceSizes;
    }

    /**
     * Vertex index of every face corner, face after face.
     *
     * @return the corner vertices
     */
    public int[] faceVertices() { return topo.hOrig; }

    /**
     * True if face f is a hole (refined, but not rendered).
     *
     * @param face the face index
     * @return whether it is a hole
     */
    public boolean isHole(int face) { return topo.hole != null && topo.hole[face]; }

    /**
     * True if any face is a hole.
     *
     * @return whether any face is a hole
     */
    public boolean hasHoles() {
        if (topo.hole == null) return false;
        for (boolean b : topo.hole) if (b) return true;
        return false;
    }

    /**
     * (u, v) pairs, or null when the mesh has no UVs.
     *
     * @return the UVs, or null
     */
    public double[] uvs() {
        if (uv == null) return null;
        return level == 0 ? control.uvs() : uv.values();
    }

    /**
     * Index into {@link #uvs()} of every face corner, parallel to {@link #faceVertices()}, or null.
     *
     * @return the indices, or null
     */
    public int[] faceUvs() {
        if (uv == null) return null;
        return level == 0 ? control.faceUvIndices() : uv.level().hOrig;
    }

    /** The UV value mesh of this level, or null (for tests and benchmarks). */
    Level uvTopology() { return uv == null ? null : uv.level(); }

    /**
     * Number of edges (Far's edges: a non-manifold edge counts once per instance).
     *
     * @return the edge count
     */
    public int edgeCount() { return topo.nE; }

    /**
     * The two vertices of every edge, in Far's edge order and vertex order: the point of edge e
     * is vertex {@code vertexCount() + faceCount() + e} of the next level ({@code vertexCount() + e}
     * with Loop, which makes no face points).
     *
     * @return two vertex indices per edge
     */
    public int[] edgeVertices() {
        topo.edgeCodes();
        int[] ev = new int[2 * topo.nE];
        for (int h = 0; h < topo.nH; h++) {
            if (!topo.primary(h)) continue;
            int e = topo.edge(h);
            ev[2 * e] = topo.edgeV0(h);
            ev[2 * e + 1] = topo.edgeV1(h);
        }
        return ev;
    }

    /**
     * For every face corner (in {@link #faceVertices()} order), the corner of the neighbouring face
     * that starts the same edge from the other end, or -1 on a boundary or non-manifold edge.
     *
     * @return one index per corner
     */
    public int[] cornerTwins() { return topo.hTwin; }

    /**
     * For every face corner, whether the edge from it to the face's next corner is infinitely sharp
     * at this level: a boundary or non-manifold edge, or an infinitely sharp crease. The limit
     * surface has a tangent plane on each side of such an edge.
     *
     * @return one flag per corner
     */
    public boolean[] sharpEdges() {
        if (topo.eSharp != null) topo.edgeCodes();
        boolean[] sharp = new boolean[topo.nH];
        for (int h = 0; h < sharp.length; h++) sharp[h] = Crease.isInfinite(topo.edgeSharpness(h));
        return sharp;
    }

    /**
     * Bytes of the refined surface as the renderer holds it: this level's topology, its positions
     * and one limit normal per vertex (counted whether or not normals were asked for yet). UVs
     * are not included.
     *
     * @return the bytes
     */
    public long memoryBytes() {
        return topo.memoryBytes() + 8L * positions.length + 24L * topo.nV;
    }

    /**
     * Limit-surface position of every vertex (x, y, z each), from Sdc's limit masks: exact for
     * smooth, crease and corner vertices; where semi-sharp features have not yet decayed, Far's
     * value (the sharp rule applied as if infinitely sharp). Computed on first use.
     *
     * @return three doubles per vertex
     */
    public synchronized double[] limitPositions() {
        if (limitPositions == null) {
            double[] pos = new double[3 * topo.nV];
            Limit.evaluate(topo, SchemeRules.of(control.options()), positions, pos, null);
            limitPositions = pos;
        }
        return limitPositions;
    }

    /**
     * Unit limit-surface normal of every vertex (x, y, z each), on the side the faces wind
     * counter-clockwise: the cross product of Sdc's two limit tangents (exact for smooth vertices
     * and regular creases and boundaries; Far's tangent conventions at corners and irregular
     * crease spans). Computed on first use.
     *
     * @return three doubles per vertex
     */
    public synchronized double[] limitNormals() {
        if (limitNormals == null) {
            double[] nrm = new double[3 * topo.nV];
            Limit.evaluate(topo, SchemeRules.of(control.options()), positions, null, nrm);
            limitNormals = nrm;
        }
        return limitNormals;
    }
}
