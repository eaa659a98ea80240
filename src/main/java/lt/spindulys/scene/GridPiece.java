package lt.spindulys.scene;

import lt.spindulys.accel.GridPatch;
import lt.spindulys.accel.GridTriangleVisitor;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;

/**
 * A piece of a face's grid (at most about 17 x 17 vertices) on the limit surface: float positions,
 * normals and texture coordinates per vertex, and its {@link GridPatch} over them (implicit
 * topology, no triangle index stored).
 */
final class GridPiece implements TessellationPiece {
    final GridPatch grid;
    private final float[] xyz, normals, uvs;
    private final long bytes;

    /**
     * @param grid the grid over {@code xyz} (which it keeps, not copies)
     * @param xyz the positions, 3 per vertex
     * @param normals unit normals, 3 per vertex, or null (flat shading)
     * @param uvs texture coordinates, 2 per vertex, or null
     */
    GridPiece(GridPatch grid, float[] xyz, float[] normals, float[] uvs) {
        this.grid = grid;
        this.xyz = xyz;
        this.normals = normals;
        this.uvs = uvs;
        // The grid counts its positions and normals; the uvs and this object are ours.
        bytes = grid.bytes() + (uvs == null ? 0 : 16 + 4L * uvs.length) + 32;
    }

    @Override public long bytes() { return bytes; }

    @Override public int triangleCount() { return grid.triangleCount(); }

    @Override
    public boolean intersect(Ray ray, PrimitiveHit hit, TraceContext ctx) { return grid.intersect(ray, hit, ctx); }

    @Override
    public boolean occluded(Ray ray, TraceContext ctx) { return grid.occluded(ray, ctx); }

    @Override
    public void addCrossings(int prim, Ray ray, TraceContext ctx) {
        ctx.crossingPiece = prim;
        grid.visitTriangles(ray, ctx, CROSSING);
    }

    /** Adds a triangle's crossing, as part {@code sub} of the primitive the context names. */
    private static final GridTriangleVisitor CROSSING = (g, sub, ray, s) -> {
        TraceContext ctx = (TraceContext) s;
        TriangleSpans.addCrossing(g.cornerCoordinate(sub, 0, 0), g.cornerCoordinate(sub, 0, 1), g.cornerCoordinate(sub, 0, 2),
                g.cornerCoordinate(sub, 1, 0), g.cornerCoordinate(sub, 1, 1), g.cornerCoordinate(sub, 1, 2),
                g.cornerCoordinate(sub, 2, 0), g.cornerCoordinate(sub, 2, 1), g.cornerCoordinate(sub, 2, 2), ctx.crossingPiece, sub, ray, ctx);
    };

    @Override
    public void shade(boolean smooth, int sub, double u, double v, ShadingData sd) {
        double[] c = sd.corners;
        for (int k = 0; k < 3; k++) {
            int w = grid.triangleVertex(sub, k);
            for (int a = 0; a < 3; a++) c[3 * k + a] = xyz[3 * w + a];
            if (smooth && normals != null) for (int a = 0; a < 3; a++) c[TriangleShading.NORMALS + 3 * k + a] = normals[3 * w + a];
            if (uvs != null) {
                c[TriangleShading.UVS + 2 * k] = uvs[2 * w];
                c[TriangleShading.UVS + 2 * k + 1] = uvs[2 * w + 1];
            }
        }
        TriangleShading.shadeCorners(smooth && normals != null, uvs != null, u, v, sd);
    }

    /** The piece as a mesh: its vertices (as doubles), per-vertex normals and uvs where it has them, its triangles. */
    lt.spindulys.mesh.MeshData mesh() {
        double[] p = new double[xyz.length];
        for (int a = 0; a < p.length; a++) p[a] = xyz[a];
        double[] n = null, t = null;
        if (normals != null) {
            n = new double[normals.length];
            for (int a = 0; a < n.length; a++) n[a] = normals[a];
        }
        if (uvs != null) {
            t = new double[uvs.length];
            for (int a = 0; a < t.length; a++) t[a] = uvs[a];
        }
        int nt = grid.triangleCount();
        int[] sizes = new int[nt], vi = new int[3 * nt];
        java.util.Arrays.fill(sizes, 3);
        for (int q = 0; q < nt; q++) for (int k = 0; k < 3; k++) vi[3 * q + k] = grid.triangleVertex(q, k);
        return new lt.spindulys.mesh.MeshData(p, n, t, sizes, vi, n != null ? vi : null, t != null ? vi : null, null, null, null);
    }

    @Override
    public void include(double[] box) {
        double[] b = new double[6];
        grid.bounds(b);
        for (int a = 0; a < 3; a++) {
            box[a] = Math.min(box[a], b[a]);
            box[a + 3] = Math.max(box[a + 3], b[a + 3]);
        }
    }
}
