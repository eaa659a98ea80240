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

    /** Lane i holds the float whose bits are the integer 1 << i (never computed with, only blended). */
    private static final FloatVector LANE_BITS = IntVector.fromArray(I, new int[] {1, 2, 4, 8, 16, 32, 64, 128}, 0).reinterpretAsFloats();
    private static final FloatVector ZERO = FloatVector.zero(S);

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
        // The six rows decoded here and the tail written out (in both tests), not in helpers: a
        // helper C2 declines to inline boxes its vectors, and one more call site can push the
        // method past C2's inlining node budget (docs/performance.md, one record per wide node).
        // Maxima and minima are compares and blends: the distances are never NaN (inverse
        // directions are clamped and finite), and FloatVector.max pays five instructions for
        // Java's NaN and signed-zero rules.
        FloatVector t0 = ((FloatVector) ByteVector.fromArray(B, q, o + nx).convertShape(VectorOperators.B2F, S, 0)).mul(sx).add(bx).sub(oxn).mul(ix);
        FloatVector t1 = ((FloatVector) ByteVector.fromArray(B, q, o + (8 - nx)).convertShape(VectorOperators.B2F, S, 0)).mul(sx).add(bx).sub(oxf).mul(ix);
        FloatVector y0 = ((FloatVector) ByteVector.fromArray(B, q, o + 16 + ny).convertShape(VectorOperators.B2F, S, 0)).mul(sy).add(by).sub(oyn).mul(iy);
        FloatVector y1 = ((FloatVector) ByteVector.fromArray(B, q, o + 16 + (8 - ny)).convertShape(VectorOperators.B2F, S, 0)).mul(sy).add(by).sub(oyf).mul(iy);
        FloatVector z0 = ((FloatVector) ByteVector.fromArray(B, q, o + 32 + nz).convertShape(VectorOperators.B2F, S, 0)).mul(sz).add(bz).sub(ozn).mul(iz);
        FloatVector z1 = ((FloatVector) ByteVector.fromArray(B, q, o + 32 + (8 - nz)).convertShape(VectorOperators.B2F, S, 0)).mul(sz).add(bz).sub(ozf).mul(iz);
        t0 = t0.blend(y0, t0.compare(VectorOperators.LT, y0));
        t1 = t1.blend(y1, t1.compare(VectorOperators.GT, y1));
        t0 = t0.blend(z0, t0.compare(VectorOperators.LT, z0));
        t1 = t1.blend(z1, t1.compare(VectorOperators.GT, z1));
        t0 = t0.blend(tMin, t0.compare(VectorOperators.LT, tMin));
        t1 = t1.blend(tMax, t1.compare(VectorOperators.GT, tMax));
        t0 = t0.abs().mul(-GAMMA).add(t0);
        t1 = t1.abs().mul(GAMMA).add(t1);
        VectorMask<Float> m = t0.compare(VectorOperators.LE, t1);
        if (!m.anyTrue()) return 0;
        t0.blend(Float.POSITIVE_INFINITY, m.not()).intoArray(dist, 0);
        // The lanes' bits as one integer sum: VectorMask.toLong() is not an instruction on JDK 17
        return ZERO.blend(LANE_BITS, m).reinterpretAsInts().reduceLanes(VectorOperators.ADD);
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
        FloatVector y0 = row(planes, o + 16 + ny).sub(oyn).mul(iy);
        FloatVector y1 = row(planes, o + 16 + (8 - ny)).sub(oyf).mul(iy);
        FloatVector z0 = row(planes, o + 32 + nz).sub(ozn).mul(iz);
        FloatVector z1 = row(planes, o + 32 + (8 - nz)).sub(ozf).mul(iz);
        t0 = t0.blend(y0, t0.compare(VectorOperators.LT, y0));
        t1 = t1.blend(y1, t1.compare(VectorOperators.GT, y1));
        t0 = t0.blend(z0, t0.compare(VectorOperators.LT, z0));
        t1 = t1.blend(z1, t1.compare(VectorOperators.GT, z1));
        t0 = t0.blend(tMin, t0.compare(VectorOperators.LT, tMin));
        t1 = t1.blend(tMax, t1.compare(VectorOperators.GT, tMax));
        t0 = t0.abs().mul(-GAMMA).add(t0);
        t1 = t1.abs().mul(GAMMA).add(t1);
        VectorMask<Float> m = t0.compare(VectorOperators.LE, t1);
        if (!m.anyTrue()) return 0;
        t0.blend(Float.POSITIVE_INFINITY, m.not()).intoArray(dist, 0);
        // The lanes' bits as one integer sum: VectorMask.toLong() is not an instruction on JDK 17
        return ZERO.blend(LANE_BITS, m).reinterpretAsInts().reduceLanes(VectorOperators.ADD);
    }

    /** Eight floats stored as bits at p[o..o+7]. */
    private static FloatVector row(int[] p, int o) {
        return IntVector.fromArray(I, p, o).reinterpretAsFloats();
    }
}
