package lt.spindulys.io;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.io.SceneGrammar.Block;
import lt.spindulys.io.SceneGrammar.Key;
import lt.spindulys.io.SceneLexer.Kind;
import lt.spindulys.io.SceneLexer.Token;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.Cylinder;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.scene.Triangle;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
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
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.TextureImage;
import lt.spindulys.texture.Uv;
import lt.spindulys.texture.Wood;
import lt.spindulys.texture.Wrap;

/**
 * Reads a .dat scene file (the language is described in docs/scene-format.md) into a
 * {@link SceneBuilder}, using only the builder's public API, so a scene read from a file and the
 * same scene written in Java are built alike. The builder is returned unbuilt so that the command
 * line can still override settings.
 *
 * <p>Every error is a {@link SceneException} naming file:line:column of the offending token; values
 * the builder API refuses are reported at the key that gave them. The first error stops parsing.
 */
public final class SceneParser {
    private final SceneLexer lex;
    private final String file;
    /** The file as objects' sources name it ("&lt;input&gt;" for text without a name), one string for all. */
    private final String sourceName;
    private final Path baseDir;
    private final SceneBuilder builder = new SceneBuilder();
    private Token settingsAt, cameraAt;
    /** Where each named material was defined, for "already defined at" and suggestions. */
    private final Map<String, Token> materialsAt = new LinkedHashMap<>();
    /** Named textures and where each was defined. */
    private final Map<String, Texture> textures = new HashMap<>();
    private final Map<String, Token> texturesAt = new LinkedHashMap<>();
    /** Every image of this parse, loaded once however many textures name it. */
    private final TextureCache textureCache = new TextureCache();
    /** The first mesh read from each file; later statements naming the file get instances of it. */
    private final Map<Path, TriangleMesh> meshes = new HashMap<>();
    /** Likewise for subdivision surfaces, by everything that decides the refined surface. */
    private final Map<SubdivKey, SubdivisionSurface> surfaces = new HashMap<>();

    private SceneParser(String text, String file, Path baseDir) {
        this.lex = new SceneLexer(text, file);
        this.file = file;
        this.sourceName = SceneException.location(file, 0, 0);
        this.baseDir = baseDir;
    }

    /**
     * Parses a scene file, which must be UTF-8. Relative mesh paths are resolved against the file's
     * folder, and messages name the file as given.
     *
     * @throws IOException    if the file cannot be read
     * @throws SceneException if its content is not a valid scene
     */
    public static SceneBuilder parse(Path file) throws IOException {
        String name = file.toString();
        // A pipe would block and a device never end: refused before anything is opened.
        String problem = InputFiles.problem(file);
        if (problem != null) throw new SceneException(name, 0, 0, "scene file " + problem);
        byte[] bytes;
        try {
            // Decoding holds the bytes, the chars (2 bytes each) and the String's copy at once.
            bytes = InputFiles.readAllBytes(file, "scene file", 5);
        } catch (IllegalArgumentException e) {
            throw new SceneException(name, 0, 0, e.getMessage(), e);
        }
        String text = decodeUtf8(bytes, name);
        return parse(text, name, file.toAbsolutePath().getParent());
    }

    /**
     * Parses scene text.
     *
     * @param fileName name used in error messages (null: "&lt;input&gt;")
     * @param baseDir  folder against which relative mesh paths are resolved (null: the working directory)
     * @throws SceneException if the text is not a valid scene
     */
    public static SceneBuilder parse(String text, String fileName, Path baseDir) {
        Path dir = (baseDir != null ? baseDir : Path.of("")).toAbsolutePath();
        SceneParser p = new SceneParser(Objects.requireNonNull(text, "text"), fileName, dir);
        p.statements();
        p.checkMotions();
        return p.builder;
    }

    // ---- statements ----

    private void statements() {
        boolean first = true;
        while (true) {
            Token t = lex.next();
            // A Workframe mesh is a .dat file like a scene; its first token is its point count.
            if (first && t.kind() == Kind.NUMBER && SceneLexer.isIntegerLiteral(t.text())) throw meshGiven(t, "a Workframe mesh");
            first = false;
            switch (t.kind()) {
                case EOF -> { return; }
                case WORD -> statement(t);
                case CLOSE -> throw error(t, "unexpected '}': no block is open");
                default -> throw error(t, "expected a statement (" + String.join(", ", SceneGrammar.statementNames())
                        + "), found " + t.describe());
            }
        }
    }

    /** A mesh file given where a scene is expected: what it is and how to render it. */
    private SceneException meshGiven(Token at, String kind) {
        String name = file == null ? "MESH.dat" : Path.of(file).getFileName().toString();
        String quoted = MessageText.quote(name, "\"");
        return error(at, "this is " + kind + ", not a scene: to render it, name it in a scene's mesh { file " + quoted
                + " } or subdiv { file " + quoted + " } block, or refine it with render subdivide");
    }

    private void statement(Token kw) {
        Block b = SceneGrammar.statement(kw.text());
        if (b == null) throw unknownStatement(kw);
        switch (b.category()) {
            case SETTINGS -> settings(kw);
            case CAMERA -> camera(kw);
            case LIGHT -> light(kw);
            case MATERIAL -> namedMaterial(kw);
            case TEXTURE -> texture(kw);
            case OBJECT, CSG -> builder.add(object(kw, b));
            case MAP, MOTION -> throw new IllegalStateException(b.keyword() + " is not a statement");
        }
    }

    private SceneException unknownStatement(Token kw) {
        String w = kw.text();
        String hint = SceneGrammar.didYouMean(w, SceneGrammar.statementNames());
        if (hint.isEmpty()) {
            // A property outside any block usually means a '}' came too early.
            List<String> owners = new ArrayList<>();
            for (Block b : SceneGrammar.STATEMENTS) if (b.key(w) != null) owners.add(b.keyword());
            if (!owners.isEmpty()) hint = " (" + MessageText.quote(w) + " is a property of " + orList(owners) + ": was a block closed too early?)";
        }
        return error(kw, "unknown statement " + MessageText.quote(w) + hint);
    }

    private void settings(Token kw) {
        if (settingsAt != null) throw error(kw, "settings is already defined at " + settingsAt.position());
        settingsAt = kw;
        Props p = block(SceneGrammar.SETTINGS, kw, null);
        RenderSettings s = builder.settings();
        for (Prop pr : p.all) {
            Object v = pr.value;
            try {
                s = switch (pr.key.name()) {
                    case "width" -> s.withSize((Integer) v, s.height());
                    case "height" -> s.withSize(s.width(), (Integer) v);
                    case "samples" -> s.withSamplesPerPixel((Integer) v);
                    case "maxdepth" -> s.withMaxDepth((Integer) v);
                    case "mincontribution" -> s.withMinContribution((Double) v);
                    case "background" -> s.withBackground((Color) v);
                    case "ambient" -> s.withAmbient((Color) v);
                    case "encoding" -> s.withSrgb("srgb".equals(v));
                    case "seed" -> s.withSeed((Long) v);
                    case "accelerator" -> s.withAccelerator(AcceleratorKind.fromKeyword((String) v));
                    case "aov" -> s.withAovs(aovs((List<?>) v));
                    case "shutter" -> s.withShutter(((double[]) v)[0], ((double[]) v)[1]);
                    case "timesteps" -> s.withTimeSteps((Integer) v);
                    default -> throw unhandled(pr);
                };
            } catch (IllegalArgumentException e) {
                throw wrap(pr.at, e);
            }
        }
        // The frame is allocated from these keys; its size is checked against the heap once the
        // command line's overrides are known, and reported here (the last of width, height and aov).
        Prop sizeAt = null;
        for (Prop pr : p.all) {
            String k = pr.key.name();
            if (k.equals("width") || k.equals("height") || k.equals("aov")) sizeAt = pr;
        }
        if (sizeAt != null) builder.frameSource(SceneException.location(file, sizeAt.at.line(), sizeAt.at.column()));
        Prop steps = p.prop("timesteps");
        if (steps != null) {
            try {
                s.checkTimeSteps();
            } catch (IllegalArgumentException e) {
                throw wrap(steps.at, e);
            }
        }
        builder.settings(s);
    }

    private static Set<Aov> aovs(List<?> keywords) {
        Set<Aov> out = EnumSet.noneOf(Aov.class);
        for (Object k : keywords) out.add(Aov.fromKeyword((String) k));
        return out;
    }

    private void camera(Token kw) {
        if (cameraAt != null) throw error(kw, "camera is already defined at " + cameraAt.position());
        cameraAt = kw;
        Props p = block(SceneGrammar.CAMERA, kw, null);
        PinholeCamera view;
        try {
            view = new PinholeCamera(p.vec("eye"), p.vec("lookat"), p.vec("up"), p.num("fov"));
        } catch (IllegalArgumentException e) {
            throw blame(p, e);
        }
        Prop aperture = p.prop("aperture"), focus = p.prop("focus"), point = p.prop("focuspoint"), lens = p.prop("lens");
        if (aperture == null && focus == null && point == null && lens == null) {
            builder.camera(view);
            return;
        }
        if (focus != null && point != null) {
            Prop later = p.all.indexOf(focus) > p.all.indexOf(point) ? focus : point;
            throw error(later.at, "camera has both 'focus' and 'focuspoint': give one");
        }
        double distance;
        if (point != null) {
            try {
                distance = ThinLensCamera.focusDistanceTo(view, (Vec3) point.value);
            } catch (IllegalArgumentException e) {
                throw wrap(point.at, e);
            }
        } else {
            distance = focus != null ? (Double) focus.value : ThinLensCamera.lookAtDistance(view);
        }
        try {
            builder.camera(new ThinLensCamera(view, p.num("aperture"), distance, LensPattern.fromKeyword((String) p.get("lens"))));
        } catch (IllegalArgumentException e) {
            throw blame(p, e);
        }
    }

    private void light(Token kw) {
        Props p = block(SceneGrammar.LIGHT, kw, null);
        PointLight.Falloff falloff = switch ((String) p.get("falloff")) {
            case "none" -> PointLight.Falloff.NONE;
            case "inverse-square" -> PointLight.Falloff.INVERSE_SQUARE;
            default -> throw new IllegalStateException("falloff choice without a mapping: " + p.get("falloff"));
        };
        try {
            builder.light(new PointLight(p.vec("position"), (Color) p.get("color"), p.num("intensity"), falloff));
        } catch (IllegalArgumentException e) {
            throw blame(p, e);
        }
    }

    private void namedMaterial(Token kw) {
        Token n = lex.next();
        if (n.kind() != Kind.WORD) {
            throw error(n, "expected a material name after 'material', found " + n.describe()
                    + (n.kind() == Kind.STRING ? " (material names are bare words, without quotes)" : ""));
        }
        Token first = materialsAt.get(n.text());
        if (first != null) throw error(n, "material " + MessageText.quote(n.text()) + " is already defined at " + first.position());
        Material m = material(block(SceneGrammar.MATERIAL, kw, n.text()), n.text());
        builder.defineMaterial(n.text(), m);
        materialsAt.put(n.text(), kw);
    }

    /** texture NAME { ... }: an image or a procedural pattern, kept by name for materials' map blocks. */
    private void texture(Token kw) {
        Token n = lex.next();
        if (n.kind() != Kind.WORD) {
            throw error(n, "expected a texture name after 'texture', found " + n.describe()
                    + (n.kind() == Kind.STRING ? " (texture names are bare words, without quotes)" : ""));
        }
        Token first = texturesAt.get(n.text());
        if (first != null) throw error(n, "texture " + MessageText.quote(n.text()) + " is already defined at " + first.position());
        String label = "texture " + MessageText.quote(n.text());
        Props p = block(SceneGrammar.TEXTURE, kw, n.text());
        Prop image = p.prop("image"), pattern = p.prop("pattern");
        if (image != null && pattern != null) throw error(pattern.at, label + " has both 'image' and 'pattern': give one");
        if (image == null && pattern == null) throw error(kw, label + " needs 'image' or 'pattern'");
        // Keys that only the other kind uses are errors rather than silently ignored.
        for (Prop pr : p.all) {
            String k = pr.key.name();
            boolean imageKey = k.equals("filter") || k.equals("wrap");
            if (image != null && !imageKey && !k.equals("image")) throw error(pr.at, "'" + k + "' applies to pattern textures, not to an image");
            if (pattern != null && imageKey) throw error(pr.at, "'" + k + "' applies to image textures, not to a pattern");
        }
        Texture t = image != null ? imageTexture(p, image) : pattern(p, pattern);
        textures.put(n.text(), t);
        texturesAt.put(n.text(), kw);
    }

    private Texture imageTexture(Props p, Prop image) {
        Path path = existingFile(image, "texture image");
        TextureImage img;
        try {
            img = textureCache.load(path);
        } catch (IOException e) {
            // The cache says "FILE: reason"; the scene location and the name as written replace FILE.
            String reason = String.valueOf(e.getMessage());
            if (reason.startsWith(path + ": ")) reason = reason.substring(path.toString().length() + 2);
            throw error(image.valueAt, "cannot read texture image " + MessageText.quote((String) image.value) + ": " + reason);
        }
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
            throw wrap(p.prop("filter") != null ? p.prop("filter").at : image.valueAt, e);
        }
    }

    /** Turbulence of marble and wood when the block gives none: veins and rings visibly disturbed. */
    private static final double MARBLE_TURBULENCE = 4, WOOD_TURBULENCE = 1;
    /** Noise octaves when the block gives none. */
    private static final int OCTAVES = 4;

    /** A procedural texture from a texture block's pattern keys. */
    private Texture pattern(Props p, Prop pattern) {
        String kind = (String) pattern.value;
        boolean turbulent = kind.equals("marble") || kind.equals("wood");
        Prop turbulence = p.prop("turbulence"), octaves = p.prop("octaves");
        if (turbulence != null && !turbulent) throw error(turbulence.at, "'turbulence' applies to marble and wood, not to " + kind);
        if (octaves != null && kind.equals("checker")) throw error(octaves.at, "'octaves' applies to noise, marble and wood, not to checker");
        Color a = (Color) p.get("color1"), b = (Color) p.get("color2");
        double scale = p.num("scale");
        boolean solid = (Boolean) p.get("solid");
        int oct = octaves != null ? (Integer) octaves.value : OCTAVES;
        try {
            return switch (kind) {
                case "checker" -> new Checker(a, b, scale, solid);
                case "noise" -> new Noise(a, b, scale, oct, solid);
                case "marble" -> new Marble(a, b, scale, turbulence != null ? (Double) turbulence.value : MARBLE_TURBULENCE, oct, solid);
                case "wood" -> new Wood(a, b, scale, turbulence != null ? (Double) turbulence.value : WOOD_TURBULENCE, oct, solid);
                default -> throw new IllegalStateException("pattern choice without a texture: " + kind);
            };
        } catch (IllegalArgumentException e) {
            throw blame(p, e);
        }
    }

    /** A texture bound to a channel by a material's map block. */
    private record Binding(Channel channel, Texture texture, Mapping mapping, Double strength) {}

    /** The keys of a map block that place a projection; the uv mapping takes none of them. */
    private static final List<String> PROJECTION_KEYS = List.of("center", "axis", "reference");

    /** map { texture NAME channel ... mapping ... }, after a material's 'map' key. */
    private Binding binding(Token keyToken) {
        Props p = block(SceneGrammar.MAP, keyToken, null);
        Channel channel = Channel.fromKeyword((String) p.get("channel"));
        String mapping = (String) p.get("mapping");
        Prop strength = p.prop("strength");
        if (strength != null && channel != Channel.BUMP) throw error(strength.at, "'strength' applies only to channel bump, not " + channel.keyword());
        if (mapping.equals("uv")) {
            for (String k : PROJECTION_KEYS) {
                Prop pr = p.prop(k);
                if (pr != null) throw error(pr.at, "'" + k + "' does not apply to mapping uv (only to planar, spherical and cylindrical)");
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
            throw blame(p, e);
        }
        return new Binding(channel, (Texture) p.get("texture"), m, strength == null ? null : (Double) strength.value);
    }

    /** A material from its block's keys, applied through the validating builder in the order written. */
    private Material material(Props p, String name) {
        Material.Builder mb = Material.builder();
        for (Prop pr : p.all) {
            Object v = pr.value;
            try {
                switch (pr.key.name()) {
                    case "color" -> mb.color((Color) v);
                    case "ka" -> mb.ka((Double) v);
                    case "kd" -> mb.kd((Double) v);
                    case "ks" -> mb.ks((Double) v);
                    case "shininess" -> mb.shininess((Double) v);
                    case "kr" -> mb.kr((Double) v);
                    case "kt" -> mb.kt((Double) v);
                    case "ior" -> mb.ior((Double) v);
                    case "beta" -> mb.beta((Color) v);
                    case "filter" -> mb.filter((Color) v);
                    case "fresnel" -> mb.fresnel((Boolean) v);
                    case "map" -> {
                        Binding bd = (Binding) v;
                        mb.texture(bd.channel, bd.texture, bd.mapping);
                        if (bd.strength != null) mb.bumpStrength(bd.strength);
                    }
                    default -> throw unhandled(pr);
                }
            } catch (IllegalArgumentException e) {
                throw wrap(pr.at, e);
            }
        }
        if (name != null) mb.name(name);
        try {
            return mb.build();
        } catch (IllegalArgumentException e) {
            // kr + kt too large: reported at whichever of the two came last.
            Prop kr = p.prop("kr"), kt = p.prop("kt");
            Prop at = kr == null ? kt : kt == null ? kr : p.all.indexOf(kr) > p.all.indexOf(kt) ? kr : kt;
            throw at != null ? wrap(at.at, e) : wrap(p.opener, e);
        }
    }

    /** The object of an object or CSG statement, with its common keys applied; not yet added to the builder. */
    private GObject object(Token kw, Block b) {
        return object(block(b, kw, null));
    }

    /** The object of a block read by {@link #block}, with its common keys applied. */
    private GObject object(Props p) {
        Block b = p.block;
        GObject o;
        if (b.category() == SceneGrammar.Category.CSG) {
            o = bool(p);
        } else if (b == SceneGrammar.MESH) {
            o = mesh(p);
        } else if (b == SceneGrammar.SUBDIV) {
            o = subdiv(p);
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
                throw blame(p, e);
            }
        }
        // Errors found only when the scene is built name this statement.
        o.source(sourceName, p.opener.line(), p.opener.column());
        // Common keys; transforms compose in the order written (GObject.transform appends).
        for (Prop pr : p.all) {
            switch (pr.key.name()) {
                case "material" -> o.material((Material) pr.value);
                case "name" -> o.name((String) pr.value);
                case "motion" -> o.motion((Motion) pr.value);
                case "translate", "rotate", "scale" -> {
                    try {
                        o.transform((Transform) pr.value);
                    } catch (IllegalArgumentException e) {
                        throw wrap(pr.at, "invalid '" + pr.key.name() + "': ", e);
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
        for (Operand o : p.operands) objects.add(o.object);
        try {
            return new Bool(op, objects);
        } catch (IllegalArgumentException e) {
            Matcher m = OPERAND_NUMBER.matcher(e.getMessage() == null ? "" : e.getMessage());
            int k = m.find() ? Integer.parseInt(m.group(1)) : 0;
            throw wrap(k >= 1 && k <= p.operands.size() ? p.operands.get(k - 1).at : p.opener, e);
        }
    }

    /** How Bool's messages number an operand (from 1). */
    private static final Pattern OPERAND_NUMBER = Pattern.compile("\\boperand (\\d+)\\b");

    /**
     * An object statement nested in a CSG block: one of the block's operands. Shapes without an
     * inside are refused at their keyword, before their block is read.
     */
    private GObject operand(Token kw, Block b, Block parent) {
        if (!b.operand()) {
            throw error(kw, article(b.keyword()) + " cannot be " + article(parent.keyword()) + " operand: it is not a closed solid"
                    + " (operands are " + orList(SceneGrammar.operandNames()) + ")");
        }
        return object(kw, b);
    }

    /** "a plane", "an intersection". */
    private static String article(String word) {
        return ("aeio".indexOf(word.charAt(0)) >= 0 ? "an " : "a ") + word;
    }

    private GObject mesh(Props p) {
        Prop f = p.prop("file");
        String rel = (String) f.value;
        Path path;
        try {
            path = baseDir.resolve(rel).normalize();
        } catch (InvalidPathException e) {
            throw error(f.valueAt, "mesh file name " + MessageText.quote(rel) + " is not a valid path: " + e.getReason());
        }
        // Checked here rather than left to the reader so the message points into the scene file.
        String problem = InputFiles.problem(path);
        if (problem != null) throw error(f.valueAt, "mesh file " + MessageText.quote(rel) + " " + problem + " (looked in " + MessageText.cut(path.toString(), 200) + ")");
        TriangleMesh first = meshes.get(path);
        if (first != null) {
            // The same file again: another placement of the same geometry, read and indexed once.
            TriangleMesh m = first.instance();
            Object shading = p.get("shading");
            m.smooth(shading != null ? "smooth".equals(shading) : first.hasNormals());
            return m;
        }
        MeshData data;
        try {
            data = ObjReader.read(path);
        } catch (IOException e) {
            throw error(f.valueAt, "cannot read mesh file " + MessageText.quote(rel) + ": " + e.getMessage());
        }
        TriangleMesh m;
        try {
            m = new TriangleMesh(data);
        } catch (IllegalArgumentException e) {
            throw wrap(f.valueAt, e);
        }
        Object shading = p.get("shading");
        m.smooth(shading != null ? "smooth".equals(shading) : data.normals() != null);
        meshes.put(path, m);
        return m;
    }

    /**
     * A subdivision surface: the control mesh from an OBJ (with its tags) or a Workframe .dat
     * file, an optional .tex unwrap as its UVs, the block's scheme keys over the file's options.
     */
    private GObject subdiv(Props p) {
        Prop levelProp = p.prop("level");
        int level = (Integer) p.get("level");
        Token levelAt = levelProp != null ? levelProp.at : p.opener;
        try {
            SubdivisionSurface.checkLevel(level);
        } catch (IllegalArgumentException e) {
            throw wrap(levelAt, e);
        }
        Prop f = p.prop("file");
        String rel = (String) f.value;
        Path path = existingFile(f, "subdivision mesh file");
        Prop uvProp = p.prop("uv");
        SubdivKey key = new SubdivKey(path, uvProp != null ? existingFile(uvProp, "unwrap file") : null, level,
                "smooth".equals(p.get("shading")), (String) p.get("boundary"), (String) p.get("uvinterpolation"),
                (String) p.get("creasing"), (String) p.get("triangles"));
        SubdivisionSurface same = surfaces.get(key);
        if (same != null) return same.instance(); // the same surface again: refined once, placed twice
        SubdivisionSurface made = refineSurface(p, f, rel, path, levelAt, level);
        surfaces.put(key, made);
        return made;
    }

    /** What makes two subdiv statements the same surface: file, unwrap, level, shading and scheme words. */
    private record SubdivKey(Path file, Path uv, int level, boolean smooth, String boundary, String uvinterpolation,
                             String creasing, String triangles) {}

    private SubdivisionSurface refineSurface(Props p, Prop f, String rel, Path path, Token levelAt, int level) {
        String ext = extension(rel);
        if (!ext.equals("obj") && !ext.equals("dat")) {
            throw error(f.valueAt, "subdivision mesh file " + MessageText.quote(rel) + " must be a Wavefront .obj or a Workframe .dat file");
        }
        SubdivInput input;
        try {
            input = ext.equals("obj") ? ObjReader.readSubdiv(path) : SubdivInput.of(WorkframeReader.readMesh(path));
        } catch (IOException e) {
            throw error(f.valueAt, "cannot read subdivision mesh file " + MessageText.quote(rel) + ": " + e.getMessage());
        }
        Prop uv = p.prop("uv");
        if (uv != null) {
            Path uvPath = existingFile(uv, "unwrap file");
            try {
                input = input.withCornerUvs(WorkframeReader.readUnwrap(uvPath, input.mesh()));
            } catch (IOException e) {
                throw error(uv.valueAt, "cannot read unwrap file " + MessageText.quote((String) uv.value) + ": " + e.getMessage());
            }
        }
        input = input.withOptions(options(p, input.options()));
        try {
            SubdivisionSurface.checkLevel(level, input.refinedFaceCount(level));
        } catch (IllegalArgumentException e) {
            throw wrap(levelAt, e);
        }
        try {
            ControlMesh control = input.toControlMesh();
            return new SubdivisionSurface(control, level, "smooth".equals(p.get("shading")));
        } catch (IllegalArgumentException e) {
            throw wrap(f.valueAt, e);
        }
    }

    /** The file's options with the block's scheme keys, where given, in their place. */
    private static SubdivOptions options(Props p, SubdivOptions o) {
        return subdivOptions(o, (String) p.get("boundary"), (String) p.get("uvinterpolation"), (String) p.get("creasing"), (String) p.get("triangles"));
    }

    /** {@code base} with each scheme choice of a subdiv block (its grammar word, or null to keep base's) in its place. */
    static SubdivOptions subdivOptions(SubdivOptions base, String boundary, String uvinterpolation, String creasing, String triangles) {
        SubdivOptions o = base;
        if (boundary != null) {
            o = o.withBoundary(switch (boundary) {
                case "edge-only" -> SubdivOptions.Boundary.EDGE_ONLY;
                case "edge-and-corner" -> SubdivOptions.Boundary.EDGE_AND_CORNER;
                case "none" -> SubdivOptions.Boundary.NONE;
                default -> throw new IllegalStateException("boundary choice without a mapping: " + boundary);
            });
        }
        if (uvinterpolation != null) {
            o = o.withFaceVarying(switch (uvinterpolation) {
                case "none" -> SubdivOptions.FaceVarying.NONE;
                case "corners-only" -> SubdivOptions.FaceVarying.CORNERS_ONLY;
                case "corners-plus1" -> SubdivOptions.FaceVarying.CORNERS_PLUS1;
                case "corners-plus2" -> SubdivOptions.FaceVarying.CORNERS_PLUS2;
                case "boundaries" -> SubdivOptions.FaceVarying.BOUNDARIES;
                case "all" -> SubdivOptions.FaceVarying.ALL;
                default -> throw new IllegalStateException("uvinterpolation choice without a mapping: " + uvinterpolation);
            });
        }
        if (creasing != null) {
            o = o.withCreasing(switch (creasing) {
                case "uniform" -> SubdivOptions.Creasing.UNIFORM;
                case "chaikin" -> SubdivOptions.Creasing.CHAIKIN;
                default -> throw new IllegalStateException("creasing choice without a mapping: " + creasing);
            });
        }
        if (triangles != null) {
            o = o.withTriangles(switch (triangles) {
                case "catmark" -> SubdivOptions.Triangles.CATMARK;
                case "smooth" -> SubdivOptions.Triangles.SMOOTH;
                default -> throw new IllegalStateException("triangles choice without a mapping: " + triangles);
            });
        }
        return o;
    }

    /** The file a string key names, resolved against the scene's folder; an error at the value if it does not exist. */
    private Path existingFile(Prop f, String what) {
        String rel = (String) f.value;
        Path path;
        try {
            path = baseDir.resolve(rel).normalize();
        } catch (InvalidPathException e) {
            throw error(f.valueAt, what + " name " + MessageText.quote(rel) + " is not a valid path: " + e.getReason());
        }
        String problem = InputFiles.problem(path);
        if (problem != null) throw error(f.valueAt, what + " " + MessageText.quote(rel) + " " + problem + " (looked in " + MessageText.cut(path.toString(), 200) + ")");
        return path;
    }

    /** The lower-case extension of a file name ("" when it has none). */
    private static String extension(String name) {
        String base = name.substring(Math.max(name.lastIndexOf('/'), name.lastIndexOf('\\')) + 1);
        int dot = base.lastIndexOf('.');
        return dot < 0 ? "" : base.substring(dot + 1).toLowerCase(java.util.Locale.ROOT);
    }

    // ---- blocks and values ----

    /** One key as written: the key token, the first token of its value, and the value. */
    private record Prop(Key key, Token at, Token valueAt, Object value) {}

    /** One operand of a CSG block: its statement keyword and the object it made. */
    private record Operand(Token at, GObject object) {}

    /** The keys given in one block, in order, with the block's defaults behind them. */
    private static final class Props {
        final Block block;
        final Token opener;
        final List<Prop> all = new ArrayList<>();
        final Map<String, Prop> first = new HashMap<>();
        /** The nested object statements of a CSG block, in order; empty for other blocks. */
        final List<Operand> operands = new ArrayList<>();

        Props(Block block, Token opener) {
            this.block = block;
            this.opener = opener;
        }

        Prop prop(String name) { return first.get(name); }

        /** The value given, else the grammar's default (null when the default is the builder's own). */
        Object get(String name) {
            Prop p = first.get(name);
            if (p != null) return p.value;
            Key k = block.key(name);
            if (k == null) throw new IllegalStateException(block.keyword() + " has no key '" + name + "'");
            return k.defaultValue();
        }

        Vec3 vec(String name) { return (Vec3) get(name); }
        double num(String name) { return (Double) get(name); }
    }

    /**
     * Reads "{ key value ... }" after {@code kw} (the statement keyword, or the 'material' key of
     * an inline material) and checks that every required key is present. A CSG block also holds
     * object statements, its operands, among its keys; it needs at least two.
     *
     * @param name the material's name for a named material, else null
     */
    private Props block(Block b, Token kw, String name) {
        String label = name == null ? b.keyword() : b.keyword() + " " + MessageText.quote(name);
        Token open = lex.next();
        if (open.kind() != Kind.OPEN) {
            throw error(open, "expected '{' after " + MessageText.quote(b.keyword() + (name == null ? "" : " " + name)) + ", found " + open.describe());
        }
        Props p = new Props(b, kw);
        // The CSG blocks enclosing the one being read, innermost last. A CSG operand of a CSG block
        // is read by this loop, not by recursion, so that the stack does not grow with the nesting
        // (other blocks nest a fixed number of levels). This block, if CSG, is level 1.
        List<Props> outer = new ArrayList<>();
        while (true) {
            boolean csg = p.block.category() == SceneGrammar.Category.CSG;
            Token t = lex.next();
            if (t.kind() == Kind.CLOSE) {
                checkComplete(p, label);
                if (outer.isEmpty()) return p;
                GObject o = object(p);
                Token at = p.opener;
                p = outer.remove(outer.size() - 1);
                p.operands.add(new Operand(at, o));
                label = p.block.keyword();
                continue;
            }
            if (t.kind() == Kind.EOF) {
                throw error(t, "unexpected end of file: missing '}' to close '" + p.block.keyword() + "' opened at " + p.opener.position());
            }
            if (t.kind() != Kind.WORD) {
                throw error(t, "expected a property " + (csg ? "or an operand " : "") + "of " + label + " or '}', found " + t.describe());
            }
            Key k = p.block.key(t.text());
            if (k == null && csg) {
                Block nested = SceneGrammar.statement(t.text());
                if (nested != null && nested.category().isObject()) {
                    if (nested.category() != SceneGrammar.Category.CSG) {
                        p.operands.add(new Operand(t, operand(t, nested, p.block)));
                        continue;
                    }
                    int level = outer.size() + 2;
                    if (level > Bool.MAX_NESTING) {
                        throw error(t, "CSG nesting deeper than " + Bool.MAX_NESTING + " levels: this '" + t.text() + "' is level " + level
                                + " (union and intersection take any number of operands, so a long chain can be one block)");
                    }
                    Token nestedOpen = lex.next();
                    if (nestedOpen.kind() != Kind.OPEN) {
                        throw error(nestedOpen, "expected '{' after '" + nested.keyword() + "', found " + nestedOpen.describe());
                    }
                    outer.add(p);
                    p = new Props(nested, t);
                    label = nested.keyword();
                    continue;
                }
            }
            if (k == null) throw unknownKey(t, p.block, label, p.opener);
            Prop earlier = p.first.get(k.name());
            if (earlier != null && !k.repeatable()) {
                throw error(t, "'" + k.name() + "' given twice in " + label + " (first at " + earlier.at.position() + ")");
            }
            Token valueAt = lex.peek();
            Prop pr = new Prop(k, t, valueAt, value(p.block, k, t));
            p.all.add(pr);
            p.first.putIfAbsent(k.name(), pr);
        }
    }

    /** Every required key of a block just closed is present, and a CSG block has at least two operands. */
    private void checkComplete(Props p, String label) {
        Block b = p.block;
        List<String> missing = new ArrayList<>();
        for (Key k : b.keys()) if (k.required() && !p.first.containsKey(k.name())) missing.add("'" + k.name() + "'");
        if (!missing.isEmpty()) throw error(p.opener, label + " needs " + andList(missing));
        if (b.category() == SceneGrammar.Category.CSG && p.operands.size() < 2) {
            throw error(p.opener, b.keyword() + " needs at least 2 operands, found " + p.operands.size());
        }
    }

    private SceneException unknownKey(Token t, Block b, String label, Token opener) {
        boolean csg = b.category() == SceneGrammar.Category.CSG;
        List<String> candidates = b.keyNames();
        if (csg) candidates.addAll(SceneGrammar.operandNames());
        String hint = SceneGrammar.didYouMean(t.text(), candidates);
        if (hint.isEmpty() && SceneGrammar.statement(t.text()) != null) {
            hint = " (is a '}' missing to close '" + b.keyword() + "' opened at " + opener.position() + "?)";
        }
        return error(t, "unknown " + (csg ? "property or operand" : "property") + " " + MessageText.quote(t.text()) + " in " + label + hint);
    }

    private Object value(Block b, Key k, Token keyToken) {
        String n = k.name();
        return switch (k.kind()) {
            case NUMBER -> number("expected a number for '" + n + "'");
            case INTEGER -> integer(n, false);
            case LONG -> integer(n, true);
            case VECTOR -> vector("expected 3 numbers for '" + n + "'");
            case COLOR -> color(n);
            case VERTICES -> {
                String m = "expected 9 numbers (3 points) for '" + n + "'";
                yield new Vec3[] {vector(m), vector(m), vector(m)};
            }
            case BOOLEAN -> "true".equals(choice(n, List.of("true", "false")));
            case CHOICE -> choice(n, k.choices());
            case CHOICES -> choices(b, n, k.choices());
            case STRING -> string(n);
            case MATERIAL -> materialValue(keyToken);
            case MAP -> binding(keyToken);
            case MOTION -> motionValue(keyToken);
            case INTERVAL -> {
                String m = "expected 2 numbers for '" + n + "'";
                yield new double[] {number(m), number(m)};
            }
            case TEXTURE -> textureValue(n);
            case PAIR -> {
                double u = number("expected 1 or 2 numbers for '" + n + "'");
                yield new double[] {u, numberAhead() ? number("expected 1 or 2 numbers for '" + n + "'") : u};
            }
            case TRANSLATE -> {
                Vec3 v = vector("expected 3 numbers for 'translate'");
                yield transform(keyToken, () -> Transform.translate(v));
            }
            case ROTATE -> b == SceneGrammar.MOTION ? new AxisAngle(rotationAxis(), rotationAngle()) : rotate(keyToken);
            case SCALE -> {
                double x = number("expected 1 or 3 numbers for 'scale'");
                boolean three = numberAhead();
                double y = three ? number("expected 1 or 3 numbers for 'scale'") : x;
                double z = three ? number("expected 1 or 3 numbers for 'scale'") : x;
                if (b == SceneGrammar.MOTION) yield new Vec3(x, y, z);
                yield transform(keyToken, () -> Transform.scale(x, y, z));
            }
        };
    }

    /** A number, or an error "{expected}, found ...". */
    private double number(String expected) {
        Token t = rawNumber(expected);
        // Bounded so that squares and products of coordinates cannot overflow (see Ranges).
        if (!Ranges.isModest(t.number())) {
            throw error(t, "number '" + t.text() + "' is out of range: scene numbers are at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude");
        }
        return t.number();
    }

    /** A number token of any finite size (integers are range-checked by their key), or an error "{expected}, found ...". */
    private Token rawNumber(String expected) {
        Token t = lex.next();
        if (t.kind() == Kind.NUMBER) return t;
        if (t.kind() == Kind.WORD && SceneLexer.isNonFiniteSpelling(t.text())) {
            throw error(t, expected + ", found " + t.describe() + " (NaN and Infinity are not allowed)");
        }
        throw error(t, expected + ", found " + t.describe());
    }

    /** True if the next token is meant as a number (including the refused NaN/Infinity words, so they are reported as such). */
    private boolean numberAhead() {
        Token t = lex.peek();
        return t.kind() == Kind.NUMBER || (t.kind() == Kind.WORD && SceneLexer.isNonFiniteSpelling(t.text()));
    }

    private Object integer(String key, boolean isLong) {
        String expected = "expected an integer for '" + key + "'";
        Token t = lex.peek();
        if (t.kind() == Kind.NUMBER && !SceneLexer.isIntegerLiteral(t.text())) {
            lex.next();
            throw error(t, expected + ", found " + t.describe());
        }
        rawNumber(expected);
        long v;
        try {
            v = Long.parseLong(t.text().startsWith("+") ? t.text().substring(1) : t.text());
        } catch (NumberFormatException e) {
            throw error(t, "integer " + MessageText.quote(t.text(), "") + " is out of range for '" + key + "'");
        }
        if (isLong) return v;
        if (v < Integer.MIN_VALUE || v > Integer.MAX_VALUE) throw error(t, "integer " + MessageText.quote(t.text(), "") + " is out of range for '" + key + "'");
        return (int) v;
    }

    private Vec3 vector(String expected) {
        return new Vec3(number(expected), number(expected), number(expected));
    }

    private Color color(String key) {
        double r = number("expected a number for '" + key + "'");
        if (!numberAhead()) return Color.grey(r);
        String expected = "expected 1 or 3 numbers for '" + key + "'";
        return new Color(r, number(expected), number(expected));
    }

    private String choice(String key, List<String> choices) {
        Token t = lex.next();
        if (t.kind() == Kind.WORD && choices.contains(t.text())) return t.text();
        String hint = t.kind() == Kind.WORD ? SceneGrammar.didYouMean(t.text(), choices) : "";
        throw error(t, "expected " + orList(choices) + " for '" + key + "', found " + t.describe() + hint);
    }

    /**
     * One or more distinct choices. The list ends at '}' or at a word that is a key of the block,
     * so any other word is reported as a wrong choice rather than as an unknown key.
     */
    private List<String> choices(Block b, String key, List<String> choices) {
        List<String> out = new ArrayList<>();
        out.add(choice(key, choices));
        while (true) {
            Token t = lex.peek();
            if (t.kind() != Kind.WORD || b.key(t.text()) != null) return List.copyOf(out);
            lex.next();
            if (!choices.contains(t.text())) {
                String hint = SceneGrammar.didYouMean(t.text(), choices);
                if (hint.isEmpty() && SceneGrammar.statement(t.text()) != null) {
                    hint = " (is a '}' missing to close '" + b.keyword() + "'?)";
                }
                throw error(t, "expected " + orList(choices) + " for '" + key + "', found " + t.describe() + hint);
            }
            if (out.contains(t.text())) throw error(t, MessageText.quote(t.text()) + " listed twice for '" + key + "'");
            out.add(t.text());
        }
    }

    private String string(String key) {
        Token t = lex.next();
        if (t.kind() == Kind.STRING) return t.text();
        throw error(t, "expected a string in double quotes for '" + key + "', found " + t.describe());
    }

    /** After an object's 'material' key: a name defined earlier, or an inline block. */
    private Material materialValue(Token keyToken) {
        Token t = lex.peek();
        if (t.kind() == Kind.OPEN) return material(block(SceneGrammar.MATERIAL, keyToken, null), null);
        lex.next();
        if (t.kind() != Kind.WORD) throw error(t, "expected a material name or '{' after 'material', found " + t.describe());
        if (builder.hasMaterial(t.text())) return builder.material(t.text());
        String hint = SceneGrammar.didYouMean(t.text(), materialsAt.keySet());
        if (hint.isEmpty()) hint = " (a material must be defined before the objects that use it)";
        throw error(t, "unknown material " + MessageText.quote(t.text()) + hint);
    }

    /** A texture name defined earlier. */
    private Texture textureValue(String key) {
        Token t = lex.next();
        if (t.kind() != Kind.WORD) throw error(t, "expected a texture name for '" + key + "', found " + t.describe());
        Texture tex = textures.get(t.text());
        if (tex != null) return tex;
        String hint = SceneGrammar.didYouMean(t.text(), texturesAt.keySet());
        if (hint.isEmpty()) hint = " (a texture must be defined before the materials that use it)";
        throw error(t, "unknown texture " + MessageText.quote(t.text()) + hint);
    }

    private Transform rotate(Token keyToken) {
        Vec3 axis = rotationAxis();
        double degrees = rotationAngle();
        return transform(keyToken, () -> Transform.rotate(axis, degrees));
    }

    /** The axis of a 'rotate' value: x, y, z or three numbers. */
    private Vec3 rotationAxis() {
        Token t = lex.peek();
        if (t.isWord("x") || t.isWord("y") || t.isWord("z")) {
            lex.next();
            return t.isWord("x") ? Vec3.X : t.isWord("y") ? Vec3.Y : Vec3.Z;
        }
        if (numberAhead()) return vector("expected an axis (x, y, z or 3 numbers) and an angle for 'rotate'");
        lex.next();
        throw error(t, "expected x, y, z or an axis (3 numbers) for 'rotate', found " + t.describe());
    }

    private double rotationAngle() { return number("expected an angle in degrees for 'rotate'"); }

    /** A motion block's 'rotate' value. */
    private record AxisAngle(Vec3 axis, double degrees) {}

    /**
     * motion { ... } after an object's 'motion' key: the end transform (translate, or direction
     * and speed; rotate; scale; about pivot) between start and finish. Open times are the
     * shutter's; they are checked against it once the whole file (and so the settings) is read.
     */
    private Motion motionValue(Token keyToken) {
        Props p = block(SceneGrammar.MOTION, keyToken, null);
        Prop translate = p.prop("translate"), direction = p.prop("direction"), speed = p.prop("speed");
        if (translate != null && direction != null) {
            Prop later = p.all.indexOf(translate) > p.all.indexOf(direction) ? translate : direction;
            throw error(later.at, "motion has both 'translate' and 'direction': give the end translation, or direction and speed");
        }
        if (direction != null && speed == null) throw error(direction.at, "'direction' needs 'speed' (units per unit of shutter time)");
        if (speed != null && direction == null) throw error(speed.at, "'speed' needs 'direction'");
        if (translate == null && direction == null && p.prop("rotate") == null && p.prop("scale") == null) {
            throw error(keyToken, "motion needs translate, direction and speed, rotate or scale: without them the object does not move");
        }
        Prop start = p.prop("start"), finish = p.prop("finish");
        double s = start != null ? (Double) start.value : Double.NaN, f = finish != null ? (Double) finish.value : Double.NaN;
        Motion m;
        try {
            if (direction != null) {
                if (p.prop("rotate") != null || p.prop("scale") != null) {
                    Prop extra = p.prop("rotate") != null ? p.prop("rotate") : p.prop("scale");
                    throw error(extra.at, "'" + extra.key.name() + "' does not combine with direction and speed (the thesis's linear motion); use translate");
                }
                m = Motion.linear(p.vec("direction"), p.num("speed"), s, f);
            } else {
                AxisAngle r = p.prop("rotate") != null ? (AxisAngle) p.get("rotate") : new AxisAngle(Vec3.Y, 0);
                Vec3 sc = p.prop("scale") != null ? (Vec3) p.get("scale") : new Vec3(1, 1, 1);
                Vec3 t = translate != null ? (Vec3) translate.value : Vec3.ZERO;
                m = Motion.of(sc, r.axis, r.degrees, t, p.vec("pivot"), s, f);
            }
        } catch (IllegalArgumentException e) {
            throw blame(p, e);
        }
        motions.add(new PendingMotion(m, p));
        return m;
    }

    /** A motion read, with its block, until its open times can be checked against the shutter. */
    private record PendingMotion(Motion motion, Props block) {}

    private final List<PendingMotion> motions = new ArrayList<>();

    /** Every motion's times, open ones filled in from the shutter, must give a finish after the start. */
    private void checkMotions() {
        RenderSettings st = builder.settings();
        for (PendingMotion pm : motions) {
            try {
                pm.motion.resolve(st.shutterOpen(), st.shutterClose());
            } catch (IllegalArgumentException e) {
                throw blame(pm.block, e);
            }
        }
    }

    private Transform transform(Token keyToken, java.util.function.Supplier<Transform> make) {
        try {
            return make.get();
        } catch (IllegalArgumentException e) {
            throw wrap(keyToken, "invalid '" + keyToken.text() + "': ", e);
        }
    }

    // ---- errors ----

    private SceneException error(Token at, String message) {
        return new SceneException(file, at.line(), at.column(), message);
    }

    private SceneException wrap(Token at, IllegalArgumentException e) {
        return wrap(at, "", e);
    }

    private SceneException wrap(Token at, String prefix, IllegalArgumentException e) {
        return new SceneException(file, at.line(), at.column(), prefix + e.getMessage(), e);
    }

    /**
     * Places a constructor's complaint at the key it names (the first key of the block, in
     * grammar order, that was given and that the message mentions as a word), else at the
     * statement: "sphere radius must be ..." is reported at 'radius'.
     */
    private SceneException blame(Props p, IllegalArgumentException e) {
        String message = e.getMessage() == null ? "" : e.getMessage();
        for (Key k : p.block.keys()) {
            Prop pr = p.first.get(k.name());
            if (pr != null && Pattern.compile("(?<![A-Za-z0-9_])" + Pattern.quote(k.name()) + "(?![A-Za-z0-9_])").matcher(message).find()) {
                return wrap(pr.at, e);
            }
        }
        return wrap(p.opener, e);
    }

    private static IllegalStateException unhandled(Prop pr) {
        return new IllegalStateException("grammar key '" + pr.key.name() + "' has no builder call");
    }

    private static String orList(List<String> words) { return list(words, "or"); }

    private static String andList(List<String> words) { return list(words, "and"); }

    private static String list(List<String> words, String conjunction) {
        if (words.size() == 1) return words.get(0);
        return String.join(", ", words.subList(0, words.size() - 1)) + " " + conjunction + " " + words.get(words.size() - 1);
    }

    /** Decodes strictly, so that a file in another encoding is reported rather than read as garbage. */
    private static String decodeUtf8(byte[] bytes, String name) {
        return SceneLexer.decodeUtf8(bytes, name, "the file");
    }
}
