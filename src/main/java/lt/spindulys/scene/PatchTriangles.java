package lt.spindulys.scene;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.PrimitiveVisitor;
import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.accel.WatertightTriangles;
import lt.spindulys.math.Ray;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;

/**
 * The triangles of one coarse face of an adaptive subdivision surface, refined on demand: flat
 * arrays as a {@link TriangleMesh} keeps them (three position indices per triangle, per-corner
 * normal and uv indices) with a small structure of their own. Immutable once made, so any number
 * of render threads may read one; a cache may drop it while a thread still holds it.
 */
final class PatchTriangles implements TessellationPiece, PrimitiveSet {
    /** The top structure's primitive this patch refines (spans name it). */
    final int prim;
    final int[] tri, triNormal, triUv;
    final double[] pos, normals, uvs;
    final int triangleCount;
    final Accelerator accel;
    private final long bytes;
    /** Made once so that collecting crossings allocates nothing per ray. */
    final PrimitiveVisitor crossingCollector = this::collectCrossing;

    /** Triangulates {@code d} (fans for polygons, as {@link TriangleMesh} does) and builds a structure of the given kind. */
    PatchTriangles(int prim, MeshData d, AcceleratorKind kind) {
        this.prim = prim;
        int[] sizes = d.faceSizes(), vi = d.vertexIndex(), ni = d.normalIndex(), ti = d.uvIndex();
        int n = 0;
        for (int s : sizes) n += s - 2;
        triangleCount = n;
        tri = new int[3 * n];
        triNormal = ni != null ? new int[3 * n] : null;
        triUv = ti != null ? new int[3 * n] : null;
        int k = 0, corner = 0;
        for (int size : sizes) {
            for (int j = 1; j + 1 < size; j++, k += 3) {
                int ca = corner, cb = corner + j, cc = corner + j + 1;
                tri[k] = vi[ca]; tri[k + 1] = vi[cb]; tri[k + 2] = vi[cc];
                if (triNormal != null) { triNormal[k] = ni[ca]; triNormal[k + 1] = ni[cb]; triNormal[k + 2] = ni[cc]; }
                if (triUv != null) { triUv[k] = ti[ca]; triUv[k + 1] = ti[cb]; triUv[k + 2] = ti[cc]; }
            }
            corner += size;
        }
        pos = d.positions();
        normals = d.normals();
        uvs = d.uvs();
        accel = kind.buildOnThisThread(this);
        bytes = 96 + 4L * (tri.length + len(triNormal) + len(triUv)) + 8L * (pos.length + len(normals) + len(uvs)) + accel.memoryBytes();
    }

    private static int len(int[] a) { return a == null ? 0 : a.length; }
    private static int len(double[] a) { return a == null ? 0 : a.length; }

    @Override public long bytes() { return bytes; }

    @Override public int triangleCount() { return triangleCount; }

    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraceContext ctx) {
        if (!accel.intersect(ray, hit, ctx)) return false;
        hit.sub = hit.prim;
        return true;
    }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) { return accel.occluded(ray, ctx); }

    /** {@inheritDoc} The primitive is the one this patch was made for. */
    @Override
    public void addCrossings(int prim, Ray ray, TraceContext ctx) { accel.visit(ray, ctx, crossingCollector); }

    @Override
    public void shade(boolean smooth, int sub, double u, double v, ShadingData sd) {
        TriangleShading.shade(tri, pos, smooth, triNormal, normals, null, triUv, uvs, sub, u, v, sd);
    }

    private void collectCrossing(int i, Ray ray, TraversalScratch traversal) {
        TriangleSpans.addCrossing(tri, pos, i, prim, i, ray, (TraceContext) traversal);
    }

    @Override
    public void include(double[] out) {
        for (int v = 0; v < pos.length; v += 3) {
            for (int a = 0; a < 3; a++) {
                out[a] = Math.min(out[a], pos[v + a]);
                out[a + 3] = Math.max(out[a + 3], pos[v + a]);
            }
        }
    }

    // ---- PrimitiveSet: the triangles ----

    @Override public int size() { return triangleCount; }

    @Override
    public void bounds(int i, double[] out) { WatertightTriangles.bounds(tri, pos, i, out); }

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
