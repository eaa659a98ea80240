package lt.spindulys.scene;

import lt.spindulys.math.Placement;
import lt.spindulys.math.Ray;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;
import lt.spindulys.trace.TraceContext;

/**
 * The tessellation of one adaptive subdivision surface in one scene build, shared by every
 * instance of it: chosen from the view once every placement is known ({@link #finish}), then
 * queried in object space by the render threads. Two kinds: {@link GridTessellation} (integer
 * rates per control edge, the limit surface evaluated on grids: what a target means by default)
 * and {@link AdaptiveTessellation} (the thesis's power-of-two levels, per edge or per object).
 */
interface SurfaceTessellation {
    /**
     * Records one placement (object to world over the shutter) of a surface using this
     * tessellation; {@code backHidden} when the camera cannot see the surface's back faces there
     * (a closed, opaque surface outside any CSG solid).
     */
    void addPlacement(Placement p, boolean backHidden);

    /** Chooses the tessellation and builds its eager part; called once, after every placement is known. */
    void finish(BuildShared shared, BuildContext root);

    /** True if some part is built on demand while tracing. */
    boolean refinesWhileTracing();

    boolean intersect(Ray ray, Hit hit, TraceContext ctx);

    boolean occluded(Ray ray, TraceContext ctx);

    /** Appends the spans of {@code owner} along the ray (object space) for CSG. */
    void spans(Ray ray, SpanBuffer out, TraceContext ctx, GObject owner);

    void shade(double x, double y, double z, Hit hit, ShadingData sd);

    /** The control face group of a hit's primitive and part, or -1. */
    int faceGroup(int prim, int sub);

    /** The whole tessellation as one welded, crack-free mesh (object space). */
    MeshData welded();

    /** Per control edge, the power-of-two level its tessellation corresponds to. */
    int[] edgeLevels();

    /** One line for --stats. */
    String statistics();

    /** Triangles of the tessellation (every face, built or not), for --stats. */
    long triangleCount();
}
