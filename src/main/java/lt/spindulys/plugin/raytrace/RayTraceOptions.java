package lt.spindulys.plugin.raytrace;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.ControlMesh;

/**
 * The ray tracer's options, and how their values, the surfaces and the view resolve into a
 * {@link SceneDescription}: materials, lights placed around the surfaces' bounds, the floor,
 * texture mappings fitted to each surface, and how each surface is refined.
 */
final class RayTraceOptions {
    private RayTraceOptions() {}

    // Keys of the options that concern the whole picture.
    static final String WIDTH = "width", HEIGHT = "height", SAMPLES = "samples", BACKGROUND = "background",
            LIGHTING = "lighting", FLOOR = "floor", IDENTIFY = "identify", SAVE_SCENE = "save-scene";
    // Per-surface option names; the key is surface.N.name.
    static final String MATERIAL = "material", COLOR = "color", IOR = "ior", TINT = "tint", ATTENUATION = "attenuation",
            REFLECTIVITY = "reflectivity", TEXTURE = "texture", MAPPING = "mapping", RENDERING = "rendering", SHADING = "shading";

    static final List<String> LIGHTINGS = List.of("studio", "headlight", "sun");
    static final List<String> FLOORS = List.of("none", "plain", "checker");
    static final List<String> MATERIALS = List.of("opaque", "transparent", "mirror");
    static final List<String> MAPPINGS = List.of("uv", "planar", "spherical", "cylindrical");
    static final List<String> RENDERINGS = List.of("limit", "host-level", "adaptive");
    static final List<String> SHADINGS = List.of("smooth", "flat");

    /** Target edge length in pixels of the adaptive rendering (the thesis's one pixel). */
    static final double ADAPTIVE_TARGET = 1;
    /**
     * Target of the limit rendering of a surface too large to refine uniformly: half a pixel, so
     * the refined surface is within a fraction of a pixel of the limit everywhere.
     */
    static final double LIMIT_TARGET = 0.5;

    /** Default surface colours, by surface index: warm and cool tones that read well under white light. */
    private static final Color[] COLOURS = {
        new Color(0.8, 0.45, 0.25), new Color(0.3, 0.5, 0.8), new Color(0.45, 0.7, 0.35), new Color(0.85, 0.75, 0.3),
        new Color(0.65, 0.4, 0.75), new Color(0.35, 0.7, 0.7), new Color(0.85, 0.4, 0.55), new Color(0.6, 0.6, 0.6),
    };

    /** What the host's values resolve to: the scene, and what else to write. */
    record Resolved(SceneDescription scene, boolean identify, boolean saveScene) {}

    /** The key of a surface's option: {@code surface.2.material}. */
    static String surfaceKey(int surface, String name) { return "surface." + surface + "." + name; }

    /** An option's label and key for messages, found by its key alone (for places that have no option list). */
    static String describe(String key) {
        int dot = key.lastIndexOf('.');
        String name = dot < 0 ? key : key.substring(dot + 1);
        String label = switch (name) {
            case TEXTURE -> "Texture image";
            case MAPPING -> "Texture mapping";
            default -> name;
        };
        return label + " (" + key + ")";
    }

    /** The options for these surfaces and this view, in the order a form shows them. */
    static List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view) {
        List<PluginOption> o = new ArrayList<>();
        String image = "Image", light = "Lighting", output = "Output";
        o.add(PluginOption.integer(WIDTH, "Image width", image, view.width(), 1, RenderSettings.MAX_SIDE, "Width of the picture in pixels; the viewport's by default."));
        o.add(PluginOption.integer(HEIGHT, "Image height", image, view.height(), 1, RenderSettings.MAX_SIDE, "Height of the picture in pixels; the viewport's by default."));
        o.add(PluginOption.integer(SAMPLES, "Samples per pixel", image, 4, 1, 1024, "Antialiasing samples per pixel: more is smoother and slower."));
        o.add(PluginOption.of(BACKGROUND, "Background colour", image, PluginOption.Kind.COLOR, "0.18 0.2 0.23", "Colour of rays that hit nothing."));
        o.add(PluginOption.choice(LIGHTING, "Lighting", light, "studio", LIGHTINGS,
                "studio: key, fill and rim lights around the surfaces; headlight: one light at the eye; sun: one high light."));
        Bounds b = Bounds.of(surfaces);
        Vec3 up = view.up().normalized();
        boolean eyeAbove = view.eye().dot(up) > floorOffset(b, up);
        o.add(PluginOption.choice(FLOOR, "Floor", light, eyeAbove ? "checker" : "none", FLOORS,
                "A plane just under the surfaces, across the view's up direction: plain or a checker."));
        o.add(PluginOption.of(IDENTIFY, "Identification image", output, PluginOption.Kind.BOOLEAN, "false",
                "Also write OUT.surfaces.png: each surface in its own colour, with a legend naming it and its subdivision."));
        o.add(PluginOption.of(SAVE_SCENE, "Also save the scene as .dat", output, PluginOption.Kind.BOOLEAN, "false",
                "Also write OUT.dat, the scene in the scene language, with each control mesh as an OBJ beside it."));
        Set<String> names = new HashSet<>();
        for (int i = 0; i < surfaces.size(); i++) {
            DisplayedSurface s = surfaces.get(i);
            String group = MessageText.cut(SceneDescription.oneLine(s.name()));
            if (!names.add(group)) group = group + " (surface " + i + ")";
            boolean subdivided = s.scheme() != DisplayedSurface.Scheme.NONE;
            boolean smooth = s.shading() == DisplayedSurface.Shading.SMOOTH;
            o.add(PluginOption.choice(surfaceKey(i, MATERIAL), "Material", group, "opaque", MATERIALS,
                    "opaque: coloured; transparent: glass with an index of refraction and a tint; mirror: reflects."));
            o.add(PluginOption.of(surfaceKey(i, COLOR), "Colour", group, PluginOption.Kind.COLOR, colourText(COLOURS[i % COLOURS.length]),
                    "Colour of an opaque or mirror surface (white under a texture).").onlyWhen(surfaceKey(i, MATERIAL), "opaque", "mirror"));
            o.add(PluginOption.number(surfaceKey(i, IOR), "Index of refraction", group, 1.5, 1, 5, "Of a transparent surface: glass 1.5, water 1.33.")
                    .onlyWhen(surfaceKey(i, MATERIAL), "transparent"));
            o.add(PluginOption.of(surfaceKey(i, TINT), "Tint", group, PluginOption.Kind.COLOR, "1 1 1", "Colour a transparent surface gives the light passing through it.")
                    .onlyWhen(surfaceKey(i, MATERIAL), "transparent"));
            o.add(PluginOption.number(surfaceKey(i, ATTENUATION), "Attenuation", group, 0, 0, 1000,
                    "Of a transparent surface: absorption per unit of distance inside it (Beer's law); 0 for none.")
                    .onlyWhen(surfaceKey(i, MATERIAL), "transparent"));
            o.add(PluginOption.number(surfaceKey(i, REFLECTIVITY), "Reflectivity", group, 0.8, 0, 1, "Of a mirror surface: the share of light it reflects.")
                    .onlyWhen(surfaceKey(i, MATERIAL), "mirror"));
            o.add(PluginOption.of(surfaceKey(i, TEXTURE), "Texture image", group, PluginOption.Kind.FILE, "",
                    "An image (PNG, JPEG, TGA) to colour the surface with; empty for none."));
            o.add(PluginOption.choice(surfaceKey(i, MAPPING), "Texture mapping", group, s.control().uvs() != null ? "uv" : "spherical", MAPPINGS,
                    "How the texture is laid on the surface: its own texture coordinates (uv), or projected around its bounds."));
            o.add(PluginOption.choice(surfaceKey(i, RENDERING), "Rendering", group, subdivided && smooth ? "limit" : "host-level", RENDERINGS,
                    "limit: the smooth limit surface; host-level: subdivided as the viewer shows it; adaptive: refined to one-pixel edges."));
            o.add(PluginOption.choice(surfaceKey(i, SHADING), "Shading", group, smooth ? "smooth" : "flat", SHADINGS,
                    "smooth: limit-surface normals; flat: each facet's own normal."));
        }
        return o;
    }

    /**
     * Checks the values and resolves them.
     *
     * @throws IllegalArgumentException one line naming the option at fault
     */
    static Resolved resolve(List<DisplayedSurface> surfaces, PluginView view, Map<String, String> values) {
        List<PluginOption> options = options(surfaces, view);
        String problem = PluginOption.check(options, values);
        if (problem != null) throw new IllegalArgumentException(problem);
        Map<String, String> v = new HashMap<>();
        Map<String, PluginOption> byKey = new HashMap<>();
        for (PluginOption o : options) {
            v.put(o.key(), o.valueIn(values).strip());
            byKey.put(o.key(), o);
        }

        Bounds all = Bounds.of(surfaces);
        Vec3 f = view.target().minus(view.eye()).normalized();
        Vec3 right = f.cross(view.up()).normalized();   // the image's right-hand direction (docs/scene-format.md, camera)
        Vec3 up = right.cross(f);                       // the view's up, perpendicular to the view direction
        Vec3 worldUp = view.up().normalized();

        SceneDescription.ImageSpec image = new SceneDescription.ImageSpec(Integer.parseInt(v.get(WIDTH)), Integer.parseInt(v.get(HEIGHT)),
                Integer.parseInt(v.get(SAMPLES)), colour(v.get(BACKGROUND)));
        SceneDescription.CameraSpec camera = new SceneDescription.CameraSpec(view.eye(), view.target(), view.up(), view.fovDegrees());
        List<SceneDescription.LightSpec> lights = lights(v.get(LIGHTING), all, view.eye(), f, right, up);
        SceneDescription.FloorSpec floor = floor(v.get(FLOOR), all, worldUp);

        List<SceneDescription.SurfaceSpec> specs = new ArrayList<>();
        for (int i = 0; i < surfaces.size(); i++) {
            DisplayedSurface s = surfaces.get(i);
            String name = SceneDescription.oneLine(s.name());
            String material = v.get(surfaceKey(i, MATERIAL));
            String texture = v.get(surfaceKey(i, TEXTURE));
            String mapping = v.get(surfaceKey(i, MAPPING));
            SceneDescription.TextureSpec tex = null;
            if (!texture.isEmpty()) {
                if (mapping.equals("uv") && s.control().uvs() == null) {
                    throw new IllegalArgumentException(byKey.get(surfaceKey(i, MAPPING)).describe() + " is uv, but surface '" + MessageText.cut(name)
                            + "' has no texture coordinates; choose planar, spherical or cylindrical");
                }
                tex = texture(Path.of(texture), mapping, Bounds.of(s.control()), f, right, worldUp);
            }
            SceneDescription.MaterialSpec m = material(material, colour(v.get(surfaceKey(i, COLOR))), tex != null,
                    Double.parseDouble(v.get(surfaceKey(i, IOR))), colour(v.get(surfaceKey(i, TINT))),
                    Double.parseDouble(v.get(surfaceKey(i, ATTENUATION))), Double.parseDouble(v.get(surfaceKey(i, REFLECTIVITY))));
            boolean smooth = v.get(surfaceKey(i, SHADING)).equals("smooth");
            specs.add(surface(i, name, s, v.get(surfaceKey(i, RENDERING)), smooth, m, tex));
        }
        SceneDescription scene = new SceneDescription(image, camera, lights, floor, specs);
        return new Resolved(scene, Boolean.parseBoolean(v.get(IDENTIFY)), Boolean.parseBoolean(v.get(SAVE_SCENE)));
    }

    /** How a surface is refined for its rendering choice, and the phrase legends use for it. */
    private static SceneDescription.SurfaceSpec surface(int i, String name, DisplayedSurface s, String rendering, boolean smooth,
                                                        SceneDescription.MaterialSpec m, SceneDescription.TextureSpec tex) {
        ControlMesh c = s.control();
        boolean shownRefined = s.scheme() != DisplayedSurface.Scheme.NONE;
        return switch (rendering) {
            case "limit" -> {
                // The host's level with every vertex on the limit surface; a surface the host shows
                // unrefined gets a few levels, else its "limit" would be its own cage shrunk.
                int level = shownRefined ? s.level() : LIMIT_LEVEL_OF_A_POLYHEDRON;
                if (fits(c, level, SubdivisionSurface.BYTES_PER_FACE + SubdivisionSurface.LIMIT_POSITION_BYTES_PER_FACE)) {
                    yield new SceneDescription.SurfaceSpec(i, name, c, SceneDescription.Method.UNIFORM, level, Double.NaN, true, smooth, m, tex,
                            "limit surface (level " + level + ", vertices at their limit positions)");
                }
                // Limit positions need uniform refinement; too large for it, the surface is refined
                // adaptively to half-pixel edges instead, which the eye cannot tell from the limit.
                yield new SceneDescription.SurfaceSpec(i, name, c, SceneDescription.Method.COMBINED, -1, LIMIT_TARGET, false, smooth, m, tex,
                        "limit surface (adaptive, " + LIMIT_TARGET + " px edges: level " + level + " is too large to refine whole)");
            }
            case "adaptive" -> new SceneDescription.SurfaceSpec(i, name, c, SceneDescription.Method.COMBINED, -1, ADAPTIVE_TARGET, false, smooth, m, tex,
                    "adaptive (" + (int) ADAPTIVE_TARGET + " px edges)");
            case "host-level" -> {
                int level = shownRefined ? s.level() : 0;
                String what = level == 0 ? "control mesh" : "level " + level;
                if (fits(c, level, SubdivisionSurface.BYTES_PER_FACE)) {
                    yield new SceneDescription.SurfaceSpec(i, name, c, SceneDescription.Method.UNIFORM, level, Double.NaN, false, smooth, m, tex, what);
                }
                // As the scene parser does: a level too large to refine whole is rendered by the
                // combined method at the same level, the same triangles within the memory budget.
                yield new SceneDescription.SurfaceSpec(i, name, c, SceneDescription.Method.COMBINED, level, Double.NaN, false, smooth, m, tex,
                        what + " (combined method: too large to refine whole)");
            }
            default -> throw new IllegalStateException("rendering without a method: " + rendering);
        };
    }

    /** Levels of the limit rendering of a surface the host shows without subdivision. */
    static final int LIMIT_LEVEL_OF_A_POLYHEDRON = 3;

    /** Whether uniform refinement to {@code level} fits the face limit and the heap. */
    private static boolean fits(ControlMesh c, int level, long bytesPerFace) {
        try {
            SubdivisionSurface.checkLevel(level, c.refinedFaceCount(level), bytesPerFace);
            return true;
        } catch (IllegalArgumentException tooLarge) {
            return false;
        }
    }

    private static SceneDescription.MaterialSpec material(String kind, Color colour, boolean textured, double ior, Color tint,
                                                         double attenuation, double reflectivity) {
        // A texture multiplies the colour: white shows it as it is.
        Color c = textured ? Color.WHITE : colour;
        return switch (kind) {
            case "opaque" -> new SceneDescription.MaterialSpec(c, 0.1, 0.75, 0.35, 60, 0, 0, 1, Color.BLACK, Color.WHITE, false);
            case "transparent" -> new SceneDescription.MaterialSpec(textured ? Color.WHITE : tint, 0, 0.05, 0.8, 200, 0.05, 0.9, ior,
                    Color.grey(attenuation), tint, true);
            case "mirror" -> new SceneDescription.MaterialSpec(c, 0.05, 0.8 * (1 - reflectivity), 0.6, 300, reflectivity, 0, 1,
                    Color.BLACK, Color.WHITE, false);
            default -> throw new IllegalStateException("material without coefficients: " + kind);
        };
    }

    /** The preset's lights, placed around the surfaces' bounds relative to the view; no falloff, so only directions matter. */
    private static List<SceneDescription.LightSpec> lights(String preset, Bounds b, Vec3 eye, Vec3 f, Vec3 right, Vec3 up) {
        double d = Math.max(eye.minus(b.centre).length(), 3 * b.radius);
        return switch (preset) {
            case "headlight" -> List.of(new SceneDescription.LightSpec(eye, Color.WHITE, 1));
            case "sun" -> List.of(light(b, d * 3, up.times(2).minus(f.times(0.8)).plus(right.times(0.5)), new Color(1, 0.97, 0.9), 1));
            case "studio" -> List.of(
                    light(b, d, f.times(-1).minus(right.times(0.8)).plus(up.times(0.9)), new Color(1, 0.97, 0.92), 0.8),   // key: front left, above
                    light(b, d, f.times(-1).plus(right).plus(up.times(0.2)), new Color(0.85, 0.9, 1), 0.35),             // fill: front right
                    light(b, d, f.plus(up.times(1.2)).plus(right.times(0.3)), Color.WHITE, 0.5));                      // rim: behind, above
            default -> throw new IllegalStateException("lighting without lights: " + preset);
        };
    }

    private static SceneDescription.LightSpec light(Bounds b, double distance, Vec3 direction, Color c, double intensity) {
        return new SceneDescription.LightSpec(b.centre.plus(direction.normalized().times(distance)), c, intensity);
    }

    /** The plane just under the surfaces across the up direction: a gap of a thousandth of their size, so a flat bottom does not coincide with it. */
    private static double floorOffset(Bounds b, Vec3 up) {
        return b.min(up) - 1e-3 * b.radius;
    }

    private static SceneDescription.FloorSpec floor(String kind, Bounds b, Vec3 up) {
        if (kind.equals("none")) return null;
        boolean checker = kind.equals("checker");
        SceneDescription.MaterialSpec m = new SceneDescription.MaterialSpec(checker ? Color.WHITE : Color.grey(0.7), 0.1, 0.8, 0, 20, 0, 0, 1,
                Color.BLACK, Color.WHITE, false);
        // Squares half the surfaces' radius wide: a few under the surfaces, many to the horizon.
        return new SceneDescription.FloorSpec(up, floorOffset(b, up), m, checker, 2 / b.radius, Color.grey(0.8), Color.grey(0.45));
    }

    /** A texture fitted to the surface's bounds: the projections cover it once. */
    private static SceneDescription.TextureSpec texture(Path image, String mapping, Bounds b, Vec3 f, Vec3 right, Vec3 up) {
        return switch (mapping) {
            case "uv" -> new SceneDescription.TextureSpec(image, "uv", Vec3.ZERO, Vec3.Y, Vec3.X, 1, 1);
            case "planar" -> {
                // Projected towards the eye, u to the right and v up as the view shows them.
                Vec3 n = f.times(-1), v = n.cross(right);
                double u0 = b.min(right), v0 = b.min(v);
                yield new SceneDescription.TextureSpec(image, "planar", right.times(u0).plus(v.times(v0)), n, right,
                        extent(b.max(right) - u0, b.radius), extent(b.max(v) - v0, b.radius));
            }
            case "spherical" -> new SceneDescription.TextureSpec(image, "spherical", b.centre, up, perpendicular(up, right), 1, 1);
            case "cylindrical" -> {
                double h0 = b.min(up);
                Vec3 centre = b.centre.plus(up.times(h0 - b.centre.dot(up)));
                yield new SceneDescription.TextureSpec(image, "cylindrical", centre, up, perpendicular(up, right), 1, extent(b.max(up) - h0, b.radius));
            }
            default -> throw new IllegalStateException("mapping without a projection: " + mapping);
        };
    }

    /** A repeat size: the extent, or the radius where the surface is flat that way. */
    private static double extent(double e, double radius) {
        return e > 1e-9 * radius ? e : radius;
    }

    /** {@code r} made perpendicular to the unit axis, or another perpendicular when it is parallel. */
    private static Vec3 perpendicular(Vec3 axis, Vec3 r) {
        Vec3 p = r.minus(axis.times(r.dot(axis)));
        if (p.length() > 1e-6) return p.normalized();
        Vec3 other = Math.abs(axis.x()) < 0.9 ? Vec3.X : Vec3.Y;
        return other.minus(axis.times(other.dot(axis))).normalized();
    }

    private static Color colour(String text) {
        String[] p = text.strip().split("\\s+");
        return new Color(Double.parseDouble(p[0]), Double.parseDouble(p[1]), Double.parseDouble(p[2]));
    }

    private static String colourText(Color c) {
        return c.r() + " " + c.g() + " " + c.b();
    }

    /** The control points of surfaces: the limit surface lies in their convex hull, so within these bounds. */
    static final class Bounds {
        private final List<double[]> points;
        final Vec3 centre;
        /** Half the box's diagonal; positive. */
        final double radius;

        private Bounds(List<double[]> points) {
            this.points = points;
            double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
            double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (double[] p : points) {
                for (int i = 0; i < p.length; i++) {
                    lo[i % 3] = Math.min(lo[i % 3], p[i]);
                    hi[i % 3] = Math.max(hi[i % 3], p[i]);
                }
            }
            centre = new Vec3((lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2);
            double r = new Vec3(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]).length() / 2;
            radius = r > 0 ? r : 1;
        }

        static Bounds of(ControlMesh c) { return new Bounds(List.of(c.positions())); }

        static Bounds of(List<DisplayedSurface> surfaces) {
            return new Bounds(surfaces.stream().map(s -> s.control().positions()).toList());
        }

        /** The least {@code p . d} over the points. */
        double min(Vec3 d) {
            double m = Double.POSITIVE_INFINITY;
            for (double[] p : points) {
                for (int i = 0; i < p.length; i += 3) m = Math.min(m, p[i] * d.x() + p[i + 1] * d.y() + p[i + 2] * d.z());
            }
            return m;
        }

        /** The greatest {@code p . d} over the points. */
        double max(Vec3 d) {
            return -min(d.times(-1));
        }
    }
}
