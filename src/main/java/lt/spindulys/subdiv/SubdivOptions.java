package lt.spindulys.subdiv;

/**
 * Catmull-Clark options, named after OpenSubdiv's Sdc options they reproduce.
 *
 * @param boundary  how boundary vertices and edges are treated
 * @param fvar      how face-varying data (UVs) is interpolated
 * @param creasing  how semi-sharp crease sharpness decays from level to level
 * @param triangles the weights used at triangles
 */
public record SubdivOptions(Boundary boundary, FaceVarying fvar, Creasing creasing, Triangles triangles) {
    /** OpenSubdiv's defaults: EDGE_ONLY boundaries, linear-all UVs (FVAR_LINEAR_ALL), uniform creasing, Catmark triangles. */
    public static final SubdivOptions DEFAULT = new SubdivOptions(Boundary.EDGE_ONLY, FaceVarying.ALL, Creasing.UNIFORM, Triangles.CATMARK);

    /** Sdc VtxBoundaryInterpolation. */
    public enum Boundary { NONE, EDGE_ONLY, EDGE_AND_CORNER }

    /** Sdc FVarLinearInterpolation. */
    public enum FaceVarying { NONE, CORNERS_ONLY, CORNERS_PLUS1, CORNERS_PLUS2, BOUNDARIES, ALL }

    /** Sdc CreasingMethod. */
    public enum Creasing { UNIFORM, CHAIKIN }

    /** Sdc TriangleSubdivision. */
    public enum Triangles { CATMARK, SMOOTH }

    public SubdivOptions {
        java.util.Objects.requireNonNull(boundary);
        java.util.Objects.requireNonNull(fvar);
        java.util.Objects.requireNonNull(creasing);
        java.util.Objects.requireNonNull(triangles);
    }

    public SubdivOptions withBoundary(Boundary b) { return new SubdivOptions(b, fvar, creasing, triangles); }
    public SubdivOptions withFaceVarying(FaceVarying f) { return new SubdivOptions(boundary, f, creasing, triangles); }
    public SubdivOptions withCreasing(Creasing c) { return new SubdivOptions(boundary, fvar, c, triangles); }
    public SubdivOptions withTriangles(Triangles t) { return new SubdivOptions(boundary, fvar, creasing, t); }
}
