package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import java.util.Arrays;
import java.util.concurrent.ForkJoinTask;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.BruteForce;
import lt.spindulys.accel.Bvh;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.PrimitiveVisitor;
import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.accel.WatertightTriangles;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Motion;
import lt.spindulys.material.Material;

/**
 * A triangle mesh held in flat arrays (no object per triangle) with its own acceleration
 * structure, of the scene's {@link AcceleratorKind}, built when the mesh is frozen.
 * Polygons are triangulated as fans; triangles of zero area are dropped (and counted). Closed
 * when every undirected edge, with coinciding vertex positions treated as one vertex, belongs to
 * exactly two triangles.
 *
 * <p>Ray/triangle tests are watertight (Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2013): a ray through an edge or vertex shared by several triangles hits at
 * least one of them, so closed meshes have no cracks. A hit records the triangle index as
 * {@code prim} and the barycentric weights of its second and third corner as {@code u}, {@code v}.
 * Counter-clockwise winding seen from outside gives the outward normal.
 *
 * <p>The mesh is also the {@link PrimitiveSet} of its triangles (in object space), which is what
 * its acceleration structure indexes. The parts that work on index arrays alone live beside it:
 * the ray test in {@link WatertightTriangles}, the data checks and the closedness census in
 * {@code MeshTopology}, the crossings CSG pairs into spans in {@code TriangleSpans}; this class
 * triangulates, owns the arrays and their structures, and shades.
 */
public final class TriangleMesh extends GObject implements lt.spindulys.accel.TriangleSet {
    /**
     * Where the mesh came from, for messages. The polygon record itself is not kept: its
     * per-corner index arrays would cost another 18 bytes per triangle of a quad mesh, and the
     * triangle arrays below carry everything rendering needs.
     */
    private final String source;
    /** Positions; shared with the source data until {@link #reorder} makes the mesh its own copy. */
    private double[] pos;
    private final double[] normals;
    private final double[] uvs;
    /** Three position indices per triangle. */
    private final int[] tri;
    /** Three normal indices per triangle (-1 where a triangle has none), or null when none has any. */
    private final int[] triNormal;
    /** Three texture coordinate indices per triangle (-1 where a triangle has none), or null. */
    private final int[] triUv;
    /** The face group of each triangle (its polygon's; -1: none), or null when the data has no groups. */
    private final short[] triGroup;
    /** The face groups' names, or null. */
    private final String[] groupNames;
    private final int triangleCount, degenerateCount;
    private final boolean needsVertexNormals;
    private final boolean closed;
    /** Every vertex of the triangles on one plane (see {@link #flat()}). */
    private final boolean flat;
    private final Bounds bounds;
    /** Set by {@link #freeze}, before the scene is shared: the structure of {@link #root()} for the scene's kind. */
    private Accelerator accel;
    /**
     * The mesh this one is an {@link #instance()} of, or null: instances share its arrays and its
     * structures, so another placement of the same geometry costs no copy.
     */
    private final TriangleMesh prototype;
    /**
     * True for an {@link #instance()} and for a scene's copy of one; false for a mesh made from
     * data and for a scene's copy of it, which shares the arrays but stands for the original.
     */
    private final boolean instance;
    /**
     * Structures over this mesh's triangles, one per kind asked for, shared by its instances and
     * by the frozen copies scenes make of it ({@link #copy()}), so building the same mesh into
     * another scene (the next frame) does not build them again; only a prototype keeps them,
     * guarded by its lock, as scenes may be built on several threads. The first one built may
     * renumber the triangles ({@link #reorder}).
     */
    private final java.util.EnumMap<AcceleratorKind, Accelerator> structures;
    /** Made once so that collecting crossings allocates nothing per ray. */
    private final PrimitiveVisitor crossingCollector = this::collectCrossing;

    private boolean smooth;
    /** Area-weighted normal per position, for smooth shading of triangles without file normals. */
    private double[] vertexNormals;

    /**
     * Triangulates and indexes {@code data}. Shading is smooth when the data has normals, flat
     * otherwise; see {@link #smooth(boolean)}.
     *
     * @param data the positions, faces and optional normals and texture coordinates
     * @throws IllegalArgumentException if the arrays are inconsistent, an index is out of range or a position is not finite
     */
    public TriangleMesh(MeshData data) {
        this.prototype = null;
        this.instance = false;
        this.structures = new java.util.EnumMap<>(AcceleratorKind.class);
        this.source = data.source();
        MeshTopology.validate(data);
        pos = data.positions();
        normals = data.normals();
        uvs = data.uvs();
        int[] sizes = data.faceSizes(), vi = data.vertexIndex(), ni = data.normalIndex(), ti = data.uvIndex();
        int[] groups = data.faceGroups();
        groupNames = data.groupNames();

        long total = 0;
        for (int s : sizes) total += s - 2;
        if (3 * total > Integer.MAX_VALUE - 8) throw new IllegalArgumentException(where() + "too many triangles (" + total + ")");
        int[] t = new int[(int) (3 * total)];
        int[] tn = ni != null ? new int[t.length] : null;
        int[] tu = ti != null ? new int[t.length] : null;
        short[] tg = groups != null ? new short[(int) total] : null;
        int k = 0, dropped = 0, corner = 0, face = 0;
        boolean anyNormal = false, anyWithout = false, anyUv = false;
        double x0 = Double.POSITIVE_INFINITY, y0 = x0, z0 = x0, x1 = Double.NEGATIVE_INFINITY, y1 = x1, z1 = x1;
        for (int size : sizes) {
            for (int j = 1; j + 1 < size; j++) {
                int ca = corner, cb = corner + j, cc = corner + j + 1;
                int a = vi[ca], b = vi[cb], c = vi[cc];
                if (zeroArea(a, b, c)) {
                    dropped++;
                    continue;
                }
                int o = 3 * k;
                t[o] = a; t[o + 1] = b; t[o + 2] = c;
                if (tg != null) tg[k] = (short) groups[face];
                boolean hasN = ni != null && ni[ca] >= 0 && ni[cb] >= 0 && ni[cc] >= 0;
                if (tn != null) {
                    tn[o] = hasN ? ni[ca] : -1; tn[o + 1] = hasN ? ni[cb] : -1; tn[o + 2] = hasN ? ni[cc] : -1;
                }
                anyNormal |= hasN;
                anyWithout |= !hasN;
                if (tu != null) {
                    boolean hasUv = ti[ca] >= 0 && ti[cb] >= 0 && ti[cc] >= 0;
                    tu[o] = hasUv ? ti[ca] : -1; tu[o + 1] = hasUv ? ti[cb] : -1; tu[o + 2] = hasUv ? ti[cc] : -1;
                    anyUv |= hasUv;
                }
                for (int m = 0; m < 3; m++) {
                    int v = 3 * t[o + m];
                    double x = pos[v], y = pos[v + 1], z = pos[v + 2];
                    x0 = Math.min(x0, x); y0 = Math.min(y0, y); z0 = Math.min(z0, z);
                    x1 = Math.max(x1, x); y1 = Math.max(y1, y); z1 = Math.max(z1, z);
                }
                k++;
            }
            corner += size;
            face++;
        }
        triangleCount = k;
        degenerateCount = dropped;
        tri = k == total ? t : Arrays.copyOf(t, 3 * k);
        triNormal = anyNormal ? (k == total ? tn : Arrays.copyOf(tn, 3 * k)) : null;
        triUv = anyUv ? (k == total ? tu : Arrays.copyOf(tu, 3 * k)) : null;
        triGroup = tg == null || k == total ? tg : Arrays.copyOf(tg, k);
        needsVertexNormals = anyWithout;
        bounds = k == 0 ? Bounds.EMPTY : new Bounds(x0, y0, z0, x1, y1, z1);
        closed = k > 0 && MeshTopology.everyEdgeTwice(tri, triangleCount, pos);
        flat = k > 0 && planar(tri, k, pos, bounds);
        smooth(data.normalIndex() != null);
    }

    /**
     * An instance of {@code p} (a root mesh): the same arrays (no copy), its own transform,
     * material and shading; {@code instance} false for a scene's copy of {@code p} itself.
     */
    private TriangleMesh(TriangleMesh p, boolean instance) {
        prototype = p;
        this.instance = instance;
        structures = null;
        source = p.source;
        pos = p.pos;
        normals = p.normals;
        uvs = p.uvs;
        tri = p.tri;
        triNormal = p.triNormal;
        triUv = p.triUv;
        triGroup = p.triGroup;
        groupNames = p.groupNames;
        triangleCount = p.triangleCount;
        degenerateCount = p.degenerateCount;
        needsVertexNormals = p.needsVertexNormals;
        closed = p.closed;
        flat = p.flat;
        bounds = p.bounds;
        smooth = p.smooth;
    }

    /**
     * Another placement of this mesh's geometry: a new object with its own transform, material,
     * name and shading that shares this mesh's triangles, vertex data and acceleration structure
     * (built once, in object space, by whichever of them is frozen first). Instances of an
     * instance share the same original.
     *
     * @return a new unfrozen mesh sharing this one's geometry
     */
    public TriangleMesh instance() {
        return new TriangleMesh(root(), true);
    }

    /**
     * A scene's copy: an instance of the same geometry (so it shares the arrays and the
     * structures) with this mesh's transform, motion, material, name and shading.
     */
    @Override
    protected TriangleMesh copy() {
        checkCopyable();
        TriangleMesh c = new TriangleMesh(root(), instance);
        c.describeLike(this);
        c.smooth = smooth;
        return c;
    }

    /** The mesh that owns the shared arrays and structures: the prototype, or this one. */
    private TriangleMesh root() { return prototype != null ? prototype : this; }

    /**
     * True if this mesh shares another mesh's geometry ({@link #instance()}). A scene's frozen copy
     * answers as the object it was made from, so that each geometry has one mesh that is not an instance.
     *
     * @return true for an instance; false for the mesh that owns the geometry
     */
    public boolean isInstance() { return instance; }

    /** The structure over the triangles for {@code kind}, built on first request; the caller holds this (root) mesh's lock. */
    private Accelerator structure(AcceleratorKind kind) {
        Accelerator a = structures.get(kind);
        if (a == null) {
            // A mesh that fits in one leaf is tested directly: the object's box is tested above
            // it, and a tree would only add its own entry and box (the peer scene's ground).
            a = triangleCount <= Bvh.DEFAULT_LEAF_SIZE ? new BruteForce(this) : kind.build(this);
            structures.put(kind, a);
        }
        return a;
    }

    /** Area-weighted vertex normals of the (possibly renumbered) positions, computed once per geometry. */
    private double[] sharedVertexNormals() {
        if (vertexNormals == null) vertexNormals = computeVertexNormals();
        return vertexNormals;
    }

    private String where() {
        return source == null ? "" : source + ": ";
    }

    private boolean zeroArea(int a, int b, int c) {
        double ax = pos[3 * a], ay = pos[3 * a + 1], az = pos[3 * a + 2];
        double ux = pos[3 * b] - ax, uy = pos[3 * b + 1] - ay, uz = pos[3 * b + 2] - az;
        double vx = pos[3 * c] - ax, vy = pos[3 * c + 1] - ay, vz = pos[3 * c + 2] - az;
        return uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0;
    }

    // ---- options and queries ----

    /**
     * Smooth shading interpolates normals (the file's where a triangle has them, otherwise
     * area-weighted vertex normals); flat shading uses each triangle's geometric normal.
     *
     * @param on true for smooth shading, false for flat
     * @return this mesh, for chaining
     */
    public TriangleMesh smooth(boolean on) {
        checkMutable();
        smooth = on;
        return this;
    }

    /**
     * True if shading interpolates normals (see {@link #smooth(boolean)}).
     *
     * @return true for smooth shading, false for flat
     */
    public boolean isSmooth() { return smooth; }
    /**
     * True if the source gave normals (some triangles may still lack them).
     *
     * @return true if the mesh data has normals
     */
    public boolean hasNormals() { return normals != null; }
    /** The structure rays are traced through, once frozen (shared with instances); null before. */
    Accelerator accelerator() { return accel; }
    /**
     * The mesh as triangles (degenerate ones dropped): positions, normals and texture coordinates
     * as given, one face of three corners per triangle. The arrays are copies, as large as the
     * mesh's own (nothing in the renderer calls this; it is for callers that read the mesh back):
     * changing them changes nothing in the mesh.
     *
     * @return a triangles-only copy of the mesh
     */
    public MeshData data() {
        int[] sizes = new int[triangleCount];
        Arrays.fill(sizes, 3);
        // The owner's positions: an unfrozen instance's may predate the renumbering (reorder).
        int[] groups = null;
        if (triGroup != null) {
            groups = new int[triangleCount];
            for (int t = 0; t < triangleCount; t++) groups[t] = triGroup[t];
        }
        return new MeshData(root().pos.clone(), copyOf(normals), copyOf(uvs), sizes, tri.clone(), copyOf(triNormal), copyOf(triUv), source, groups,
                groupNames == null ? null : groupNames.clone());
    }

    private static double[] copyOf(double[] a) { return a == null ? null : a.clone(); }
    private static int[] copyOf(int[] a) { return a == null ? null : a.clone(); }

    /**
     * The names of the face groups (the OBJ file's usemtl names), by group index, or null when
     * the mesh has none; see {@link #groupMaterial(String, Material)}.
     *
     * @return the names, or null
     */
    public String[] groupNames() { return groupNames == null ? null : groupNames.clone(); }

    /**
     * Gives the faces of one group (one usemtl name of the OBJ file) a material of their own. The
     * object's {@link #material(Material)}, when given, overrides every group's; faces of groups
     * given none, and faces in no group, take the object's material (or the one it inherits).
     *
     * @param name the group's name, one of {@link #groupNames()}
     * @param m the material, or null to take the object's again
     * @return this mesh, for chaining
     * @throws IllegalArgumentException if the mesh has no group of that name
     */
    public TriangleMesh groupMaterial(String name, Material m) {
        setGroupMaterial(groupNames, name, m);
        return this;
    }

    @Override
    protected int groupCount() { return groupNames == null ? 0 : groupNames.length; }

    @Override
    protected int faceGroup(int prim, int sub) { return triGroup == null ? -1 : triGroup[prim]; }
    /**
     * Triangles of area above zero, the ones rendered.
     *
     * @return the number of triangles rendered
     */
    public int triangleCount() { return triangleCount; }
    /**
     * Triangles dropped because their area is zero.
     *
     * @return the number of zero-area triangles dropped
     */
    public int degenerateCount() { return degenerateCount; }

    /**
     * Bytes held by the mesh's arrays (positions, normals, texture coordinates, triangle and
     * per-corner indices, vertex normals) and the acceleration structures built over it (one per
     * kind a scene asked for); array headers and the few fixed fields are left out. An
     * {@link #isInstance() instance} holds none of its own: 0.
     *
     * @return the bytes held, 0 for an instance
     */
    public long memoryBytes() {
        if (instance) return 0;
        TriangleMesh r = root();
        synchronized (r) {
            long b = bytes(r.pos) + bytes(normals) + bytes(uvs) + bytes(tri) + bytes(triNormal) + bytes(triUv) + bytes(r.vertexNormals)
                    + (triGroup == null ? 0 : 2L * triGroup.length);
            for (Accelerator a : r.structures.values()) b += a.memoryBytes();
            return b;
        }
    }

    private static long bytes(double[] a) { return a == null ? 0 : 8L * a.length; }
    private static long bytes(int[] a) { return a == null ? 0 : 4L * a.length; }

    /**
     * Position index of corner {@code corner} (0..2) of triangle {@code t}.
     *
     * @param t triangle index, 0 to {@link #triangleCount()} - 1
     * @param corner corner index, 0, 1 or 2
     * @return the index of the corner's position (a vertex index)
     */
    public int triangleVertex(int t, int corner) { return tri[3 * t + corner]; }

    private double[] computeVertexNormals() {
        double[] n = new double[pos.length];
        for (int t = 0; t < triangleCount; t++) {
            int a = 3 * tri[3 * t], b = 3 * tri[3 * t + 1], c = 3 * tri[3 * t + 2];
            double ux = pos[b] - pos[a], uy = pos[b + 1] - pos[a + 1], uz = pos[b + 2] - pos[a + 2];
            double vx = pos[c] - pos[a], vy = pos[c + 1] - pos[a + 1], vz = pos[c + 2] - pos[a + 2];
            // The unnormalised cross product is twice the area: summing it weights by area.
            double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            n[a] += nx; n[a + 1] += ny; n[a + 2] += nz;
            n[b] += nx; n[b + 1] += ny; n[b + 2] += nz;
            n[c] += nx; n[c + 1] += ny; n[c + 2] += nz;
        }
        return n;
    }

    /**
     * Edges used by exactly one triangle, vertices merged by position as for {@link #isClosed()}:
     * the edges along the holes of an open mesh (0 for a closed one; an edge shared by three or
     * more triangles also keeps a mesh from being closed but is not a boundary edge).
     *
     * @return the number of boundary edges, 0 for a closed mesh
     */
    public int boundaryEdgeCount() {
        return MeshTopology.boundaryEdgeCount(tri, triangleCount, root().pos); // the owner's: an unfrozen instance's may predate the renumbering
    }

    // ---- GObject ----

    // ---- builder methods, returning this type (see GObject for what each does) ----

    /** {@inheritDoc} */
    @Override public TriangleMesh transform(Transform t) { super.transform(t); return this; }

    /** {@inheritDoc} */
    @Override public TriangleMesh motion(Motion m) { super.motion(m); return this; }

    /** {@inheritDoc} */
    @Override public TriangleMesh material(Material m) { super.material(m); return this; }

    /** {@inheritDoc} */
    @Override public TriangleMesh name(String n) { super.name(n); return this; }

    /** {@inheritDoc} */
    @Override public TriangleMesh source(String where) { super.source(where); return this; }

    /** {@inheritDoc} */
    @Override public TriangleMesh source(String file, int line, int column) { super.source(file, line, column); return this; }

    @Override public String kind() { return "mesh"; }
    @Override public Bounds localBounds() { return bounds; }
    @Override public boolean isClosed() { return closed; }

    @Override public boolean flat() { return flat; }

    /**
     * True if every vertex of the k triangles lies on the plane of the first, to within 1e-12 of
     * the bounds' size: far below the offset a shadow ray starts at, so no such ray can meet the
     * mesh again.
     */
    private static boolean planar(int[] tri, int k, double[] pos, Bounds b) {
        int a = 3 * tri[0], c1 = 3 * tri[1], c2 = 3 * tri[2];
        double ux = pos[c1] - pos[a], uy = pos[c1 + 1] - pos[a + 1], uz = pos[c1 + 2] - pos[a + 2];
        double vx = pos[c2] - pos[a], vy = pos[c2 + 1] - pos[a + 1], vz = pos[c2 + 2] - pos[a + 2];
        double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        double len = Math.sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 0)) return false;
        nx /= len; ny /= len; nz /= len;
        double size = Math.max(b.maxX() - b.minX(), Math.max(b.maxY() - b.minY(), b.maxZ() - b.minZ()));
        double tolerance = 1e-12 * size;
        for (int i = 0; i < 3 * k; i++) {
            int v = 3 * tri[i];
            double d = (pos[v] - pos[a]) * nx + (pos[v + 1] - pos[a + 1]) * ny + (pos[v + 2] - pos[a + 2]) * nz;
            if (!(Math.abs(d) <= tolerance)) return false;
        }
        return true;
    }

    /** Places the mesh and takes the shared structure of the context's kind, built if it is the first to ask. */
    @Override
    protected int freeze(BuildContext context, int ids) {
        int next = super.freeze(context, ids);
        TriangleMesh r = root();
        synchronized (r) {
            try {
                accel = r.structure(context.accelerator());
            } catch (IllegalArgumentException e) {
                throw SceneBuildException.of(this, e);
            }
            // The first structure may have renumbered the vertices into a new array: read it after.
            pos = r.pos;
            vertexNormals = smooth && needsVertexNormals ? r.sharedVertexNormals() : null;
        }
        return next;
    }

    @Override
    protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) {
        return accel.intersect(ray, hit, ctx);
    }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) {
        ctx.blockingPrimitive = -1; // set again by the triangle test that blocks
        return accel.occluded(toLocal(ray, ctx), ctx);
    }

    /** The triangle that blocked: the structure's leaves test this mesh's own triangles. */
    @Override
    int blockingPart(TraceContext ctx) { return ctx.blockingPrimitive; }

    @Override
    boolean occludedByPart(Ray ray, int part, TraceContext ctx) {
        return WatertightTriangles.test(tri, pos, null, part, part + 1, toLocal(ray, ctx), null, ctx);
    }

    @Override
    protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {
        TriangleShading.shade(tri, pos, smooth, triNormal, normals, vertexNormals, triUv, uvs, hit.prim, hit.u, hit.v, sd);
    }

    /** The crossings of the whole line, paired into spans: see {@code TriangleSpans.spans}. */
    @Override
    protected void spansLocal(Ray ray, SpanBuffer out, TraceContext ctx) {
        TriangleSpans.spans(accel, crossingCollector, this, ray, out, ctx);
    }

    private void collectCrossing(int i, Ray ray, TraversalScratch traversal) {
        // The structure hands back the context spansLocal gave it; the crossing list is the scene's scratch.
        TriangleSpans.addCrossing(tri, pos, i, ray, (TraceContext) traversal);
    }

    // ---- PrimitiveSet: the triangles, in object space ----

    @Override public int size() { return triangleCount; }

    @Override
    public void bounds(int i, double[] out) { WatertightTriangles.bounds(tri, pos, i, out); }

    @Override
    public void corners(int i, double[] out) {
        for (int c = 0; c < 3; c++) {
            int p = 3 * tri[3 * i + c];
            out[3 * c] = pos[p]; out[3 * c + 1] = pos[p + 1]; out[3 * c + 2] = pos[p + 2];
        }
    }

    @Override
    public double maxAbsCoordinate() {
        double m = 0;
        for (double p : pos) m = Math.max(m, Math.abs(p));
        return m;
    }

    /**
     * Puts the triangles in the structure's leaf order and numbers the vertices by first use in
     * that order, so a ray's triangle tests read nearby memory instead of jumping across the
     * whole mesh. Called once, at freeze, before any ray; triangle indices (hit.prim,
     * {@link #triangleVertex}, {@link #data()}) refer to this order afterwards.
     */
    @Override
    public boolean reorder(int[] order) {
        int n = triangleCount;
        // Only the geometry's owner, and only before any structure (which would index the old order) exists.
        if (order.length != n || prototype != null || !structures.isEmpty()) return false;
        // Called from inside a fork/join pool (the parallel BVH build does), the copies are split
        // across it; each element lands where the serial copy puts it.
        boolean fork = ForkJoinTask.inForkJoinPool();
        permuteTriangles(tri, order, fork);
        if (triNormal != null) permuteTriangles(triNormal, order, fork);
        if (triUv != null) permuteTriangles(triUv, order, fork);
        if (triGroup != null) {
            short[] old = triGroup.clone();
            for (int k = 0; k < n; k++) triGroup[k] = old[order[k]];
        }
        int nv = pos.length / 3;
        int[] newId = new int[nv];
        Arrays.fill(newId, -1);
        int next = 0;
        for (int k = 0; k < tri.length; k++) {
            int v = tri[k];
            if (newId[v] < 0) newId[v] = next++;
            tri[k] = newId[v];
        }
        for (int v = 0; v < nv; v++) if (newId[v] < 0) newId[v] = next++; // unused vertices keep a slot at the end
        pos = permuteVertices(pos, newId, fork);
        if (vertexNormals != null) vertexNormals = permuteVertices(vertexNormals, newId, fork);
        return true;
    }

    /** Ranges of at least this many triangles or vertices are copied in two halves on the pool. */
    private static final int COPY_GRAIN = 1 << 16;

    private static void permuteTriangles(int[] a, int[] order, boolean fork) {
        int[] old = a.clone();
        forRange(0, order.length, fork, (lo, hi) -> {
            for (int k = lo; k < hi; k++) {
                int o = 3 * order[k], t = 3 * k;
                a[t] = old[o]; a[t + 1] = old[o + 1]; a[t + 2] = old[o + 2];
            }
        });
    }

    /** A renumbered copy: the positions may be shared with other meshes made from the same data. */
    private static double[] permuteVertices(double[] a, int[] newId, boolean fork) {
        double[] out = new double[a.length];
        forRange(0, newId.length, fork, (lo, hi) -> {
            for (int v = lo; v < hi; v++) {
                int o = 3 * newId[v], f = 3 * v;
                out[o] = a[f]; out[o + 1] = a[f + 1]; out[o + 2] = a[f + 2];
            }
        });
        return out;
    }

    /** Work on a range [lo, hi) of indices. */
    @FunctionalInterface
    private interface RangeWork { void run(int lo, int hi); }

    /** Does {@code work} on [lo, hi): in halves on the current fork/join pool when {@code fork} and the range is large. */
    private static void forRange(int lo, int hi, boolean fork, RangeWork work) {
        if (fork && hi - lo >= 2 * COPY_GRAIN) {
            int mid = (lo + hi) >>> 1;
            ForkJoinTask.invokeAll(ForkJoinTask.adapt(() -> forRange(lo, mid, true, work)),
                    ForkJoinTask.adapt(() -> forRange(mid, hi, true, work)));
        } else {
            work.run(lo, hi);
        }
    }

    @Override
    public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        return WatertightTriangles.test(tri, pos, null, i, i + 1, ray, hit, ctx);
    }

    @Override
    public boolean occluded(int i, Ray ray, TraversalScratch ctx) {
        return WatertightTriangles.test(tri, pos, null, i, i + 1, ray, null, ctx);
    }

    @Override
    public boolean intersectRange(int[] prims, int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        return WatertightTriangles.test(tri, pos, prims, from, to, ray, hit, ctx);
    }

    @Override
    public boolean occludedRange(int[] prims, int from, int to, Ray ray, TraversalScratch ctx) {
        return WatertightTriangles.test(tri, pos, prims, from, to, ray, null, ctx);
    }
}
