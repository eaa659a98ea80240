package lt.spindulys.accel;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The conservative float test of a {@link TriangleBlocks} block in one pass of 256-bit float
 * vectors (the species of {@link SimdBoxes}, so that the two share the compiled vector paths).
 */
final class SimdTriangles {
    private static final VectorSpecies<Float> S = FloatVector.SPECIES_256;
    private static final float EPS = 0x1p-24f;

    private static final FloatVector LANE_BITS = jdk.incubator.vector.IntVector.fromArray(jdk.incubator.vector.IntVector.SPECIES_256, new int[] {1, 2, 4, 8, 16, 32, 64, 128}, 0).reinterpretAsFloats();
    private static final FloatVector ZERO = FloatVector.zero(S);

    private SimdTriangles() {}

    /**
     * The lanes of the block at f[o..o+71] that the ray may hit, as bits: those whose float edge
     * functions are not of strictly mixed signs beyond their error bound. The ray's origin is
     * (ox, oy, oz) in the permuted axes (kx, ky, kz), its shear (sx, sy); delta bounds the
     * error of each sheared coordinate ({@link TriangleBlocks}).
     */
    static int candidates(float[] f, int o, int kx, int ky, int kz, float ox, float oy, float oz,
                          float sx, float sy, float delta, float[] lanes) {
        FloatVector az = FloatVector.fromArray(S, f, o + 8 * kz).sub(oz);
        FloatVector bz = FloatVector.fromArray(S, f, o + 24 + 8 * kz).sub(oz);
        FloatVector cz = FloatVector.fromArray(S, f, o + 48 + 8 * kz).sub(oz);
        FloatVector ax = FloatVector.fromArray(S, f, o + 8 * kx).sub(ox).sub(az.mul(sx));
        FloatVector ay = FloatVector.fromArray(S, f, o + 8 * ky).sub(oy).sub(az.mul(sy));
        FloatVector bx = FloatVector.fromArray(S, f, o + 24 + 8 * kx).sub(ox).sub(bz.mul(sx));
        FloatVector by = FloatVector.fromArray(S, f, o + 24 + 8 * ky).sub(oy).sub(bz.mul(sy));
        FloatVector cx = FloatVector.fromArray(S, f, o + 48 + 8 * kx).sub(ox).sub(cz.mul(sx));
        FloatVector cy = FloatVector.fromArray(S, f, o + 48 + 8 * ky).sub(oy).sub(cz.mul(sy));
        FloatVector u = cx.mul(by).sub(cy.mul(bx));
        FloatVector v = ax.mul(cy).sub(ay.mul(cx));
        FloatVector w = bx.mul(ay).sub(by.mul(ax));
        // S, the largest magnitude, by compares and blends (FloatVector.max pays five
        // instructions for Java's NaN rules; a NaN here only keeps the lane)
        FloatVector s = ax.abs(), m = ay.abs();
        s = s.blend(m, s.compare(VectorOperators.LT, m));
        m = bx.abs();
        s = s.blend(m, s.compare(VectorOperators.LT, m));
        m = by.abs();
        s = s.blend(m, s.compare(VectorOperators.LT, m));
        m = cx.abs();
        s = s.blend(m, s.compare(VectorOperators.LT, m));
        m = cy.abs();
        s = s.blend(m, s.compare(VectorOperators.LT, m));
        // 2 (4 eps S^2 + 4 delta S + 2 delta^2), at least a normal float (below, products underflow)
        FloatVector e = s.mul(8 * EPS).add(8 * delta).mul(s).add(4 * delta * delta + 0x1p-100f);
        FloatVector ne = e.neg();
        VectorMask<Float> below = u.compare(VectorOperators.LT, ne).or(v.compare(VectorOperators.LT, ne)).or(w.compare(VectorOperators.LT, ne));
        VectorMask<Float> above = u.compare(VectorOperators.GT, e).or(v.compare(VectorOperators.GT, e)).or(w.compare(VectorOperators.GT, e));
        VectorMask<Float> miss = below.and(above);
        if (miss.allTrue()) return 0;
        // The lanes' bits as one integer sum: VectorMask.toLong() is not an instruction on JDK 17
        return LANE_BITS.blend(ZERO, miss).reinterpretAsInts().reduceLanes(VectorOperators.ADD);
    }
}
