package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;

import java.util.ArrayList;
import java.util.List;

import lt.spindulys.accel.Accelerator;
import lt.spindulys.accel.BoxList;
import lt.spindulys.accel.Bvh;
import lt.spindulys.accel.PrimitiveHit;
import lt.spindulys.accel.PrimitiveSet;
import lt.spindulys.accel.TraversalScratch;
import lt.spindulys.camera.Camera;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.math.Ray;

/**
 * A frozen scene: objects with composed transforms and world bounds, an acceleration structure
 * over them, lights, camera and settings. Immutable and shared by all render threads.
 * Made by {@link SceneBuilder#build()}, which freezes its own copies of the objects it was given
 * (see {@link GObject}): they are {@link #objects()}, and the caller's objects stay unfrozen.
 */
public final class Scene {
    private final RenderSettings settings;
    private final Camera camera;
    private final List<PointLight> lights;
    private final List<AreaLight> areaLights;
    private final List<GObject> objects;
    private final GObject[] bounded;
    private final GObject[] unbounded;
    private final Accelerator accel;
    private final int objectIds;
    private final boolean transparent;
    private final boolean moving;
    private final Environment environment;
    /** The environment's sampling tables when it is a light with some brightness, else null. */
    private final EnvironmentLight environmentLight;

    /**
     * Builds the scene from copies of {@code given}: see {@link SceneBuilder#build()}.
     *
     * @throws IllegalArgumentException if an object cannot be placed (a {@link SceneBuildException}
     *         naming it) or the copies would not fit in the heap
     */
    Scene(RenderSettings settings, Camera camera, List<PointLight> lights, List<AreaLight> areaLights, List<GObject> given, Environment environment) {
        this.settings = settings.checkTimeSteps().checkNoiseControl();
        this.environment = environment;
        EnvironmentLight el = environment != null && environment.isLight() ? EnvironmentLight.of(environment) : null;
        this.environmentLight = el == null || el.isBlack() ? null : el;
        this.camera = camera;
        this.lights = List.copyOf(lights);
        this.areaLights = List.copyOf(areaLights);
        long count = 0;
        for (GObject o : given) count = HeapBudget.sum(count, o.objectCount());
        HeapBudget.require(HeapBudget.product(count, BYTES_PER_COPY), "the scene's " + count + " objects");
        // The shutter fills in motions' open start and finish times; bounds cover all of it.
        BuildContext world = BuildContext.of(settings, camera);
        GObject[] frozen = new GObject[given.size()];
        int ids = 0;
        for (int i = 0; i < frozen.length; i++) {
            GObject o = given.get(i);
            try {
                frozen[i] = o.copy();
                ids = frozen[i].freeze(world, ids);
            } catch (IllegalArgumentException e) {
                throw SceneBuildException.of(o, e).inScene(i);
            }
        }
        // Shared adaptive tessellations choose their levels now that every placement is known.
        world.shared().finish(world);
        adaptive = world.shared().tessellations();
        adaptiveBudget = world.shared().budgetNotes();
        this.objects = List.of(frozen);
        objectIds = ids;
        boolean[] anyTransparent = {false};
        for (GObject o : frozen) o.forEachMaterial(m -> anyTransparent[0] |= m.isTransparent());
        transparent = anyTransparent[0];
        boolean moves = false;
        for (GObject o : frozen) moves |= o.movesAnything();
        moving = moves;
        List<GObject> b = new ArrayList<>(), u = new ArrayList<>();
        for (GObject o : frozen) {
            if (o.bounds().isEmpty()) continue;
            (o.bounds().isFinite() ? b : u).add(o);
        }
        bounded = b.toArray(new GObject[0]);
        unbounded = u.toArray(new GObject[0]);
        // A handful of objects are each tested behind their own box, so that a ray enters only
        // the objects whose box it crosses (a mesh's own structure costs more to enter than a
        // box test, and a flat list of boxes less than a tree over them; docs/performance.md).
        ObjectSet set = new ObjectSet(this, bounded);
        accel = bounded.length > Bvh.DEFAULT_LEAF_SIZE ? settings.accelerator().build(set) : new BoxList(set);
    }

    /**
     * Heap one frozen copy of an object takes at most, beyond the data it shares with the caller's
     * object: the object's fields and, for a CSG node, its operand array and list (a sphere's copy
     * is under 150 bytes, a mesh's under 250).
     */
    static final long BYTES_PER_COPY = 512;

    /** The adaptive subdivision surfaces' tessellations, for their statistics. */
    private final List<SurfaceTessellation> adaptive;
    /** What the adaptive surfaces' budget became where it differs from what was asked (capped by the heap, the cache shrunk). */
    private final List<String> adaptiveBudget;

    /**
     * The triangles of every adaptive subdivision tessellation of this scene (built or not), for --stats.
     *
     * @return the count, 0 without adaptive surfaces
     */
    public long adaptiveTriangleCount() {
        long t = 0;
        for (SurfaceTessellation a : adaptive) t = lt.spindulys.limits.HeapBudget.sum(t, a.triangleCount());
        return t;
    }

    /**
     * One line per adaptive subdivision tessellation of this scene (instances of one surface share
     * one): its method, levels, patches built, cache hits, misses and evictions, peak bytes and the
     * histogram of levels used. Counters grow as the scene is rendered.
     *
     * @return the lines, empty when the scene has no adaptive surface
     */
    public List<String> adaptiveStatistics() {
        List<String> lines = new ArrayList<>(adaptiveBudget);
        for (SurfaceTessellation t : adaptive) lines.add(t.statistics());
        return lines;
    }

    /**
     * One line per triangle mesh among the scene's objects that owns its geometry (instances
     * share their original's structure) and has a hierarchy over its triangles: its name,
     * triangle count and the hierarchy's SAH cost ({@link lt.spindulys.accel.Bvh#sahCost()}),
     * so that a change to the build shows whether the tree kept its quality; whether the wide
     * tree's leaves hold their triangles or name them (the compact layout, chosen or forced by
     * the heap); and the mesh's bytes per triangle, arrays and structures.
     *
     * @return the lines, empty when no mesh has a hierarchy
     */
    public List<String> structureStatistics() {
        List<String> lines = new ArrayList<>();
        for (GObject o : objects) {
            if (o instanceof TriangleMesh m && !m.isInstance()) {
                double sah = m.accelerator() == null ? Double.NaN : m.accelerator().sahCost();
                if (!Double.isNaN(sah)) {
                    String leaves = m.accelerator() instanceof lt.spindulys.accel.WideBvh w
                            ? (w.hasLeafBlocks() ? ", triangles in the leaves" : ", leaves naming their triangles") : "";
                    lines.add(String.format(java.util.Locale.ROOT, "mesh %s: %d triangles, SAH cost %.4f%s, %.1f bytes/triangle",
                            m.name(), m.size(), sah, leaves, (double) m.memoryBytes() / Math.max(1, m.size())));
                }
            }
        }
        return lines;
    }

    /**
     * True if some surface of the scene refines patches while it is traced (an adaptive surface by
     * the lazy method, or the combined method beyond its eager budget): a renderer should then
     * trace neighbouring pixels together, so that the patches they share stay in the cache.
     *
     * @return whether rendering builds patches on demand
     */
    public boolean refinesWhileTracing() {
        for (SurfaceTessellation t : adaptive) if (t.refinesWhileTracing()) return true;
        return false;
    }

    /**
     * The settings the scene was built with (film size, sampling, shutter, structure kind).
     *
     * @return the render settings, never null
     */
    public RenderSettings settings() { return settings; }

    /**
     * What rays that hit nothing see instead of the background colour, or null for the colour.
     *
     * @return the environment, or null
     */
    public Environment environment() { return environment; }

    /**
     * The environment as a light, with its brightness distribution built when the scene was
     * frozen: null unless the environment {@link Environment#isLight() is a light} and not black.
     *
     * @return the environment light, or null
     */
    public EnvironmentLight environmentLight() { return environmentLight; }
    /**
     * The camera the scene is rendered through.
     *
     * @return the camera, never null (the default one if the builder had none)
     */
    public Camera camera() { return camera; }
    /**
     * The lights, in the order they were added (read-only).
     *
     * @return an unmodifiable list of the lights
     */
    public List<PointLight> lights() { return lights; }
    /**
     * The area lights, in the order they were added (read-only).
     *
     * @return an unmodifiable list of the area lights
     */
    public List<AreaLight> areaLights() { return areaLights; }
    /**
     * The top-level objects, in the order they were added (read-only): the scene's own frozen
     * copies of the objects given to the builder, with ids, world bounds and resolved materials.
     *
     * @return an unmodifiable list of the top-level frozen objects
     */
    public List<GObject> objects() { return objects; }
    /**
     * Number of object ids assigned (every object, containers and their children included).
     *
     * @return the number of ids; every id is below it
     */
    public int objectIdCount() { return objectIds; }

    /**
     * True if some object transmits light, so shadow rays must look through surfaces.
     *
     * @return true if a shadow ray may pass through a surface
     */
    public boolean hasTransparentObjects() { return transparent; }

    /**
     * True if some object (or CSG operand) moves while the shutter is open, so that rays' times matter.
     *
     * @return true if an object's placement depends on the time
     */
    public boolean hasMovingObjects() { return moving; }

    /**
     * Nearest hit along the ray in (tMin, tMax); ray.tMax is left unchanged.
     *
     * @param ray world-space ray; only hits with t in (tMin, tMax) count
     * @param hit reset, then filled in with the nearest hit if there is one
     * @param ctx the calling thread's scratch space
     * @return true if the ray hits something
     */
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) {
        hit.reset(ray.tMax);
        double saved = ray.tMax;
        boolean any = accel.intersect(ray, hit, ctx);
        if (any) ray.tMax = hit.t;
        for (GObject o : unbounded) {
            if (o.intersect(ray, hit, ctx)) {
                any = true;
                ray.tMax = hit.t;
            }
        }
        ray.tMax = saved;
        return any;
    }

    /**
     * True if anything blocks the ray in (tMin, tMax).
     *
     * @param ray world-space ray; the segment (tMin, tMax) is tested
     * @param ctx the calling thread's scratch space
     * @return true if some object blocks the segment
     */
    public boolean occluded(Ray ray, TraceContext ctx) {
        // The slot's last occluder first: the same light stratum seen from a neighbouring point
        // is often blocked by the same triangle, and one triangle test then replaces a traversal.
        // It says true only where the query below would, so images are the same.
        int slot = ctx.occluderSlot;
        if (ctx.occluderScene != this) {
            java.util.Arrays.fill(ctx.occluders, null);
            ctx.occluderScene = this;
        } else {
            GObject last = (GObject) ctx.occluders[slot];
            if (last != null && last.occludedByPart(ray, ctx.occluderParts[slot], ctx)) return true;
        }
        for (GObject o : unbounded) {
            if (o != ctx.shadowReceiver && o.occluded(ray, ctx)) {
                rememberOccluder(o, ctx);
                return true;
            }
        }
        return accel.occluded(ray, ctx);
    }

    /** Keeps {@code o}, which has just blocked a shadow ray, in the thread's occluder cache if it names a cheap part. */
    private void rememberOccluder(GObject o, TraceContext ctx) {
        int part = o.blockingPart(ctx);
        if (part < 0 || ctx.occluderScene != this) return;
        ctx.occluders[ctx.occluderSlot] = o;
        ctx.occluderParts[ctx.occluderSlot] = part;
    }

    /**
     * The scene's objects as primitives of the top-level structure. The structure passes back the
     * scene's own hit and context it was given (it knows them only as its base types), so the casts
     * below always succeed; they are checks against final classes, no extra call.
     */
    private record ObjectSet(Scene scene, GObject[] objects) implements PrimitiveSet {
        @Override public int size() { return objects.length; }

        @Override public void bounds(int i, double[] out) {
            var b = objects[i].bounds();
            out[0] = b.minX(); out[1] = b.minY(); out[2] = b.minZ();
            out[3] = b.maxX(); out[4] = b.maxY(); out[5] = b.maxZ();
        }

        @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
            return objects[i].intersect(ray, (Hit) hit, (TraceContext) ctx);
        }

        @Override public boolean occluded(int i, Ray ray, TraversalScratch ctx) {
            TraceContext c = (TraceContext) ctx;
            if (objects[i] == c.shadowReceiver || !objects[i].occluded(ray, c)) return false;
            scene.rememberOccluder(objects[i], c);
            return true;
        }
    }
}
