package lt.spindulys.trace;

import lt.spindulys.material.Material;
import lt.spindulys.math.Ray;

/**
 * What the per-ray records ({@link Hit}, {@link SpanBuffer}, {@link ShadingData}) and the integrator
 * need of a scene object: the scene's objects ({@code lt.spindulys.scene.GObject}) implement it.
 * It lets this package sit below the scene package, so that the records stay internal to the
 * renderer while the objects are public API.
 */
public interface TracedObject {
    /**
     * Fills {@code sd} for {@code hit}, found on {@code ray} by this object (phase two: shading data once).
     *
     * @param ray the ray that found the hit
     * @param hit the hit
     * @param sd receives the shading data
     */
    void shade(Ray ray, Hit hit, ShadingData sd);

    /**
     * The object's id in its frozen scene.
     *
     * @return the id, from 0
     */
    int id();

    /**
     * The solid this object bounds as seen from outside (a CSG result is one solid), for the medium stack.
     *
     * @return the solid, possibly this object itself
     */
    TracedObject solid();

    /**
     * The object's material after freezing (inherited if it had none of its own).
     *
     * @return the material
     */
    Material material();

    /**
     * The material a primitive of the object is shaded with after freezing: {@link #material()},
     * or the primitive's face group's where the object gives its groups materials.
     *
     * @param prim the primitive, as a hit records it
     * @param sub the primitive's part, as a hit records it
     * @return the material
     */
    Material material(int prim, int sub);

    /**
     * True if the object's whole surface lies in one plane (a plane, a triangle, a planar mesh):
     * a shadow ray leaving a point of it, off the surface towards the light, cannot meet it
     * again, so the shadow query skips it (Scene#occluded with TraceContext#shadowReceiver).
     *
     * @return whether the surface is flat
     */
    default boolean flat() { return false; }
}
