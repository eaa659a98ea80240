package lt.spindulys.subdiv;

/**
 * The subdivision scheme and its options, named after OpenSubdiv's Sdc scheme type and options.
 *
 * @param scheme    the refinement scheme: Catmull-Clark, Loop or bilinear
 * @param boundary  how boundary vertices and edges are treated
 * @param fvar      how face-varying data (UVs) is interpolated
 * @param creasing  how semi-sharp crease sharpness decays from level to level
 * @param triangles the weights used at triangles
 */
public record SubdivOptions(Scheme scheme, Boundary boundary, FaceVarying fvar, Creasing creasing, Triangles triangles) {
    /** Catmull-Clark with OpenSubdiv's defaults: EDGE_ONLY boundaries, linear-all UVs (FVAR_LINEAR_ALL), uniform creasing, Catmark triangles. */
    public static final SubdivOptions DEFAULT = new SubdivOptions(Scheme.CATMARK, Boundary.EDGE_ONLY, FaceVarying.ALL, Creasing.UNIFORM, Triangles.CATMARK);

    /** Sdc SchemeType: the three schemes OpenSubdiv has. */
    public enum Scheme {
        /** Catmull-Clark: any polygon splits into quads; smooth limit surface (the default). */
        CATMARK,
        /** Loop: triangles only, each split into four; smooth limit surface. */
        LOOP,
        /** Bilinear: any polygon splits into quads linearly; the limit is the piecewise bilinear cage. */
        BILINEAR;

        /** {@return the lower-case name used in scene files, OBJ tags and on the command line} */
        public String keyword() { return name().toLowerCase(java.util.Locale.ROOT); }

        /**
         * The scheme of a keyword ({@code catmark}, {@code loop} or {@code bilinear}).
         *
         * @param word the keyword
         * @return the scheme, or null if the word names none
         */
        public static Scheme ofKeyword(String word) {
            for (Scheme s : values()) if (s.keyword().equals(word)) return s;
            return null;
        }
    }

    /** Sdc VtxBoundaryInterpolation. */
    public enum Boundary {
        /** Boundary edges are not interpolated: the faces along the boundary do not reach it. */
        NONE,
        /** Boundary edges are infinitely sharp, so the surface reaches them; corners stay smooth. */
        EDGE_ONLY,
        /** Boundary edges and corner vertices (one face) are infinitely sharp. */
        EDGE_AND_CORNER
    }

    /** Sdc FVarLinearInterpolation. */
    public enum FaceVarying {
        /** UVs smooth everywhere, their boundaries interpolated like boundary edges ("edge only"). */
        NONE,
        /** UVs smooth but pinned at their corners. */
        CORNERS_ONLY,
        /** As {@link #CORNERS_ONLY}, also pinned where three or more UV regions meet. */
        CORNERS_PLUS1,
        /** As {@link #CORNERS_PLUS1}, also pinned at concave UV corners. */
        CORNERS_PLUS2,
        /** UVs linear along their boundaries (seams), smooth inside. */
        BOUNDARIES,
        /** UVs linear everywhere: each face's UVs are interpolated bilinearly (the default). */
        ALL
    }

    /** Sdc CreasingMethod. */
    public enum Creasing {
        /** A semi-sharp edge's sharpness drops by 1 at every level. */
        UNIFORM,
        /** Chaikin's rule: a crease's sharpness is averaged with its neighbours' along the crease. */
        CHAIKIN
    }

    /** Sdc TriangleSubdivision: Catmull-Clark's weights at triangles (the other schemes ignore it). */
    public enum Triangles {
        /** Catmull-Clark's own weights at triangles. */
        CATMARK,
        /** Modified weights that give triangles a smoother limit surface. */
        SMOOTH
    }

    /**
     * Catmull-Clark options (the scheme most meshes use).
     *
     * @param boundary how boundaries are treated
     * @param fvar how UVs are interpolated
     * @param creasing how crease sharpness decays
     * @param triangles the weights at triangles
     */
    public SubdivOptions(Boundary boundary, FaceVarying fvar, Creasing creasing, Triangles triangles) {
        this(Scheme.CATMARK, boundary, fvar, creasing, triangles);
    }

    /**
     * Checks that every option is given.
     *
     * @param scheme the refinement scheme
     * @param boundary how boundaries are treated
     * @param fvar how UVs are interpolated
     * @param creasing how crease sharpness decays
     * @param triangles the weights at triangles
     * @throws NullPointerException if one is null
     */
    public SubdivOptions {
        java.util.Objects.requireNonNull(scheme);
        java.util.Objects.requireNonNull(boundary);
        java.util.Objects.requireNonNull(fvar);
        java.util.Objects.requireNonNull(creasing);
        java.util.Objects.requireNonNull(triangles);
    }

    /**
     * A copy with another scheme.
     *
     * @param s the scheme
     * @return the options
     */
    public SubdivOptions withScheme(Scheme s) { return new SubdivOptions(s, boundary, fvar, creasing, triangles); }

    /**
     * A copy with other boundary rules.
     *
     * @param b the rules
     * @return the options
     */
    public SubdivOptions withBoundary(Boundary b) { return new SubdivOptions(scheme, b, fvar, creasing, triangles); }
    /**
     * A copy with another UV interpolation.
     *
     * @param f the interpolation
     * @return the options
     */
    public SubdivOptions withFaceVarying(FaceVarying f) { return new SubdivOptions(scheme, boundary, f, creasing, triangles); }
    /**
     * A copy with another creasing method.
     *
     * @param c the method
     * @return the options
     */
    public SubdivOptions withCreasing(Creasing c) { return new SubdivOptions(scheme, boundary, fvar, c, triangles); }
    /**
     * A copy with other triangle weights.
     *
     * @param t the weights
     * @return the options
     */
    public SubdivOptions withTriangles(Triangles t) { return new SubdivOptions(scheme, boundary, fvar, creasing, t); }
}
