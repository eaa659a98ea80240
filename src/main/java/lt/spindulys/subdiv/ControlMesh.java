package lt.spindulys.subdiv;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The input of subdivision: a polygon mesh (faces of any size) as flat index arrays, optional
 * face-varying UVs, and the sharpness tags OpenSubdiv knows (creases on edges, corners on
 * vertices, holes on faces) with the scheme options. Immutable; made with {@link #builder}.
 * Sharpness is kept as {@code float}, as OpenSubdiv stores it, so semi-sharp results match it
 * bit for bit; 10 and above is infinitely sharp.
 *
 * <p>TEMPORARY body for the renderer branch: simple storage, replaced by the core's version.
 */
public final class ControlMesh {
    /** Sharpness at or above which an edge or vertex is infinitely sharp. */
    public static final float INFINITELY_SHARP = 10f;

    final double[] positions;
    final int[] faceSizes, faceVertices;
    final double[] uvs;
    final int[] faceUvs;
    /** Edge key (see {@link #edgeKey}) to sharpness. */
    final Map<Long, Float> creases;
    final float[] corners;
    final boolean[] holes;
    final SubdivOptions options;
    final String source;

    ControlMesh(Builder b) {
        positions = b.positions;
        faceSizes = b.faceSizes;
        faceVertices = b.faceVertices;
        uvs = b.uvs;
        faceUvs = b.faceUvs;
        creases = new HashMap<>(b.creases);
        int n = positions.length / 3;
        corners = new float[n];
        for (int[] c : b.cornerList) corners[c[0]] = Float.intBitsToFloat(c[1]);
        holes = new boolean[faceSizes.length];
        for (int h : b.holeList) holes[h] = true;
        options = b.options;
        source = b.source;
    }

    static long edgeKey(int a, int b) {
        return ((long) Math.min(a, b) << 32) | Math.max(a, b);
    }

    /**
     * Starts a mesh from positions (x, y, z per vertex), face sizes and the vertex index of every
     * face corner (face after face).
     */
    public static Builder builder(double[] positions, int[] faceSizes, int[] faceVertices) {
        return new Builder(positions, faceSizes, faceVertices);
    }

    /** Collects UVs, tags and options; {@link #build()} validates and names the face or vertex at fault. */
    public static final class Builder {
        private final double[] positions;
        private final int[] faceSizes, faceVertices;
        private double[] uvs;
        private int[] faceUvs;
        private final Map<Long, Float> creases = new HashMap<>();
        private final List<int[]> cornerList = new ArrayList<>();
        private final List<Integer> holeList = new ArrayList<>();
        private SubdivOptions options = SubdivOptions.DEFAULT;
        private String source;

        Builder(double[] positions, int[] faceSizes, int[] faceVertices) {
            this.positions = positions;
            this.faceSizes = faceSizes;
            this.faceVertices = faceVertices;
        }

        /** Face-varying texture coordinates: (u, v) pairs and one index into them per face corner. */
        public Builder uvs(double[] uvs, int[] faceUvIndices) {
            this.uvs = uvs;
            this.faceUvs = faceUvIndices;
            return this;
        }

        /** A crease on the edge between vertices a and b. */
        public Builder crease(int a, int b, float sharpness) {
            creases.put(edgeKey(a, b), sharpness);
            return this;
        }

        public Builder corner(int vertex, float sharpness) {
            cornerList.add(new int[] {vertex, Float.floatToIntBits(sharpness)});
            return this;
        }

        public Builder hole(int face) {
            holeList.add(face);
            return this;
        }

        public Builder options(SubdivOptions options) {
            this.options = options;
            return this;
        }

        /** A name for error messages, such as the file the mesh came from. */
        public Builder source(String name) {
            this.source = name;
            return this;
        }

        /** Validates and freezes; throws IllegalArgumentException naming the face or vertex at fault. */
        public ControlMesh build() {
            String w = source == null ? "" : source + ": ";
            int n = positions.length / 3;
            int corner = 0;
            for (int f = 0; f < faceSizes.length; f++) {
                if (faceSizes[f] < 3) throw new IllegalArgumentException(w + "face " + f + " has fewer than 3 vertices");
                for (int j = 0; j < faceSizes[f]; j++, corner++) {
                    int v = faceVertices[corner];
                    if (v < 0 || v >= n) throw new IllegalArgumentException(w + "face " + f + " uses vertex " + v + ", which does not exist");
                }
            }
            if (corner != faceVertices.length) throw new IllegalArgumentException(w + "face sizes do not match the corners");
            if (faceUvs != null && faceUvs.length != faceVertices.length) throw new IllegalArgumentException(w + "one UV index per corner is needed");
            for (int[] c : cornerList) if (c[0] < 0 || c[0] >= n) throw new IllegalArgumentException(w + "corner vertex " + c[0] + " does not exist");
            for (int h : holeList) if (h < 0 || h >= faceSizes.length) throw new IllegalArgumentException(w + "hole face " + h + " does not exist");
            return new ControlMesh(this);
        }
    }
}
