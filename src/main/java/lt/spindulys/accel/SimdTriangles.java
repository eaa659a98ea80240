package lt.spindulys.accel;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;
import jdk.incubator.vector.VectorSpecies;

/**
 * The four-triangle watertight test of a {@link TriangleBlocks} block in 128-bit float vectors:
 * every lane does exactly the float operations of {@link TriangleBlocks#testScalar}, in the same
 * order, so the two agree to the bit. Names the incubating Vector API, so it is loaded only when
 * {@link WideBvh#AVAILABLE} says the module is there.
 */
final class SimdTriangles {
    private static final VectorSpecies<Float> S = FloatVector.SPECIES_128;

    private SimdTriangles() {}

    /**
     * As {@link TriangleBlocks#testScalar}, with the same arguments and outputs, except that it
     * returns -1 (and nothing in {@code s}) when a lane inside has an edge function exactly 0.
     */
    static int test(float[] f, int o, int kx, int ky, int kz, float ox, float oy, float oz,
                    float sx, float sy, float sz, float tMin, float tMax, float[] s) {
        FloatVector az = FloatVector.fromArray(S, f, o + 4 * kz).sub(oz);
        FloatVector bz = FloatVector.fromArray(S, f, o + 12 + 4 * kz).sub(oz);
        FloatVector cz = FloatVector.fromArray(S, f, o + 24 + 4 * kz).sub(oz);
        FloatVector ax = FloatVector.fromArray(S, f, o + 4 * kx).sub(ox).sub(az.mul(sx));
        FloatVector ay = FloatVector.fromArray(S, f, o + 4 * ky).sub(oy).sub(az.mul(sy));
        FloatVector bx = FloatVector.fromArray(S, f, o + 12 + 4 * kx).sub(ox).sub(bz.mul(sx));
        FloatVector by = FloatVector.fromArray(S, f, o + 12 + 4 * ky).sub(oy).sub(bz.mul(sy));
        FloatVector cx = FloatVector.fromArray(S, f, o + 24 + 4 * kx).sub(ox).sub(cz.mul(sx));
        FloatVector cy = FloatVector.fromArray(S, f, o + 24 + 4 * ky).sub(oy).sub(cz.mul(sy));
        FloatVector u = cx.mul(by).sub(cy.mul(bx));
        FloatVector v = ax.mul(cy).sub(ay.mul(cx));
        FloatVector w = bx.mul(ay).sub(by.mul(ax));
        // inside unless the signs are strictly mixed; written out, since a call taking vectors
        // that C2 declines to inline boxes them
        VectorMask<Float> neg = u.lt(0f).or(v.lt(0f)).or(w.lt(0f));
        VectorMask<Float> pos = u.compare(VectorOperators.GT, 0f).or(v.compare(VectorOperators.GT, 0f)).or(w.compare(VectorOperators.GT, 0f));
        VectorMask<Float> in = neg.and(pos).not();
        // rare (a ray through an edge or vertex): the caller redoes the block with the scalar
        // kernel, which gives the same bits; no vector stays live across a call, which would box it
        if (u.eq(0f).or(v.eq(0f)).or(w.eq(0f)).and(in).anyTrue()) return -1;
        FloatVector det = u.add(v).add(w);
        FloatVector t = u.mul(az.mul(sz)).add(v.mul(bz.mul(sz))).add(w.mul(cz.mul(sz))).div(det);
        // NaN lanes (the padding) fail the comparisons of t
        VectorMask<Float> hit = in.and(det.compare(VectorOperators.NE, 0f))
                .and(t.compare(VectorOperators.GT, tMin)).and(t.compare(VectorOperators.LT, tMax));
        if (!hit.anyTrue()) return 0;
        t.blend(Float.POSITIVE_INFINITY, hit.not()).intoArray(s, TriangleBlocks.T);
        v.intoArray(s, TriangleBlocks.V);
        w.intoArray(s, TriangleBlocks.W);
        det.intoArray(s, TriangleBlocks.DET);
        // lane bits from the stored distances: VectorMask.toLong() is not an instruction on JDK 17
        int bits = 0;
        for (int l = 0; l < 4; l++) bits |= (s[TriangleBlocks.T + l] < Float.POSITIVE_INFINITY ? 1 : 0) << l;
        return bits;
    }
}
