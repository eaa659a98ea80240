package lt.spindulys.accel;

import jdk.incubator.vector.ByteVector;
import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.IntVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The eight-box slab test of a {@link WideBvh} node in one pass of 256-bit float vectors. The
 * only class that names the JDK's incubating Vector API, so nothing else fails to load when the
 * module is absent.
 */
final class SimdBoxes {
    private static final VectorSpecies<Float> S = FloatVector.SPECIES_256;
    private static final VectorSpecies<Byte> B = ByteVector.SPECIES_64;
    private static final VectorSpecies<Integer> I = IntVector.SPECIES_256;
    /**
     * Relative widening of every computed distance: each is three float roundings away from the
     * exact value for the (shifted) float origin, and 8 ulps leave room to spare.
     */
    private static final float GAMMA = 8 * 0x1p-24f;

    private SimdBoxes() {}

    /** Whether 8-lane float vectors are compiled to single instructions on this machine. */
    static boolean supported() {
        return FloatVector.SPECIES_PREFERRED.vectorBitSize() >= 256;
    }

    /**
     * Tests the eight boxes of a node: their planes are bytes {@code q[o..o+47]} (min x of the
     * eight children, max x, min y, ... as rows of eight), each decoded as base + q * scale with
     * the node's frame {@code frame[f..f+5]} (base x, y, z, scale x, y, z). Writes each box's
     * widened entry distance to {@code dist[0..7]} and returns the lanes hit as bits.
     */
    static int test(byte[] q, int o, float[] frame, int f, int nx, int ny, int nz,
                    float oxn, float oxf, float oyn, float oyf, float ozn, float ozf,
                    float ix, float iy, float iz, float tMin, float tMax, float[] dist) {
        float bx = frame[f], by = frame[f + 1], bz = frame[f + 2], sx = frame[f + 3], sy = frame[f + 4], sz = frame[f + 5];
        FloatVector t0 = plane(q, o + nx, sx, bx).sub(oxn).mul(ix);
        FloatVector t1 = plane(q, o + (8 - nx), sx, bx).sub(oxf).mul(ix);
        t0 = t0.max(plane(q, o + 16 + ny, sy, by).sub(oyn).mul(iy));
        t1 = t1.min(plane(q, o + 16 + (8 - ny), sy, by).sub(oyf).mul(iy));
        t0 = t0.max(plane(q, o + 32 + nz, sz, bz).sub(ozn).mul(iz));
        t1 = t1.min(plane(q, o + 32 + (8 - nz), sz, bz).sub(ozf).mul(iz));
        t0 = t0.max(tMin);
        t1 = t1.min(tMax);
        t0 = t0.abs().mul(-GAMMA).add(t0);
        t1 = t1.abs().mul(GAMMA).add(t1);
        VectorMask<Float> m = t0.compare(VectorOperators.LE, t1);
        // The lanes hit are read back from the stored distances, not with VectorMask.toLong():
        // JDK 17 does not compile that to an instruction, which made the whole render slower
        // (docs/performance.md, the wide vector BVH).
        if (!m.anyTrue()) return 0;
        t0.blend(Float.POSITIVE_INFINITY, m.not()).intoArray(dist, 0);
        int bits = 0;
        for (int i = 0; i < 8; i++) bits |= (dist[i] < Float.POSITIVE_INFINITY ? 1 : 0) << i;
        return bits;
    }

    /** Eight planes: the signed bytes q[o..o+7] as floats, times scale, plus base (as {@link WideBvh#decode}). */
    private static FloatVector plane(byte[] q, int o, float scale, float base) {
        return ((FloatVector) ByteVector.fromArray(B, q, o).convertShape(VectorOperators.B2F, S, 0)).mul(scale).add(base);
    }

    /**
     * The same test of eight boxes stored as float bits: {@code planes[o..o+47]} are min x of the eight, max x,
     * min y, ... as rows of eight ({@link GridPatch}'s node records).
     */
    static int test(int[] planes, int o, int nx, int ny, int nz,
                    float oxn, float oxf, float oyn, float oyf, float ozn, float ozf,
                    float ix, float iy, float iz, float tMin, float tMax, float[] dist) {
        FloatVector t0 = row(planes, o + nx).sub(oxn).mul(ix);
        FloatVector t1 = row(planes, o + (8 - nx)).sub(oxf).mul(ix);
        t0 = t0.max(row(planes, o + 16 + ny).sub(oyn).mul(iy));
        t1 = t1.min(row(planes, o + 16 + (8 - ny)).sub(oyf).mul(iy));
        t0 = t0.max(row(planes, o + 32 + nz).sub(ozn).mul(iz));
        t1 = t1.min(row(planes, o + 32 + (8 - nz)).sub(ozf).mul(iz));
        t0 = t0.max(tMin);
        t1 = t1.min(tMax);
        t0 = t0.abs().mul(-GAMMA).add(t0);
        t1 = t1.abs().mul(GAMMA).add(t1);
        VectorMask<Float> m = t0.compare(VectorOperators.LE, t1);
        if (!m.anyTrue()) return 0;
        t0.blend(Float.POSITIVE_INFINITY, m.not()).intoArray(dist, 0);
        int bits = 0;
        for (int i = 0; i < 8; i++) bits |= (dist[i] < Float.POSITIVE_INFINITY ? 1 : 0) << i;
        return bits;
    }

    /** Eight floats stored as bits at p[o..o+7]. */
    private static FloatVector row(int[] p, int o) {
        return IntVector.fromArray(I, p, o).reinterpretAsFloats();
    }
}
