package lt.spindulys.io;

import java.util.ArrayList;
import java.util.Collection;
import java.util.List;

import lt.spindulys.image.Aov;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.camera.PixelFilter;
import lt.spindulys.scene.IntegratorKind;

/**
 * The statements of the scene language and the keys each block accepts, with their value kinds,
 * whether they are required or repeatable, and defaults. This table is the one place that knows
 * the grammar: the parser accepts exactly these keys, its did-you-mean suggestions draw from them,
 * and a test checks that docs/scene-format.md documents each one.
 */
final class SceneGrammar {
    private SceneGrammar() {}

    /** How a key's value is written. */
    enum Kind {
        /** One finite number. */
        NUMBER,
        /** One integer literal that fits an int. */
        INTEGER,
        /** One integer literal that fits a long. */
        LONG,
        /** Three numbers. */
        VECTOR,
        /** One number (grey) or three (r g b). */
        COLOR,
        /** Nine numbers: three points. */
        VERTICES,
        /** true or false. */
        BOOLEAN,
        /** One of the key's choices, as a bare word. */
        CHOICE,
        /** One or more of the key's choices, each at most once, as bare words up to the next key or '}'. */
        CHOICES,
        /** A double-quoted string. */
        STRING,
        /** A material name defined earlier, or an inline { ... } material block. */
        MATERIAL,
        /** translate x y z. */
        TRANSLATE,
        /** rotate x|y|z degrees, or rotate ax ay az degrees. */
        ROTATE,
        /** scale s, or scale sx sy sz. */
        SCALE,
        /** One number, or two (for u and v). */
        PAIR,
        /** The name of a texture defined earlier. */
        TEXTURE,
        /** A nested { ... } block of {@link SceneGrammar#MAP} keys: a texture bound to a material channel. */
        MAP,
        /** Two numbers. */
        INTERVAL,
        /** A nested { ... } block of {@link SceneGrammar#MOTION} keys: how an object moves during the shutter. */
        MOTION,
        /** Two integers: an animation's first and last frame. */
        FRAMES,
        /** A nested { ... } block of {@link SceneGrammar#KEYS} keys: keyframed transforms over the frames. */
        KEYS,
        /** A frame number, then a nested { ... } block of {@link SceneGrammar#KEY} keys: one key's pose. */
        KEY,
        /** A nested { ... } block of {@link SceneGrammar#TURNTABLE} keys: whole turns over the frame range. */
        TURNTABLE,
        /** A double-quoted face group (OBJ usemtl) name, then a material as {@link #MATERIAL} takes it. */
        GROUP_MATERIAL
    }

    /** What a block makes, which decides how the parser turns its keys into builder calls. */
    enum Category {
        SETTINGS, CAMERA, LIGHT,
        /** A light with an extent (scene.AreaLight): rectangle, disc or sphere. */
        AREA_LIGHT,
        /** The lat-long image that rays hitting nothing see (scene.Environment). */
        ENVIRONMENT,
        MATERIAL,
        /** A named texture: an image or a procedural pattern. */
        TEXTURE,
        /** A texture binding nested in a material (not a statement). */
        MAP,
        /** An object's motion nested in an object statement (not a statement). */
        MOTION,
        /** The scene's frame range, frame rate and shutter angle (scene.Animation). */
        ANIMATION,
        /** Keyframed transforms, their keys or a turntable, nested in an object or the camera (not statements). */
        KEYS,
        /** A shape made from its own keys. */
        OBJECT,
        /**
         * A CSG node (scene.Bool): its block holds, besides the common object keys, nested object
         * statements, its operands in order. The keyword is the operation's (Bool.Op.keyword()).
         */
        CSG;

        /** True for the statements that make a scene object (they all take {@link SceneGrammar#OBJECT_COMMON}). */
        boolean isObject() { return this == OBJECT || this == CSG; }
    }

    /**
     * A key of a block.
     *
     * @param defaultValue the value used when the key is absent, or null when absence means "the
     *                     builder's own default" (settings, materials) or the key is required
     */
    record Key(String name, Kind kind, boolean required, boolean repeatable, Object defaultValue, List<String> choices) {}

    /**
     * A statement keyword and the keys its block accepts, in documentation order.
     *
     * @param operand whether the statement may be nested in a CSG block as an operand: its objects
     *                can be closed solids. Meshes and subdivision surfaces can (Bool refuses the
     *                open ones, naming their boundary edges), and so can a plane (a half-space);
     *                a triangle never is
     */
    record Block(String keyword, Category category, boolean operand, List<Key> keys) {
        Key key(String name) {
            for (Key k : keys) if (k.name.equals(name)) return k;
            return null;
        }

        List<String> keyNames() {
            List<String> names = new ArrayList<>();
            for (Key k : keys) names.add(k.name);
            return names;
        }
    }

    private static Key req(String name, Kind kind) { return new Key(name, kind, true, false, null, List.of()); }
    private static Key opt(String name, Kind kind) { return new Key(name, kind, false, false, null, List.of()); }
    private static Key opt(String name, Kind kind, Object dflt) { return new Key(name, kind, false, false, dflt, List.of()); }
    private static Key choice(String name, String dflt, String... choices) { return new Key(name, Kind.CHOICE, false, false, dflt, List.of(choices)); }
    private static Key repeat(String name, Kind kind) { return new Key(name, kind, false, true, null, List.of()); }

    /** Keys every object block accepts after its own. */
    static final List<Key> OBJECT_COMMON = List.of(
            opt("material", Kind.MATERIAL),
            repeat("translate", Kind.TRANSLATE),
            repeat("rotate", Kind.ROTATE),
            repeat("scale", Kind.SCALE),
            opt("motion", Kind.MOTION),
            opt("keys", Kind.KEYS),
            opt("turntable", Kind.TURNTABLE),
            opt("name", Kind.STRING));

    // Frame N is at time N / fps; the shutter is open for shutter / 360 of a frame interval, centred on it.
    static final Block ANIMATION = new Block("animation", Category.ANIMATION, false, List.of(
            req("frames", Kind.FRAMES),
            opt("fps", Kind.NUMBER, 24.0),
            opt("shutter", Kind.NUMBER, 180.0)));

    /** The keys of an object's or the camera's nested 'keys' block: poses at frames, in increasing frame order. */
    static final Block KEYS = new Block("keys", Category.KEYS, false, List.of(
            choice("interpolation", "linear", "linear", "ease", "smooth"),
            opt("pivot", Kind.VECTOR, Vec3.ZERO),
            repeat("key", Kind.KEY)));

    /** One key's pose (after 'key FRAME'): each absent part is the identity's. */
    static final Block KEY = new Block("key", Category.KEYS, false, List.of(
            opt("translate", Kind.VECTOR, Vec3.ZERO),
            opt("rotate", Kind.VECTOR, Vec3.ZERO),
            opt("scale", Kind.SCALE, new Vec3(1, 1, 1))));

    /** Whole turns about an axis over the animation's frames (frame last + 1 would repeat the first). */
    static final Block TURNTABLE = new Block("turntable", Category.KEYS, false, List.of(
            opt("axis", Kind.VECTOR, Vec3.Y),
            opt("center", Kind.VECTOR, Vec3.ZERO),
            opt("turns", Kind.NUMBER, 1.0)));

    static final Block SETTINGS = new Block("settings", Category.SETTINGS, false, List.of(
            opt("width", Kind.INTEGER),
            opt("height", Kind.INTEGER),
            opt("samples", Kind.INTEGER),
            opt("maxdepth", Kind.INTEGER),
            opt("mincontribution", Kind.NUMBER),
            opt("background", Kind.COLOR),
            opt("ambient", Kind.COLOR),
            choice("encoding", null, "linear", "srgb"),
            opt("seed", Kind.LONG),
            choice("accelerator", null, "bvh", "bvh-compact", "bvh2", "octree", "bruteforce"),
            new Key("aov", Kind.CHOICES, false, false, null, Aov.keywords()),
            opt("shutter", Kind.INTERVAL),
            opt("timesteps", Kind.INTEGER),
            opt("subdivmemory", Kind.NUMBER),
            opt("subdivcache", Kind.NUMBER),
            choice("subdivpolicy", null, "lru", "last-two"),
            opt("subdivtarget", Kind.NUMBER),
            new Key("integrator", Kind.CHOICE, false, false, null, IntegratorKind.keywords()),
            opt("clamp", Kind.NUMBER),
            new Key("filter", Kind.CHOICE, false, false, null, PixelFilter.keywords()),
            opt("filterwidth", Kind.NUMBER),
            opt("noisethreshold", Kind.NUMBER),
            opt("minsamples", Kind.INTEGER),
            opt("denoise", Kind.BOOLEAN, false)));

    // A thin lens when any of the lens keys is given, else a pinhole. 'focus' and 'focuspoint'
    // exclude each other (checked by the parser); without either the look-at point is in focus.
    // 'projection orthographic' sees 'width' scene units across and takes neither fov nor lens keys.
    static final Block CAMERA = new Block("camera", Category.CAMERA, false, List.of(
            req("eye", Kind.VECTOR),
            req("lookat", Kind.VECTOR),
            opt("up", Kind.VECTOR, Vec3.Y),
            choice("projection", "perspective", "perspective", "orthographic"),
            opt("fov", Kind.NUMBER, 45.0),
            opt("width", Kind.NUMBER),
            opt("aperture", Kind.NUMBER, 0.0),
            opt("focus", Kind.NUMBER),
            opt("focuspoint", Kind.VECTOR),
            new Key("lens", Kind.CHOICE, false, false, LensPattern.CONCENTRIC.keyword(), LensPattern.keywords()),
            opt("keys", Kind.KEYS),
            opt("turntable", Kind.TURNTABLE)));

    static final Block LIGHT = new Block("light", Category.LIGHT, false, List.of(
            req("position", Kind.VECTOR),
            opt("color", Kind.COLOR, Color.WHITE),
            opt("intensity", Kind.NUMBER, 1.0),
            choice("falloff", "none", "none", "inverse-square")));

    // Area lights: placed by centre and normal (a rectangle also by the tangent its width runs
    // along), sized by width and height or radius; 'samples' shadow rays per pixel sample.
    static final Block RECTLIGHT = new Block("rectlight", Category.AREA_LIGHT, false, List.of(
            req("center", Kind.VECTOR),
            opt("normal", Kind.VECTOR, new Vec3(0, -1, 0)),
            opt("tangent", Kind.VECTOR, Vec3.X),
            req("width", Kind.NUMBER),
            req("height", Kind.NUMBER),
            opt("color", Kind.COLOR, Color.WHITE),
            opt("intensity", Kind.NUMBER, 1.0),
            opt("power", Kind.NUMBER),
            opt("onesided", Kind.BOOLEAN, false),
            opt("samples", Kind.INTEGER, 1)));

    static final Block DISCLIGHT = new Block("disclight", Category.AREA_LIGHT, false, List.of(
            req("center", Kind.VECTOR),
            opt("normal", Kind.VECTOR, new Vec3(0, -1, 0)),
            req("radius", Kind.NUMBER),
            opt("color", Kind.COLOR, Color.WHITE),
            opt("intensity", Kind.NUMBER, 1.0),
            opt("power", Kind.NUMBER),
            opt("onesided", Kind.BOOLEAN, false),
            opt("samples", Kind.INTEGER, 1)));

    static final Block SPHERELIGHT = new Block("spherelight", Category.AREA_LIGHT, false, List.of(
            req("center", Kind.VECTOR),
            req("radius", Kind.NUMBER),
            opt("color", Kind.COLOR, Color.WHITE),
            opt("intensity", Kind.NUMBER, 1.0),
            opt("power", Kind.NUMBER),
            opt("samples", Kind.INTEGER, 1)));

    // Rotation about the up axis (+Y) in degrees; intensity scales every value; light makes it
    // light surfaces with 'samples' shadow rays per pixel sample (scene.Environment; samples only with light true).
    static final Block ENVIRONMENT = new Block("environment", Category.ENVIRONMENT, false, List.of(
            req("file", Kind.STRING),
            opt("rotate", Kind.NUMBER, 0.0),
            opt("intensity", Kind.NUMBER, 1.0),
            opt("light", Kind.BOOLEAN, false),
            opt("samples", Kind.INTEGER),
            // What camera rays see: the map or the settings' background colour, and at what intensity.
            opt("background", Kind.BOOLEAN, true),
            opt("visibleintensity", Kind.NUMBER)));

    // Which keys apply depends on the model (Material.Model#ownKeys), wherever 'model' stands in
    // the block: the parser checks them once the block is read.
    static final Block MATERIAL = new Block("material", Category.MATERIAL, false, List.of(
            new Key("model", Kind.CHOICE, false, false, null, Material.Model.keywords()),
            opt("color", Kind.COLOR),
            opt("ka", Kind.NUMBER),
            opt("kd", Kind.NUMBER),
            opt("ks", Kind.NUMBER),
            opt("shininess", Kind.NUMBER),
            opt("kr", Kind.NUMBER),
            opt("kt", Kind.NUMBER),
            opt("fresnel", Kind.BOOLEAN),
            opt("metallic", Kind.NUMBER),
            opt("roughness", Kind.NUMBER),
            opt("transmission", Kind.NUMBER),
            opt("ior", Kind.NUMBER),
            opt("beta", Kind.COLOR),
            opt("filter", Kind.COLOR),
            opt("emission", Kind.COLOR),
            repeat("map", Kind.MAP)));

    /** Texture kinds of a texture block's 'pattern' key. */
    static final List<String> PATTERNS = List.of("checker", "noise", "marble", "wood");

    // Either 'image' or 'pattern' (checked by the parser); filter and wrap apply to images, the
    // rest to patterns. Turbulence and octaves default per pattern (in the parser).
    static final Block TEXTURE = new Block("texture", Category.TEXTURE, false, List.of(
            opt("image", Kind.STRING),
            choice("pattern", null, PATTERNS.toArray(String[]::new)),
            choice("filter", "bilinear", "bilinear", "nearest", "trilinear"),
            choice("wrap", "repeat", "repeat", "clamp", "mirror"),
            opt("scale", Kind.NUMBER, 1.0),
            opt("color1", Kind.COLOR, Color.WHITE),
            opt("color2", Kind.COLOR, Color.BLACK),
            opt("solid", Kind.BOOLEAN, false),
            opt("turbulence", Kind.NUMBER),
            opt("octaves", Kind.INTEGER)));

    /** The keys of a material's nested 'map' block. */
    static final Block MAP = new Block("map", Category.MAP, false, List.of(
            req("texture", Kind.TEXTURE),
            new Key("channel", Kind.CHOICE, false, false, "diffuse", lt.spindulys.texture.Channel.keywords()),
            choice("mapping", "uv", "uv", "planar", "spherical", "cylindrical"),
            opt("center", Kind.VECTOR, Vec3.ZERO),
            opt("axis", Kind.VECTOR, Vec3.Y),
            opt("reference", Kind.VECTOR, Vec3.X),
            opt("scale", Kind.PAIR, new double[] {1, 1}),
            opt("strength", Kind.NUMBER)));

    /**
     * The keys of an object's nested 'motion' block. translate, rotate and scale are the end
     * transform (written as the object keys are, but given once each); direction and speed are the
     * thesis's linear motion instead of translate. Start and finish default to the shutter's
     * (filled in by the parser once the settings are known).
     */
    static final Block MOTION = new Block("motion", Category.MOTION, false, List.of(
            opt("translate", Kind.VECTOR),
            opt("direction", Kind.VECTOR),
            opt("speed", Kind.NUMBER),
            opt("rotate", Kind.ROTATE),
            opt("scale", Kind.SCALE),
            opt("pivot", Kind.VECTOR, Vec3.ZERO),
            opt("start", Kind.NUMBER),
            opt("finish", Kind.NUMBER)));

    static final Block SPHERE = solid("sphere",
            opt("center", Kind.VECTOR, Vec3.ZERO),
            opt("radius", Kind.NUMBER, 1.0));

    // As a solid a plane is the half-space behind it, so it can cut (intersection) or be cut away (difference).
    static final Block PLANE = solid("plane",
            opt("normal", Kind.VECTOR, Vec3.Y),
            opt("offset", Kind.NUMBER, 0.0));

    static final Block BOX = solid("box",
            req("min", Kind.VECTOR),
            req("max", Kind.VECTOR));

    static final Block CYLINDER = solid("cylinder",
            req("base", Kind.VECTOR),
            req("top", Kind.VECTOR),
            opt("radius", Kind.NUMBER, 1.0));

    static final Block TRIANGLE = surface("triangle",
            req("vertices", Kind.VERTICES));

    // No default for shading: absent means "smooth if the OBJ has normals", decided after reading it.
    // 'usemtl' gives the faces of one OBJ usemtl name a scene material (over the .mtl file's).
    static final Block MESH = solid("mesh",
            req("file", Kind.STRING),
            choice("shading", null, "smooth", "flat"),
            opt("terminator", Kind.BOOLEAN, true),
            repeat("usemtl", Kind.GROUP_MATERIAL));

    // No defaults for the scheme options: absent means "as the file's tags say, else OpenSubdiv's default".
    static final Block SUBDIV = solid("subdiv",
            req("file", Kind.STRING),
            opt("level", Kind.INTEGER, 3),
            choice("method", "uniform", "uniform", "projected", "lazy", "combined"),
            opt("target", Kind.NUMBER),
            choice("levels", "rate", "rate", "edge", "object"),
            opt("maxlevel", Kind.INTEGER),
            choice("scheme", null, "catmark", "loop", "bilinear"),
            choice("boundary", null, "edge-only", "edge-and-corner", "none"),
            choice("uvinterpolation", null, "none", "corners-only", "corners-plus1", "corners-plus2", "boundaries", "all"),
            choice("creasing", null, "uniform", "chaikin"),
            choice("triangles", null, "catmark", "smooth"),
            choice("shading", "smooth", "smooth", "flat"),
            opt("uv", Kind.STRING),
            choice("positions", "refined", "refined", "limit"),
            opt("terminator", Kind.BOOLEAN, true),
            repeat("usemtl", Kind.GROUP_MATERIAL));

    // CSG: only the common keys; the operands are the object statements nested in the block.
    static final Block UNION = new Block("union", Category.CSG, true, OBJECT_COMMON);
    static final Block INTERSECTION = new Block("intersection", Category.CSG, true, OBJECT_COMMON);
    static final Block DIFFERENCE = new Block("difference", Category.CSG, true, OBJECT_COMMON);

    /** Every top-level statement, in documentation order. */
    static final List<Block> STATEMENTS = List.of(SETTINGS, ANIMATION, CAMERA, LIGHT, RECTLIGHT, DISCLIGHT, SPHERELIGHT, ENVIRONMENT, TEXTURE, MATERIAL, SPHERE, PLANE, BOX, CYLINDER, TRIANGLE, MESH, SUBDIV,
            UNION, INTERSECTION, DIFFERENCE);

    /** An object statement whose objects may be CSG operands. */
    private static Block solid(String keyword, Key... own) { return object(keyword, true, own); }

    /** An object statement whose objects have no inside, so they cannot be CSG operands. */
    private static Block surface(String keyword, Key... own) { return object(keyword, false, own); }

    private static Block object(String keyword, boolean operand, Key... own) {
        List<Key> keys = new ArrayList<>(List.of(own));
        keys.addAll(OBJECT_COMMON);
        return new Block(keyword, Category.OBJECT, operand, List.copyOf(keys));
    }

    /** The statements that may be nested in a CSG block as operands, in documentation order. */
    static List<String> operandNames() {
        List<String> names = new ArrayList<>();
        for (Block b : STATEMENTS) if (b.operand) names.add(b.keyword);
        return names;
    }

    /** The statement with this keyword, or null. */
    static Block statement(String keyword) {
        for (Block b : STATEMENTS) if (b.keyword.equals(keyword)) return b;
        return null;
    }

    static List<String> statementNames() {
        List<String> names = new ArrayList<>();
        for (Block b : STATEMENTS) names.add(b.keyword);
        return names;
    }

    /**
     * The candidate nearest to {@code word} by edit distance (a swap of neighbours counts as one
     * edit), if it is at most 2 and less than the word's length (so that "ab" does not suggest an
     * unrelated two-letter key); the first in the given order wins ties. Null if there is none.
     */
    static String nearest(String word, Collection<String> candidates) {
        // Only words of plausible length are compared, so the cost stays bounded whatever the input.
        int longest = 0;
        for (String c : candidates) longest = Math.max(longest, c.length());
        if (word.length() > Math.min(MAX_SUGGESTED_LENGTH, 2 * longest + 2)) return null;
        String best = null;
        int bestDistance = Integer.MAX_VALUE;
        for (String c : candidates) {
            // The distance is at least the difference in length: such a candidate could not be suggested.
            if (Math.abs(c.length() - word.length()) > 2) continue;
            int d = editDistance(word, c);
            if (d < bestDistance) {
                best = c;
                bestDistance = d;
            }
        }
        return best != null && bestDistance <= 2 && bestDistance < word.length() ? best : null;
    }

    /** Words longer than this get no suggestion (nor those longer than twice the longest candidate + 2). */
    static final int MAX_SUGGESTED_LENGTH = 64;

    /** " (did you mean 'x'?)" for the nearest candidate, or "" when none is close. */
    static String didYouMean(String word, Collection<String> candidates) {
        String n = nearest(word, candidates);
        return n == null ? "" : " (did you mean '" + n + "'?)";
    }

    /** Optimal string alignment distance: insertions, deletions, substitutions and adjacent swaps. */
    static int editDistance(String a, String b) {
        int[][] d = new int[a.length() + 1][b.length() + 1];
        for (int i = 0; i <= a.length(); i++) d[i][0] = i;
        for (int j = 0; j <= b.length(); j++) d[0][j] = j;
        for (int i = 1; i <= a.length(); i++) {
            for (int j = 1; j <= b.length(); j++) {
                int cost = a.charAt(i - 1) == b.charAt(j - 1) ? 0 : 1;
                int v = Math.min(Math.min(d[i - 1][j] + 1, d[i][j - 1] + 1), d[i - 1][j - 1] + cost);
                if (i > 1 && j > 1 && a.charAt(i - 1) == b.charAt(j - 2) && a.charAt(i - 2) == b.charAt(j - 1)) {
                    v = Math.min(v, d[i - 2][j - 2] + 1);
                }
                d[i][j] = v;
            }
        }
        return d[a.length()][b.length()];
    }
}
