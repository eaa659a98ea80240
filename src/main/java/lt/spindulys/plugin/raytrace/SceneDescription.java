package lt.spindulys.plugin.raytrace;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.limits.MessageText;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Checker;
import lt.spindulys.texture.Cylindrical;
import lt.spindulys.texture.Filter;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.Mapping;
import lt.spindulys.texture.Planar;
import lt.spindulys.texture.Spherical;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.Uv;
import lt.spindulys.texture.Wrap;

/**
 * The scene the ray tracer makes of what a host shows, with every choice resolved to numbers. It
 * is the one description from which both the {@link SceneBuilder} that is rendered and the
 * {@code .dat} text that is saved are made, so the saved scene is the rendered one: every number
 * is written with {@link Double#toString}, which the scene parser reads back to the same double.
 *
 * @param image    size, samples and background
 * @param camera   the host's view
 * @param lights   the lighting preset's lights
 * @param floor    the floor, or null for none
 * @param surfaces the surfaces, in the host's order (so surface i is object i of the scene)
 */
record SceneDescription(ImageSpec image, CameraSpec camera, List<LightSpec> lights, FloorSpec floor, List<SurfaceSpec> surfaces) {

    SceneDescription {
        lights = List.copyOf(lights);
        surfaces = List.copyOf(surfaces);
    }

    /** Image size in pixels, samples per pixel, background colour; 8-bit images are sRGB-encoded. */
    record ImageSpec(int width, int height, int samples, Color background) {}

    /** A pinhole camera. */
    record CameraSpec(Vec3 eye, Vec3 target, Vec3 up, double fovDegrees) {}

    /** A point light without falloff (the classic Whitted light). */
    record LightSpec(Vec3 position, Color color, double intensity) {}

    /** The plane {@code normal . p = offset}, plain or with a checker of squares {@code 1 / checkerScale} wide. */
    record FloorSpec(Vec3 normal, double offset, MaterialSpec material, boolean checker, double checkerScale, Color color1, Color color2) {}

    /** A material's coefficients, as the scene format's material keys. */
    record MaterialSpec(Color color, double ka, double kd, double ks, double shininess, double kr, double kt, double ior,
                        Color beta, Color filter, boolean fresnel) {}

    /**
     * An image texture on the diffuse channel.
     *
     * @param image     the image file
     * @param mapping   uv, planar, spherical or cylindrical
     * @param center    projection centre (not for uv)
     * @param axis      projection axis (not for uv)
     * @param reference the +u direction (not for uv)
     * @param su        repeat size along u
     * @param sv        repeat size along v
     */
    record TextureSpec(Path image, String mapping, Vec3 center, Vec3 axis, Vec3 reference, double su, double sv) {}

    /** How a surface is refined: uniformly at a level, or by the combined adaptive method. */
    enum Method { UNIFORM, COMBINED }

    /**
     * One surface as rendered.
     *
     * @param index      the host's index of the surface
     * @param name       its name, on one line
     * @param control    the host's control mesh
     * @param method     uniform or combined
     * @param level      the uniform (or fixed adaptive) level, or -1 to choose from the view
     * @param target     the adaptive target edge length in pixels, or NaN when a level is fixed
     * @param limitPositions with the uniform method: the refined vertices at their limit positions
     * @param smooth     limit normals interpolated, or flat facets
     * @param material   its material
     * @param texture    its texture, or null
     * @param renderedAs how it was rendered, for legends ("limit surface (adaptive, 0.5 px edges)")
     */
    record SurfaceSpec(int index, String name, ControlMesh control, Method method, int level, double target, boolean limitPositions, boolean smooth,
                       MaterialSpec material, TextureSpec texture, String renderedAs) {}

    /** The render settings the description gives. */
    RenderSettings settings() {
        return RenderSettings.builder().size(image.width, image.height).samplesPerPixel(image.samples)
                .background(image.background).srgb(true).build();
    }

    /**
     * The scene through the public builder API.
     *
     * @param textures where texture images are read (one cache per run, so an image named twice is read once)
     * @return a new builder
     * @throws IllegalArgumentException naming the texture option if a texture image cannot be read
     */
    SceneBuilder toBuilder(TextureCache textures) {
        SceneBuilder b = new SceneBuilder().settings(settings())
                .camera(new PinholeCamera(camera.eye, camera.target, camera.up, camera.fovDegrees));
        for (LightSpec l : lights) b.light(new PointLight(l.position, l.color, l.intensity, PointLight.Falloff.NONE));
        for (SurfaceSpec s : surfaces) {
            GObject o;
            if (s.method == Method.UNIFORM) {
                o = new SubdivisionSurface(s.control, s.level, s.smooth,
                        s.limitPositions ? SubdivisionSurface.Positions.LIMIT : SubdivisionSurface.Positions.REFINED);
            } else {
                AdaptiveSubdivisionSurface a = new AdaptiveSubdivisionSurface(s.control, AdaptiveSubdivisionSurface.Method.COMBINED, s.smooth);
                a.level(s.level);
                if (!Double.isNaN(s.target)) a.target(s.target);
                o = a;
            }
            Material.Builder mb = material(s.material);
            if (s.texture != null) {
                ImageTexture t;
                try {
                    t = new ImageTexture(textures.load(s.texture.image), Filter.BILINEAR, Wrap.REPEAT);
                } catch (IOException | IllegalArgumentException e) {
                    throw new IllegalArgumentException(RayTraceOptions.describe(RayTraceOptions.surfaceKey(s.index, RayTraceOptions.TEXTURE))
                            + " of surface '" + MessageText.cut(s.name) + "' cannot be used: " + e.getMessage(), e);
                }
                mb.texture(Channel.DIFFUSE, t, mapping(s.texture));
            }
            b.add(o.material(mb.build()).name(s.name));
        }
        if (floor != null) {
            Material.Builder mb = material(floor.material);
            if (floor.checker) mb.texture(Channel.DIFFUSE, new Checker(floor.color1, floor.color2, floor.checkerScale, false), new Uv(1, 1));
            b.add(new Plane(floor.normal, floor.offset).material(mb.build()).name("floor"));
        }
        return b;
    }

    private static Material.Builder material(MaterialSpec m) {
        return Material.builder().color(m.color).ka(m.ka).kd(m.kd).ks(m.ks).shininess(m.shininess).kr(m.kr).kt(m.kt)
                .ior(m.ior).beta(m.beta).filter(m.filter).fresnel(m.fresnel);
    }

    private static Mapping mapping(TextureSpec t) {
        return switch (t.mapping) {
            case "uv" -> new Uv(t.su, t.sv);
            case "planar" -> new Planar(t.center, t.axis, t.reference, t.su, t.sv);
            case "spherical" -> new Spherical(t.center, t.axis, t.reference, t.su, t.sv);
            case "cylindrical" -> new Cylindrical(t.center, t.axis, t.reference, t.su, t.sv);
            default -> throw new IllegalStateException("mapping without a texture mapping: " + t.mapping);
        };
    }

    /**
     * The same scene in the scene language (docs/scene-format.md).
     *
     * @param meshFiles the file name of each surface's control mesh, as the scene should name it
     *                  (relative to the scene's folder), in the order of {@link #surfaces()}
     * @param sceneDir  the scene file's folder, to name texture images relative to it where they lie below it
     * @param comment   a first comment line
     * @return the text, ending with a line end
     */
    String toText(List<String> meshFiles, Path sceneDir, String comment) {
        if (meshFiles.size() != surfaces.size()) throw new IllegalArgumentException(meshFiles.size() + " mesh files for " + surfaces.size() + " surfaces");
        StringBuilder t = new StringBuilder();
        t.append("# ").append(oneLine(comment)).append('\n');
        t.append("settings { width ").append(image.width).append("  height ").append(image.height)
                .append("  samples ").append(image.samples).append("  background ").append(colour(image.background))
                .append("  encoding srgb }\n");
        t.append("camera { eye ").append(vec(camera.eye)).append("  lookat ").append(vec(camera.target))
                .append("  up ").append(vec(camera.up)).append("  fov ").append(num(camera.fovDegrees)).append(" }\n");
        for (LightSpec l : lights) {
            t.append("light { position ").append(vec(l.position)).append("  color ").append(colour(l.color))
                    .append("  intensity ").append(num(l.intensity)).append("  falloff none }\n");
        }
        for (SurfaceSpec s : surfaces) {
            if (s.texture != null) {
                t.append("texture surface").append(s.index).append("-image { image ").append(string(imageName(s.texture.image, sceneDir)))
                        .append("  filter bilinear  wrap repeat }\n");
            }
        }
        if (floor != null && floor.checker) {
            t.append("texture floor-checker { pattern checker  scale ").append(num(floor.checkerScale))
                    .append("  color1 ").append(colour(floor.color1)).append("  color2 ").append(colour(floor.color2)).append(" }\n");
        }
        for (int i = 0; i < surfaces.size(); i++) {
            SurfaceSpec s = surfaces.get(i);
            t.append("\n# ").append(s.name).append(": ").append(s.renderedAs).append('\n');
            t.append("subdiv { file ").append(string(meshFiles.get(i)));
            if (s.method == Method.UNIFORM) {
                t.append("  level ").append(s.level);
                if (s.limitPositions) t.append("  positions limit");
            } else {
                t.append("  method combined");
                if (s.level >= 0) t.append("  level ").append(s.level);
                if (!Double.isNaN(s.target)) t.append("  target ").append(num(s.target));
            }
            SubdivOptions o = s.control.options();
            // The OBJ beside says it too; the scene says it as well, so that it reads as what it renders.
            if (o.scheme() != SubdivOptions.Scheme.CATMARK) t.append("  scheme ").append(o.scheme().keyword());
            t.append("\n    boundary ").append(word(o.boundary())).append("  uvinterpolation ").append(word(o.fvar()))
                    .append("  creasing ").append(word(o.creasing())).append("  triangles ").append(word(o.triangles()))
                    .append("  shading ").append(s.smooth ? "smooth" : "flat");
            t.append("\n    material { ").append(materialKeys(s.material));
            if (s.texture != null) t.append("\n               ").append(map("surface" + s.index + "-image", s.texture));
            t.append(" }\n    name ").append(string(s.name)).append(" }\n");
        }
        if (floor != null) {
            t.append("\nplane { normal ").append(vec(floor.normal)).append("  offset ").append(num(floor.offset))
                    .append("\n    material { ").append(materialKeys(floor.material));
            if (floor.checker) t.append("  map { texture floor-checker  channel diffuse  mapping uv }");
            t.append(" }\n    name \"floor\" }\n");
        }
        return t.toString();
    }

    private static String materialKeys(MaterialSpec m) {
        return "color " + colour(m.color) + "  ka " + num(m.ka) + "  kd " + num(m.kd) + "  ks " + num(m.ks)
                + "  shininess " + num(m.shininess) + "  kr " + num(m.kr) + "  kt " + num(m.kt) + "  ior " + num(m.ior)
                + "  beta " + colour(m.beta) + "  filter " + colour(m.filter) + "  fresnel " + m.fresnel;
    }

    private static String map(String texture, TextureSpec t) {
        String s = "map { texture " + texture + "  channel diffuse  mapping " + t.mapping;
        if (!t.mapping.equals("uv")) s += "  center " + vec(t.center) + "  axis " + vec(t.axis) + "  reference " + vec(t.reference);
        return s + "  scale " + num(t.su) + " " + num(t.sv) + " }";
    }

    /** A texture image's name in the scene: relative to the scene's folder when it lies below it, else absolute; '/' separators. */
    private static String imageName(Path image, Path sceneDir) {
        Path abs = image.toAbsolutePath().normalize();
        Path dir = sceneDir.toAbsolutePath().normalize();
        Path shown = abs.startsWith(dir) ? dir.relativize(abs) : abs;
        return shown.toString().replace('\\', '/');
    }

    /** An enum constant as the scene language's word: EDGE_AND_CORNER is edge-and-corner. */
    private static String word(Enum<?> e) {
        return e.name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }

    /** A number the parser reads back to the same double. */
    static String num(double d) {
        if (!Double.isFinite(d)) throw new IllegalArgumentException("a scene number must be finite, found " + d);
        return Double.toString(d);
    }

    private static String vec(Vec3 v) { return num(v.x()) + " " + num(v.y()) + " " + num(v.z()); }

    private static String colour(Color c) { return num(c.r()) + " " + num(c.g()) + " " + num(c.b()); }

    /** A scene-language string: quotes and backslashes escaped (the text is already one line). */
    private static String string(String s) {
        return "\"" + oneLine(s).replace("\\", "\\\\").replace("\"", "\\\"") + "\"";
    }

    /** Line ends and other control characters become spaces, so text stays on its line. */
    static String oneLine(String s) {
        StringBuilder b = new StringBuilder(Objects.requireNonNull(s).length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            b.append(Character.isISOControl(c) || c == '\u2028' || c == '\u2029' ? ' ' : c);
        }
        return b.toString();
    }
}
