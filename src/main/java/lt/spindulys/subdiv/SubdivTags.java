package lt.spindulys.subdiv;

import java.util.List;
import java.util.Objects;

/**
 * The sharpness tags and scheme options a mesh file gives for subdivision, as OpenSubdiv's
 * {@code t} lines in an OBJ file state them, ready to be applied to a {@link ControlMesh.Builder}.
 * Indices are 0-based and have been checked against the mesh they came with. Arrays are not
 * copied; do not change them.
 *
 * @param creases         vertex pairs (a0, b0, a1, b1, ...), one pair per creased edge
 * @param creaseSharpness sharpness of each pair ({@link ControlMesh#INFINITELY_SHARP} and above: infinitely sharp)
 * @param corners         vertex indices of the sharp corners
 * @param cornerSharpness sharpness of each corner
 * @param holes           indices of the faces that are holes
 * @param options         the scheme options ({@link SubdivOptions#DEFAULT} changed by the tags)
 * @param ignored         names of tags that were read but have no effect (OpenSubdiv's Far ignores
 *                        them too: the hierarchical edits and facevaryingpropagatecorners)
 */
public record SubdivTags(int[] creases, float[] creaseSharpness, int[] corners, float[] cornerSharpness,
                         int[] holes, SubdivOptions options, List<String> ignored) {
    /** No tags and the default options. */
    public static final SubdivTags NONE = new SubdivTags(new int[0], new float[0], new int[0], new float[0], new int[0],
            SubdivOptions.DEFAULT, List.of());

    /**
     * Checks that the arrays pair up and copies the list of ignored tags.
     *
     * @param creases vertex pairs, one per creased edge
     * @param creaseSharpness sharpness per pair
     * @param corners vertex indices of the corners
     * @param cornerSharpness sharpness per corner
     * @param holes face indices of the holes
     * @param options the scheme options
     * @param ignored names of tags read without effect
     * @throws IllegalArgumentException if the sharpness arrays do not match the index arrays
     */
    public SubdivTags {
        Objects.requireNonNull(options, "options");
        ignored = List.copyOf(ignored);
        if (creases.length != 2 * creaseSharpness.length) {
            throw new IllegalArgumentException("creases need one sharpness per vertex pair: " + creases.length + " indices, "
                    + creaseSharpness.length + " sharpness values");
        }
        if (corners.length != cornerSharpness.length) {
            throw new IllegalArgumentException("corners need one sharpness each: " + corners.length + " corners, "
                    + cornerSharpness.length + " sharpness values");
        }
    }

    /**
     * The same tags with other options (the scene's keys override the file's).
     *
     * @param o the options
     * @return the tags
     */
    public SubdivTags withOptions(SubdivOptions o) {
        return new SubdivTags(creases, creaseSharpness, corners, cornerSharpness, holes, o, ignored);
    }

    /**
     * Number of creased edges.
     *
     * @return the count
     */
    public int creaseCount() { return creaseSharpness.length; }

    /**
     * Gives the builder every crease, corner and hole, and the options.
     *
     * @param b the builder
     * @return {@code b}
     */
    public ControlMesh.Builder applyTo(ControlMesh.Builder b) {
        for (int i = 0; i < creaseSharpness.length; i++) b.crease(creases[2 * i], creases[2 * i + 1], creaseSharpness[i]);
        for (int i = 0; i < corners.length; i++) b.corner(corners[i], cornerSharpness[i]);
        for (int h : holes) b.hole(h);
        return b.options(options);
    }
}
