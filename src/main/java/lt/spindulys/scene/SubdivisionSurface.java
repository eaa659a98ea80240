package lt.spindulys.scene;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;

/**
 * A Catmull-Clark subdivision surface: a control mesh refined uniformly to a fixed level once, at
 * construction, and rendered as the triangles of the refined quads. Hole faces are left out; each
 * quad is split into two triangles along its shorter diagonal. Smooth shading interpolates the
 * limit-surface normals of the refined vertices, which makes even a low level look round; flat
 * shading uses each triangle's own normal and shows the facets.
 *
 * <p>The triangles are an ordinary {@link TriangleMesh} (positions of the refined vertices, limit
 * normals, refined face-varying UVs), and every query is delegated to it: the surface hits,
 * shades and reports spans exactly as that mesh does, and it is closed (has an inside, for
 * refraction and CSG) when the refined mesh is.
 */
public final class SubdivisionSurface extends GObject {
    /** The deepest level: a quad becomes 4^8 = 65,536 quads. */
    public static final int MAX_LEVEL = 8;

    private final int level;
    private final boolean smooth;
    private final RefinedMesh refined;
    private final TriangleMesh mesh;

    /** The surface at {@code level} with smooth shading. */
    public SubdivisionSurface(ControlMesh control, int level) {
        this(control, level, true);
    }

    /**
     * Refines {@code control} {@code level} times and builds the triangles.
     *
     * @param smooth limit normals interpolated (true) or flat facets
     * @throws IllegalArgumentException if the level is not between 0 and {@link #MAX_LEVEL}
     */
    public SubdivisionSurface(ControlMesh control, int level, boolean smooth) {
        checkLevel(level);
        this.level = level;
        this.smooth = smooth;
        this.refined = CatmullClark.refine(control, level);
        this.mesh = new TriangleMesh(triangles(refined, smooth));
        mesh.smooth(smooth);
        // The inner mesh is never part of a scene; frozen in place, its own queries (occluded)
        // take the object-space rays this surface hands it unchanged.
        mesh.freeze(Transform.IDENTITY, null, 0);
    }

    /**
     * Refuses a level outside 0..{@link #MAX_LEVEL}; returns it otherwise.
     *
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
     * @param refinedFaces the faces the control mesh has after {@code level} refinements
     */
    public static int checkLevel(int level, long refinedFaces) {
        checkLevel(level);
        if (refinedFaces > MAX_FACES) {
            throw new IllegalArgumentException("subdivision level " + level + " would make " + refinedFaces + " faces from this mesh, more than the "
                    + MAX_FACES + " allowed (choose a lower level)");
        }
        return level;
    }

    /**
     * The triangles of a refined mesh as MeshData: its positions, its limit normals (smooth
     * shading only: one per vertex, indexed like the positions) and its face-varying UVs; quads
     * split along the shorter diagonal, other polygons (at level 0) left to TriangleMesh's fans,
     * holes dropped.
     */
    static MeshData triangles(RefinedMesh r, boolean smooth) {
        double[] p = r.positions();
        int[] sizes = r.faceSizes(), fv = r.faceVertices(), fuv = r.faceUvs();
        double[] uvs = r.uvs();
        boolean withUv = uvs != null && fuv != null;
        int faces = 0, corners = 0;
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            if (r.isHole(f)) continue;
            faces += sizes[f] == 4 ? 2 : 1;
            corners += sizes[f] == 4 ? 6 : sizes[f];
        }
        int[] outSizes = new int[faces], outV = new int[corners], outUv = withUv ? new int[corners] : null;
        int o = 0, k = 0;
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            if (r.isHole(f)) continue;
            if (sizes[f] == 4) {
                int a = fv[c], b = fv[c + 1], cc = fv[c + 2], d = fv[c + 3];
                // The shorter diagonal keeps the two triangles closest to the (curved) quad.
                int s = dist2(p, a, cc) <= dist2(p, b, d) ? 0 : 1;
                int[] order = s == 0 ? SPLIT_AC : SPLIT_BD;
                for (int j : order) {
                    outV[k] = fv[c + j];
                    if (withUv) outUv[k] = fuv[c + j];
                    k++;
                }
                outSizes[o++] = 3;
                outSizes[o++] = 3;
            } else {
                for (int j = 0; j < sizes[f]; j++) {
                    outV[k] = fv[c + j];
                    if (withUv) outUv[k] = fuv[c + j];
                    k++;
                }
                outSizes[o++] = sizes[f];
            }
        }
        double[] normals = smooth ? r.limitNormals() : null;
        return new MeshData(p, normals, withUv ? uvs : null, outSizes, outV, smooth ? outV : null, outUv, null);
    }

    /** Corners of the two triangles of a quad abcd cut along ac, or along bd; both keep the winding. */
    private static final int[] SPLIT_AC = {0, 1, 2, 0, 2, 3}, SPLIT_BD = {0, 1, 3, 1, 2, 3};

    private static double dist2(double[] p, int a, int b) {
        double dx = p[3 * a] - p[3 * b], dy = p[3 * a + 1] - p[3 * b + 1], dz = p[3 * a + 2] - p[3 * b + 2];
        return dx * dx + dy * dy + dz * dz;
    }

    public int level() { return level; }
    public boolean isSmooth() { return smooth; }
    /** The refined mesh the triangles come from (holes included). */
    public RefinedMesh refined() { return refined; }
    public int triangleCount() { return mesh.triangleCount(); }

    // ---- GObject: everything through the triangle mesh ----

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
