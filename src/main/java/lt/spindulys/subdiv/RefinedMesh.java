package lt.spindulys.subdiv;

/**
 * One level of a subdivided mesh: positions, faces (quads after the first level), which faces
 * are holes, face-varying UVs, and, on request, limit positions and normals of its vertices.
 * Arrays returned are the mesh's own; do not modify them.
 */
public final class RefinedMesh {
    RefinedMesh() { throw new UnsupportedOperationException("TODO"); }

    public int level() { throw new UnsupportedOperationException("TODO"); }
    public int vertexCount() { throw new UnsupportedOperationException("TODO"); }
    /** x, y, z per vertex. */
    public double[] positions() { throw new UnsupportedOperationException("TODO"); }
    public int faceCount() { throw new UnsupportedOperationException("TODO"); }
    /** Corners per face (all 4 after level 0). */
    public int[] faceSizes() { throw new UnsupportedOperationException("TODO"); }
    /** Vertex index of every face corner, face after face. */
    public int[] faceVertices() { throw new UnsupportedOperationException("TODO"); }
    /** True if face f is a hole (refined, but not rendered). */
    public boolean isHole(int face) { throw new UnsupportedOperationException("TODO"); }
    /** (u, v) pairs, or null when the mesh has no UVs. */
    public double[] uvs() { throw new UnsupportedOperationException("TODO"); }
    /** Index into {@link #uvs()} of every face corner, parallel to {@link #faceVertices()}, or null. */
    public int[] faceUvs() { throw new UnsupportedOperationException("TODO"); }
    /** Limit-surface position of every vertex (x, y, z each). */
    public double[] limitPositions() { throw new UnsupportedOperationException("TODO"); }
    /** Unit limit-surface normal of every vertex (x, y, z each), on the side the faces wind counter-clockwise. */
    public double[] limitNormals() { throw new UnsupportedOperationException("TODO"); }
}
