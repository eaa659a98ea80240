package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.SpanBuffer;

import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Motion;
import lt.spindulys.math.ObjectMapping;
import lt.spindulys.math.Placement;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.trace.TracedObject;

/**
 * Base of every scene object (the thesis's name). An object is built in its own space, placed by
 * a transform and given a material; building a scene freezes it, composing the transforms of every
 * enclosing object into one object-to-world transform, after which it is immutable and safe to
 * share between render threads.
 *
 * <p><b>Objects are descriptions; scenes freeze copies.</b> {@link SceneBuilder#build()} freezes a
 * private {@link #copy() copy} of each object tree it was given and never changes the caller's
 * objects, so after a build the caller may change a transform or a material and build again (the
 * next frame of an animation), and one object may be added to several builders, several times to
 * one builder, or be an operand of several {@link Bool}s. The copies share the big immutable data
 * (a mesh's arrays and its object-space acceleration structure, built once), so another build of
 * the same mesh is cheap. The frozen objects are those of {@link Scene#objects()}; only they answer
 * {@link #id()}, {@link #bounds()} and rays. A build reads the objects without locking them: do
 * not change an object on another thread while a scene is being built from it.
 *
 * <p>Intersection has two phases, as in pbrt: {@link #intersect} finds the nearest (t, object,
 * primitive, u, v) and nothing more; {@link #shade} derives point, normals, uv and derivatives once
 * for the hit that is finally shaded. Closed solids also report every span the ray spends inside
 * them ({@link #spans}), which is what CSG combines.
 *
 * <p>Leaf shapes implement the {@code *Local} methods in object space; this class maps the world
 * ray into object space (direction not renormalised, so t is shared) and maps results back.
 *
 * <p><b>Motion.</b> An object may also be given a {@link Motion}, applied after its own transform
 * and before the enclosing object's placement, so its object-to-world mapping at time t is: own
 * transform, own motion at t, then the parent's mapping at t (a {@link Placement}). A ray is
 * answered at its {@link Ray#time}, and shading uses the same time. Objects with no motion
 * anywhere in their chain keep one composed transform and pay nothing per ray for the feature.
 * {@link #keys(Keyframes) Keys} (an animation's keyframed transforms) are placed the same way,
 * between the transform and the motion, and move the object across the frames of an
 * {@link Animation} and, within a frame, while its shutter is open.
 *
 * <p><b>Not for subclassing outside this library.</b> The per-ray methods ({@link #intersect},
 * {@link #shade}, {@link #spans} and the {@code *Local} ones) take the renderer's hit records,
 * which the module {@code lt.spindulys} does not export: they are renderer machinery, not API.
 * Build scenes from the shapes here and combine them with {@link Bool}.
 */
public abstract class GObject implements TracedObject, Cloneable {
    private Transform transform = Transform.IDENTITY;
    private Motion motion;
    private Keyframes keys;
    /** The shutter a frozen object was built for (what its keys are swept over); the default before. */
    private double shutterOpen = Placement.OPEN, shutterClose = Placement.CLOSE;
    private Material material;
    /**
     * Materials of the face groups given to this object (meshes and subdivision surfaces: their
     * OBJ usemtl runs), by group index, null entries for none; null when none is given. Replaced,
     * never changed in place, so copies may share it.
     */
    private Material[] groupMaterials;
    /**
     * Frozen: the material each face group is shaded with, or null when every face takes
     * {@link #material} (the object has no groups, or its own material overrides theirs).
     */
    private Material[] palette;
    private String name;
    /** Whether shadow rays leave smooth-shaded triangles from the lifted point (TriangleShading#liftShadowOrigin). */
    private boolean shadowTerminator = true;
    /**
     * Where the object was made, for messages only (see {@link #source(String)}): the whole text,
     * or a file name shared by every object of the file with the line and column apart, so that
     * a scene of many small objects does not keep a string per object.
     */
    private String source;
    private int sourceLine, sourceColumn;

    /** Composed object-to-world transform of an object that does not move (else null); set by {@link #freeze}. */
    protected Transform objectToWorld;
    /** Object-to-world mapping of an object that moves (itself or an enclosing one), else null; set by {@link #freeze}. */
    private Placement moving;
    private boolean frozen;
    private Bounds worldBounds;
    private int id = -1;

    // ---- building (before the scene freezes) ----

    /**
     * Appends {@code t} to this object's placement (applied after the ones already given).
     *
     * @param t the transform to apply after this object's current one
     * @return this object, for chaining (each shape returns its own type)
     * @throws IllegalStateException if this is a frozen object of a built scene
     */
    public GObject transform(Transform t) {
        checkMutable();
        transform = transform.then(t);
        return this;
    }

    /**
     * This object's own placement in its parent's space (the identity unless given), without its motion.
     *
     * @return the object's own transform, the identity if none was given
     */
    public Transform transform() { return transform; }

    /**
     * Gives this object a motion during the shutter, applied after its transform (null: none).
     * An open start or finish of the motion becomes the scene's shutter time when it is built.
     *
     * @param m the motion, or null for none
     * @return this object, for chaining
     * @throws IllegalStateException if this is a frozen object of a built scene
     */
    public GObject motion(Motion m) {
        checkMutable();
        motion = m;
        return this;
    }

    /**
     * This object's own motion, or null (after freezing, with its times filled in from the shutter).
     *
     * @return the motion, or null if the object has none of its own
     */
    public Motion motion() { return motion; }

    /**
     * Gives this object keyframed transforms (an animation's keys or a turntable), applied after
     * its transform and before its motion (null: none). The keys' times are the scene's: an
     * animation's frame N is at N / fps (see {@link Animation}).
     *
     * @param k the keys, or null for none
     * @return this object, for chaining
     * @throws IllegalStateException if this is a frozen object of a built scene
     */
    public GObject keys(Keyframes k) {
        checkMutable();
        keys = k;
        return this;
    }

    /**
     * This object's own keyframed transforms, or null.
     *
     * @return the keys, or null if the object has none of its own
     */
    public Keyframes keys() { return keys; }

    /** The shutter's open time this object was frozen for (the default shutter's before). */
    final double shutterOpen() { return shutterOpen; }

    /** The shutter's close time this object was frozen for (the default shutter's before). */
    final double shutterClose() { return shutterClose; }

    /**
     * Sets this object's material; null inherits the enclosing object's or the scene default.
     *
     * @param m the material, or null to inherit one
     * @return this object, for chaining
     * @throws IllegalStateException if this is a frozen object of a built scene
     */
    public GObject material(Material m) {
        checkMutable();
        material = m;
        return this;
    }

    /**
     * Sets whether shadow rays towards lights on the outward side of this object's smooth-shaded
     * triangles start on the curved surface their vertex normals describe (Hanika's shadow
     * terminator offset; on by default), rather than on the flat triangle, which at a coarse
     * tessellation shadows itself in steps near the terminator. Shapes without smooth-shaded
     * triangles ignore it.
     *
     * @param on false to start shadow rays on the triangles themselves
     * @return this object, for chaining
     * @throws IllegalStateException if this is a frozen object of a built scene
     */
    public GObject shadowTerminator(boolean on) {
        checkMutable();
        shadowTerminator = on;
        return this;
    }

    /** Whether shadow rays leave smooth-shaded triangles from the lifted point ({@link #shadowTerminator(boolean)}). */
    public boolean shadowTerminator() { return shadowTerminator; }

    /**
     * The material given to this object, or null if it inherits one; on a frozen object, the one
     * it is shaded with (inherited ones filled in).
     */
    public Material material() { return material; }

    /**
     * The material a primitive of this frozen object is shaded with: its face group's, where the
     * object has groups with materials, else the object's.
     *
     * @param prim the primitive, as a hit records it
     * @param sub the primitive's part, as a hit records it
     * @return the material
     */
    @Override
    public final Material material(int prim, int sub) {
        if (palette == null) return material;
        int g = faceGroup(prim, sub);
        return g < 0 ? material : palette[g];
    }

    /**
     * The number of face groups (0 for objects without them); see {@link #faceGroup}.
     *
     * @return the number of groups
     */
    protected int groupCount() { return 0; }

    /**
     * The face group of a primitive, as {@link #intersectLocal} records it, or -1 for none. Called
     * per hit of an object with group materials: it must not allocate.
     *
     * @param prim the primitive
     * @param sub the primitive's part
     * @return the group index, or -1
     */
    protected int faceGroup(int prim, int sub) { return -1; }

    /**
     * Sets the material of the face group named {@code name} among {@code names} (the shape's
     * public {@code groupMaterial} methods call this).
     *
     * @param names the object's group names, by index, or null when it has none
     * @param name the group's name
     * @param m the material, or null for the object's
     * @throws IllegalArgumentException if there is no group of that name
     */
    protected final void setGroupMaterial(String[] names, String name, Material m) {
        checkMutable();
        int g = -1;
        if (names != null) for (int i = 0; i < names.length && g < 0; i++) if (names[i].equals(name)) g = i;
        if (g < 0) {
            throw new IllegalArgumentException(name() + " has no face group " + MessageText.quote(name)
                    + (names == null || names.length == 0 ? " (it has no groups)" : " (its groups: " + MessageText.cut(String.join(", ", names), 200) + ")"));
        }
        Material[] next = groupMaterials == null ? new Material[names.length] : groupMaterials.clone();
        next[g] = m;
        groupMaterials = next;
    }

    /**
     * Names this object for messages (null: none, then it is named by its {@link #kind()}).
     *
     * @param n the name, or null for none
     * @return this object, for chaining
     * @throws IllegalStateException if this is a frozen object of a built scene
     */
    public GObject name(String n) {
        checkMutable();
        name = n;
        return this;
    }

    /**
     * A name for messages: the one given, or the kind of object.
     *
     * @return the given name, or {@link #kind()} if none; never null
     */
    public String name() { return name != null ? name : kind(); }

    /**
     * The kind of object for messages, for example "sphere".
     *
     * @return a short lower-case noun such as "sphere"; never null
     */
    public abstract String kind();

    /**
     * Records where this object was made, such as "scene.dat:12:3" for the statement that made it,
     * so that errors found only when the scene is built name that place ({@link SceneBuildException}).
     * Used for messages only; null: none.
     *
     * @param where the place, such as "scene.dat:12:3", or null for none
     * @return this object, for chaining
     */
    public GObject source(String where) {
        checkMutable();
        source = where;
        sourceLine = sourceColumn = 0;
        return this;
    }

    /**
     * {@link #source(String)} as "file:line:column" (the scene parser's; "file:line" if the column
     * is 0), kept without making the string until a message needs it.
     *
     * @param file   the file name, as messages should show it
     * @param line   line number, from 1
     * @param column column number, from 1 (0: none)
     * @return this object, for chaining
     * @throws IllegalArgumentException if {@code line} is below 1
     */
    public GObject source(String file, int line, int column) {
        checkMutable();
        if (line < 1) throw new IllegalArgumentException("source line must be at least 1, found " + line);
        source = file;
        sourceLine = line;
        sourceColumn = Math.max(column, 0);
        return this;
    }

    /**
     * Where this object was made (see {@link #source(String)}), or null.
     *
     * @return "file:line:column", "file:line" or the string given, or null if none was recorded
     */
    public String source() {
        if (sourceLine == 0) return source;
        return source + ":" + sourceLine + (sourceColumn > 0 ? ":" + sourceColumn : "");
    }

    /** The object as build errors name it: its kind, and its name if it was given one ("sphere 'ball'"). */
    final String label() {
        return name == null ? kind() : kind() + " " + MessageText.quote(name);
    }

    /**
     * Refuses a change to a frozen object: call first in every builder method of a subclass.
     *
     * @throws IllegalStateException if this object is frozen
     */
    protected final void checkMutable() {
        if (frozen) throw new IllegalStateException(name() + " is part of a frozen scene and cannot change");
    }

    // ---- copying and freezing ----

    /**
     * A new, unfrozen object with this one's description (shape, transform, motion, material,
     * name, source, options), for a scene to freeze without touching this one. The default is a
     * shallow {@link Object#clone()}, right for shapes whose fields are immutable or replaced (never
     * changed in place) by their builder methods; containers copy their children, and objects
     * whose copies must share a cache with them (a mesh's structures) override it.
     *
     * @return a new unfrozen object, independent of this one for building
     * @throws IllegalStateException if this object is frozen (its description was resolved in place)
     */
    protected GObject copy() {
        checkCopyable();
        try {
            GObject c = (GObject) super.clone();
            c.solid = null;
            return c;
        } catch (CloneNotSupportedException e) {
            throw new AssertionError(e); // GObject implements Cloneable
        }
    }

    /** Objects a {@link #copy()} of this one makes, itself and everything inside it (a CSG node counts its operands). */
    long objectCount() { return 1; }

    /** Refuses to copy a frozen object, whose description was resolved in place (for every {@link #copy()}). */
    final void checkCopyable() {
        if (frozen) throw new IllegalStateException(name() + " is a built scene's object; copy the object it was built from");
    }

    /** Gives this new object the description every object has (for {@link #copy()}s that construct). */
    final void describeLike(GObject from) {
        transform = from.transform;
        motion = from.motion;
        keys = from.keys;
        material = from.material;
        shadowTerminator = from.shadowTerminator;
        groupMaterials = from.groupMaterials;
        name = from.name;
        source = from.source;
        sourceLine = from.sourceLine;
        sourceColumn = from.sourceColumn;
    }

    /**
     * Fixes this object in place (the scene calls it on its own {@link #copy()}): composes its
     * transform with the context's placement, fills in an inherited material and the motion's
     * open times, computes world bounds and assigns ids. Containers override to freeze their
     * children under {@link BuildContext#within a derived context}, then call super; objects with
     * primitives of their own (meshes) build their acceleration structure here, of the context's
     * kind; an object that depends on the view reads the context's camera, film and shutter.
     *
     * @param context where the parent is placed, what it passes on, and the view
     * @param ids     next free object id
     * @return the next free id after this object and its children
     * @throws SceneBuildException (an IllegalArgumentException) naming this object if it cannot be placed
     * @throws IllegalStateException if this object is frozen already
     */
    protected int freeze(BuildContext context, int ids) {
        if (frozen) throw new IllegalStateException(name() + " is frozen already");
        Placement parentToWorld = context.placement();
        Placement p;
        try {
            if (motion != null) motion = motion.resolve(parentToWorld.open(), parentToWorld.close());
            shutterOpen = parentToWorld.open();
            shutterClose = parentToWorld.close();
            p = placementIn(parentToWorld);
        } catch (IllegalArgumentException e) {
            throw SceneBuildException.of(this, e);
        }
        frozen = true;
        if (p.isStatic()) objectToWorld = p.staticTransform();
        else moving = p;
        // The object's own material overrides its face groups'; without one, groups given none
        // (and faces in no group) take the material it inherits.
        boolean own = material != null;
        if (!own) material = context.material();
        int groups = groupCount();
        if (!own && groups > 0 && groupMaterials != null) {
            palette = new Material[groups];
            for (int g = 0; g < groups; g++) palette[g] = groupMaterials[g] != null ? groupMaterials[g] : material;
        }
        id = ids;
        worldBounds = computeWorldBounds();
        return ids + 1;
    }

    /**
     * World bounds; the default transforms the object-space bounds' corners. The contract for
     * structures over objects: these bounds must enclose the object at every time of the shutter
     * interval a ray may carry, so an object that moves must return the union over its motion.
     *
     * @return world bounds enclosing the object at every time of the shutter interval
     */
    protected Bounds computeWorldBounds() {
        return moving == null ? localBounds().transformed(objectToWorld) : moving.bounds(localBounds());
    }

    /**
     * This object's object-to-world mapping inside a parent placed by {@code parentToWorld}: its
     * transform, its motion (open times from the parent's shutter), then the parent's.
     *
     * @param parentToWorld the parent's object-to-world mapping; its open and close times are the shutter's
     * @return the mapping from this object's space to world space, static or moving
     * @throws SceneBuildException if composing overflows or makes the transform singular
     */
    protected final Placement placementIn(Placement parentToWorld) {
        try {
            Placement own = Placement.of(transform, parentToWorld.open(), parentToWorld.close());
            // Keys that hold one pose through this shutter place the object as a still one: no per-ray cost.
            if (keys != null) own = keys.isStill(parentToWorld.open(), parentToWorld.close()) ? own.then(keys.at(parentToWorld.open())) : own.then(keys);
            if (motion != null) own = own.then(motion);
            return own.then(parentToWorld);
        } catch (IllegalArgumentException e) {
            // Composing may overflow or make a transform singular that was fine alone.
            throw SceneBuildException.of(this, e);
        }
    }

    /**
     * True if this object moves during the shutter (by its own motion or an enclosing object's); known once frozen.
     *
     * @return true if the object moves; false for a static or not yet frozen object
     */
    public final boolean isMoving() { return moving != null; }

    /** Whether this object or anything inside it (a CSG node's operands) moves while the shutter is open. */
    boolean movesAnything() { return moving != null; }

    /**
     * The object-to-world transform at {@code time} (allocates; for tests and tools). Only after freezing.
     *
     * @param time a time in the shutter interval, in the scene's time units (ignored if the object does not move)
     * @return the object-to-world transform at {@code time}; a new one for a moving object
     */
    public final Transform objectToWorld(double time) {
        if (!frozen) throw new IllegalStateException(name() + " is not frozen yet");
        return moving == null ? objectToWorld : moving.at(time);
    }

    /**
     * World bounds over the whole shutter interval (see {@link #computeWorldBounds()}); set at freeze.
     *
     * @return the world bounds, or null before the object is frozen
     */
    public final Bounds bounds() { return worldBounds; }

    /**
     * This object's id in its scene, unique among the scene's objects and their operands (the
     * first top-level object 0, a CSG node before its operands); -1 until frozen.
     */
    public final int id() { return id; }

    /** Whether the object's material, or any face group's, lets light through (valid once frozen). */
    protected final boolean anyTransparentMaterial() {
        if (material != null && material.isTransparent()) return true;
        if (palette != null) for (Material m : palette) if (m != null && m.isTransparent()) return true;
        return false;
    }

    /**
     * The solid this object bounds as seen from outside: the outermost {@link Bool} it is an
     * operand of (at any depth), or the object itself. A ray crossing a surface enters or leaves
     * this solid, which is what keeps the integrator's medium stack consistent when a CSG
     * result's entry and exit surfaces belong to different leaves. Set at freeze: before, and for
     * the caller's objects, which are never frozen, it is the object itself.
     */
    public final GObject solid() { return solid != null ? solid : this; }

    /** Set to the outermost CSG node by the enclosing node's freeze before it freezes this object. */
    void solid(GObject s) { solid = s; }

    private GObject solid;

    /**
     * True for the objects of a built scene ({@link Scene#objects()} and their operands); false
     * for the objects a caller made, which building never freezes.
     *
     * @return true for an object of a built scene, which refuses changes
     */
    public final boolean isFrozen() { return frozen; }

    /**
     * Visits the material of this object and of every object inside it (after freezing).
     *
     * @param visitor called with each object's material, once per object (a shared material may come more than once)
     */
    public void forEachMaterial(java.util.function.Consumer<Material> visitor) {
        visitor.accept(material);
        if (palette != null) for (Material m : palette) visitor.accept(m);
    }

    /**
     * Bounds in the object's own space.
     *
     * @return the object-space bounds, before transform and motion
     */
    public abstract Bounds localBounds();

    /**
     * True if the object bounds a volume (spans and CSG are defined only then).
     *
     * @return true if the object has an inside (spans and CSG allowed), false for an open surface
     */
    public abstract boolean isClosed();

    // ---- phase 1: nearest hit ----

    /**
     * Finds the nearest intersection with t in (ray.tMin, ray.tMax). On a hit records it in
     * {@code hit} and returns true; the caller then shrinks ray.tMax to hit.t.
     *
     * @param ray world-space ray; only hits with t in (tMin, tMax) count, and tMax is not changed
     * @param hit receives the hit (t, object, material, ...) when there is one
     * @param ctx the calling thread's scratch space
     * @return true if a hit was found and recorded in {@code hit}
     */
    public boolean intersect(Ray ray, Hit hit, TraceContext ctx) {
        Ray local = toLocal(ray, ctx);
        if (!intersectLocal(local, hit, ctx)) return false;
        hit.object = this;
        // A farther candidate found earlier on this ray may have been a subtracted CSG surface.
        hit.flipNormal = false;
        // A leaf's own (its face group's, if it has group materials); an enclosing object with a material overrides it after.
        hit.material = material(hit.prim, hit.sub);
        hit.materialSpace = null;
        return true;
    }

    /**
     * True if anything blocks the ray in (tMin, tMax); may stop at the first hit found.
     *
     * @param ray world-space ray; the segment (tMin, tMax) is tested
     * @param ctx the calling thread's scratch space (its scratch hit is overwritten)
     * @return true if something blocks the segment
     */
    public boolean occluded(Ray ray, TraceContext ctx) {
        return intersect(ray, ctx.scratchHit.reset(ray.tMax), ctx);
    }

    /**
     * The part of this object that blocked the ray of its last {@link #occluded} call on this
     * thread (which returned true), for the scene's occluder cache: a part that
     * {@link #occludedByPart} tests alone for the cost of one primitive test, or -1 if there is
     * none (testing the object again would cost a whole query; it is then not cached).
     *
     * @param ctx the thread's scratch, as given to that call
     * @return the part, or -1
     */
    int blockingPart(TraceContext ctx) { return -1; }

    /**
     * Whether part {@code part} (from {@link #blockingPart}) alone blocks the ray in (tMin,
     * tMax): true only where {@link #occluded} would be true.
     *
     * @param ray world-space ray
     * @param part a part that {@link #blockingPart} gave
     * @param ctx the calling thread's scratch space
     * @return true if that part blocks the segment
     */
    boolean occludedByPart(Ray ray, int part, TraceContext ctx) { return occluded(ray, ctx); }

    /**
     * Appends every span inside this (closed) object that overlaps (ray.tMin, ray.tMax), with its
     * true endpoints, in increasing order. Open objects throw.
     *
     * @param ray world-space ray
     * @param out receives the spans, appended after those it holds
     * @param ctx the calling thread's scratch space
     */
    public void spans(Ray ray, SpanBuffer out, TraceContext ctx) {
        if (!isClosed()) throw new UnsupportedOperationException(name() + " is not closed and has no inside");
        spansLocal(toLocal(ray, ctx), out, ctx);
    }

    // ---- phase 2: shading data ----

    /**
     * Fills {@code sd} for {@code hit} (found on {@code ray} by this object): world point, outward
     * normals (flipped if the hit says so), material, and uv and derivatives if the material is
     * textured ({@link ShadingData#needsParameters}).
     */
    public void shade(Ray ray, Hit hit, ShadingData sd) {
        shade(ray, hit, sd, false);
    }

    /**
     * As {@link #shade(Ray, Hit, ShadingData)}, with uv and derivatives computed also for an
     * untextured material when {@code parameters} is true (for tools that show them).
     *
     * @param ray the ray the hit was found on
     * @param hit a hit this object recorded on {@code ray}
     * @param sd filled in with the world-space shading data
     * @param parameters true to compute uv and derivatives even for an untextured material
     */
    public void shade(Ray ray, Hit hit, ShadingData sd, boolean parameters) {
        sd.p[0] = ray.pointX(hit.t);
        sd.p[1] = ray.pointY(hit.t);
        sd.p[2] = ray.pointZ(hit.t);
        sd.object = this;
        sd.prim = hit.prim;
        sd.material = hit.material != null ? hit.material : material;
        sd.needsParameters = parameters || sd.material.isTextured();
        // Object-space point, for the shape's own parametrisation.
        double[] q = sd.dpdu; // scratch; shadeLocal overwrites it
        // A moving object is shaded through its transform at the ray's time, evaluated into the shading scratch.
        ObjectMapping map = objectToWorld;
        if (moving != null) {
            moving.evaluate(ray.time, sd.placementAtTime);
            map = sd.placementAtTime;
        }
        map.toLocalPoint(sd.p, q);
        double lx = q[0], ly = q[1], lz = q[2];
        sd.pObject[0] = lx; sd.pObject[1] = ly; sd.pObject[2] = lz;
        sd.lifted = false;
        shadeLocal(lx, ly, lz, hit, sd);
        // The lift is an object-space offset towards the outward side: a cut that shows the inside has no use for it.
        if (sd.lifted && (hit.flipNormal || !shadowTerminator)) sd.lifted = false;
        if (sd.lifted) {
            double[] o = sd.shadowOrigin;
            if (!map.isIdentity()) map.vectorInPlace(o, 0);
            o[0] += sd.p[0]; o[1] += sd.p[1]; o[2] += sd.p[2];
        }
        if (sd.needsParameters) {
            System.arraycopy(sd.dpdu, 0, sd.dpduObject, 0, 3);
            System.arraycopy(sd.dpdv, 0, sd.dpdvObject, 0, 3);
            if (!map.isIdentity()) {
                map.vectorInPlace(sd.dpdu, 0);
                map.vectorInPlace(sd.dpdv, 0);
            }
        }
        double[] ng = sd.ng, ns = sd.ns;
        boolean same = ns[0] == ng[0] && ns[1] == ng[1] && ns[2] == ng[2];
        map.normalInPlace(ng, 0);
        // A flat surface's shading normal is its geometric one: the same result, without a second square root.
        if (same) System.arraycopy(ng, 0, ns, 0, 3);
        else map.normalInPlace(ns, 0);
        if (hit.flipNormal) sd.flipNormals();
        if (hit.materialSpace != null && sd.needsParameters) ((GObject) hit.materialSpace).mappingInputsInto(ray.time, sd);
    }

    /**
     * Re-expresses what texture mappings read ({@link ShadingData#pObject}, dpduObject,
     * dpdvObject) in this object's space, from the world point and derivatives already in
     * {@code sd}: for a CSG node whose material shades a leaf's surface, so that the node is
     * textured as one solid (uv stays the leaf's own). Runs after the leaf's shading is complete,
     * so the leaf's mapping scratch may be reused.
     */
    final void mappingInputsInto(double time, ShadingData sd) {
        ObjectMapping map = objectToWorld;
        if (moving != null) {
            moving.evaluate(time, sd.placementAtTime);
            map = sd.placementAtTime;
        }
        map.toLocalPoint(sd.p, sd.pObject);
        System.arraycopy(sd.dpdu, 0, sd.dpduObject, 0, 3);
        System.arraycopy(sd.dpdv, 0, sd.dpdvObject, 0, 3);
        map.vectorToLocalInPlace(sd.dpduObject, 0);
        map.vectorToLocalInPlace(sd.dpdvObject, 0);
    }

    // ---- what leaf shapes implement, in object space ----

    /**
     * Nearest hit of an object-space ray; set t, prim, u, v in {@code hit} (object and material are set by the caller).
     *
     * @param ray object-space ray; only hits with t in (tMin, tMax) count
     * @param hit receives t, prim, u and v on a hit
     * @param ctx the calling thread's scratch space
     * @return true if the ray hits in (tMin, tMax)
     */
    protected abstract boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx);

    /**
     * Spans of an object-space ray; only closed shapes are asked.
     *
     * @param ray object-space ray
     * @param out receives the spans, in increasing order, after those it holds
     * @param ctx the calling thread's scratch space
     */
    protected void spansLocal(Ray ray, SpanBuffer out, TraceContext ctx) {
        throw new UnsupportedOperationException(name() + " does not report spans");
    }

    /**
     * Shading data in object space at object-space point (x, y, z): normals (outward,
     * unnormalised is fine: they are normalised after transforming), and uv, dpdu, dpdv, which
     * may be skipped when {@link ShadingData#needsParameters} is false.
     *
     * @param x object-space x of the hit point
     * @param y object-space y of the hit point
     * @param z object-space z of the hit point
     * @param hit the hit being shaded, with the prim, u and v {@link #intersectLocal} set
     * @param sd receives the object-space normals and, when needed, uv, dpdu and dpdv
     */
    protected abstract void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd);

    /**
     * The ray in object space: the world ray itself when the transform is the identity; for a
     * moving object, mapped by the transform at the ray's time.
     *
     * @param ray world-space ray
     * @param ctx the calling thread's scratch space, whose local ray may be used
     * @return {@code ray} itself, or the context's local ray (overwritten by the next call)
     */
    protected final Ray toLocal(Ray ray, TraceContext ctx) {
        if (moving != null) {
            moving.evaluate(ray.time, ctx.placementAtTime);
            ctx.placementAtTime.toLocal(ray, ctx.localRay);
            return ctx.localRay;
        }
        if (objectToWorld.isIdentity()) return ray;
        objectToWorld.toLocal(ray, ctx.localRay);
        return ctx.localRay;
    }
}
