package lt.spindulys.texture;

/**
 * Turns a shading point into texture coordinates. Immutable and thread-safe; {@link #map} must not
 * allocate (it runs once per textured hit).
 *
 * <p>Footprint contract: on entry {@code out.footprint} holds the width of the pixel's footprint on
 * the surface in object-space units (0 = sharpest); {@code map} converts it into (u, v) units from
 * the mapping's analytic derivatives, never from differences between neighbouring samples, so a
 * seam (u jumping from 1 to 0) cannot inflate it. Where one direction's derivative blows up (the
 * poles, an axis) the larger footprint is limited to {@link #MAX_ANISOTROPY} times the smaller,
 * so a pole is not blurred to the coarsest mip level.
 */
public interface Mapping {
    /** Largest ratio between the (u, v) footprints along the two directions that is kept. */
    double MAX_ANISOTROPY = 4;

    /**
     * Fills out.u, out.v (before wrapping), out.x, out.y, out.z (the object-space point, for solid
     * textures) and converts out.footprint from object-space to (u, v) units.
     *
     * <p>The surface's own parameters come as plain values rather than the scene's shading record,
     * so textures stay below the scene in the package graph.
     *
     * @param out receives the texture point
     * @param u           the surface's own u parameter at the hit
     * @param v           the surface's own v parameter at the hit
     * @param dpdu        dp/du in the object's own space (not normalised; zero where undefined)
     * @param dpdv        dp/dv in the object's own space
     * @param objectPoint the hit point in the object's own space
     */
    void map(double u, double v, double[] dpdu, double[] dpdv, double[] objectPoint, TexturePoint out);

    /**
     * The isotropic (u, v) footprint from the footprints along u and v: the larger, limited to
     * {@link #MAX_ANISOTROPY} times the smaller; 0 when the object-space footprint is 0.
     *
     * @param objectFootprint the footprint in object units
     * @param fu object units per unit of u
     * @param fv object units per unit of v
     * @return the footprint in (u, v) units
     */
    static double combine(double objectFootprint, double fu, double fv) {
        if (!(objectFootprint > 0)) return 0;
        double lo = Math.min(fu, fv), hi = Math.max(fu, fv);
        double f = Math.min(hi, MAX_ANISOTROPY * lo);
        return Double.isFinite(f) ? f : 0;
    }
}
