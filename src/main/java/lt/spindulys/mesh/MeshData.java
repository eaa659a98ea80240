package lt.spindulys.mesh;

/**
 * A polygon mesh as flat arrays, as read from a file: positions, optional normals and texture
 * coordinates, and faces of any size. Face f has {@code faceSizes[f]} corners starting at
 * {@code faceStarts[f]} in the per-corner index arrays. Immutable by convention (arrays are not
 * copied; do not change them after construction).
 *
 * @param positions   x, y, z per vertex
 * @param normals     x, y, z per normal, or null
 * @param uvs         u, v per texture coordinate, or null
 * @param faceSizes   corners per face
 * @param vertexIndex position index per face corner
 * @param normalIndex normal index per face corner, or null; -1 where a corner has none
 * @param uvIndex     texture coordinate index per face corner, or null; -1 where a corner has none
 * @param source      where the mesh came from, for messages (a file name), or null
 */
public record MeshData(double[] positions, double[] normals, double[] uvs,
                       int[] faceSizes, int[] vertexIndex, int[] normalIndex, int[] uvIndex, String source) {
    /** {@return the number of positions} */
    public int vertexCount() { return positions.length / 3; }
    /** {@return the number of faces} */
    public int faceCount() { return faceSizes.length; }
}
