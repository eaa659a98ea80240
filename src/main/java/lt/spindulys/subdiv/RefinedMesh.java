package lt.spindulys.subdiv;

/**
 * One level of a subdivided mesh: positions, faces (quads after the first level), which faces
 * are holes, face-varying UVs, and, on request, limit positions and normals of its vertices.
 * Arrays returned are the mesh's own; do not modify them.
 *
 * <p>TEMPORARY body for the renderer branch: limit positions are the positions and limit normals
 * area-weighted face normals; replaced by the core's version.
 */
public final class RefinedMesh {
    private final int level;
    private final double[] positions;
    private final int[] faceSizes, faceVertices;
    private final boolean[] holes;
    private final double[] uvs;
    private final int[] faceUvs;
    private double[] normals;

    RefinedMesh(int level, double[] positions, int[] faceSizes, int[] faceVertices, boolean[] holes, double[] uvs, int[] faceUvs) {
        this.level = level;
        this.positions = positions;
        this.faceSizes = faceSizes;
        this.faceVertices = faceVertices;
        this.holes = holes;
        this.uvs = uvs;
        this.faceUvs = faceUvs;
    }

    public int level() { return level; }
    public int vertexCount() { return positions.length / 3; }
    /** x, y, z per vertex. */
    public double[] positions() { return positions; }
    public int faceCount() { return faceSizes.length; }
    /** Corners per face (all 4 after level 0). */
    public int[] faceSizes() { return faceSizes; }
    /** Vertex index of every face corner, face after face. */
    public int[] faceVertices() { return faceVertices; }
    /** True if face f is a hole (refined, but not rendered). */
    public boolean isHole(int face) { return holes[face]; }
    /** (u, v) pairs, or null when the mesh has no UVs. */
    public double[] uvs() { return uvs; }
    /** Index into {@link #uvs()} of every face corner, parallel to {@link #faceVertices()}, or null. */
    public int[] faceUvs() { return faceUvs; }
    /** Limit-surface position of every vertex (x, y, z each). */
    public double[] limitPositions() { return positions; }

    /** Unit limit-surface normal of every vertex (x, y, z each), on the side the faces wind counter-clockwise. */
    public synchronized double[] limitNormals() {
        if (normals != null) return normals;
        double[] n = new double[positions.length];
        int c = 0;
        for (int f = 0; f < faceSizes.length; f++) {
            int s = faceSizes[f];
            for (int j = 0; j < s; j++) {
                int p = 3 * faceVertices[c + (j + s - 1) % s], q = 3 * faceVertices[c + j], r = 3 * faceVertices[c + (j + 1) % s];
                double ux = positions[r] - positions[q], uy = positions[r + 1] - positions[q + 1], uz = positions[r + 2] - positions[q + 2];
                double vx = positions[p] - positions[q], vy = positions[p + 1] - positions[q + 1], vz = positions[p + 2] - positions[q + 2];
                n[q] += uy * vz - uz * vy;
                n[q + 1] += uz * vx - ux * vz;
                n[q + 2] += ux * vy - uy * vx;
            }
            c += s;
        }
        for (int i = 0; i < n.length; i += 3) {
            double l = Math.sqrt(n[i] * n[i] + n[i + 1] * n[i + 1] + n[i + 2] * n[i + 2]);
            if (l > 0) { n[i] /= l; n[i + 1] /= l; n[i + 2] /= l; }
        }
        return normals = n;
    }
}
