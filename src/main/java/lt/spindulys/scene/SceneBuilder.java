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
 */
public final class SceneBuilder {
    private RenderSettings settings = RenderSettings.DEFAULT;
    private Camera camera;
    private final List<PointLight> lights = new ArrayList<>();
    private final List<GObject> objects = new ArrayList<>();
    private final Map<String, Material> materials = new LinkedHashMap<>();
    private boolean built;
    private String frameSource;

    public SceneBuilder settings(RenderSettings s) { settings = Objects.requireNonNull(s); return this; }
    public RenderSettings settings() { return settings; }

    public SceneBuilder camera(Camera c) { camera = Objects.requireNonNull(c); return this; }

    /** The camera of a scene that gives none: at (0, 0, -5) looking at the origin, 45 degrees. */
    public static final PinholeCamera DEFAULT_CAMERA = new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 45);

    /** The camera given so far, or null (then {@link #build()} uses {@link #DEFAULT_CAMERA}). */
    public Camera camera() { return camera; }

    /**
     * Adds a light.
     *
     * @throws IllegalArgumentException if the lights' total (intensity times largest colour
     *         component, summed) would exceed {@link Ranges#MAX_TOTAL_LIGHT}
     */
    public SceneBuilder light(PointLight l) {
        double total = totalLight + Objects.requireNonNull(l).power();
        if (!(total <= Ranges.MAX_TOTAL_LIGHT)) {
            throw new IllegalArgumentException("light intensity " + l.intensity() + " brings the lights' total (intensity times the largest colour component, summed over the lights) to "
                    + total + ", more than " + Ranges.show(Ranges.MAX_TOTAL_LIGHT));
        }
        totalLight = total;
        lights.add(l);
        return this;
    }

    /** Sum of {@link PointLight#power()} over the lights added so far. */
    private double totalLight;

    /** The lights added so far, in order (read-only view). */
    public List<PointLight> lights() { return Collections.unmodifiableList(lights); }

    /** The top-level objects added so far, in order (read-only view), to inspect before building. */
    public List<GObject> objects() { return Collections.unmodifiableList(objects); }

    /** Registers a named material for later lookup with {@link #material(String)}. */
    public SceneBuilder defineMaterial(String name, Material m) {
        if (materials.containsKey(name)) throw new IllegalArgumentException("material '" + name + "' is already defined");
        materials.put(name, Objects.requireNonNull(m));
        return this;
    }

    /** A material defined earlier with {@link #defineMaterial}; throws if there is none of that name. */
    public Material material(String name) {
        Material m = materials.get(name);
        if (m == null) {
            throw new IllegalArgumentException("unknown material '" + name + "'"
                    + (materials.isEmpty() ? " (no materials are defined)" : " (defined: " + String.join(", ", materials.keySet()) + ")"));
        }
        return m;
    }

    public boolean hasMaterial(String name) { return materials.containsKey(name); }

    /** Adds a top-level object; it must not be part of another scene or container. */
    public SceneBuilder add(GObject o) {
        if (o.isFrozen()) throw new IllegalArgumentException(o.name() + " already belongs to a built scene");
        objects.add(Objects.requireNonNull(o));
        return this;
    }

    /** Freezes everything added into an immutable scene. A builder builds once. */
    public Scene build() {
        if (built) throw new IllegalStateException("this builder has already built its scene");
        built = true;
        Camera c = camera != null ? camera : DEFAULT_CAMERA;
        return new Scene(settings, c, lights, objects);
    }

    /**
     * Records where the frame's size was given, such as "scene.dat:3:14" for the settings key that
     * set it, so that a frame the heap cannot hold is reported there (the size is checked only
     * once every override is known, just before rendering). Used for messages only; null: none.
     */
    public SceneBuilder frameSource(String where) { frameSource = where; return this; }

    /** Where the frame's size was given (see {@link #frameSource(String)}), or null. */
    public String frameSource() { return frameSource; }

    /** Convenience for code: the ambient light intensity. */
    public SceneBuilder ambient(Color c) { settings = settings.toBuilder().ambient(c).build(); return this; }
}
