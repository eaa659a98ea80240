package lt.spindulys.scene;

import lt.spindulys.material.Material;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import lt.spindulys.camera.Camera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Vec3;

/**
 * The public way to make a scene, used alike by Java code, the scene-file parser and the viewer
 * plugin, so a scene written in code and the same scene read from a file render identically.
 *
 * <pre>{@code
 * SceneBuilder b = new SceneBuilder()
 *     .settings(RenderSettings.builder().size(800, 600).samplesPerPixel(4).build())
 *     .camera(new PinholeCamera(new Vec3(0, 2, -6), new Vec3(0, 1, 0), Vec3.Y, 45))
 *     .light(new PointLight(new Vec3(5, 10, -5), Color.WHITE));
 * Material glass = Material.builder().color(Color.WHITE).kd(0.1).ks(0.8).shininess(100)
 *     .kr(0.1).kt(0.9).ior(1.5).build();
 * b.add(new Sphere(new Vec3(0, 1, 0), 1).material(glass));
 * b.add(new Plane(Vec3.Y, 0));
 * Scene scene = b.build();
 * }</pre>
 * Validation happens where a value is given; each method throws IllegalArgumentException with a
 * message that names the value and what was expected.
 *
 * <p>A builder may build any number of times: each {@link #build()} freezes fresh copies of the
 * objects as they are then and leaves the builder and the objects unchanged, so an animation keeps
 * one builder, changes a transform, and builds the next frame (see {@link GObject}).
 */
public final class SceneBuilder {
    private RenderSettings settings = RenderSettings.DEFAULT;
    private Camera camera;
    private final List<PointLight> lights = new ArrayList<>();
    private final List<AreaLight> areaLights = new ArrayList<>();
    private final List<GObject> objects = new ArrayList<>();
    private final Map<String, Material> materials = new LinkedHashMap<>();
    private String frameSource, samplesSource;
    private final List<InputFile> inputFiles = new ArrayList<>();
    private Environment environment;
    private Animation animation;

    /**
     * A new builder with everything given to this one so far (settings, camera, lights, environment, objects,
     * named materials, frame source); later changes to either do not reach the other. The objects
     * themselves are shared, not copied: building never changes them.
     *
     * @return the copy
     */
    public SceneBuilder copy() {
        SceneBuilder c = new SceneBuilder();
        c.settings = settings;
        c.camera = camera;
        c.lights.addAll(lights);
        c.areaLights.addAll(areaLights);
        c.totalLight = totalLight;
        c.objects.addAll(objects);
        c.materials.putAll(materials);
        c.frameSource = frameSource;
        c.samplesSource = samplesSource;
        c.inputFiles.addAll(inputFiles);
        c.environment = environment;
        c.animation = animation;
        return c;
    }

    /**
     * Sets the render settings (film size, sampling, shutter, structure kind, ...); replaces the earlier ones.
     *
     * @param s the settings (not null)
     * @return this builder, for chaining
     */
    public SceneBuilder settings(RenderSettings s) { settings = Objects.requireNonNull(s); return this; }

    /**
     * The render settings given so far ({@link RenderSettings#DEFAULT} unless set).
     *
     * @return the current settings, never null
     */
    public RenderSettings settings() { return settings; }

    /**
     * Sets the camera; replaces the earlier one.
     *
     * @param c the camera (not null)
     * @return this builder, for chaining
     */
    public SceneBuilder camera(Camera c) { camera = Objects.requireNonNull(c); return this; }

    /** The camera of a scene that gives none: at (0, 0, -5) looking at the origin, 45 degrees. */
    public static final PinholeCamera DEFAULT_CAMERA = new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 45);

    /**
     * The camera given so far, or null (then {@link #build()} uses {@link #DEFAULT_CAMERA}).
     *
     * @return the camera given, or null if none was
     */
    public Camera camera() { return camera; }

    /**
     * Adds a light.
     *
     * @param l the light to add (not null)
     * @return this builder, for chaining
     * @throws IllegalArgumentException if the lights' total (intensity times largest colour
     *         component, summed) would exceed {@link Ranges#MAX_TOTAL_LIGHT}
     */
    public SceneBuilder light(PointLight l) {
        countLight("light", Objects.requireNonNull(l).intensity(), l.power());
        lights.add(l);
        return this;
    }

    /** Adds a light's power to the lights' total, refusing it (naming it and its intensity) past the limit. */
    private void countLight(String what, double intensity, double power) {
        double total = totalLight + power;
        if (!(total <= Ranges.MAX_TOTAL_LIGHT)) {
            throw new IllegalArgumentException(what + " intensity " + intensity + " brings the lights' total (intensity times the largest colour component, summed over the lights) to "
                    + total + ", more than " + Ranges.show(Ranges.MAX_TOTAL_LIGHT));
        }
        totalLight = total;
    }

    /**
     * Adds an area light (soft shadows).
     *
     * @param l the light to add (not null)
     * @return this builder
     * @throws IllegalArgumentException if the lights' total (intensity times largest colour
     *         component, summed over point and area lights) would exceed {@link Ranges#MAX_TOTAL_LIGHT}
     */
    public SceneBuilder areaLight(AreaLight l) {
        countLight("area light", Objects.requireNonNull(l).intensity(), l.power());
        areaLights.add(l);
        return this;
    }

    /**
     * The area lights added so far, in order (read-only view).
     *
     * @return an unmodifiable view of the area lights, which follows later additions
     */
    public List<AreaLight> areaLights() { return Collections.unmodifiableList(areaLights); }

    /** Sum of {@link PointLight#power()} and {@link AreaLight#power()} over the lights added so far. */
    private double totalLight;

    /**
     * The lights added so far, in order (read-only view).
     *
     * @return an unmodifiable view of the lights, which follows later additions
     */
    public List<PointLight> lights() { return Collections.unmodifiableList(lights); }

    /**
     * The top-level objects added so far, in order (read-only view), to inspect before building.
     *
     * @return an unmodifiable view of the objects, which follows later additions
     */
    public List<GObject> objects() { return Collections.unmodifiableList(objects); }

    /**
     * Registers a named material for later lookup with {@link #material(String)}.
     *
     * @param name the name to look the material up by; must not be defined already
     * @param m the material (not null)
     * @return this builder, for chaining
     */
    public SceneBuilder defineMaterial(String name, Material m) {
        if (materials.containsKey(name)) throw new IllegalArgumentException("material '" + name + "' is already defined");
        materials.put(name, Objects.requireNonNull(m));
        return this;
    }

    /**
     * A material defined earlier with {@link #defineMaterial}; throws if there is none of that name.
     *
     * @param name the name the material was defined under
     * @return the material of that name, never null
     */
    public Material material(String name) {
        Material m = materials.get(name);
        if (m == null) {
            throw new IllegalArgumentException("unknown material '" + name + "'"
                    + (materials.isEmpty() ? " (no materials are defined)" : " (defined: " + String.join(", ", materials.keySet()) + ")"));
        }
        return m;
    }

    /**
     * True if a material of this name was defined with {@link #defineMaterial}.
     *
     * @param name the material name to look for
     * @return true if {@link #material(String)} would find it
     */
    public boolean hasMaterial(String name) { return materials.containsKey(name); }

    /**
     * Adds a top-level object. The builder keeps the object itself, not a copy: changes made to it
     * before a {@link #build()} are in that build's scene. The same object may be added to several
     * builders, or more than once (each time is one more object in the scene).
     *
     * @param o the object (not null), kept by reference rather than copied
     * @return this builder, for chaining
     * @throws IllegalArgumentException if {@code o} is an object of a built scene (add the one it was built from)
     */
    public SceneBuilder add(GObject o) {
        if (Objects.requireNonNull(o).isFrozen()) throw new IllegalArgumentException(o.name() + " is an object of a built scene; add the object it was built from");
        objects.add(o);
        return this;
    }

    /**
     * Freezes copies of everything added, as it is now, into an immutable scene, its objects
     * placed and given ids in the order added (each CSG node before its operands). The builder
     * and the objects given are left unchanged, so it may build again after a change; a mesh
     * built before shares its acceleration structure with the new scene instead of building it
     * again.
     *
     * @return a new immutable scene, independent of this builder
     * @throws IllegalArgumentException if an object cannot be placed (a {@link SceneBuildException}
     *         naming it), the settings are inconsistent, or the scene's objects do not fit in the heap
     */
    public Scene build() {
        Camera c = camera != null ? camera : DEFAULT_CAMERA;
        return new Scene(settings, c, lights, areaLights, objects, environment);
    }

    /**
     * Records where the frame's size was given, such as "scene.dat:3:14" for the settings key that
     * set it, so that a frame the heap cannot hold is reported there (the size is checked only
     * once every override is known, just before rendering). Used for messages only; null: none.
     *
     * @param where the place, such as "scene.dat:3:14", or null for none
     * @return this builder, for chaining
     */
    public SceneBuilder frameSource(String where) { frameSource = where; return this; }

    /**
     * Where the frame's size was given (see {@link #frameSource(String)}), or null.
     *
     * @return the place recorded, or null
     */
    public String frameSource() { return frameSource; }

    /**
     * Records where the samples that size the render threads' buffers were given, such as
     * "scene.dat:2:40" for the settings' {@code samples} key (or, without one, the {@code samples}
     * of the light that has the most), so that buffers the heap cannot hold are reported there.
     * Used for messages only; null: none.
     *
     * @param where the place, or null for none
     * @return this builder, for chaining
     */
    public SceneBuilder samplesSource(String where) { samplesSource = where; return this; }

    /**
     * Where the samples were given (see {@link #samplesSource(String)}), or null.
     *
     * @return the place recorded, or null
     */
    public String samplesSource() { return samplesSource; }

    /**
     * Records a file this description was read from (the scene file, a mesh, a material library,
     * an image, an unwrap), so that a run can refuse to write its output over one of them
     * ({@link InputFile#checkOutput}). {@link lt.spindulys.io.SceneParser} records every file it
     * reads; a scene made in code may record the files it read its parts from.
     *
     * @param file the file read
     * @return this builder, for chaining
     */
    public SceneBuilder inputFile(InputFile file) {
        inputFiles.add(Objects.requireNonNull(file, "file"));
        return this;
    }

    /**
     * The files this description was read from, in the order they were recorded ({@link #inputFile}).
     *
     * @return an unmodifiable view, empty for a scene made in code
     */
    public List<InputFile> inputFiles() { return Collections.unmodifiableList(inputFiles); }

    /**
     * Sets what rays that hit nothing see: a lat-long image instead of the settings' background
     * colour (see {@link Environment} for its orientation); null goes back to the colour. An
     * environment that {@link Environment#isLight() is a light} also lights the scene; its
     * sampling tables ({@link EnvironmentLight}) are made by {@link #build()}.
     *
     * @param e the environment, or null
     * @return this builder, for chaining
     */
    public SceneBuilder environment(Environment e) { environment = e; return this; }

    /**
     * The environment set, or null.
     *
     * @return the environment, or null
     */
    public Environment environment() { return environment; }

    /**
     * Sets the scene's frame range, frame rate and shutter angle (null: none, a still). The
     * builder still builds with its own settings; a frame is built from the settings
     * {@link Animation#settingsFor} gives, which {@link #forFrame} applies.
     *
     * @param a the animation, or null
     * @return this builder, for chaining
     */
    public SceneBuilder animation(Animation a) { animation = a; return this; }

    /**
     * The animation set, or null.
     *
     * @return the animation, or null for a still
     */
    public Animation animation() { return animation; }

    /**
     * A copy of this builder set up for one frame of its animation: its settings with that
     * frame's shutter and seed ({@link Animation#settingsFor}). Build it to get the frame's scene.
     *
     * @param frame the frame number, within the animation's range
     * @return a new builder for the frame; this one is unchanged
     * @throws IllegalArgumentException if there is no animation or the frame is outside its range
     */
    public SceneBuilder forFrame(int frame) {
        if (animation == null) throw new IllegalArgumentException("frame " + frame + " asked of a scene without an animation");
        return copy().settings(animation.settingsFor(settings, frame));
    }

    /**
     * Convenience for code: the ambient light intensity.
     *
     * @param c the ambient light colour, replacing the settings' ambient
     * @return this builder, for chaining
     */
    public SceneBuilder ambient(Color c) { settings = settings.toBuilder().ambient(c).build(); return this; }
}
