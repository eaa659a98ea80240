package lt.spindulys.accel;

import lt.spindulys.math.Ray;

/**
 * The watertight ray/triangle test (Woop, Benthin and Wald, "Watertight Ray/Triangle
 * Intersection", JCGT 2013) of indexed triangles held in flat arrays: three position indices per
 * triangle in {@code tri}, x, y, z per position in {@code pos}. A ray through an edge or vertex
 * shared by several triangles hits at least one of them, so closed meshes have no cracks. Works
 * on the arrays alone (no mesh object), so that any primitive set made of triangles can test
 * them; the per-direction constants come from the caller's {@link TraversalScratch}.
 *
 * <p>A hit records the triangle index as {@code prim} and the barycentric weights of its second
 * and third corner as {@code u}, {@code v}.
 */
public final class WatertightTriangles {
    private WatertightTriangles() {}

    /**
     * The box of triangle {@code i} (three position indices per triangle in {@code tri}, x, y, z
     * per position in {@code pos}) as minX, minY, minZ, maxX, maxY, maxZ into {@code out[0..5]}.
     *
     * @param tri three position indices per triangle
     * @param pos three coordinates per position
     * @param i the triangle
     * @param out receives six doubles
     */
    public static void bounds(int[] tri, double[] pos, int i, double[] out) {
        int a = 3 * tri[3 * i], b = 3 * tri[3 * i + 1], c = 3 * tri[3 * i + 2];
        for (int k = 0; k < 3; k++) {
            out[k] = Math.min(pos[a + k], Math.min(pos[b + k], pos[c + k]));
            out[k + 3] = Math.max(pos[a + k], Math.max(pos[b + k], pos[c + k]));
        }
    }

    /**
     * The test of triangles prims[from..to) (or from..to themselves when prims is null), with the
     * per-ray constants read once. Vertices are translated to the ray origin, permuted so the ray
     * runs along the (new) z axis and sheared so it becomes the z axis itself; the 2D edge
     * functions of the vertices then decide the hit. Each vertex is transformed the same way
     * whichever triangle it is used by, and an edge's function in one triangle is exactly the
     * negation of its function in the neighbour (products commute, IEEE subtraction is
     * antisymmetric), so a ray can never pass between two triangles that share the edge. With
     * {@code hit} null this is an any-hit query and returns at the first hit (its triangle left in
     * {@link TraversalScratch#blockingPrimitive}); otherwise every hit
     * nearer than ray.tMax is recorded and shrinks ray.tMax.
     */
    public static boolean test(int[] tri, double[] pos, int[] prims, int from, int to, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
        ctx.direction(ray);
        final int kx = ctx.shearKx, ky = ctx.shearKy, kz = ctx.shearKz;
        final double sx = ctx.shearSx, sy = ctx.shearSy, sz = ctx.shearSz;
        final double okx = kx == 0 ? ray.ox : kx == 1 ? ray.oy : ray.oz;
        final double oky = ky == 0 ? ray.ox : ky == 1 ? ray.oy : ray.oz;
        final double okz = kz == 0 ? ray.ox : kz == 1 ? ray.oy : ray.oz;
        final double tMin = ray.tMin;
        boolean any = false;
        for (int k = from; k < to; k++) {
            if (TraversalScratch.COUNTING) ctx.triangleTests[ctx.rayKind]++;
            final int i = prims == null ? k : prims[k];
            final int i3 = 3 * i;
            final int a = 3 * tri[i3], b = 3 * tri[i3 + 1], c = 3 * tri[i3 + 2];
            final double az = pos[a + kz] - okz, bz = pos[b + kz] - okz, cz = pos[c + kz] - okz;
            final double ax = pos[a + kx] - okx - sx * az, ay = pos[a + ky] - oky - sy * az;
            final double bx = pos[b + kx] - okx - sx * bz, by = pos[b + ky] - oky - sy * bz;
            final double cx = pos[c + kx] - okx - sx * cz, cy = pos[c + ky] - oky - sy * cz;
            final double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
            if (Math.min(u, Math.min(v, w)) < 0 && Math.max(u, Math.max(v, w)) > 0) continue; // signs differ: outside
            final double det = u + v + w;
            if (det == 0) continue;
            final double t = (u * (sz * az) + v * (sz * bz) + w * (sz * cz)) / det;
            if (!(t > tMin && t < ray.tMax)) continue;
            if (hit == null) {
                ctx.blockingPrimitive = i;
                return true;
            }
            double inv = 1 / det;
            hit.t = t;
            hit.prim = i;
            hit.u = v * inv;
            hit.v = w * inv;
            ray.tMax = t;
            any = true;
        }
        return any;
    }
}
