package lt.spindulys.scene;

import java.util.Objects;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Transform;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.RefinedTriangles;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.math.Motion;
import lt.spindulys.material.Material;

/**
 * A subdivision surface of any of the three schemes (the control mesh's
 * {@link lt.spindulys.subdiv.SubdivOptions#scheme()}: Catmull-Clark, Loop or bilinear): a control
 * mesh refined uniformly to a fixed level once, at construction, and rendered as the triangles of the
 * refined faces. Hole faces are left out; each refined quad (Catmull-Clark, bilinear) is split
 * into two triangles along its shorter diagonal, and each refined triangle (Loop) is one. Smooth
 * shading interpolates the limit-surface normals of the refined vertices, which makes even a low
 * level look round (at a sharp edge, where the limit surface has a tangent plane on either side,
 * each side keeps its own normal); flat shading uses each triangle's own normal and shows the
 * facets. The triangles' corners are the refined vertices where the refinement puts them, or, with
 * {@link Positions#LIMIT}, their limit-surface positions, so that every corner lies on the
 * surface.
 *
 * <p>The triangles are an ordinary {@link TriangleMesh} (positions of the refined vertices, limit
 * normals, refined face-varying UVs), and every query is delegated to it: the surface hits,
 * shades and reports spans exactly as that mesh does, and it is closed (has an inside, for
 * refraction and CSG) when the refined mesh is.
 */
public final class SubdivisionSurface extends GObject {
    /** The deepest level: a quad becomes 4^8 = 65,536 quads, a Loop triangle as many triangles. */
    public static final int MAX_LEVEL = 8;

    /**
     * Where the refined vertices are placed, and so the corners of the rendered triangles.
     * Uniform refinement only: an adaptive surface ({@link AdaptiveSubdivisionSurface}) places
     * its vertices at their refined positions.
     */
    public enum Positions {
        /** Where the level's refinement puts them: the triangles approximate the limit surface from the control side. */
        REFINED("refined"),
        /**
         * On the limit surface ({@link RefinedMesh#limitPositions()}, OpenSubdiv's limit
         * evaluation): every triangle corner lies exactly on the surface the level approximates.
         */
        LIMIT("limit");

        private final String word;

        Positions(String word) { this.word = word; }

        /** {@return the scene file's word for it: "refined" or "limit"} */
        public String word() { return word; }
    }

    /**
     * Heap each refined face costs with {@link Positions#LIMIT}, on top of {@link #BYTES_PER_FACE}:
     * the limit positions, three doubles per refined vertex (about one vertex per face, a few more
     * along boundaries).
     */
    public static final long LIMIT_POSITION_BYTES_PER_FACE = 32;

    private final int level;
    private final boolean smooth;
    private final Positions positions;
    private final RefinedMesh refined;
    private final TriangleMesh mesh;

    /**
     * The surface at {@code level} with smooth shading.
     *
     * @param control the control mesh to refine
     * @param level times to refine, 0 to {@link #MAX_LEVEL}
     */
    public SubdivisionSurface(ControlMesh control, int level) {
        this(control, level, true);
    }

    /**
     * Refines {@code control} {@code level} times and builds the triangles.
     *
     * @param control the control mesh to refine
     * @param level times to refine, 0 to {@link #MAX_LEVEL}
     * @param smooth limit normals interpolated (true) or flat facets
     * @throws IllegalArgumentException if the level is not between 0 and {@link #MAX_LEVEL}
     */
    public SubdivisionSurface(ControlMesh control, int level, boolean smooth) {
        this(control, level, smooth, Positions.REFINED);
    }

    /**
     * Refines {@code control} {@code level} times and builds the triangles with their corners at
     * the refined vertices' {@code positions}: where the refinement puts them, or on the limit
     * surface.
     *
     * @param control the control mesh to refine
     * @param level times to refine, 0 to {@link #MAX_LEVEL}
     * @param smooth limit normals interpolated (true) or flat facets
     * @param positions where the refined vertices are placed
     * @throws IllegalArgumentException if the level is not between 0 and {@link #MAX_LEVEL}, or its
     *         faces do not fit in the heap
     */
    public SubdivisionSurface(ControlMesh control, int level, boolean smooth, Positions positions) {
        Objects.requireNonNull(positions, "positions");
        checkLevel(level, control.refinedFaceCount(level), bytesPerFace(control.options().scheme(), positions == Positions.LIMIT));
        this.level = level;
        this.smooth = smooth;
        this.positions = positions;
        this.refined = Subdivision.refine(control, level);
        this.mesh = new TriangleMesh(positions == Positions.LIMIT ? RefinedTriangles.triangles(refined, refined.limitPositions(), smooth)
                : triangles(refined, smooth));
        mesh.smooth(smooth);
    }

    /** An instance of {@code p} or a scene's copy of it: its refined mesh shared, {@code mesh} made from p's triangles. */
    private SubdivisionSurface(SubdivisionSurface p, TriangleMesh mesh) {
        level = p.level;
        smooth = p.smooth;
        positions = p.positions;
        refined = p.refined;
        this.mesh = mesh;
        mesh.smooth(smooth);
    }

    /**
     * Another placement of this surface: a new object with its own transform, material and name
     * that shares the refined mesh, its triangles and its acceleration structure (refined and
     * built once).
     *
     * @return a new unfrozen surface sharing this one's refinement and structures
     */
    public SubdivisionSurface instance() {
        return new SubdivisionSurface(this, mesh.instance());
    }

    /**
     * True if this surface shares another's refinement ({@link #instance()}; a scene's copy answers as its original).
     *
     * @return true for an instance; false for the surface that refined the mesh
     */
    public boolean isInstance() { return mesh.isInstance(); }

    /**
     * A scene's copy: an {@link #instance()} (the refinement, triangles and structures shared)
     * with this surface's transform, motion, material and name.
     */
    @Override
    protected SubdivisionSurface copy() {
        checkCopyable();
        SubdivisionSurface c = new SubdivisionSurface(this, mesh.copy());
        c.describeLike(this);
        return c;
    }

    /** Places the surface and freezes its triangles, which take the mesh's shared structure of the context's kind. */
    @Override
    protected int freeze(BuildContext context, int ids) {
        int next = super.freeze(context, ids);
        // The inner mesh is never part of a scene; frozen in place, its own queries (occluded)
        // take the object-space rays this surface hands it unchanged.
        try {
            mesh.freeze(context.within(Placement.of(Transform.IDENTITY, context.shutterOpen(), context.shutterClose()), null), 0);
        } catch (IllegalArgumentException e) {
            // Named as this surface: the inner mesh is not an object of the scene.
            throw SceneBuildException.of(this, e instanceof SceneBuildException b ? (IllegalArgumentException) b.getCause() : e);
        }
        return next;
    }

    /**
     * Refuses a level outside 0..{@link #MAX_LEVEL}; returns it otherwise.
     *
     * @param level the subdivision level to check
     * @return {@code level}, unchanged
     * @throws IllegalArgumentException "subdivision level must be between 0 and 8, found 9"
     */
    public static int checkLevel(int level) {
        if (level < 0 || level > MAX_LEVEL) {
            throw new IllegalArgumentException("subdivision level must be between 0 and " + MAX_LEVEL + ", found " + level);
        }
        return level;
    }

    /**
     * The most faces a surface may have after refinement: a sanity limit (at a few hundred bytes
     * per face for vertices, triangles and BVH, this many already need gigabytes of heap).
     */
    public static final long MAX_FACES = 1L << 24;

    /**
     * {@link #checkLevel(int)}, and refuses a level that would make more than {@link #MAX_FACES}
     * faces, before any memory is spent on them.
     *
     * @param level the subdivision level to check
     * @param refinedFaces the faces the control mesh has after {@code level} refinements
     * @return {@code level}, unchanged
     */
    public static int checkLevel(int level, long refinedFaces) {
        return checkLevel(level, refinedFaces, BYTES_PER_FACE);
    }

    /**
     * Heap a surface needs per refined face while it is built, at its peak: the refined mesh, its
     * limit normals, the triangles and the acceleration structure, with the garbage of the
     * earlier levels. The measured peak with a margin above it, so that a level the check lets
     * through does not end in OutOfMemoryError; the measurement is in docs/performance.md (heap
     * per refined face).
     */
    public static final long BYTES_PER_FACE = 560;

    /**
     * {@link #BYTES_PER_FACE} for a Loop surface, whose refined faces are triangles: one triangle
     * and about half a vertex each, where a quad is two triangles and about one vertex. Measured
     * beside Catmull-Clark in one harness (docs/performance.md, heap per refined face: Loop's peak
     * is two thirds of a quad's), with the same margin over the peak as {@link #BYTES_PER_FACE}.
     */
    public static final long LOOP_BYTES_PER_FACE = 380;

    /**
     * Heap a surface of this scheme needs per refined face at its peak while it is built:
     * {@link #LOOP_BYTES_PER_FACE} for Loop's triangles, {@link #BYTES_PER_FACE} for the quads of
     * Catmull-Clark and bilinear, with {@link #LIMIT_POSITION_BYTES_PER_FACE} more for limit
     * positions.
     *
     * @param scheme the control mesh's scheme
     * @param limit  whether the vertices are placed at their limit positions
     * @return bytes per refined face, for {@link #checkLevel(int, long, long)}
     */
    public static long bytesPerFace(SubdivOptions.Scheme scheme, boolean limit) {
        return (scheme == SubdivOptions.Scheme.LOOP ? LOOP_BYTES_PER_FACE : BYTES_PER_FACE) + (limit ? LIMIT_POSITION_BYTES_PER_FACE : 0);
    }

    /**
     * {@link #checkLevel(int, long)} with the heap each refined face costs given: also refuses a
     * level whose {@code refinedFaces * bytesPerFace} the heap cannot give now, with a message that
     * says how much it needs and how much is free.
     *
     * @param level the subdivision level to check
     * @param refinedFaces the faces the control mesh has after {@code level} refinements
     * @param bytesPerFace heap needed per refined face while building, in bytes ({@link #BYTES_PER_FACE} for a surface)
     * @return {@code level}, unchanged
     * @throws IllegalArgumentException (an {@link InsufficientMemoryException} when it is the heap)
     */
    public static int checkLevel(int level, long refinedFaces, long bytesPerFace) {
        checkLevel(level);
        if (refinedFaces > MAX_FACES) {
            throw new IllegalArgumentException("subdivision level " + level + " would make " + refinedFaces + " faces from this mesh, more than the "
                    + MAX_FACES + " allowed (choose a lower level)");
        }
        // Uniform refinement splits every face to the level asked, whether the camera needs that
        // detail or not; a level that does not fit is refused here (a scene file's subdiv then
        // renders it by the combined adaptive method instead: AdaptiveSubdivisionSurface).
        HeapBudget.require(HeapBudget.product(refinedFaces, bytesPerFace), "subdivision level " + level + " of this mesh ("
                + refinedFaces + " faces; uniform refinement; choose a lower level, give more heap, or refine adaptively)");
        return level;
    }

    /**
     * The triangles of a refined mesh as MeshData: {@link RefinedTriangles#triangles(RefinedMesh, boolean)},
     * the implementation the per-face patches share.
     */
    static MeshData triangles(RefinedMesh r, boolean smooth) {
        return RefinedTriangles.triangles(r, smooth);
    }

    /**
     * Boundary edges of the control mesh: edges of a face that no other face shares, counting the
     * edges a face shares only with a hole face as boundary too (holes are left out of the
     * surface). A non-manifold edge counts once per face using it. If the control mesh has none
     * but the refined triangles are still open (faces that collapse to nothing), the triangles'
     * count ({@link TriangleMesh#boundaryEdgeCount()}) is returned instead, so an open surface
     * never reports 0.
     *
     * @return the number of boundary edges; 0 only when the surface is closed
     */
    public int boundaryEdgeCount() {
        RefinedMesh base = level == 0 ? refined : Subdivision.refine(refined.controlMesh(), 0);
        int[] sizes = base.faceSizes(), twin = base.cornerTwins();
        int[] faceOf = new int[twin.length];
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int k = 0; k < sizes[f]; k++) faceOf[c + k] = f;
        }
        int count = 0;
        for (int c = 0; c < twin.length; c++) {
            if (base.isHole(faceOf[c])) continue;
            if (twin[c] < 0 || base.isHole(faceOf[twin[c]])) count++;
        }
        return count == 0 && !mesh.isClosed() ? mesh.boundaryEdgeCount() : count;
    }

    /**
     * Times the control mesh was refined (0 to {@link #MAX_LEVEL}).
     *
     * @return the subdivision level, 0 to {@link #MAX_LEVEL}
     */
    public int level() { return level; }
    /**
     * True if shading interpolates the limit normals, false for flat facets.
     *
     * @return true for smooth shading, false for flat facets
     */
    public boolean isSmooth() { return smooth; }
    /**
     * Where the refined vertices, the triangles' corners, are placed.
     *
     * @return {@link Positions#REFINED} (the default) or {@link Positions#LIMIT}
     */
    public Positions positions() { return positions; }
    /**
     * The refined mesh the triangles come from (holes included); with {@link Positions#LIMIT} the
     * triangles' corners are its {@link RefinedMesh#limitPositions()}, not its positions.
     *
     * @return the refined mesh, shared with instances
     */
    public RefinedMesh refined() { return refined; }
    /**
     * The triangles rendered ({@link TriangleMesh#data()}): corners at the refined or the limit
     * positions ({@link #positions()}), normals and UVs, copied from the mesh's arrays. Once the
     * scene is built, the vertices are in the order of the acceleration structure.
     *
     * @return a copy of the triangles
     */
    public MeshData triangleData() { return mesh.data(); }
    /**
     * Triangles rendered: two per refined quad, one per refined Loop triangle, holes left out.
     *
     * @return the number of triangles rendered
     */
    public int triangleCount() { return mesh.triangleCount(); }


    /**
     * The names of the face groups (the control mesh's, such as the OBJ file's usemtl names), by
     * group index, or null when it has none; every refined face belongs to its control face's group.
     *
     * @return the names, or null
     */
    public String[] groupNames() { return refined.controlMesh().groupNames(); }

    /**
     * Gives the faces of one group (one usemtl name of the OBJ file), and every face refined from
     * them, a material of their own. The object's {@link #material(Material)}, when given,
     * overrides every group's; faces of groups given none, and faces in no group, take the
     * object's material (or the one it inherits).
     *
     * @param name the group's name, one of {@link #groupNames()}
     * @param m the material, or null to take the object's again
     * @return this surface, for chaining
     * @throws IllegalArgumentException if the surface has no group of that name
     */
    public SubdivisionSurface groupMaterial(String name, Material m) {
        setGroupMaterial(refined.controlMesh().groupNames(), name, m);
        return this;
    }

    @Override
    protected int groupCount() { return refined.controlMesh().groupCount(); }

    @Override
    protected int faceGroup(int prim, int sub) { return mesh.faceGroup(prim, sub); }

    // ---- GObject: everything through the triangle mesh ----

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public SubdivisionSurface transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public SubdivisionSurface motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public SubdivisionSurface material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public SubdivisionSurface name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public SubdivisionSurface source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public SubdivisionSurface source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "subdiv"; }
    @Override public Bounds localBounds() { return mesh.localBounds(); }
    @Override public boolean isClosed() { return mesh.isClosed(); }

    @Override
    protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        return mesh.intersectLocal(ray, hit, ctx);
    }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) {
        return mesh.occluded(toLocal(ray, ctx), ctx);
    }

    @Override
    int blockingPart(TraceContext ctx) { return mesh.blockingPart(ctx); }

    @Override
    boolean occludedByPart(Ray ray, int part, TraceContext ctx) { return mesh.occludedByPart(toLocal(ray, ctx), part, ctx); }

    @Override
    protected void spansLocal(Ray ray, SpanBuffer out, TraceContext ctx) {
        int first = out.size();
        mesh.spansLocal(ray, out, ctx);
        // The mesh names itself at the span ends; this surface is what the scene knows and shades.
        out.relabel(first, this);
    }

    @Override
    protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        mesh.shadeLocal(x, y, z, hit, sd);
    }
}
