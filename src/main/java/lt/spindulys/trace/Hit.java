package lt.spindulys.trace;

import lt.spindulys.material.Material;

import lt.spindulys.accel.PrimitiveHit;

/**
 * The nearest-hit record of the first intersection phase: the acceleration structures' record
 * (distance, primitive within the leaf object, two primitive-local parameters) extended with the
 * leaf object hit and its material and CSG state. Shading data is derived from it once, for the
 * nearest hit only, by {@link TracedObject#shade}. Mutable per-thread scratch.
 */
public final class Hit extends PrimitiveHit {
    /** The leaf object hit; null while nothing is hit. */
    public TracedObject object;
    /** True where the visible surface faces the other way from its object's outward normal (a CSG cut). */
    public boolean flipNormal;
    /** The material to shade with; set by the leaf, overridden by an enclosing object that has one. */
    public Material material;
    /**
     * The CSG node whose own material {@link #material} is (texture mappings then take points in
     * its space, so the block is textured as one solid), or null: the leaf's material, mapped in
     * the leaf's space.
     */
    public TracedObject materialSpace;

    public Hit reset(double tMax) {
        t = tMax;
        object = null;
        prim = -1;
        sub = 0;
        u = v = 0;
        flipNormal = false;
        material = null;
        materialSpace = null;
        return this;
    }

    public boolean found() { return object != null; }

    public void set(Hit o) {
        t = o.t; object = o.object; prim = o.prim; sub = o.sub; u = o.u; v = o.v; flipNormal = o.flipNormal; material = o.material;
        materialSpace = o.materialSpace;
    }
}
