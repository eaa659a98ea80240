package lt.spindulys.io;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;

import lt.spindulys.io.SceneBlockReader.Prop;
import lt.spindulys.io.SceneBlockReader.Props;
import lt.spindulys.io.SceneGrammar.Block;
import lt.spindulys.io.SceneLexer.Kind;
import lt.spindulys.io.SceneLexer.Token;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Motion;
import lt.spindulys.scene.Animation;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.scene.AreaLight;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.Texture;

/**
 * Reads a .dat scene file (the language is described in docs/scene-format.md) into a
 * {@link SceneBuilder}, using only the builder's public API, so a scene read from a file and the
 * same scene written in Java are built alike. The builder is returned unbuilt so that the command
 * line can still override settings.
 *
 * <p>Every error is a {@link SceneException} naming file:line:column of the offending token; values
 * the builder API refuses are reported at the key that gave them. The first error stops parsing.
 *
 * <p>This class reads the statements and keeps the file's names (materials, textures) and the
 * builder; a statement's block is read by {@link SceneBlockReader} (value parsing), made into
 * objects by {@link SceneObjectFactory} (object construction), whose files are read once by
 * {@link SceneAssetCache}.
 */
public final class SceneParser {
    private final SceneLexer lex;
    private final String file;
    private final SceneErrors err;
    private final SceneBlockReader in;
    private final SceneObjectFactory objects;
    private final SceneBuilder builder = new SceneBuilder();
    /** What the scene may read, and what it has read. */
    private final AssetGate gate;
    private Token settingsAt, cameraAt, environmentAt, animationAt;
    /** The camera block's 'projection orthographic' key, where an orthographic camera was chosen; null otherwise. */
    private Prop orthographicAt;
    private final SceneAssetCache assets;
    /** The settings' 'shutter' key, which an animation's shutter angle replaces; null if not given. */
    private Prop shutterAt;
    /** The settings' samples key, and the samples key of the light with the most samples (lightSamplesMax): where sample buffers are reported. */
    private Prop settingsSamplesAt, lightSamplesAt;
    private int lightSamplesMax;
    private Animation animation;
    /** Where each named material was defined, for "already defined at" and suggestions. */
    private final Map<String, Token> materialsAt = new LinkedHashMap<>();
    /** Named textures and where each was defined. */
    private final Map<String, Texture> textures = new HashMap<>();
    private final Map<String, Token> texturesAt = new LinkedHashMap<>();

    private SceneParser(String text, String file, Path baseDir, AssetGate gate) {
        this.lex = new SceneLexer(text, file);
        this.file = file;
        this.err = new SceneErrors(file);
        this.gate = gate;
        this.in = new SceneBlockReader(lex, err, new Values());
        this.assets = new SceneAssetCache(err, baseDir, gate, file);
        this.objects = new SceneObjectFactory(err, assets, SceneException.location(file, 0, 0));
    }

    /**
     * Parses a scene file, which must be UTF-8. Relative mesh paths are resolved against the file's
     * folder, and messages name the file as given.
     *
     * @param file the scene file
     * @return a builder holding the scene, not yet built, so that settings can still be changed
     * @throws IOException    if the file cannot be read
     * @throws SceneException if its content is not a valid scene
     */
    public static SceneBuilder parse(Path file) throws IOException {
        return parse(file, AssetRoots.ANY);
    }

    /**
     * Tells a scene file from a Workframe mesh, both named {@code .dat}: a mesh's first token is
     * its point count, a number; a scene's is a statement's word ({@code settings},
     * {@code camera}, an object). Only the lines up to the first one that is not blank or a
     * comment are read. A file with nothing else (empty, or only comments) is an empty scene.
     *
     * @param file a {@code .dat} file
     * @return false if its first token starts as a number does (a digit, a sign or a point), else true
     * @throws IOException if the file cannot be read
     */
    public static boolean isSceneFile(Path file) throws IOException {
        try (java.io.BufferedReader r = new java.io.BufferedReader(new java.io.InputStreamReader(
                java.nio.file.Files.newInputStream(file), java.nio.charset.StandardCharsets.UTF_8))) {
            boolean first = true;
            for (String line; (line = r.readLine()) != null; first = false) {
                String s = (first && line.startsWith("\uFEFF") ? line.substring(1) : line).strip();
                if (s.isEmpty() || s.startsWith("#")) continue;
                char c = s.charAt(0);
                return !(c >= '0' && c <= '9' || c == '+' || c == '-' || c == '.');
            }
            return true;
        }
    }

    /**
     * Parses a scene file as {@link #parse(Path)} does, reading only inside {@code roots}: the
     * scene file itself and every file it names (meshes, subdivision meshes, unwraps, material
     * libraries and their texture maps, images) must be inside one of the folders once links are
     * resolved, or the parse stops with an error at the key that named it, before that file is
     * opened. Every file read is recorded on the builder ({@link SceneBuilder#inputFiles()}).
     *
     * @param file  the scene file
     * @param roots the folders the scene may read from; {@link AssetRoots#ANY} for anywhere
     * @return a builder holding the scene, not yet built
     * @throws IOException    if the file cannot be read
     * @throws SceneException if its content is not a valid scene, or it reads outside {@code roots}
     */
    public static SceneBuilder parse(Path file, AssetRoots roots) throws IOException {
        String name = file.toString();
        String refusal = roots.refusal(file);
        if (refusal != null) throw new SceneException(name, 0, 0, "scene file " + refusal);
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
        AssetGate gate = new AssetGate(roots);
        gate.record(file, "scene file", null);
        return parse(text, name, file.toAbsolutePath().getParent(), gate);
    }

    /**
     * Parses scene text.
     *
     * @param text     the scene
     * @param fileName name used in error messages (null: "&lt;input&gt;")
     * @param baseDir  folder against which relative mesh paths are resolved (null: the working directory)
     * @return a builder holding the scene, not yet built
     * @throws SceneException if the text is not a valid scene
     */
    public static SceneBuilder parse(String text, String fileName, Path baseDir) {
        return parse(text, fileName, baseDir, AssetRoots.ANY);
    }

    /**
     * Parses scene text, reading only inside {@code roots} (see {@link #parse(Path, AssetRoots)}).
     *
     * @param text     the scene
     * @param fileName name used in error messages (null: "&lt;input&gt;")
     * @param baseDir  folder against which relative mesh paths are resolved (null: the working directory)
     * @param roots    the folders the scene may read from; {@link AssetRoots#ANY} for anywhere
     * @return a builder holding the scene, not yet built, with the files it read recorded
     * @throws SceneException if the text is not a valid scene, or it reads outside {@code roots}
     */
    public static SceneBuilder parse(String text, String fileName, Path baseDir, AssetRoots roots) {
        return parse(text, fileName, baseDir, new AssetGate(Objects.requireNonNull(roots, "roots")));
    }

    private static SceneBuilder parse(String text, String fileName, Path baseDir, AssetGate gate) {
        Path dir = (baseDir != null ? baseDir : Path.of("")).toAbsolutePath();
        SceneParser p = new SceneParser(Objects.requireNonNull(text, "text"), fileName, dir, gate);
        p.statements();
        p.checkMotions();
        p.checkOrthographicSubdivision();
        for (lt.spindulys.scene.InputFile f : gate.read()) p.builder.inputFile(f);
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
            case ANIMATION -> animation(kw);
            case CAMERA -> camera(kw);
            case LIGHT -> light(kw);
            case AREA_LIGHT -> areaLight(b, kw);
            case ENVIRONMENT -> environment(kw);
            case MATERIAL -> namedMaterial(kw);
            case TEXTURE -> texture(kw);
            case OBJECT, CSG -> builder.add(objects.object(in.block(b, kw, null)));
            case MAP, MOTION, KEYS -> throw new IllegalStateException(b.keyword() + " is not a statement");
        }
    }

    private SceneException unknownStatement(Token kw) {
        String w = kw.text();
        String hint = SceneGrammar.didYouMean(w, SceneGrammar.statementNames());
        if (hint.isEmpty()) {
            // A property outside any block usually means a '}' came too early.
            List<String> owners = new ArrayList<>();
            for (Block b : SceneGrammar.STATEMENTS) if (b.key(w) != null) owners.add(b.keyword());
            if (!owners.isEmpty()) hint = " (" + MessageText.quote(w) + " is a property of " + SceneErrors.orList(owners) + ": was a block closed too early?)";
        }
        return error(kw, "unknown statement " + MessageText.quote(w) + hint);
    }

    private void settings(Token kw) {
        if (settingsAt != null) throw error(kw, "settings is already defined at " + settingsAt.position());
        settingsAt = kw;
        Props p = in.block(SceneGrammar.SETTINGS, kw, null);
        RenderSettings s = objects.settings(p, builder.settings());
        // The frame is allocated from these keys; its size is checked against the heap once the
        // command line's overrides are known, and reported here (the last of width, height and aov).
        Prop sizeAt = null;
        for (Prop pr : p.all) {
            String k = pr.key().name();
            if (k.equals("width") || k.equals("height") || k.equals("aov")) sizeAt = pr;
        }
        if (sizeAt != null) builder.frameSource(SceneException.location(file, sizeAt.at().line(), sizeAt.at().column()));
        settingsSamplesAt = p.prop("samples");
        noteSamples();
        shutterAt = p.prop("shutter");
        if (shutterAt != null && animationAt != null) throw shutterConflict();
        builder.settings(s);
    }

    /** animation { frames FIRST LAST  fps F  shutter ANGLE }: at most once, before any keys. */
    private void animation(Token kw) {
        if (animationAt != null) throw error(kw, "animation is already defined at " + animationAt.position());
        animationAt = kw;
        Props p = in.block(SceneGrammar.ANIMATION, kw, null);
        animation = objects.animation(p);
        if (shutterAt != null) throw shutterConflict();
        builder.animation(animation);
    }

    /** A settings 'shutter' in an animated scene, reported at the settings key. */
    private SceneException shutterConflict() {
        return error(shutterAt.at(), "'shutter' in settings does not combine with the animation at " + animationAt.position()
                + ": each frame's shutter is set by the animation's shutter angle");
    }

    private void camera(Token kw) {
        if (cameraAt != null) throw error(kw, "camera is already defined at " + cameraAt.position());
        cameraAt = kw;
        Props p = in.block(SceneGrammar.CAMERA, kw, null);
        builder.camera(objects.camera(p));
        if ("orthographic".equals(p.get("projection"))) orthographicAt = p.prop("projection");
    }

    /**
     * Adaptive subdivision measures edges by their angle at the eye, which an orthographic camera
     * does not have: refused at whichever of the two comes later in the file.
     */
    private void checkOrthographicSubdivision() {
        Prop method = assets.firstAdaptiveMethod();
        if (orthographicAt == null || method == null) return;
        boolean cameraLater = orthographicAt.at().line() > method.at().line()
                || orthographicAt.at().line() == method.at().line() && orthographicAt.at().column() > method.at().column();
        if (cameraLater) {
            throw error(orthographicAt.at(), "an orthographic camera does not combine with adaptive subdivision (method " + method.value() + " at "
                    + method.at().position() + "): adaptive levels are sized by angles at the eye, which parallel rays do not have; use method uniform with a level");
        }
        throw error(method.at(), "method " + method.value() + " does not combine with the orthographic camera at " + orthographicAt.at().position()
                + ": adaptive levels are sized by angles at the eye, which parallel rays do not have; use method uniform with a level");
    }

    private void light(Token kw) {
        Props p = in.block(SceneGrammar.LIGHT, kw, null);
        PointLight light = objects.light(p);
        try {
            builder.light(light); // refuses a total intensity over the limit, summed over the lights so far
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    private void areaLight(Block b, Token kw) {
        Props p = in.block(b, kw, null);
        AreaLight light = objects.areaLight(p);
        lightSamples(p.prop("samples"), light.samples());
        try {
            builder.areaLight(light); // refuses a total intensity over the limit, summed over the lights so far
        } catch (IllegalArgumentException e) {
            throw err.blame(p, e);
        }
    }

    /** environment { file "..." rotate DEGREES intensity I }: at most once. */
    private void environment(Token kw) {
        if (environmentAt != null) throw error(kw, "environment is already defined at " + environmentAt.position());
        environmentAt = kw;
        Props p = in.block(SceneGrammar.ENVIRONMENT, kw, null);
        lt.spindulys.scene.Environment e = objects.environment(p);
        if (e.isLight()) lightSamples(p.prop("samples"), e.samples());
        builder.environment(e);
    }

    /** A light's samples key: the place to report the render threads' sample buffers at, when no settings' samples key is given, is the largest light's. */
    private void lightSamples(Prop at, int samples) {
        if (at == null || samples <= lightSamplesMax) return;
        lightSamplesMax = samples;
        lightSamplesAt = at;
        noteSamples();
    }

    /** Tells the builder where the samples that size the threads' buffers were given: the settings' key first, else the largest light's. */
    private void noteSamples() {
        Prop at = settingsSamplesAt != null ? settingsSamplesAt : lightSamplesAt;
        if (at != null) builder.samplesSource(SceneException.location(file, at.at().line(), at.at().column()));
    }

    private void namedMaterial(Token kw) {
        Token n = lex.next();
        if (n.kind() != Kind.WORD) {
            throw error(n, "expected a material name after 'material', found " + n.describe()
                    + (n.kind() == Kind.STRING ? " (material names are bare words, without quotes)" : ""));
        }
        Token first = materialsAt.get(n.text());
        if (first != null) throw error(n, "material " + MessageText.quote(n.text()) + " is already defined at " + first.position());
        Material m = objects.material(in.block(SceneGrammar.MATERIAL, kw, n.text()), n.text());
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
        Texture t = objects.texture(in.block(SceneGrammar.TEXTURE, kw, n.text()), n.text());
        textures.put(n.text(), t);
        texturesAt.put(n.text(), kw);
    }

    /** What the block reader asks of the parser: objects made from blocks, and names defined earlier. */
    private final class Values implements SceneBlockReader.Values {
        @Override
        public GObject object(Props p) { return objects.object(p); }

        @Override
        public Material material(Props p) { return objects.material(p, null); }

        @Override
        public Material material(Token t) {
            if (builder.hasMaterial(t.text())) return builder.material(t.text());
            String hint = SceneGrammar.didYouMean(t.text(), materialsAt.keySet());
            if (hint.isEmpty()) hint = " (a material must be defined before the objects that use it)";
            throw error(t, "unknown material " + MessageText.quote(t.text()) + hint);
        }

        @Override
        public Texture texture(Token t) {
            Texture tex = textures.get(t.text());
            if (tex != null) return tex;
            String hint = SceneGrammar.didYouMean(t.text(), texturesAt.keySet());
            if (hint.isEmpty()) hint = " (a texture must be defined before the materials that use it)";
            throw error(t, "unknown texture " + MessageText.quote(t.text()) + hint);
        }

        @Override
        public SceneObjectFactory.Binding binding(Props p) { return objects.binding(p); }

        @Override
        public Motion motion(Props p, Token keyToken) {
            Motion m = objects.motion(p, keyToken);
            motions.add(new PendingMotion(m, p));
            return m;
        }

        @Override
        public Keyframes keyframes(Props p, Token keyToken) { return objects.keyframes(p, requireAnimation(keyToken)); }

        @Override
        public Keyframes turntable(Props p, Token keyToken) { return objects.turntable(p, requireAnimation(keyToken)); }
    }

    /** The animation keys are timed by: defined before them, else an error at the key. */
    private Animation requireAnimation(Token keyToken) {
        if (animation == null) {
            throw error(keyToken, MessageText.quote(keyToken.text()) + " needs an animation statement before it (such as animation { frames 1 48  fps 24 }): key frames are read on its clock");
        }
        return animation;
    }

    /** A motion read, with its block, until its open times can be checked against the shutter. */
    private record PendingMotion(Motion motion, Props block) {}

    private final List<PendingMotion> motions = new ArrayList<>();

    /** Every motion's times, open ones filled in from the shutter, must give a finish after the start. */
    private void checkMotions() {
        RenderSettings st = builder.settings();
        // Frames move the shutter along: an open finish closes earliest at the first frame, an open start opens latest at the last.
        RenderSettings[] shutters = animation == null ? new RenderSettings[] {st}
                : new RenderSettings[] {animation.settingsFor(st, animation.first()), animation.settingsFor(st, animation.last())};
        for (PendingMotion pm : motions) {
            for (RenderSettings sh : shutters) {
                try {
                    pm.motion.resolve(sh.shutterOpen(), sh.shutterClose());
                } catch (IllegalArgumentException e) {
                    throw err.blame(pm.block, e);
                }
            }
        }
    }

    private SceneException error(Token at, String message) {
        return err.error(at, message);
    }

    /** Decodes strictly, so that a file in another encoding is reported rather than read as garbage. */
    private static String decodeUtf8(byte[] bytes, String name) {
        return SceneLexer.decodeUtf8(bytes, name, "the file");
    }
}
