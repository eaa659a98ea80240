package lt.spindulys.scene;

import java.util.Arrays;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.PrimitiveVisitor;
import lt.spindulys.math.Ray;
import lt.spindulys.trace.SpanBuffer;
import lt.spindulys.trace.TraceContext;

/**
 * The spans CSG asks of a closed surface made of indexed triangles (three position indices per
 * triangle in {@code tri}, x, y, z per position in {@code pos}): the crossings of the whole line
 * with the triangles, sorted, with the duplicates a line through a shared edge or vertex produces
 * merged, and entering crossings paired with leaving ones into the intervals inside. Works on the
 * arrays and a structure over them, not on a mesh object, so that any closed triangle surface can
 * report its spans. The crossing list is the per-thread scratch of the {@link TraceContext}, so
 * nothing is allocated per ray once it has grown.
 */
final class TriangleSpans {
    private TriangleSpans() {}

    /**
     * Appends to {@code out} the spans of {@code owner} along {@code ray} that overlap
     * (ray.tMin, ray.tMax), with their true endpoints. Collects every crossing of the whole line
     * (ignoring tMin/tMax, so the inside state at any t is known) by visiting {@code accel} with
     * {@code collector} (which calls {@link #addCrossing} for the triangles it is given), sorts
     * them, merges the duplicates, and pairs entering (against the outward normal) with leaving
     * crossings by a running count.
     */
    static void spans(Accelerator accel, PrimitiveVisitor collector, GObject owner, Ray ray, SpanBuffer out, TraceContext ctx) {
        double tMin = ray.tMin, tMax = ray.tMax;
        ctx.crossingCount = 0;
        ray.tMin = Double.NEGATIVE_INFINITY;
        ray.tMax = Double.POSITIVE_INFINITY;
        try {
            accel.visit(ray, ctx, collector);
        } finally {
            ray.tMin = tMin;
            ray.tMax = tMax;
        }
        int n = ctx.crossingCount;
        double[] c = ctx.crossings;
        sortCrossings(c, n);
        int inside = 0, start = -1;
        for (int k = 0; k < n; k++) {
            int o = 4 * k;
            boolean entering = c[o + 1] >= 0;
            if (k > 0 && c[o] == c[o - 4] && entering == (c[o - 3] >= 0)) continue; // same point, same facing
            if (entering) {
                if (inside++ == 0) start = o;
            } else if (inside > 0 && --inside == 0) {
                // Zero-length spans (a line grazing an edge or vertex from outside) enclose nothing.
                double tIn = c[start], tOut = c[o];
                if (tOut > tIn && tOut > tMin && tIn < tMax) {
                    long in = (long) c[start + 1], outId = (long) (-1 - c[o + 1]);
                    out.add(tIn, owner, (int) (in & PRIM_MASK), (int) (in >>> SUB_SHIFT), c[start + 2], c[start + 3],
                            tOut, owner, (int) (outId & PRIM_MASK), (int) (outId >>> SUB_SHIFT), c[o + 2], c[o + 3]);
                }
            }
            // A leaving crossing while outside can only come from an inconsistently wound mesh; ignored.
        }
    }

    /**
     * Appends the crossing of the line with triangle {@code i}, if any, to the context's
     * crossing list as (t, code, u, v) with code = i when entering and -1 - i when leaving. The
     * line is sheared as in the watertight ray test ({@link lt.spindulys.accel.WatertightTriangles}),
     * and a line through an edge or vertex gets a t that depends only on that edge or vertex, so
     * the duplicates from the triangles sharing it compare exactly equal.
     */
    static void addCrossing(int[] tri, double[] pos, int i, Ray ray, TraceContext ctx) {
        addCrossing(tri, pos, i, i, 0, ray, ctx);
    }

    /** A crossing's primitive and part are packed into one double: part above bit 31, exact below 2^53. */
    private static final int SUB_SHIFT = 31;
    private static final long PRIM_MASK = (1L << SUB_SHIFT) - 1;

    /**
     * {@link #addCrossing(int[], double[], int, Ray, TraceContext)} of triangle {@code i} of the
     * arrays, recorded as primitive {@code prim} with part {@code sub} (a lazily refined patch and
     * its triangle; sub below 2^21).
     */
    static void addCrossing(int[] tri, double[] pos, int i, int prim, int sub, Ray ray, TraceContext ctx) {
        final int i3 = 3 * i;
        final int a = 3 * tri[i3], b = 3 * tri[i3 + 1], c = 3 * tri[i3 + 2];
        addCrossing(pos[a], pos[a + 1], pos[a + 2], pos[b], pos[b + 1], pos[b + 2], pos[c], pos[c + 1], pos[c + 2], prim, sub, ray, ctx);
    }

    /**
     * {@link #addCrossing(int[], double[], int, int, int, Ray, TraceContext)} of the triangle with
     * corners a, b, c given by their coordinates (a grid's triangle, whose corners are implicit).
     */
    static void addCrossing(double pax, double pay, double paz, double pbx, double pby, double pbz, double pcx, double pcy, double pcz,
                            int prim, int sub, Ray ray, TraceContext ctx) {
        ctx.direction(ray);
        final int kx = ctx.shearKx, ky = ctx.shearKy, kz = ctx.shearKz;
        final double sx = ctx.shearSx, sy = ctx.shearSy, sz = ctx.shearSz;
        final double okx = kx == 0 ? ray.ox : kx == 1 ? ray.oy : ray.oz;
        final double oky = ky == 0 ? ray.ox : ky == 1 ? ray.oy : ray.oz;
        final double okz = kz == 0 ? ray.ox : kz == 1 ? ray.oy : ray.oz;
        final double az = pick(pax, pay, paz, kz) - okz, bz = pick(pbx, pby, pbz, kz) - okz, cz = pick(pcx, pcy, pcz, kz) - okz;
        final double ax = pick(pax, pay, paz, kx) - okx - sx * az, ay = pick(pax, pay, paz, ky) - oky - sy * az;
        final double bx = pick(pbx, pby, pbz, kx) - okx - sx * bz, by = pick(pbx, pby, pbz, ky) - oky - sy * bz;
        final double cx = pick(pcx, pcy, pcz, kx) - okx - sx * cz, cy = pick(pcx, pcy, pcz, ky) - oky - sy * cz;
        final double u = cx * by - cy * bx, v = ax * cy - ay * cx, w = bx * ay - by * ax;
        if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return;
        final double det = u + v + w;
        if (det == 0) return;
        final double saz = sz * az, sbz = sz * bz, scz = sz * cz;
        double t;
        if (u != 0 && v != 0 && w != 0) {
            t = (u * saz + v * sbz + w * scz) / det;
        } else if (v == 0 && w == 0) {
            t = saz;
        } else if (u == 0 && w == 0) {
            t = sbz;
        } else if (u == 0 && v == 0) {
            t = scz;
        } else if (u == 0) {
            t = edgeT(bx, by, sbz, cx, cy, scz);
        } else if (v == 0) {
            t = edgeT(ax, ay, saz, cx, cy, scz);
        } else {
            t = edgeT(ax, ay, saz, bx, by, sbz);
        }
        int k = ctx.crossingCount, o = 4 * k;
        double[] list = ctx.crossings;
        if (o + 4 > list.length) list = ctx.crossings = Arrays.copyOf(list, Math.max(2 * list.length, 64));
        double inv = 1 / det;
        list[o] = t;
        // The signed projected area det is positive exactly when dot(ng, d) < 0: the line enters.
        double id = (double) (((long) sub << SUB_SHIFT) | prim);
        list[o + 1] = det > 0 ? id : -1 - id;
        list[o + 2] = v * inv;
        list[o + 3] = w * inv;
        ctx.crossingCount = k + 1;
    }

    /** Coordinate k (0 x, 1 y, 2 z) of a point. */
    private static double pick(double x, double y, double z, int k) { return k == 0 ? x : k == 1 ? y : z; }

    /**
     * Where the line (the sheared origin, (0, 0)) crosses edge pq, computed from the two ends in a
     * fixed order so that both triangles sharing the edge get the identical value.
     */
    private static double edgeT(double px, double py, double pz, double qx, double qy, double qz) {
        if (px > qx || px == qx && (py > qy || py == qy && pz > qz)) {
            double s = px; px = qx; qx = s;
            s = py; py = qy; qy = s;
            s = pz; pz = qz; qz = s;
        }
        double dx = qx - px, dy = qy - py;
        double f = Math.abs(dx) >= Math.abs(dy) ? -px / dx : -py / dy;
        return pz + f * (qz - pz);
    }

    /** Sorts (t, code, u, v) records by t, entering before leaving at equal t. */
    private static void sortCrossings(double[] c, int n) {
        if (n <= 32) {
            for (int i = 1; i < n; i++) {
                for (int j = i; j > 0 && before(c, j, j - 1); j--) swap(c, j, j - 1);
            }
            return;
        }
        // Heapsort: in place and O(n log n) for the rare line that crosses a dense mesh many times.
        for (int i = n / 2 - 1; i >= 0; i--) siftDown(c, i, n);
        for (int end = n - 1; end > 0; end--) {
            swap(c, 0, end);
            siftDown(c, 0, end);
        }
    }

    private static void siftDown(double[] c, int i, int n) {
        while (true) {
            int l = 2 * i + 1;
            if (l >= n) return;
            int m = l + 1 < n && before(c, l, l + 1) ? l + 1 : l;
            if (!before(c, i, m)) return;
            swap(c, i, m);
            i = m;
        }
    }

    private static boolean before(double[] c, int i, int j) {
        double ti = c[4 * i], tj = c[4 * j];
        return ti < tj || ti == tj && c[4 * i + 1] >= 0 && c[4 * j + 1] < 0;
    }

    private static void swap(double[] c, int i, int j) {
        for (int k = 0; k < 4; k++) {
            double s = c[4 * i + k];
            c[4 * i + k] = c[4 * j + k];
            c[4 * j + k] = s;
        }
    }
}
