package lt.spindulys.mesh;

/**
 * A polygon mesh as flat arrays, as read from a file: positions, optional normals and texture
 * coordinates, faces of any size, and optional face groups. Face f has {@code faceSizes[f]}
 * corners starting at {@code faceStarts[f]} in the per-corner index arrays. Immutable by
 * convention (arrays are not copied; do not change them after construction).
 *
 * <p>Face groups are the OBJ file's {@code usemtl} runs: {@code faceGroups[f]} is the index of
 * face f's group in {@code groupNames}, or -1 for a face before any {@code usemtl}. A scene gives
 * each group a material; the mesh itself only carries the names.
 *
 * @param positions   x, y, z per vertex
 * @param normals     x, y, z per normal, or null
 * @param uvs         u, v per texture coordinate, or null
 * @param faceSizes   corners per face
 * @param vertexIndex position index per face corner
 * @param normalIndex normal index per face corner, or null; -1 where a corner has none
 * @param uvIndex     texture coordinate index per face corner, or null; -1 where a corner has none
 * @param source      where the mesh came from, for messages (a file name), or null
 * @param faceGroups  group index per face (-1: none), or null when no face has a group
 * @param groupNames  the groups' names, by index; null exactly when {@code faceGroups} is
 */
public record MeshData(double[] positions, double[] normals, double[] uvs,
                       int[] faceSizes, int[] vertexIndex, int[] normalIndex, int[] uvIndex, String source,
                       int[] faceGroups, String[] groupNames) {
    /**
     * A mesh without face groups.
     *
     * @param positions   x, y, z per vertex
     * @param normals     x, y, z per normal, or null
     * @param uvs         u, v per texture coordinate, or null
     * @param faceSizes   corners per face
     * @param vertexIndex position index per face corner
     * @param normalIndex normal index per face corner, or null
     * @param uvIndex     texture coordinate index per face corner, or null
     * @param source      where the mesh came from, or null
     */
    public MeshData(double[] positions, double[] normals, double[] uvs,
                    int[] faceSizes, int[] vertexIndex, int[] normalIndex, int[] uvIndex, String source) {
        this(positions, normals, uvs, faceSizes, vertexIndex, normalIndex, uvIndex, source, null, null);
    }

    /** The most face groups a mesh may have: a rendered triangle keeps its group in a short. */
    public static final int MAX_GROUPS = Short.MAX_VALUE;

    /** {@return the number of positions} */
    public int vertexCount() { return positions.length / 3; }
    /** {@return the number of faces} */
    public int faceCount() { return faceSizes.length; }

    /**
     * The same mesh with other face groups (the arrays are shared, not copied).
     *
     * @param groups group index per face (-1: none), or null for none
     * @param names  the groups' names, or null with {@code groups} null
     * @return the mesh
     */
    public MeshData withGroups(int[] groups, String[] names) {
        return new MeshData(positions, normals, uvs, faceSizes, vertexIndex, normalIndex, uvIndex, source, groups, names);
    }
}
