package lt.spindulys.light;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import lt.spindulys.math.Ranges;
import lt.spindulys.math.Ray;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.trace.TracedObject;

/**
 * A frozen scene's lights as the integrator samples them, in the order they are shaded: the point
 * lights, then the area lights, then the environment if it is a light (and not black). Immutable
 * and shared by the render threads.
 */
public final class Lights {
    private final Light[] all;
    private final AreaSource[] surfaces;
    private final int stratified;
    /** Index in {@link #all} of the first area light (the point lights come before them). */
    private final int firstSurface;

    /** The emissive meshes among the lights, by mesh (empty unless made by {@link #withEmissiveMeshes}). */
    private final Map<TracedObject, MeshEmitter> emitters;

    private Lights(Light[] all, AreaSource[] surfaces, int firstSurface, Map<TracedObject, MeshEmitter> emitters) {
        this.all = all;
        this.emitters = emitters;
        this.surfaces = surfaces;
        this.firstSurface = firstSurface;
        int n = 0;
        for (Light l : all) if (!l.isDelta()) n++;
        stratified = n;
    }

    /**
     * The lights of {@code scene}. A point light's inverse-square falloff never divides by less
     * than the squared distance at which all of them together could deliver
     * {@link Ranges#MAX_IRRADIANCE}: a point (nearly) on a light would otherwise receive an
     * unbounded amount; for lights of everyday intensities this distance is below 1e-12 and
     * changes nothing.
     *
     * @param scene the scene
     * @return its lights
     */
    public static Lights of(Scene scene) {
        // Copies of the scene's unmodifiable lists: the shading loop reads arrays of its own.
        PointLight[] points = scene.lights().toArray(new PointLight[0]);
        AreaLight[] areas = scene.areaLights().toArray(new AreaLight[0]);
        double power = 0;
        for (PointLight l : points) if (l.falloff() == PointLight.Falloff.INVERSE_SQUARE) power += l.power();
        double minDistance2 = power / Ranges.MAX_IRRADIANCE;
        boolean environment = scene.environmentLight() != null;
        Light[] all = new Light[points.length + areas.length + (environment ? 1 : 0)];
        AreaSource[] surfaces = new AreaSource[areas.length];
        int i = 0;
        for (PointLight l : points) all[i++] = new PointSource(l, minDistance2);
        for (int a = 0; a < areas.length; a++) {
            surfaces[a] = switch (areas[a].shape()) {
                case RECTANGLE -> new RectangleSource(areas[a]);
                case DISC -> new DiscSource(areas[a]);
                case SPHERE -> new SphereSource(areas[a]);
            };
            all[i++] = surfaces[a];
        }
        if (environment) all[i] = new EnvironmentSource(scene.environmentLight());
        return new Lights(all, surfaces, points.length, Map.of());
    }

    /**
     * The lights of {@code scene} as {@link #of} makes them, followed by its emissive meshes
     * ({@link MeshEmitter}): the lights a path tracer samples. The Whitted tracer lights by
     * {@link #of} alone, as it always has; emission only adds to the surface that emits there.
     *
     * @param scene the scene
     * @return its lights and emissive meshes
     * @throws lt.spindulys.limits.InsufficientMemoryException if the heap cannot hold the
     *         emissive triangles' copies
     */
    public static Lights withEmissiveMeshes(Scene scene) {
        Lights base = of(scene);
        List<MeshEmitter> found = new ArrayList<>();
        for (GObject o : scene.objects()) {
            if (o instanceof TriangleMesh mesh) {
                MeshEmitter e = MeshEmitter.of(mesh);
                if (e != null) found.add(e);
            }
        }
        if (found.isEmpty()) return base;
        Light[] all = Arrays.copyOf(base.all, base.all.length + found.size());
        Map<TracedObject, MeshEmitter> byMesh = new IdentityHashMap<>();
        for (int i = 0; i < found.size(); i++) {
            all[base.all.length + i] = found.get(i);
            byMesh.put(found.get(i).mesh(), found.get(i));
        }
        return new Lights(all, base.surfaces, base.firstSurface, Collections.unmodifiableMap(byMesh));
    }

    /**
     * The light made of {@code object}'s emissive triangles, if it is one.
     *
     * @param object an object a ray hit
     * @return its light, or null
     */
    public MeshEmitter emitterOf(TracedObject object) { return emitters.isEmpty() ? null : emitters.get(object); }

    /**
     * Every light, in shading order; do not modify.
     *
     * @return the lights
     */
    public Light[] all() { return all; }

    /**
     * How many of the lights are not deltas (they take strata of the unit square).
     *
     * @return the count
     */
    public int stratified() { return stratified; }

    /**
     * Whether some light has a surface that rays can reach.
     *
     * @return true if there are area lights
     */
    public boolean hasSurfaces() { return surfaces.length > 0; }

    /**
     * If {@code ray} reaches an area light before {@code tBound} (and within its own range), writes
     * the radiance it sees there to out[0..2] (black from a one-sided light's back) and the ray
     * parameter of the crossing to out[3], and returns which light it is; else returns -1 and
     * leaves out alone.
     *
     * @param ray    the ray
     * @param tBound where the nearest surface is along it, or +Infinity
     * @param out    receives r, g, b and t: at least four entries
     * @return the light's index in {@link #all()}, or -1
     */
    public int nearestSurface(Ray ray, double tBound, double[] out) {
        double best = Math.min(tBound, ray.tMax);
        int seen = -1;
        for (int i = 0; i < surfaces.length; i++) {
            double t = surfaces[i].intersect(ray, best);
            if (t == t) {
                best = t;
                seen = i;
            }
        }
        if (seen < 0) return -1;
        surfaces[seen].radiance(ray.dx, ray.dy, ray.dz, out);
        out[3] = best;
        return firstSurface + seen;
    }
}
