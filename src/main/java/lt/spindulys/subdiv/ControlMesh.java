package lt.spindulys.subdiv;

import java.util.Arrays;
import java.util.Objects;

/**
 * The input of subdivision: a polygon mesh (faces of any size) as flat index arrays, optional
 * face-varying UVs, and the sharpness tags OpenSubdiv knows (creases on edges, corners on
 * vertices, holes on faces) with the scheme options. Immutable; made with {@link #builder}.
 * Sharpness is kept as {@code float}, as OpenSubdiv stores it, so semi-sharp results match it
 * bit for bit; 10 and above is infinitely sharp.
 *
 * <p>Topology is accepted wherever OpenSubdiv's Far accepts it, and treated the same way:
 * non-manifold edges (more than two faces, or two faces winding the same way, or an edge used
 * twice by one face), faces that repeat a vertex, unused vertices and vertices where separate
 * fans of faces meet are all allowed; such edges and vertices become infinitely sharp. What is
 * refused (with an {@link IllegalArgumentException} naming the face, vertex or tag) is input
 * that does not describe a mesh: indices out of range, faces with fewer than 3 corners,
 * non-finite coordinates, tags naming missing vertices, edges or faces.
 *
 * <p>The arrays it returns are its own, not copies: a control mesh may hold millions of faces,
 * the level 0 of its refinement shares them ({@link RefinedMesh}), and the scene reads its
 * positions and face groups on every adaptive tessellation. Do not modify them.
 */
public final class ControlMesh {
    /** Sharpness at or above which an edge or vertex is infinitely sharp. */
    public static final float INFINITELY_SHARP = 10f;

    private final double[] positions;
    private final int[] faceSizes, faceVertices;
    private final double[] uvs;
    private final int[] faceUvIndices;
    private final SubdivOptions options;
    private final String source;
    /** Group per face (-1: none) and the groups' names, or both null (see {@link Builder#faceGroups}). */
    private final int[] faceGroups;
    private final String[] groupNames;
    /** The tags as given to the builder, for writing the mesh back out (the level holds them as applied). */
    private final SubdivTags tags;
    /** Level-0 topology with its tags. */
    final Level base;
    /** Level-0 UV value mesh, or null without UVs. */
    final FaceVarying.Channel uvChannel;

    private ControlMesh(Builder b, Level base, FaceVarying.Channel uvChannel) {
        this.positions = b.positions;
        this.faceSizes = b.faceSizes;
        this.faceVertices = b.faceVertices;
        this.uvs = b.uvs;
        this.faceUvIndices = b.faceUvs;
        this.options = b.options;
        this.source = b.source;
        this.faceGroups = b.faceGroups;
        this.groupNames = b.groupNames;
        this.tags = new SubdivTags(Arrays.copyOf(b.creases, 2 * b.creaseCount), Arrays.copyOf(b.creaseSharp, b.creaseCount),
                Arrays.copyOf(b.corners, b.cornerCount), Arrays.copyOf(b.cornerSharp, b.cornerCount),
                Arrays.copyOf(b.holes, b.holeCount), b.options, java.util.List.of());
        this.base = base;
        this.uvChannel = uvChannel;
    }

    /**
     * Starts a mesh from positions (x, y, z per vertex), face sizes and the vertex index of every
     * face corner (face after face). The arrays are copied when the mesh is built.
     *
     * @param positions x, y, z per vertex
     * @param faceSizes corners per face, at least 3 each
     * @param faceVertices vertex index per face corner
     * @return the builder
     */
    public static Builder builder(double[] positions, int[] faceSizes, int[] faceVertices) {
        return new Builder(positions, faceSizes, faceVertices);
    }

    /** {@return the number of vertices} */
    public int vertexCount() { return positions.length / 3; }

    /** {@return the number of faces} */
    public int faceCount() { return faceSizes.length; }

    /**
     * Faces the mesh has after {@code level} uniform refinements with its scheme: its own at level
     * 0, then four times more each level (see {@link #refinedFaceCount(SubdivOptions.Scheme, int, long, int)}).
     * For refusing levels too deep for memory.
     *
     * @param level refinements, at least 0
     * @return the face count; past 2^60 it stops growing (already far too many)
     */
    public long refinedFaceCount(int level) { return refinedFaceCount(options.scheme(), faceSizes.length, faceVertices.length, level); }

    /**
     * {@link #refinedFaceCount(int)} of a mesh with these counts, before it is built: Catmull-Clark
     * and bilinear make one quad per face corner at the first level, Loop four triangles per
     * triangle; every further level multiplies by four.
     *
     * @param scheme  the scheme
     * @param faces   the mesh's faces
     * @param corners the mesh's face corners
     * @param level   refinements, at least 0
     * @return the face count, saturating past 2^60
     */
    public static long refinedFaceCount(SubdivOptions.Scheme scheme, int faces, long corners, int level) {
        if (level <= 0) return faces;
        long n = scheme == SubdivOptions.Scheme.LOOP ? 4L * faces : corners;
        // Saturate rather than overflow: at 2^62 the answer is "far too many" either way.
        for (int l = 1; l < level && n < (1L << 60); l++) n *= 4;
        return n;
    }

    /**
     * x, y, z per vertex (the mesh's own array: do not modify).
     *
     * @return the positions
     */
    public double[] positions() { return positions; }

    /**
     * Corners per face (the mesh's own array: do not modify).
     *
     * @return the face sizes
     */
    public int[] faceSizes() { return faceSizes; }

    /**
     * Vertex index of every face corner, face after face (the mesh's own array: do not modify).
     *
     * @return the corner vertices
     */
    public int[] faceVertices() { return faceVertices; }

    /**
     * (u, v) pairs, or null without UVs.
     *
     * @return the UVs, or null
     */
    public double[] uvs() { return uvs; }

    /**
     * Index into {@link #uvs()} of every face corner, or null without UVs.
     *
     * @return the indices, or null
     */
    public int[] faceUvIndices() { return faceUvIndices; }

    /** {@return the scheme options} */
    public SubdivOptions options() { return options; }

    /**
     * The group of every face (-1 for none), or null when the faces have no groups: what every
     * face refined from it inherits (the OBJ file's usemtl runs; the scene gives each group a
     * material). The mesh's own array: do not modify.
     *
     * @return a group index per face, or null
     */
    public int[] faceGroups() { return faceGroups; }

    /**
     * The names of the face groups, by index, or null when the faces have no groups.
     *
     * @return the names, or null
     */
    public String[] groupNames() { return groupNames == null ? null : groupNames.clone(); }

    /** The face groups' count, 0 without groups. */
    public int groupCount() { return groupNames == null ? 0 : groupNames.length; }

    /**
     * The creases, corners and holes as they were given to the builder, in that order (a later
     * value for the same edge or vertex, which replaced the earlier, is listed after it), with
     * the options: what a writer needs to write the mesh back out. The level the mesh refines
     * from applies them; boundary rules and non-manifold topology may sharpen more vertices
     * there, which is not listed here, since it follows from the mesh again. Arrays are the
     * mesh's own: do not modify.
     *
     * @return the tags
     */
    public SubdivTags tags() { return tags; }

    /**
     * The name given with {@link Builder#source}, or null.
     *
     * @return the name, or null
     */
    public String source() { return source; }

    /** Collects UVs, tags and options; {@link #build()} validates and names the face or vertex at fault. */
    public static final class Builder {
        private double[] positions;
        private int[] faceSizes, faceVertices;
        private double[] uvs;
        private int[] faceUvs;
        private int[] creases = new int[16];
        private float[] creaseSharp = new float[8];
        private int creaseCount;
        private int[] corners = new int[8];
        private float[] cornerSharp = new float[8];
        private int cornerCount;
        private int[] holes = new int[8];
        private int holeCount;
        private SubdivOptions options = SubdivOptions.DEFAULT;
        private String source;
        private int[] faceGroups;
        private String[] groupNames;
        /** Level 0 keeps per-face starts even when all faces are quads (see {@link PatchRefiner}). */
        boolean generalFaces;

        private Builder(double[] positions, int[] faceSizes, int[] faceVertices) {
            this.positions = Objects.requireNonNull(positions, "positions");
            this.faceSizes = Objects.requireNonNull(faceSizes, "faceSizes");
            this.faceVertices = Objects.requireNonNull(faceVertices, "faceVertices");
        }

        /**
         * Face-varying texture coordinates: (u, v) pairs and one index into them per face corner.
         *
         * @param uvs (u, v) pairs
         * @param faceUvIndices index of a pair per face corner
         * @return this builder
         */
        public Builder uvs(double[] uvs, int[] faceUvIndices) {
            this.uvs = Objects.requireNonNull(uvs, "uvs");
            this.faceUvs = Objects.requireNonNull(faceUvIndices, "faceUvIndices");
            return this;
        }

        /**
         * A crease on the edge between vertices a and b; a later crease on the same edge replaces it.
         *
         * @param a one vertex of the edge
         * @param b the other vertex
         * @param sharpness 0 smooth, up to {@link ControlMesh#INFINITELY_SHARP}
         * @return this builder
         */
        public Builder crease(int a, int b, float sharpness) {
            if (2 * creaseCount + 2 > creases.length) {
                creases = Arrays.copyOf(creases, 2 * creases.length);
                creaseSharp = Arrays.copyOf(creaseSharp, 2 * creaseSharp.length);
            }
            creases[2 * creaseCount] = a;
            creases[2 * creaseCount + 1] = b;
            creaseSharp[creaseCount++] = sharpness;
            return this;
        }

        /**
         * Sharpness of a vertex (a corner when sharp); a later value for the same vertex replaces it.
         *
         * @param vertex the vertex
         * @param sharpness 0 smooth, up to {@link ControlMesh#INFINITELY_SHARP}
         * @return this builder
         */
        public Builder corner(int vertex, float sharpness) {
            if (cornerCount == corners.length) {
                corners = Arrays.copyOf(corners, 2 * corners.length);
                cornerSharp = Arrays.copyOf(cornerSharp, 2 * cornerSharp.length);
            }
            corners[cornerCount] = vertex;
            cornerSharp[cornerCount++] = sharpness;
            return this;
        }

        /**
         * Marks a face as a hole: it is refined like the others but not part of the surface.
         *
         * @param face the face
         * @return this builder
         */
        public Builder hole(int face) {
            if (holeCount == holes.length) holes = Arrays.copyOf(holes, 2 * holes.length);
            holes[holeCount++] = face;
            return this;
        }

        /**
         * Sets the scheme options.
         *
         * @param options the options
         * @return this builder
         */
        public Builder options(SubdivOptions options) {
            this.options = Objects.requireNonNull(options, "options");
            return this;
        }

        /**
         * The options set so far ({@link SubdivOptions#DEFAULT} until set).
         *
         * @return the options
         */
        public SubdivOptions options() { return options; }

        /**
         * Groups of faces (such as an OBJ file's usemtl runs), which every refined face inherits
         * from its control face; a scene gives each group a material.
         *
         * @param groups group index per face, -1 for a face in none; null with {@code names} null for no groups
         * @param names the groups' names, by index (at most {@link lt.spindulys.mesh.MeshData#MAX_GROUPS})
         * @return this builder
         */
        public Builder faceGroups(int[] groups, String[] names) {
            if ((groups == null) != (names == null)) throw new IllegalArgumentException("face groups and group names must be given together");
            this.faceGroups = groups;
            this.groupNames = names;
            return this;
        }

        /**
         * A name for error messages, such as the file the mesh came from.
         *
         * @param name the name, or null
         * @return this builder
         */
        public Builder source(String name) {
            this.source = name;
            return this;
        }

        /**
         * Validates and freezes; throws IllegalArgumentException naming the face or vertex at fault.
         *
         * @return the mesh
         */
        public ControlMesh build() {
            String at = source == null ? "" : source + ": ";
            if (positions.length % 3 != 0) {
                throw new IllegalArgumentException(at + "positions hold " + positions.length + " numbers, not a multiple of 3 (x, y, z per vertex)");
            }
            int nV = positions.length / 3;
            for (int i = 0; i < positions.length; i++) {
                if (!Double.isFinite(positions[i])) {
                    throw new IllegalArgumentException(at + "vertex " + i / 3 + " has a non-finite coordinate (" + positions[i] + ")");
                }
            }
            int nF = faceSizes.length;
            if (nF == 0) throw new IllegalArgumentException(at + "the mesh has no faces");
            long cornerTotal = 0;
            for (int f = 0; f < nF; f++) {
                if (faceSizes[f] < 3) {
                    throw new IllegalArgumentException(at + "face " + f + " has " + faceSizes[f] + " corners; a face needs at least 3");
                }
                if (faceSizes[f] != 3 && options.scheme() == SubdivOptions.Scheme.LOOP) {
                    throw new IllegalArgumentException(at + "face " + f + " has " + faceSizes[f] + " corners; the Loop scheme needs triangles");
                }
                cornerTotal += faceSizes[f];
            }
            if (cornerTotal != faceVertices.length) {
                throw new IllegalArgumentException(at + "the face sizes add up to " + cornerTotal + " corners, but " + faceVertices.length + " vertex indices were given");
            }
            if (cornerTotal > Integer.MAX_VALUE / 64) throw new IllegalArgumentException(at + "too many face corners (" + cornerTotal + ")");
            for (int f = 0, h = 0; f < nF; f++) {
                for (int k = 0; k < faceSizes[f]; k++, h++) {
                    int v = faceVertices[h];
                    if (v < 0 || v >= nV) {
                        throw new IllegalArgumentException(at + "face " + f + " uses vertex " + v + ", but the mesh has " + nV + " vertices");
                    }
                }
            }
            if (uvs != null) {
                if (uvs.length % 2 != 0) throw new IllegalArgumentException(at + "UVs hold " + uvs.length + " numbers, not (u, v) pairs");
                if (faceUvs.length != faceVertices.length) {
                    throw new IllegalArgumentException(at + faceUvs.length + " UV indices for " + faceVertices.length + " face corners");
                }
                int nUv = uvs.length / 2;
                for (int f = 0, h = 0; f < nF; f++) {
                    for (int k = 0; k < faceSizes[f]; k++, h++) {
                        int u = faceUvs[h];
                        if (u < 0) {
                            throw new IllegalArgumentException(at + "face " + f + " corner " + k + " has no UV (with UVs, every face corner needs one)");
                        }
                        if (u >= nUv) {
                            throw new IllegalArgumentException(at + "face " + f + " uses UV " + u + ", but the mesh has " + nUv + " UVs");
                        }
                    }
                }
            }
            if (faceGroups != null) {
                if (faceGroups.length != nF) throw new IllegalArgumentException(at + faceGroups.length + " face groups for " + nF + " faces");
                if (groupNames.length > lt.spindulys.mesh.MeshData.MAX_GROUPS) {
                    throw new IllegalArgumentException(at + groupNames.length + " face groups, more than the " + lt.spindulys.mesh.MeshData.MAX_GROUPS + " allowed");
                }
                for (int f = 0; f < nF; f++) {
                    if (faceGroups[f] < -1 || faceGroups[f] >= groupNames.length) {
                        throw new IllegalArgumentException(at + "face " + f + " has group " + faceGroups[f] + ", but there are " + groupNames.length + " groups");
                    }
                }
            }
            double[] pos = positions.clone();
            int[] sizes = faceSizes.clone(), verts = faceVertices.clone();
            BaseLevelBuilder levelBuilder = new BaseLevelBuilder(nV, sizes, verts, generalFaces);
            Level base = levelBuilder.level;
            base.triangleSplit = options.scheme() == SubdivOptions.Scheme.LOOP;
            float[] eSharp = null;
            for (int i = 0; i < creaseCount; i++) {
                int a = creases[2 * i], b = creases[2 * i + 1];
                float s = creaseSharp[i];
                for (int v : new int[] {a, b}) {
                    if (v < 0 || v >= nV) {
                        throw new IllegalArgumentException(at + "crease " + i + " (vertices " + a + " and " + b + ") names vertex " + v + ", but the mesh has " + nV + " vertices");
                    }
                }
                if (Float.isNaN(s)) throw new IllegalArgumentException(at + "crease " + i + " (vertices " + a + " and " + b + ") has sharpness NaN");
                int e = levelBuilder.findEdge(a, b);
                if (e < 0) throw new IllegalArgumentException(at + "crease " + i + ": vertices " + a + " and " + b + " share no edge");
                if (eSharp == null) eSharp = new float[base.nE];
                eSharp[e] = s;
            }
            float[] vSharp = null;
            for (int i = 0; i < cornerCount; i++) {
                int v = corners[i];
                if (v < 0 || v >= nV) throw new IllegalArgumentException(at + "corner " + i + " names vertex " + v + ", but the mesh has " + nV + " vertices");
                if (Float.isNaN(cornerSharp[i])) throw new IllegalArgumentException(at + "corner " + i + " (vertex " + v + ") has sharpness NaN");
                if (vSharp == null) vSharp = new float[nV];
                vSharp[v] = cornerSharp[i];
            }
            boolean[] hole = null;
            for (int i = 0; i < holeCount; i++) {
                int f = holes[i];
                if (f < 0 || f >= nF) throw new IllegalArgumentException(at + "hole " + i + " names face " + f + ", but the mesh has " + nF + " faces");
                if (hole == null) hole = new boolean[nF];
                hole[f] = true;
            }
            levelBuilder.tag(options.boundary(), eSharp, vSharp, null, hole);
            Builder frozen = new Builder(pos, sizes, verts);
            frozen.options = options;
            frozen.source = source;
            if (faceGroups != null) {
                frozen.faceGroups = faceGroups.clone();
                frozen.groupNames = groupNames.clone();
            }
            frozen.creases = creases;
            frozen.creaseSharp = creaseSharp;
            frozen.creaseCount = creaseCount;
            frozen.corners = corners;
            frozen.cornerSharp = cornerSharp;
            frozen.cornerCount = cornerCount;
            frozen.holes = holes;
            frozen.holeCount = holeCount;
            FaceVarying.Channel channel = null;
            if (uvs != null) {
                frozen.uvs = uvs.clone();
                frozen.faceUvs = faceUvs.clone();
                channel = FaceVarying.build(base, sizes, frozen.faceUvs, frozen.uvs, options);
            }
            return new ControlMesh(frozen, base, channel);
        }
    }
}
