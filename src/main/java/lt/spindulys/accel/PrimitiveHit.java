package lt.spindulys.accel;

/**
 * The nearest-hit record an acceleration structure and its {@link PrimitiveSet} fill: the ray
 * distance, the primitive and two primitive-local parameters (barycentrics for triangles, surface
 * parameters for analytic shapes). It knows nothing of scene objects; the scene's hit record
 * extends it with the object, material and CSG state. Mutable per-thread scratch.
 */
public class PrimitiveHit {
    /** Ray parameter of the hit (the same in world and object space). */
    public double t;
    /** Primitive index within its set (triangle, box face, cylinder part...). */
    public int prim;
    /** Primitive-local parameters. */
    public double u, v;
    /**
     * A part of the primitive, for a set whose primitives have parts: the triangle within a lazily
     * refined patch (the patch being the primitive). Sets without parts leave it alone.
     */
    public int sub;
}
