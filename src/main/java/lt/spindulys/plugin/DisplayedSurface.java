package lt.spindulys.plugin;

import java.util.Objects;

import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * One surface a host displays: its control mesh and the subdivision the host applied to it.
 *
 * <p>The control mesh is built with {@link ControlMesh#builder(double[], int[], int[])}: vertex
 * positions (x, y, z per vertex), the number of corners of each face (3 or more, any mix) and the
 * 0-based vertex index of every face corner, faces one after another, counter-clockwise seen from
 * outside; then, where the host has them, texture coordinates with their own indices per face
 * corner ({@code uvs}: face-varying, so seams are kept), creases and corners with a sharpness
 * (0 smooth, {@link ControlMesh#INFINITELY_SHARP} and above infinitely sharp), holes, and the
 * scheme and its options (Catmull-Clark, Loop or bilinear; boundary rule, uv interpolation,
 * creasing) in {@code options}; a subdivided surface's {@link Scheme} is its options' scheme.
 * {@code build()} checks the mesh and names the face or vertex at fault; give the surface's name as
 * its {@code source} so messages name it.
 *
 * <pre>{@code
 * ControlMesh cage = ControlMesh.builder(positions, faceSizes, faceVertices)
 *         .crease(0, 1, ControlMesh.INFINITELY_SHARP)
 *         .options(SubdivOptions.DEFAULT.withBoundary(SubdivOptions.Boundary.EDGE_AND_CORNER))
 *         .source("cube")
 *         .build();
 * DisplayedSurface s = new DisplayedSurface("cube", cage, DisplayedSurface.Scheme.CATMULL_CLARK, 3,
 *         DisplayedSurface.Shading.SMOOTH);
 * }</pre>
 *
 * @param name    the name a user knows the surface by (a file name, for example); not blank
 * @param control the control mesh as the host holds it, before the host's subdivision
 * @param scheme  the subdivision the host applied: NONE, or the control mesh's own scheme
 * @param level   how many times the host subdivided it, 0 to 8 (0 for {@link Scheme#NONE})
 * @param shading how the host shades it: a plugin that makes a picture shades it alike unless told otherwise
 */
public record DisplayedSurface(String name, ControlMesh control, Scheme scheme, int level, Shading shading) {
    /** The most levels a host may report; {@code SubdivisionSurface.MAX_LEVEL}. */
    public static final int MAX_LEVEL = 8;

    /** The subdivision the host applies to the control mesh before showing it. */
    public enum Scheme {
        /** None: the host shows the control mesh itself, as a polyhedron. */
        NONE,
        /** Catmull-Clark subdivision (OpenSubdiv's {@code catmark}), with the control mesh's options. */
        CATMULL_CLARK,
        /** Loop subdivision (OpenSubdiv's {@code loop}; the control mesh is all triangles), with its options. */
        LOOP,
        /** Bilinear subdivision (OpenSubdiv's {@code bilinear}): faces split in their own plane. */
        BILINEAR;

        /**
         * The scheme a host applies when it subdivides a control mesh with {@code s}, its options' scheme.
         *
         * @param s the control mesh's scheme
         * @return CATMULL_CLARK, LOOP or BILINEAR
         */
        public static Scheme of(SubdivOptions.Scheme s) {
            return switch (s) {
                case CATMARK -> CATMULL_CLARK;
                case LOOP -> LOOP;
                case BILINEAR -> BILINEAR;
            };
        }

        /** {@return the name legends use: "Catmull-Clark", "Loop", "bilinear" (null for NONE)} */
        public String label() {
            return switch (this) {
                case NONE -> null;
                case CATMULL_CLARK -> "Catmull-Clark";
                case LOOP -> "Loop";
                case BILINEAR -> "bilinear";
            };
        }
    }

    /** How the host shades the surface it shows. */
    public enum Shading {
        /** Smooth: normals interpolated across the faces (the limit surface's, where the host has them). */
        SMOOTH,
        /** Flat facets: each face with its own normal, as a polyhedron. */
        FLAT
    }

    /**
     * A surface shaded as hosts usually show it: flat facets for the control mesh itself
     * ({@link Scheme#NONE}), smooth when subdivided.
     *
     * @param name    the name a user knows the surface by
     * @param control the control mesh
     * @param scheme  the subdivision the host applied
     * @param level   how many times the host subdivided it
     */
    public DisplayedSurface(String name, ControlMesh control, Scheme scheme, int level) {
        this(name, control, scheme, level, scheme == Scheme.NONE ? Shading.FLAT : Shading.SMOOTH);
    }

    /**
     * Checks the name, the level and the scheme.
     *
     * @throws IllegalArgumentException if the name is blank, or the level is outside 0..8 (or not 0
     *         with no subdivision), or the scheme is not the control mesh's ({@link Scheme#of}) nor NONE
     */
    public DisplayedSurface {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(control, "control");
        Objects.requireNonNull(scheme, "scheme");
        Objects.requireNonNull(shading, "shading");
        if (name.isBlank()) throw new IllegalArgumentException("a displayed surface needs a name");
        if (level < 0 || level > MAX_LEVEL) {
            throw new IllegalArgumentException("surface " + name + ": subdivision level must be between 0 and " + MAX_LEVEL + ", found " + level);
        }
        if (scheme == Scheme.NONE && level != 0) {
            throw new IllegalArgumentException("surface " + name + ": level " + level + " given without a subdivision scheme (use level 0)");
        }
        // The refinement a plugin makes follows the control mesh's options: a scheme beside them that
        // says otherwise would be a picture of another surface than the host's.
        if (scheme != Scheme.NONE && scheme != Scheme.of(control.options().scheme())) {
            throw new IllegalArgumentException("surface " + name + ": scheme " + scheme + " given, but its control mesh's options say "
                    + control.options().scheme().keyword() + " (set the scheme in the options, SubdivOptions.withScheme)");
        }
    }

    /**
     * How the host describes what it did, for legends: "Catmull-Clark, level 3", "Loop, level 2" or "control mesh".
     *
     * @return a short phrase
     */
    public String subdivisionLabel() {
        return scheme == Scheme.NONE ? "control mesh" : scheme.label() + ", level " + level;
    }
}
