package lt.spindulys.math;

/**
 * What shading needs of an object's object-to-world mapping at one time: a fixed {@link Transform}
 * or a moving object's {@link Affine} evaluated at the ray's time, so that one code path serves both.
 */
public interface ObjectMapping {
    /**
     * Writes the point {@code world[0..2]} mapped into object space to {@code local[0..2]}.
     *
     * @param world the point, 3 doubles
     * @param local receives the point in object space
     */
    void toLocalPoint(double[] world, double[] local);

    /**
     * Maps the vector {@code v[off..off+2]} in place from object to world space.
     *
     * @param v holds the vector
     * @param off index of its x
     */
    void vectorInPlace(double[] v, int off);

    /**
     * Maps the vector {@code v[off..off+2]} in place from world to object space (the inverse of {@link #vectorInPlace}).
     *
     * @param v holds the vector
     * @param off index of its x
     */
    void vectorToLocalInPlace(double[] v, int off);

    /**
     * Maps the normal {@code n[off..off+2]} in place from object to world space and normalises it.
     *
     * @param n holds the normal
     * @param off index of its x
     */
    void normalInPlace(double[] n, int off);

    /**
     * True if the mapping is the identity (vectors need no mapping).
     *
     * @return whether vectors and normals pass unchanged
     */
    boolean isIdentity();
}
