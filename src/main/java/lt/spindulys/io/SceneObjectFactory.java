package lt.spindulys.io;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.AdaptiveSettings;
import lt.spindulys.camera.Camera;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.PixelFilter;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.io.SceneBlockReader.AxisAngle;
import lt.spindulys.io.SceneBlockReader.Operand;
import lt.spindulys.io.SceneBlockReader.Prop;
import lt.spindulys.io.SceneBlockReader.Props;
import lt.spindulys.io.SceneGrammar.Block;
import lt.spindulys.io.SceneLexer.Token;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Color;
import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Motion;
import lt.spindulys.scene.Animation;
import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.io.SceneBlockReader.KeyPose;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.Cylinder;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.EnvironmentLight;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Sphere;
import lt.spindulys.scene.Triangle;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Checker;
import lt.spindulys.texture.Cylindrical;
import lt.spindulys.texture.Filter;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.Mapping;
import lt.spindulys.texture.Marble;
import lt.spindulys.texture.Noise;
import lt.spindulys.texture.Planar;
import lt.spindulys.texture.Spherical;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.TextureImage;
import lt.spindulys.texture.Uv;
import lt.spindulys.texture.Wood;
import lt.spindulys.texture.Wrap;

/**
 * The object construction of a scene file: makes what a block read by {@link SceneBlockReader}
 * describes (objects with their common keys, CSG nodes, materials, textures, map bindings,
 * motions, cameras, lights, settings) through the library's public constructors and builders, so
 * a scene read from a file and the same scene written in Java are built alike. A value the
 * library refuses is reported at the key that gave it; files are read through the
 * {@link SceneAssetCache}. Names and the scene builder are the parser's: nothing here is added
 * to a scene.
 */
final class SceneObjectFactory {
    private final SceneErrors err;
    private final SceneAssetCache assets;
    /** The file as objects' sources name it ("&lt;input&gt;" for text without a name), one string for all. */
    private final String sourceName;

    SceneObjectFactory(SceneErrors err, SceneAssetCache assets, String sourceName) {
        this.err = err;
        this.assets = assets;
        this.sourceName = sourceName;
    }

    /**
     * {@code s} with a settings block's keys applied in the order written, each reported at its
     * key if refused; samples and timesteps are checked together once all keys are in.
     */
    /**
     * Bytes of a size given in mebibytes (fractions allowed), refused when negative, not a number,
     * zero where zero has no meaning, or beyond {@link AdaptiveSettings#MAX_BYTES}.
     */
    static long mebibytes(String key, double mib, boolean zeroAllowed) {
        double bytes = mib * (1 << 20);
        if (!(bytes >= (zeroAllowed ? 0 : 1)) || bytes > AdaptiveSettings.MAX_BYTES) {
            throw new IllegalArgumentException(key + " must be " + (zeroAllowed ? "0 (automatic) or more" : "more than 0")
                    + " mebibytes and at most " + (AdaptiveSettings.MAX_BYTES >> 20) + ", found " + mib);
        }
        return (long) bytes;
    }

    RenderSettings settings(Props p, RenderSettings s) {
        RenderSettings.Builder sb = s.toBuilder();
        AdaptiveSettings adaptive = s.adaptive();
        for (Prop pr : p.all) {
            Object v = pr.value();
            try {
                switch (pr.key().name()) {
                    case "width" -> sb.width((Integer) v);
                    case "height" -> sb.height((Integer) v);
                    case "samples" -> sb.samplesPerPixel((Integer) v);
                    case "maxdepth" -> sb.maxDepth((Integer) v);
                    case "mincontribution" -> sb.minContribution((Double) v);
                    case "background" -> sb.background((Color) v);
                    case "ambient" -> sb.ambient((Color) v);
                    case "encoding" -> sb.srgb("srgb".equals(v));
                    case "seed" -> sb.seed((Long) v);
                    case "accelerator" -> sb.accelerator(AcceleratorKind.fromKeyword((String) v));
                    case "aov" -> sb.aovs(aovs((List<?>) v));
                    case "shutter" -> sb.shutter(((double[]) v)[0], ((double[]) v)[1]);
                    case "timesteps" -> sb.timeSteps((Integer) v);
                    case "subdivmemory" -> sb.adaptive(adaptive = adaptive.withMemory(mebibytes("subdivmemory", (Double) v, true)));
                    case "subdivcache" -> sb.adaptive(adaptive = adaptive.withCache(mebibytes("subdivcache", (Double) v, false)));
                    case "subdivpolicy" -> sb.adaptive(adaptive = adaptive.withLastTwoPatches("last-two".equals(v)));
                    case "subdivtarget" -> sb.adaptive(adaptive = adaptive.withTarget(AdaptiveSettings.checkTarget((Double) v)));
                    case "integrator" -> sb.integrator(IntegratorKind.fromKeyword((String) v));
                    case "clamp" -> sb.clamp((Double) v);
                    case "filter" -> sb.filter(PixelFilter.fromKeyword((String) v));
                    case "filterwidth" -> sb.filterWidth((Double) v);
                    case "noisethreshold" -> sb.noiseThreshold((Double) v);
                    case "minsamples" -> sb.minSamples((Integer) v);
                    case "denoise" -> sb.denoise((Boolean) v);
                    default -> throw unhandled(pr);
                }
            } catch (IllegalArgumentException e) {
                throw err.wrap(pr.at(), e);
            }
        }
        s = sb.build();
        Prop steps = p.prop("timesteps");
        if (steps != null) {
            try {
                s.checkTimeSteps();
            } catch (IllegalArgumentException e) {
                throw err.wrap(steps.at(), e);
            }
        }
        // Adaptive sampling against the other keys: reported at the key that asked for it.
        Prop noise = p.prop("minsamples") != null ? p.prop("minsamples") : p.prop("noisethreshold");
        if (noise == null && s.aovs().contains(Aov.NOISE)) noise = p.prop("aov");
        if (noise != null) {
            try {
                s.checkNoiseControl();
            } catch (IllegalArgumentException e) {
                throw err.wrap(noise.at(), e);
            }
        }
        return s;
    }

    private static Set<Aov> aovs(List<?> keywords) {
        Set<Aov> out = EnumSet.noneOf(Aov.class);
        for (Object k : keywords) out.add(Aov.fromKeyword((String) k));
        return out;
    }

    /** A camera block's camera: a pinhole, or a thin lens when any of the lens keys is given. */
    Camera camera(Props p) {
        Camera still = restingCamera(p);
        Prop keys = keysOf(p);
        if (keys == null) return still;
        try {
            return new AnimatedCamera(still, (Keyframes) keys.value());
        } catch (IllegalArgumentException e) {
            throw err.wrap(keys.at(), e);
        }
    }

    /** The block's 'keys' or 'turntable', or null; both is an error at the later one. */
    private Prop keysOf(Props p) {
        Prop keys = p.prop("keys"), turntable = p.prop("turntable");
        if (keys != null && turntable != null) {
            Prop later = p.all.indexOf(keys) > p.all.indexOf(turntable) ? keys : turntable, earlier = later == keys ? turntable : keys;
            throw err.error(later.at(), "'" + later.key().name() + "' and '" + earlier.key().name() + "' (at " + earlier.at().position()
                    + ") exclude each other: a turntable is keys of its own");
        }
        return keys != null ? keys : turntable;
    }

    /** animation { frames FIRST LAST  fps F  shutter ANGLE }. */
    Animation animation(Props p) {
        int[] frames = (int[]) p.get("frames");
        try {
            return new Animation(frames[0], frames[1], p.num("fps"), p.num("shutter"));
        } catch (IllegalArgumentException e) {
            // "first frame", "last frame" name no key: the frames key is meant.
            if (e.getMessage() != null && e.getMessage().contains("frame")) throw err.wrap(p.prop("frames").at(), e);
            throw err.blame(p, e);
        }
    }

    /**
     * keys { interpolation I  pivot P  key FRAME { translate T  rotate X Y Z  scale S } ... }: key
     * frames in increasing order, each at most once, timed on the animation's clock (frame / fps).
     */
    Keyframes keyframes(Props p, Animation a) {
        List<Prop> keys = new ArrayList<>();
        for (Prop pr : p.all) if (pr.key().name().equals("key")) keys.add(pr);
        if (keys.isEmpty()) throw err.error(p.opener, "keys needs at least one 'key FRAME { translate ... rotate ... scale ... }'");
        if (keys.size() > Keyframes.MAX_KEYS) throw err.error(keys.get(Keyframes.MAX_KEYS).at(), "more than " + Keyframes.MAX_KEYS + " keys in one keys block");
        double[] times = new double[keys.size()];
        Keyframes.Pose[] poses = new Keyframes.Pose[keys.size()];
        KeyPose previous = null;
        for (int i = 0; i < keys.size(); i++) {
            KeyPose k = (KeyPose) keys.get(i).value();
            if (previous != null && !(k.frame() > previous.frame())) {
                throw err.error(k.frameAt(), "key frame " + fmt(k.frame()) + " is not after the previous key's frame " + fmt(previous.frame())
                        + " (at " + previous.frameAt().position() + "): keys must be in increasing frame order, each frame once");
            }
            previous = k;
            Props pose = k.pose();
            try {
                poses[i] = new Keyframes.Pose(pose.vec("translate"), pose.vec("rotate"), (Vec3) pose.get("scale"));
            } catch (IllegalArgumentException e) {
                throw err.blame(pose, e);
            }
            times[i] = a.time(k.frame());
        }
        try {
            return Keyframes.of(times, poses, Keyframes.Interpolation.fromKeyword((String) p.get("interpolation")), Transform.translate(p.vec("pivot")));
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** turntable { axis A  center C  turns N }: N turns from the animation's first frame to the one after its last. */
    Keyframes turntable(Props p, Animation a) {
        try {
            return Keyframes.turntable(p.vec("axis"), p.vec("center"), p.num("turns"), a.time(a.first()), a.time(a.last() + 1.0));
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    private static String fmt(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? Long.toString((long) v) : Double.toString(v);
    }

    private Camera restingCamera(Props p) {
        if ("orthographic".equals(p.get("projection"))) return orthographicCamera(p);
        Prop width = p.prop("width");
        if (width != null) throw err.error(width.at(), "'width' sizes an orthographic view: it needs 'projection orthographic' (a perspective camera is sized by 'fov')");
        PinholeCamera view;
        try {
            view = new PinholeCamera(p.vec("eye"), p.vec("lookat"), p.vec("up"), p.num("fov"));
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
        Prop aperture = p.prop("aperture"), focus = p.prop("focus"), point = p.prop("focuspoint"), lens = p.prop("lens");
        if (aperture == null && focus == null && point == null && lens == null) {
            return view;
        }
        if (focus != null && point != null) {
            Prop later = p.all.indexOf(focus) > p.all.indexOf(point) ? focus : point;
            throw err.error(later.at(), "camera has both 'focus' and 'focuspoint': give one");
        }
        double distance;
        if (point != null) {
            try {
                distance = ThinLensCamera.focusDistanceTo(view, (Vec3) point.value());
            } catch (IllegalArgumentException e) {
                throw err.wrap(point.at(), e);
            }
        } else {
            distance = focus != null ? (Double) focus.value() : ThinLensCamera.lookAtDistance(view);
        }
        try {
            return new ThinLensCamera(view, p.num("aperture"), distance, LensPattern.fromKeyword((String) p.get("lens")));
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** camera { projection orthographic  width W ... }: parallel rays, no field of view and no lens. */
    private Camera orthographicCamera(Props p) {
        Prop width = p.prop("width");
        if (width == null) throw err.error(p.prop("projection").at(), "an orthographic camera needs 'width': the width of the view in scene units");
        for (String perspectiveOnly : new String[] {"fov", "aperture", "focus", "focuspoint", "lens"}) {
            Prop given = p.prop(perspectiveOnly);
            if (given != null) {
                throw err.error(given.at(), "'" + perspectiveOnly + "' needs a perspective camera: an orthographic one has "
                        + (perspectiveOnly.equals("fov") ? "'width' instead" : "no lens, so everything is sharp"));
            }
        }
        try {
            return new OrthographicCamera(p.vec("eye"), p.vec("lookat"), p.vec("up"), (Double) width.value());
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** A light block's point light. */
    /** An environment block's environment: its image read once per parse (shared with textures naming the same file). */
    Environment environment(Props p) {
        boolean light = (Boolean) p.get("light");
        if (!light && p.prop("samples") != null) throw err.error(p.prop("samples").at(), "environment samples needs 'light true' (an environment that is not a light sends no shadow rays)");
        TextureImage map = assets.image(p.prop("file"), "environment image");
        if (light) {
            try {
                EnvironmentLight.requireTables(map);
            } catch (IllegalArgumentException e) {
                throw err.wrap(p.prop("light").at(), e);
            }
        }
        try {
            Integer samples = (Integer) p.get("samples");
            Environment e = new Environment(map, p.num("rotate"), p.num("intensity"), light, samples == null ? 1 : samples);
            Prop visible = p.prop("visibleintensity");
            boolean background = (Boolean) p.get("background");
            if (!background && visible != null) {
                throw err.error(visible.at(), "visibleintensity scales what camera rays see of the environment, but 'background false' (at "
                        + p.prop("background").at().position() + ") hides it from them: give one of them");
            }
            return e.withCameraView(background, visible != null ? (Double) visible.value() : e.intensity());
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    PointLight light(Props p) {
        PointLight.Falloff falloff = switch ((String) p.get("falloff")) {
            case "none" -> PointLight.Falloff.NONE;
            case "inverse-square" -> PointLight.Falloff.INVERSE_SQUARE;
            default -> throw new IllegalStateException("falloff choice without a mapping: " + p.get("falloff"));
        };
        try {
            return new PointLight(p.vec("position"), (Color) p.get("color"), p.num("intensity"), falloff);
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** A rectlight, disclight or spherelight block's area light. */
    AreaLight areaLight(Props p) {
        Color color = (Color) p.get("color");
        double intensity = p.num("intensity");
        int samples = (Integer) p.get("samples");
        Prop given = p.prop("intensity"), power = p.prop("power");
        if (given != null && power != null) {
            Prop later = p.all.indexOf(given) > p.all.indexOf(power) ? given : power;
            throw err.error(later.at(), p.block.keyword() + " has both 'intensity' and 'power': give one");
        }
        try {
            AreaLight light = switch (p.block.keyword()) {
                case "rectlight" -> AreaLight.rectangle(p.vec("center"), p.vec("normal"), p.vec("tangent"), p.num("width"), p.num("height"),
                        color, intensity, (Boolean) p.get("onesided"), samples);
                case "disclight" -> AreaLight.disc(p.vec("center"), p.vec("normal"), p.num("radius"), color, intensity, (Boolean) p.get("onesided"), samples);
                case "spherelight" -> AreaLight.sphere(p.vec("center"), p.num("radius"), color, intensity, samples);
                default -> throw new IllegalStateException("area light statement without a mapping: " + p.block.keyword());
            };
            return power == null ? light : light.withPower((Double) power.value());
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** A texture block's texture, named {@code name}: an image or a procedural pattern. */
    Texture texture(Props p, String name) {
        String label = "texture " + MessageText.quote(name);
        Prop image = p.prop("image"), pattern = p.prop("pattern");
        if (image != null && pattern != null) throw err.error(pattern.at(), label + " has both 'image' and 'pattern': give one");
        if (image == null && pattern == null) throw err.error(p.opener, label + " needs 'image' or 'pattern'");
        // Keys that only the other kind uses are errors rather than silently ignored.
        for (Prop pr : p.all) {
            String k = pr.key().name();
            boolean imageKey = k.equals("filter") || k.equals("wrap");
            if (image != null && !imageKey && !k.equals("image")) throw err.error(pr.at(), "'" + k + "' applies to pattern textures, not to an image");
            if (pattern != null && imageKey) throw err.error(pr.at(), "'" + k + "' applies to image textures, not to a pattern");
        }
        return image != null ? imageTexture(p, image) : pattern(p, pattern);
    }

    private Texture imageTexture(Props p, Prop image) {
        TextureImage img = assets.image(image);
        Filter filter = switch ((String) p.get("filter")) {
            case "nearest" -> Filter.NEAREST;
            case "bilinear" -> Filter.BILINEAR;
            case "trilinear" -> Filter.TRILINEAR;
            default -> throw new IllegalStateException("filter choice without a mapping: " + p.get("filter"));
        };
        Wrap wrap = switch ((String) p.get("wrap")) {
            case "repeat" -> Wrap.REPEAT;
            case "clamp" -> Wrap.CLAMP;
            case "mirror" -> Wrap.MIRROR;
            default -> throw new IllegalStateException("wrap choice without a mapping: " + p.get("wrap"));
        };
        try {
            return new ImageTexture(img, filter, wrap); // trilinear builds the mip chain here, asking the heap first
        } catch (IllegalArgumentException e) {
            throw err.wrap(p.prop("filter") != null ? p.prop("filter").at() : image.valueAt(), e);
        }
    }

    /** Turbulence of marble and wood when the block gives none: veins and rings visibly disturbed. */
    private static final double MARBLE_TURBULENCE = 4, WOOD_TURBULENCE = 1;
    /** Noise octaves when the block gives none. */
    private static final int OCTAVES = 4;

    /** A procedural texture from a texture block's pattern keys. */
    private Texture pattern(Props p, Prop pattern) {
        String kind = (String) pattern.value();
        boolean turbulent = kind.equals("marble") || kind.equals("wood");
        Prop turbulence = p.prop("turbulence"), octaves = p.prop("octaves");
        if (turbulence != null && !turbulent) throw err.error(turbulence.at(), "'turbulence' applies to marble and wood, not to " + kind);
        if (octaves != null && kind.equals("checker")) throw err.error(octaves.at(), "'octaves' applies to noise, marble and wood, not to checker");
        Color a = (Color) p.get("color1"), b = (Color) p.get("color2");
        double scale = p.num("scale");
        boolean solid = (Boolean) p.get("solid");
        int oct = octaves != null ? (Integer) octaves.value() : OCTAVES;
        try {
            return switch (kind) {
                case "checker" -> new Checker(a, b, scale, solid);
                case "noise" -> new Noise(a, b, scale, oct, solid);
                case "marble" -> new Marble(a, b, scale, turbulence != null ? (Double) turbulence.value() : MARBLE_TURBULENCE, oct, solid);
                case "wood" -> new Wood(a, b, scale, turbulence != null ? (Double) turbulence.value() : WOOD_TURBULENCE, oct, solid);
                default -> throw new IllegalStateException("pattern choice without a texture: " + kind);
            };
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** A texture bound to a channel by a material's map block; channelAt is where the channel is named (the block's opener if it is not). */
    record Binding(Channel channel, Token channelAt, Texture texture, Mapping mapping, Double strength) {}

    /** The keys of a map block that place a projection; the uv mapping takes none of them. */
    private static final List<String> PROJECTION_KEYS = List.of("center", "axis", "reference");

    /** map { texture NAME channel ... mapping ... }, after a material's 'map' key. */
    Binding binding(Props p) {
        Channel channel = Channel.fromKeyword((String) p.get("channel"));
        Prop channelProp = p.prop("channel");
        Token channelAt = channelProp != null ? channelProp.valueAt() : p.opener;
        String mapping = (String) p.get("mapping");
        Prop strength = p.prop("strength");
        if (strength != null && channel != Channel.BUMP) throw err.error(strength.at(), "'strength' applies only to channel bump, not " + channel.keyword());
        if (mapping.equals("uv")) {
            for (String k : PROJECTION_KEYS) {
                Prop pr = p.prop(k);
                if (pr != null) throw err.error(pr.at(), "'" + k + "' does not apply to mapping uv (only to planar, spherical and cylindrical)");
            }
        }
        double[] scale = (double[]) p.get("scale");
        Mapping m;
        try {
            m = switch (mapping) {
                case "uv" -> new Uv(scale[0], scale[1]);
                case "planar" -> new Planar(p.vec("center"), p.vec("axis"), p.vec("reference"), scale[0], scale[1]);
                case "spherical" -> new Spherical(p.vec("center"), p.vec("axis"), p.vec("reference"), scale[0], scale[1]);
                case "cylindrical" -> new Cylindrical(p.vec("center"), p.vec("axis"), p.vec("reference"), scale[0], scale[1]);
                default -> throw new IllegalStateException("mapping choice without a mapping: " + mapping);
            };
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
        return new Binding(channel, channelAt, (Texture) p.get("texture"), m, strength == null ? null : (Double) strength.value());
    }

    /**
     * A material from its block's keys, applied through the validating builder in the order
     * written. Which keys and channels the model takes is checked first, once the whole block is
     * read, so 'model' may stand anywhere in it; a key of the other model is reported at the key.
     */
    Material material(Props p, String name) {
        Object modelWord = p.get("model");
        Material.Model model = modelWord == null ? Material.Model.WHITTED : Material.Model.fromKeyword((String) modelWord);
        for (Prop pr : p.all) {
            if (pr.value() instanceof Binding bd) {
                String refusal = model.refusal(bd.channel);
                if (refusal != null) throw err.error(bd.channelAt, refusal);
            } else {
                String refusal = model.refusal(pr.key().name());
                if (refusal != null) throw err.error(pr.at(), refusal);
            }
        }
        Material.Builder mb = Material.builder().model(model);
        for (Prop pr : p.all) {
            Object v = pr.value();
            try {
                switch (pr.key().name()) {
                    case "model" -> { } // applied above
                    case "color" -> mb.color((Color) v);
                    case "ka" -> mb.ka((Double) v);
                    case "kd" -> mb.kd((Double) v);
                    case "ks" -> mb.ks((Double) v);
                    case "shininess" -> mb.shininess((Double) v);
                    case "kr" -> mb.kr((Double) v);
                    case "kt" -> mb.kt((Double) v);
                    case "fresnel" -> mb.fresnel((Boolean) v);
                    case "metallic" -> mb.metallic((Double) v);
                    case "roughness" -> mb.roughness((Double) v);
                    case "transmission" -> mb.transmission((Double) v);
                    case "ior" -> mb.ior((Double) v);
                    case "beta" -> mb.beta((Color) v);
                    case "filter" -> mb.filter((Color) v);
                    case "emission" -> mb.emission((Color) v);
                    case "map" -> {
                        Binding bd = (Binding) v;
                        mb.texture(bd.channel, bd.texture, bd.mapping);
                        if (bd.strength != null) mb.bumpStrength(bd.strength);
                    }
                    default -> throw unhandled(pr);
                }
            } catch (IllegalArgumentException e) {
                throw err.wrap(pr.at(), e);
            }
        }
        if (name != null) mb.name(name);
        try {
            return mb.build();
        } catch (IllegalArgumentException e) {
            // kr + kt too large: reported at whichever of the two came last.
            Prop kr = p.prop("kr"), kt = p.prop("kt");
            if (kr != null || kt != null) {
                Prop at = kr == null ? kt : kt == null ? kr : p.all.indexOf(kr) > p.all.indexOf(kt) ? kr : kt;
                throw err.wrap(at.at(), e);
            }
            // A principled colour above 1: at 'color' (the message names it).
            throw err.blame(p, e);
        }
    }

    /** The object of an object or CSG statement's block, with its common keys applied; not yet added to a builder. */
    GObject object(Props p) {
        Block b = p.block;
        GObject o;
        if (b.category() == SceneGrammar.Category.CSG) {
            o = bool(p);
        } else if (b == SceneGrammar.MESH) {
            o = assets.mesh(p);
        } else if (b == SceneGrammar.SUBDIV) {
            o = assets.surface(p);
        } else {
            try {
                o = switch (b.keyword()) {
                    case "sphere" -> new Sphere(p.vec("center"), p.num("radius"));
                    case "plane" -> new Plane(p.vec("normal"), p.num("offset"));
                    case "box" -> new Box(p.vec("min"), p.vec("max"));
                    case "cylinder" -> new Cylinder(p.vec("base"), p.vec("top"), p.num("radius"));
                    case "triangle" -> {
                        Vec3[] v = (Vec3[]) p.get("vertices");
                        yield new Triangle(v[0], v[1], v[2]);
                    }
                    default -> throw new IllegalStateException("grammar has object '" + b.keyword() + "' that the parser cannot make");
                };
            } catch (IllegalArgumentException e) {
                throw err.blame(p, e);
            }
        }
        // Errors found only when the scene is built name this statement.
        o.source(sourceName, p.opener.line(), p.opener.column());
        // Common keys; transforms compose in the order written (GObject.transform appends).
        keysOf(p);
        for (Prop pr : p.all) {
            switch (pr.key().name()) {
                case "material" -> o.material((Material) pr.value());
                case "name" -> o.name((String) pr.value());
                case "terminator" -> o.shadowTerminator((Boolean) pr.value());
                case "motion" -> o.motion((Motion) pr.value());
                case "keys", "turntable" -> o.keys((Keyframes) pr.value());
                case "translate", "rotate", "scale" -> {
                    try {
                        o.transform((Transform) pr.value());
                    } catch (IllegalArgumentException e) {
                        throw err.wrap(pr.at(), "invalid '" + pr.key().name() + "': ", e);
                    }
                }
                default -> { } // the shape's own keys, used by its constructor above
            }
        }
        return o;
    }

    /**
     * A CSG node over the operands nested in its block. Its constructor checks that every operand
     * is closed; its complaint names the operand by number ("difference operand 2 (mesh) is not
     * closed: ..."), and is reported at that operand's statement.
     */
    private GObject bool(Props p) {
        Bool.Op op = null;
        for (Bool.Op o : Bool.Op.values()) if (o.keyword().equals(p.block.keyword())) op = o;
        if (op == null) throw new IllegalStateException("grammar has CSG statement '" + p.block.keyword() + "' without a Bool.Op");
        List<GObject> objects = new ArrayList<>();
        for (Operand o : p.operands) objects.add(o.object());
        try {
            return new Bool(op, objects);
        } catch (IllegalArgumentException e) {
            Matcher m = OPERAND_NUMBER.matcher(e.getMessage() == null ? "" : e.getMessage());
            int k = m.find() ? Integer.parseInt(m.group(1)) : 0;
            throw err.wrap(k >= 1 && k <= p.operands.size() ? p.operands.get(k - 1).at() : p.opener, e);
        }
    }

    /** How Bool's messages number an operand (from 1). */
    private static final Pattern OPERAND_NUMBER = Pattern.compile("\\boperand (\\d+)\\b");

    /**
     * motion { ... } after an object's 'motion' key: the end transform (translate, or direction
     * and speed; rotate; scale; about pivot) between start and finish. Open times are the
     * shutter's; they are checked against it once the whole file (and so the settings) is read.
     */
    Motion motion(Props p, Token keyToken) {
        Prop translate = p.prop("translate"), direction = p.prop("direction"), speed = p.prop("speed");
        if (translate != null && direction != null) {
            Prop later = p.all.indexOf(translate) > p.all.indexOf(direction) ? translate : direction;
            throw err.error(later.at(), "motion has both 'translate' and 'direction': give the end translation, or direction and speed");
        }
        if (direction != null && speed == null) throw err.error(direction.at(), "'direction' needs 'speed' (units per unit of shutter time)");
        if (speed != null && direction == null) throw err.error(speed.at(), "'speed' needs 'direction'");
        if (translate == null && direction == null && p.prop("rotate") == null && p.prop("scale") == null) {
            throw err.error(keyToken, "motion needs translate, direction and speed, rotate or scale: without them the object does not move");
        }
        Prop start = p.prop("start"), finish = p.prop("finish");
        double s = start != null ? (Double) start.value() : Double.NaN, f = finish != null ? (Double) finish.value() : Double.NaN;
        Motion m;
        try {
            if (direction != null) {
                if (p.prop("rotate") != null || p.prop("scale") != null) {
                    Prop extra = p.prop("rotate") != null ? p.prop("rotate") : p.prop("scale");
                    throw err.error(extra.at(), "'" + extra.key().name() + "' does not combine with direction and speed (the thesis's linear motion); use translate");
                }
                m = Motion.linear(p.vec("direction"), p.num("speed"), s, f);
            } else {
                AxisAngle r = p.prop("rotate") != null ? (AxisAngle) p.get("rotate") : new AxisAngle(Vec3.Y, 0);
                Vec3 sc = p.prop("scale") != null ? (Vec3) p.get("scale") : new Vec3(1, 1, 1);
                Vec3 t = translate != null ? (Vec3) translate.value() : Vec3.ZERO;
                m = Motion.of(sc, r.axis(), r.degrees(), t, p.vec("pivot"), s, f);
            }
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
        return m;
    }

    private static IllegalStateException unhandled(Prop pr) {
        return new IllegalStateException("grammar key '" + pr.key().name() + "' has no builder call");
    }
}
