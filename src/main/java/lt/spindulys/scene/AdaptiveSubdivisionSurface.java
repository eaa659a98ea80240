package lt.spindulys.scene;

import java.util.Locale;

import lt.spindulys.material.Material;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.PatchRefiner;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;
import lt.spindulys.trace.TraceContext;

/**
 * A subdivision surface (Catmull-Clark, Loop or bilinear: the control mesh's scheme) refined only as
 * far as the camera needs: chapter 6 of the thesis, and past it (the thesis names adaptive
 * subdivision for other schemes as future work). Each coarse face is refined on its own, from its
 * one-ring, to the level its edges need; an edge's level comes from its projected length in pixels
 * (each step halves it) and is the same for both faces sharing it, and a face refined deeper than
 * one of its edges is stitched to that edge's vertices, so the surface is watertight. At a fixed
 * level every face gives exactly the triangles the uniform {@link SubdivisionSurface} gives it.
 *
 * <p>Three methods, named as the thesis names them:
 * <ul>
 * <li>{@link Method#PROJECTED} (section 6.1): levels from the projected control edges, every
 *     patch refined when the scene is built, into one mesh;</li>
 * <li>{@link Method#LAZY} (section 6.2): subdivision during tracing: a face is refined when a ray
 *     first reaches its box (the box of its one-ring control points, which holds the whole limit
 *     patch, so the thesis's edge problem cannot arise) and kept in the scene's bounded cache;</li>
 * <li>{@link Method#COMBINED} (section 6.3): eager while the patches fit in the scene's memory
 *     budget ({@link AdaptiveSettings}), lazy for the rest. The projected method becomes combined
 *     when its tessellation does not fit.</li>
 * </ul>
 * Instances share one tessellation (and its cache entries), with each edge at the finest level
 * any of their placements needs.
 */
public final class AdaptiveSubdivisionSurface extends GObject {
    /** When the patches are refined. */
    public enum Method {
        /** Section 6.1: all patches when the scene is built. */
        PROJECTED("projected"),
        /** Section 6.2: each patch when a ray first reaches it, kept in a bounded cache. */
        LAZY("lazy"),
        /** Section 6.3: eager within the memory budget, lazy beyond it. */
        COMBINED("combined");

        private final String word;
        Method(String word) { this.word = word; }

        /**
         * The scene file's word for the method.
         *
         * @return "projected", "lazy" or "combined"
         */
        public String word() { return word; }
    }

    /** How levels are chosen when no fixed level is given. */
    public enum Levels {
        /**
         * Integer rates per control edge from their projected lengths, any number of segments, each
         * face a grid on the limit surface at its own edges' rates (the default).
         */
        RATE,
        /** The thesis's power-of-two levels per control edge, from its own projected length (neighbours agree along shared edges). */
        EDGE,
        /** The thesis's: one level for the object, from its longest projected control edge. */
        OBJECT
    }

    /** What instances share: the control mesh's per-face refiner and facts derived from it once. */
    record Geometry(PatchRefiner refiner, Bounds bounds, boolean closed, lt.spindulys.subdiv.LimitSurface limit) {
        static Geometry of(ControlMesh control) {
            PatchRefiner r = new PatchRefiner(control);
            double[] box = new double[6];
            double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
            int ne = r.edgeCount();
            int[] uses = new int[ne];
            boolean any = false;
            for (int f = 0; f < r.faceCount(); f++) {
                if (r.isHole(f)) continue;
                any = true;
                r.oneRingBounds(f, box);
                x0 = Math.min(x0, box[0]); y0 = Math.min(y0, box[1]); z0 = Math.min(z0, box[2]);
                x1 = Math.max(x1, box[3]); y1 = Math.max(y1, box[4]); z1 = Math.max(z1, box[5]);
                for (int k = 0; k < r.faceSize(f); k++) uses[r.faceEdge(f, k)]++;
            }
            boolean closed = any;
            for (int u : uses) closed &= u == 2 || u == 0;
            return new Geometry(r, any ? new Bounds(x0, y0, z0, x1, y1, z1) : Bounds.EMPTY, closed, new lt.spindulys.subdiv.LimitSurface(r));
        }
    }

    private final Geometry geometry;
    private final Method method;
    private final boolean smooth;
    private int level = -1, maxLevel = SubdivisionSurface.MAX_LEVEL;
    private double target = 1;
    private Levels levels = Levels.RATE;
    private SurfaceTessellation tessellation;

    /**
     * A surface refined by {@code method}, levels per edge for 1-pixel edges unless set otherwise.
     *
     * @param control the control mesh
     * @param method  when patches are refined
     * @param smooth  limit normals interpolated (true) or flat facets
     */
    public AdaptiveSubdivisionSurface(ControlMesh control, Method method, boolean smooth) {
        this(Geometry.of(control), method, smooth);
    }

    private AdaptiveSubdivisionSurface(Geometry g, Method method, boolean smooth) {
        this.geometry = g;
        this.method = java.util.Objects.requireNonNull(method, "method");
        this.smooth = smooth;
    }

    /**
     * Refines every face to one fixed level instead of choosing levels from the view (the lazy
     * method at the uniform path's tessellation).
     *
     * @param l the level, 0 to {@link SubdivisionSurface#MAX_LEVEL}; -1 to choose from the view again
     * @return this surface
     */
    public AdaptiveSubdivisionSurface level(int l) {
        checkMutable();
        level = l < 0 ? -1 : SubdivisionSurface.checkLevel(l);
        return this;
    }

    /**
     * The edge length in pixels the levels aim at (each level halves an edge); a scene's
     * {@link AdaptiveSettings#targetPixels()} overrides it.
     *
     * @param pixels the target edge length, see {@link AdaptiveSettings#checkTarget}
     * @return this surface
     */
    public AdaptiveSubdivisionSurface target(double pixels) {
        checkMutable();
        target = AdaptiveSettings.checkTarget(pixels);
        return this;
    }

    /**
     * Levels per edge (the default) or one per object (the thesis's).
     *
     * @param l how levels are chosen
     * @return this surface
     */
    public AdaptiveSubdivisionSurface levels(Levels l) {
        checkMutable();
        levels = java.util.Objects.requireNonNull(l, "levels");
        return this;
    }

    /**
     * The deepest level the view may ask for.
     *
     * @param l 0 to {@link SubdivisionSurface#MAX_LEVEL}
     * @return this surface
     */
    public AdaptiveSubdivisionSurface maxLevel(int l) {
        checkMutable();
        maxLevel = SubdivisionSurface.checkLevel(l);
        return this;
    }

    /**
     * Another placement of this surface, sharing its refiner and, in a scene, its tessellation.
     *
     * @return a new unfrozen surface with the same options
     */
    public AdaptiveSubdivisionSurface instance() {
        AdaptiveSubdivisionSurface c = new AdaptiveSubdivisionSurface(geometry, method, smooth);
        c.level = level;
        c.maxLevel = maxLevel;
        c.target = target;
        c.levels = levels;
        return c;
    }

    /**
     * A new surface of the same control mesh, its refiner shared, refined by {@code method} with
     * the default options and this one's shading.
     *
     * @param method when patches are refined
     * @return a new unfrozen surface
     */
    public AdaptiveSubdivisionSurface sibling(Method method) {
        return new AdaptiveSubdivisionSurface(geometry, method, smooth);
    }

    @Override
    protected AdaptiveSubdivisionSurface copy() {
        checkCopyable();
        AdaptiveSubdivisionSurface c = instance();
        c.describeLike(this);
        return c;
    }

    /** Registers this placement with the scene's shared tessellation of this geometry and options. */
    @Override
    protected int freeze(BuildContext context, int ids) {
        int next = super.freeze(context, ids);
        BuildShared shared = context.shared();
        double t = Double.isNaN(shared.settings().targetPixels()) ? target : shared.settings().targetPixels();
        Object key = java.util.List.of(geometry, method, smooth, level, maxLevel, t, levels);
        tessellation = shared.tessellation(key, () -> levels == Levels.RATE ? new GridTessellation(this, t) : new AdaptiveTessellation(this, t));
        // Back faces are seen only through a transparent material or a CSG cut, or on an open surface.
        boolean backHidden = geometry.closed() && solid() == this && !anyTransparentMaterial();
        tessellation.addPlacement(placementIn(context.placement()), backHidden);
        return next;
    }

    Geometry geometry() { return geometry; }

    /**
     * When patches are refined.
     *
     * @return the method
     */
    public Method method() { return method; }

    /**
     * True if shading interpolates the limit normals, false for flat facets.
     *
     * @return true for smooth shading
     */
    public boolean isSmooth() { return smooth; }

    /**
     * The fixed level, or -1 when levels come from the view.
     *
     * @return the fixed level or -1
     */
    public int fixedLevel() { return level; }

    /**
     * The deepest level the view may ask for.
     *
     * @return the maximum level
     */
    public int maxLevel() { return maxLevel; }

    /**
     * The target edge length in pixels.
     *
     * @return the target, in pixels
     */
    public double target() { return target; }

    /**
     * Whether levels are chosen per edge or per object.
     *
     * @return the level mode
     */
    public Levels levels() { return levels; }

    /**
     * The control mesh refined.
     *
     * @return the control mesh
     */
    public ControlMesh control() { return geometry.refiner().control(); }

    /**
     * This surface's tessellation statistics in the scene it was frozen into (see {@link Scene#adaptiveStatistics()}).
     *
     * @return one line, or a note that the surface is not frozen
     */
    public String statistics() { return tessellation == null ? name() + ": not in a built scene" : tessellation.statistics(); }

    /**
     * The tessellation this surface has in the scene it was frozen into, as one mesh in object
     * space: every coarse face refined to its chosen levels, stitched, vertices at one position
     * welded, so the mesh is crack-free (what {@code render subdivide --scene} writes).
     *
     * @return positions, per-corner normals (smooth shading) and uvs of the triangles
     * @throws IllegalStateException if the surface is not in a built scene
     * @throws lt.spindulys.limits.InsufficientMemoryException if the whole tessellation does not fit in the heap
     */
    public lt.spindulys.mesh.MeshData tessellation() {
        if (tessellation == null) throw new IllegalStateException(name() + " is not in a built scene");
        return tessellation.welded();
    }

    /**
     * The level chosen for each control edge in the scene this surface was frozen into.
     *
     * @return a level per control edge, numbered as {@link PatchRefiner#edgeVertices()} numbers them
     * @throws IllegalStateException if the surface is not in a built scene
     */
    public int[] edgeLevels() {
        if (tessellation == null) throw new IllegalStateException(name() + " is not in a built scene");
        return tessellation.edgeLevels();
    }

    /**
     * The refiner of this surface's control mesh (shared by its instances).
     *
     * @return the per-face refiner
     */
    public PatchRefiner refiner() { return geometry.refiner(); }


    /**
     * The names of the face groups (the control mesh's, such as the OBJ file's usemtl names), by
     * group index, or null when it has none; every refined face belongs to its control face's group.
     *
     * @return the names, or null
     */
    public String[] groupNames() { return geometry.refiner().control().groupNames(); }

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
    public AdaptiveSubdivisionSurface groupMaterial(String name, Material m) {
        setGroupMaterial(geometry.refiner().control().groupNames(), name, m);
        return this;
    }

    @Override
    protected int groupCount() { return geometry.refiner().control().groupCount(); }

    @Override
    protected int faceGroup(int prim, int sub) { return tessellation.faceGroup(prim, sub); }

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public AdaptiveSubdivisionSurface transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public AdaptiveSubdivisionSurface motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public AdaptiveSubdivisionSurface material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public AdaptiveSubdivisionSurface name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public AdaptiveSubdivisionSurface source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public AdaptiveSubdivisionSurface source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "subdiv"; }
    @Override public Bounds localBounds() { return geometry.bounds(); }
    @Override public boolean isClosed() { return geometry.closed(); }

    @Override
    protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        return tessellation.intersect(ray, hit, ctx);
    }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) {
        return tessellation.occluded(toLocal(ray, ctx), ctx);
    }

    @Override
    protected void spansLocal(Ray ray, SpanBuffer out, TraceContext ctx) {
        tessellation.spans(ray, out, ctx, this);
    }

    @Override
    protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        tessellation.shade(x, y, z, hit, sd);
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT, "%s (%s)", name(), method.word());
    }
}
