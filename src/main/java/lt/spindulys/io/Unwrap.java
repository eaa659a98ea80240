package lt.spindulys.io;

import java.util.Objects;

import lt.spindulys.subdiv.SubdivInput;

/**
 * Texture coordinates read from a Workframe {@code .tex} unwrap (see {@link WorkframeReader#readTex}),
 * in either of its two forms:
 * <ul>
 *   <li><b>points and faces</b> (the thesis's form, {@link #hasOwnFaces()}): texture points
 *       {@link #uvs()} and, per face corner of the mesh, the point it uses ({@link #uvIndex()}).
 *       This is OpenSubdiv's face-varying data as it is: corners that share a point share a
 *       value, and a point used on both sides of an edge makes that edge seamless.</li>
 *   <li><b>one point per corner</b>: {@link #uvs()} holds one (u, v) per face corner, face after
 *       face, and {@link #uvIndex()} is null. Corners of one mesh vertex with exactly the same
 *       (u, v) are welded into one value when applied ({@link SubdivInput#withCornerUvs}).</li>
 * </ul>
 * The arrays are handed out as they are, not copied: do not change them.
 *
 * @param uvs (u, v) pairs: the texture points, or one pair per face corner
 * @param uvIndex per face corner, the index of its pair in {@code uvs}; null for one point per corner
 */
public record Unwrap(double[] uvs, int[] uvIndex) {
    /**
     * Checks the arrays agree: pairs, and indices within them.
     *
     * @param uvs (u, v) pairs
     * @param uvIndex an index per face corner, or null
     * @throws IllegalArgumentException if {@code uvs} has an odd length or an index is out of range
     */
    public Unwrap {
        Objects.requireNonNull(uvs, "uvs");
        if (uvs.length % 2 != 0) throw new IllegalArgumentException("UVs hold " + uvs.length + " numbers, not (u, v) pairs");
        if (uvIndex != null) {
            for (int c = 0; c < uvIndex.length; c++) {
                if (uvIndex[c] < 0 || uvIndex[c] >= uvs.length / 2) {
                    throw new IllegalArgumentException("corner " + c + " uses texture point " + uvIndex[c] + ", but there are " + uvs.length / 2);
                }
            }
        }
    }

    /** {@return true for the points-and-faces form (its own face-varying topology), false for one point per corner} */
    public boolean hasOwnFaces() { return uvIndex != null; }

    /** {@return the number of face corners the unwrap covers} */
    public int cornerCount() { return uvIndex != null ? uvIndex.length : uvs.length / 2; }

    /**
     * The (u, v) of every face corner, face after face: the points-and-faces form expanded (its
     * sharing is lost), or the per-corner form's own array.
     *
     * @return two doubles per face corner
     */
    public double[] cornerUvs() {
        if (uvIndex == null) return uvs;
        double[] out = new double[2 * uvIndex.length];
        for (int c = 0; c < uvIndex.length; c++) {
            out[2 * c] = uvs[2 * uvIndex[c]];
            out[2 * c + 1] = uvs[2 * uvIndex[c] + 1];
        }
        return out;
    }

    /**
     * {@code input} with these texture coordinates as its face-varying UVs (replacing any it had):
     * the points and their per-corner indices as they are ({@link SubdivInput#withUvs}), or the
     * per-corner pairs welded per vertex ({@link SubdivInput#withCornerUvs}).
     *
     * @param input the control mesh the unwrap was read for
     * @return the input with UVs
     * @throws IllegalArgumentException if the unwrap does not cover exactly the mesh's face corners
     */
    public SubdivInput applyTo(SubdivInput input) {
        int corners = input.mesh().vertexIndex().length;
        if (cornerCount() != corners) {
            throw new IllegalArgumentException("the unwrap covers " + cornerCount() + " face corners, the mesh has " + corners);
        }
        return uvIndex != null ? input.withUvs(uvs, uvIndex) : input.withCornerUvs(uvs);
    }
}
