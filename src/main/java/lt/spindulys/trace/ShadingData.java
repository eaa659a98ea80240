package lt.spindulys.trace;

import lt.spindulys.material.Material;

import lt.spindulys.math.Affine;

/**
 * Surface data at the nearest hit, in world space, computed once per shaded hit.
 * Normals are unit length and point out of the object (not towards the ray); the integrator
 * decides which side the ray came from. Mutable per-thread scratch.
 */
public final class ShadingData {
    /**
     * The shading thread's own last patches of lazily refined surfaces (a hit is shaded once,
     * right after it was found, so its patch is usually here): a render thread's scratch makes
     * this its {@link TraceContext#recentPatches}, so that a thread has one.
     */
    public lt.spindulys.adaptive.RecentPatches recentPatches = new lt.spindulys.adaptive.RecentPatches();

    /** Hit point. */
    public final double[] p = new double[3];
    /** Scratch for a triangle's corners (positions, normals, texture coordinates) while it is shaded. */
    public final double[] corners = new double[24];
    /**
     * Where shadow rays towards lights on the outward side start, when {@link #lifted}: the hit
     * point lifted off a smooth-shaded triangle onto the curved surface its vertex normals
     * describe, so that the flat facet does not shadow itself where the shading says it is lit.
     * While a shape is shaded it holds the object-space offset from the point instead.
     */
    public final double[] shadowOrigin = new double[3];
    /** Whether {@link #shadowOrigin} holds a lifted shadow-ray origin (otherwise shadow rays start at {@link #p}). */
    public boolean lifted;
    /** Geometric normal, outward. */
    public final double[] ng = new double[3];
    /** Shading normal (interpolated or perturbed), outward, on the same side as ng. */
    public final double[] ns = new double[3];
    /** Partial derivatives of the point with respect to u and v (not normalised). */
    public final double[] dpdu = new double[3];
    public final double[] dpdv = new double[3];
    /**
     * The hit point in the object's own space (what texture mappings project); where the material
     * is a CSG node's own, in that node's space, as are dpduObject and dpdvObject.
     */
    public final double[] pObject = new double[3];
    /** dpdu and dpdv in the object's own space, before the object-to-world transform. */
    public final double[] dpduObject = new double[3];
    public final double[] dpdvObject = new double[3];
    /** Surface texture coordinates. */
    public double u, v;
    /**
     * Whether uv, dpdu and dpdv (and their object-space copies) are needed: the material is
     * textured, or the caller asked for them ({@link TracedObject#shade(lt.spindulys.math.Ray, Hit,
     * ShadingData, boolean)}). When false a shape may skip computing them and they hold no
     * meaning: an untextured mesh hit then reads none of the mesh's texture-coordinate arrays,
     * which in a large mesh are cache misses (docs/performance.md).
     */
    public boolean needsParameters;
    public Material material;
    public TracedObject object;
    public int prim;
    /** Scratch for a moving object's transform at the shaded ray's time. */
    public final Affine placementAtTime = new Affine();

    /** Sets both normals to (x, y, z) normalised. */
    public void setNormal(double x, double y, double z) {
        double len = Math.sqrt(x * x + y * y + z * z);
        if (len > 0) { x /= len; y /= len; z /= len; }
        ng[0] = ns[0] = x; ng[1] = ns[1] = y; ng[2] = ns[2] = z;
    }

    public void setDerivatives(double ux, double uy, double uz, double vx, double vy, double vz) {
        dpdu[0] = ux; dpdu[1] = uy; dpdu[2] = uz;
        dpdv[0] = vx; dpdv[1] = vy; dpdv[2] = vz;
    }

    /** Negates both normals (used where a CSG cut shows the inside of an operand). */
    public void flipNormals() {
        for (int i = 0; i < 3; i++) { ng[i] = -ng[i]; ns[i] = -ns[i]; }
    }
}
