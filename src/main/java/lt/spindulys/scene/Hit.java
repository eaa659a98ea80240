package lt.spindulys.scene;

/**
 * The nearest-hit record of the first intersection phase: distance, the leaf object and its
 * primitive, and two primitive-local parameters (barycentrics for triangles, surface parameters
 * for analytic shapes). Shading data is derived from it once, for the nearest hit only, by
 * {@link GObject#shade}. Mutable per-thread scratch.
 */
public final class Hit {
    /** Ray parameter of the hit (the same in world and object space). */
    public double t;
    /** The leaf object hit; null while nothing is hit. */
    public GObject object;
    /** Primitive index within the object (triangle, box face, cylinder part...). */
    public int prim;
    /** Primitive-local parameters. */
    public double u, v;
    /** True where the visible surface faces the other way from its object's outward normal (a CSG cut). */
    public boolean flipNormal;
    /** The material to shade with; set by the leaf, overridden by an enclosing object that has one. */
    public Material material;
    /**
     * The CSG node whose own material {@link #material} is (texture mappings then take points in
     * its space, so the block is textured as one solid), or null: the leaf's material, mapped in
     * the leaf's space.
     */
    public GObject materialSpace;

    public Hit reset(double tMax) {
        t = tMax;
        object = null;
        prim = -1;
        u = v = 0;
        flipNormal = false;
        material = null;
        materialSpace = null;
        return this;
    }

    public boolean found() { return object != null; }

    public void set(Hit o) {
        t = o.t; object = o.object; prim = o.prim; u = o.u; v = o.v; flipNormal = o.flipNormal; material = o.material;
        materialSpace = o.materialSpace;
    }
}
