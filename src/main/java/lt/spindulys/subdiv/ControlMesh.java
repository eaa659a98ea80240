package lt.spindulys.subdiv;

/**
 * The input of subdivision: a polygon mesh (faces of any size) as flat index arrays, optional
 * face-varying UVs, and the sharpness tags OpenSubdiv knows (creases on edges, corners on
 * vertices, holes on faces) with the scheme options. Immutable; made with {@link #builder}.
 * Sharpness is kept as {@code float}, as OpenSubdiv stores it, so semi-sharp results match it
 * bit for bit; 10 and above is infinitely sharp.
 */
public final class ControlMesh {
    /** Sharpness at or above which an edge or vertex is infinitely sharp. */
    public static final float INFINITELY_SHARP = 10f;

    ControlMesh() { throw new UnsupportedOperationException("TODO"); }

    /**
     * Starts a mesh from positions (x, y, z per vertex), face sizes and the vertex index of every
     * face corner (face after face).
     */
    public static Builder builder(double[] positions, int[] faceSizes, int[] faceVertices) {
        throw new UnsupportedOperationException("TODO");
    }

    /** Collects UVs, tags and options; {@link #build()} validates and names the face or vertex at fault. */
    public static final class Builder {
        /** Face-varying texture coordinates: (u, v) pairs and one index into them per face corner. */
        public Builder uvs(double[] uvs, int[] faceUvIndices) { throw new UnsupportedOperationException("TODO"); }
        /** A crease on the edge between vertices a and b. */
        public Builder crease(int a, int b, float sharpness) { throw new UnsupportedOperationException("TODO"); }
        public Builder corner(int vertex, float sharpness) { throw new UnsupportedOperationException("TODO"); }
        public Builder hole(int face) { throw new UnsupportedOperationException("TODO"); }
        public Builder options(SubdivOptions options) { throw new UnsupportedOperationException("TODO"); }
        /** A name for error messages, such as the file the mesh came from. */
        public Builder source(String name) { throw new UnsupportedOperationException("TODO"); }
        /** Validates and freezes; throws IllegalArgumentException naming the face or vertex at fault. */
        public ControlMesh build() { throw new UnsupportedOperationException("TODO"); }
    }
}
