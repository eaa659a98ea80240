package lt.spindulys.math;

/**
 * A mutable affine transform with its inverse: per-thread scratch that holds a moving object's
 * object-to-world transform at one time ({@link Placement#evaluate}). Its per-ray methods are the
 * same arithmetic as {@link Transform}'s. Never shared between threads.
 */
public final class Affine implements ObjectMapping {
    final double[] m = new double[12], inv = new double[12];
    // Intermediate products while a placement is evaluated.
    final double[] factor = new double[12], factorInv = new double[12], tmp = new double[12];

    /** Scratch with no transform in it yet: {@link Placement#evaluate} fills it before any use. */
    public Affine() {}

    /**
     * Writes {@code world} mapped into object space (the inverse) into {@code local}.
     *
     * @param world a ray in world space
     * @param local receives the ray in object space (same t parameter)
     */
    public void toLocal(Ray world, Ray local) { Transform.toLocal(inv, world, local); }

    /** Writes the point {@code world[0..2]} mapped into object space to {@code local[0..2]}. */
    @Override public void toLocalPoint(double[] world, double[] local) { Transform.toLocalPoint(inv, world, local); }

    /** Maps the vector {@code v[off..off+2]} in place from object to world space. */
    @Override public void vectorInPlace(double[] v, int off) { Transform.vectorInPlace(m, v, off); }

    /** Maps the normal {@code n[off..off+2]} in place from object to world space and normalises it. */
    @Override public void vectorToLocalInPlace(double[] v, int off) { Transform.vectorInPlace(inv, v, off); }

    @Override public void normalInPlace(double[] n, int off) { Transform.normalInPlace(inv, false, n, off); }

    /** False: an evaluated motion is treated as a general transform. */
    @Override public boolean isIdentity() { return false; }

    /**
     * A copy as an immutable transform (allocates; for tests and tools).
     *
     * @return the transform held now
     */
    public Transform toTransform() { return Transform.ofMatrix(m.clone()); }
}
