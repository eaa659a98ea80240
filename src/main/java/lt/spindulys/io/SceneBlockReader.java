package lt.spindulys.io;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import lt.spindulys.io.SceneGrammar.Block;
import lt.spindulys.io.SceneGrammar.Key;
import lt.spindulys.io.SceneLexer.Kind;
import lt.spindulys.io.SceneLexer.Token;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.math.Keyframes;
import lt.spindulys.texture.Texture;

/**
 * The value parsing of a scene file: reads a statement's "{ key value ... }" block from the lexer
 * into {@link Props}, each value typed by its key's kind in {@link SceneGrammar} (numbers within
 * range, vectors, colours, choices, strings, transforms), with the syntax errors of the format.
 * What a token cannot say alone (an object of a CSG operand's block, an inline or named material,
 * a texture by name, a map or motion block) is asked of {@link Values}, so that this class makes
 * no scene objects itself.
 */
final class SceneBlockReader {
    /**
     * The values a block reader cannot make from tokens: objects and things built from a nested
     * block just read, and names defined earlier in the file. Each is called where the value is
     * read, so errors keep the file's order.
     */
    interface Values {
        /** The object of a CSG operand's block, its common keys applied. */
        GObject object(Props p);

        /** An inline material after an object's 'material' key. */
        Material material(Props p);

        /** A material defined earlier, named by this word; an error at it if there is none. */
        Material material(Token name);

        /** A texture defined earlier, named by this word; an error at it if there is none. */
        Texture texture(Token name);

        /** A material's map block: a texture bound to a channel. */
        SceneObjectFactory.Binding binding(Props p);

        /** An object's motion block, given after {@code keyToken}. */
        Motion motion(Props p, Token keyToken);

        /** An object's or the camera's keys block, given after {@code keyToken}. */
        Keyframes keyframes(Props p, Token keyToken);

        /** An object's or the camera's turntable block, given after {@code keyToken}. */
        Keyframes turntable(Props p, Token keyToken);
    }

    private final SceneLexer lex;
    private final SceneErrors err;
    private final Values values;

    SceneBlockReader(SceneLexer lex, SceneErrors err, Values values) {
        this.lex = lex;
        this.err = err;
        this.values = values;
    }

    /** One key as written: the key token, the first token of its value, and the value. */
    record Prop(Key key, Token at, Token valueAt, Object value) {}

    /** A 'usemtl' value: the face group's name, where it is written, and the material its faces take. */
    record GroupMaterial(String group, Token at, Material material) {}

    /** One operand of a CSG block: its statement keyword and the object it made. */
    record Operand(Token at, GObject object) {}

    /** The keys given in one block, in order, with the block's defaults behind them. */
    static final class Props {
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
            if (p != null) return p.value();
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
    Props block(Block b, Token kw, String name) {
        String label = name == null ? b.keyword() : b.keyword() + " " + MessageText.quote(name);
        Token open = lex.next();
        if (open.kind() != Kind.OPEN) {
            throw err.error(open, "expected '{' after " + MessageText.quote(b.keyword() + (name == null ? "" : " " + name)) + ", found " + open.describe());
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
                GObject o = values.object(p);
                Token at = p.opener;
                p = outer.remove(outer.size() - 1);
                p.operands.add(new Operand(at, o));
                label = p.block.keyword();
                continue;
            }
            if (t.kind() == Kind.EOF) {
                throw err.error(t, "unexpected end of file: missing '}' to close '" + p.block.keyword() + "' opened at " + p.opener.position());
            }
            if (t.kind() != Kind.WORD) {
                throw err.error(t, "expected a property " + (csg ? "or an operand " : "") + "of " + label + " or '}', found " + t.describe());
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
                        throw err.error(t, "CSG nesting deeper than " + Bool.MAX_NESTING + " levels: this '" + t.text() + "' is level " + level
                                + " (union and intersection take any number of operands, so a long chain can be one block)");
                    }
                    Token nestedOpen = lex.next();
                    if (nestedOpen.kind() != Kind.OPEN) {
                        throw err.error(nestedOpen, "expected '{' after '" + nested.keyword() + "', found " + nestedOpen.describe());
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
                throw err.error(t, "'" + k.name() + "' given twice in " + label + " (first at " + earlier.at().position() + ")");
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
        if (!missing.isEmpty()) throw err.error(p.opener, label + " needs " + SceneErrors.andList(missing));
        if (b.category() == SceneGrammar.Category.CSG && p.operands.size() < 2) {
            throw err.error(p.opener, b.keyword() + " needs at least 2 operands, found " + p.operands.size());
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
        return err.error(t, "unknown " + (csg ? "property or operand" : "property") + " " + MessageText.quote(t.text()) + " in " + label + hint);
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
            case GROUP_MATERIAL -> {
                Token nameAt = lex.peek();
                String group = string(n);
                yield new GroupMaterial(group, nameAt, materialValue(keyToken));
            }
            case MAP -> values.binding(block(SceneGrammar.MAP, keyToken, null));
            case MOTION -> values.motion(block(SceneGrammar.MOTION, keyToken, null), keyToken);
            case FRAMES -> new int[] {(Integer) integer(n, false), (Integer) integer(n, false)};
            case KEYS -> values.keyframes(block(SceneGrammar.KEYS, keyToken, null), keyToken);
            case KEY -> {
                Token frameAt = lex.peek();
                double frame = number("expected a frame number after 'key'");
                yield new KeyPose(frame, frameAt, block(SceneGrammar.KEY, keyToken, null));
            }
            case TURNTABLE -> values.turntable(block(SceneGrammar.TURNTABLE, keyToken, null), keyToken);
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
                if (b == SceneGrammar.MOTION || b == SceneGrammar.KEY) yield new Vec3(x, y, z);
                yield transform(keyToken, () -> Transform.scale(x, y, z));
            }
        };
    }

    /** A number, or an error "{expected}, found ...". */
    private double number(String expected) {
        Token t = rawNumber(expected);
        // Bounded so that squares and products of coordinates cannot overflow (see Ranges).
        if (!Ranges.isModest(t.number())) {
            throw err.error(t, "number '" + t.text() + "' is out of range: scene numbers are at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude");
        }
        return t.number();
    }

    /** A number token of any finite size (integers are range-checked by their key), or an error "{expected}, found ...". */
    private Token rawNumber(String expected) {
        Token t = lex.next();
        if (t.kind() == Kind.NUMBER) return t;
        if (t.kind() == Kind.WORD && SceneLexer.isNonFiniteSpelling(t.text())) {
            throw err.error(t, expected + ", found " + t.describe() + " (NaN and Infinity are not allowed)");
        }
        throw err.error(t, expected + ", found " + t.describe());
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
            throw err.error(t, expected + ", found " + t.describe());
        }
        rawNumber(expected);
        long v;
        try {
            v = Long.parseLong(t.text().startsWith("+") ? t.text().substring(1) : t.text());
        } catch (NumberFormatException e) {
            throw err.error(t, "integer " + MessageText.quote(t.text(), "") + " is out of range for '" + key + "'");
        }
        if (isLong) return v;
        if (v < Integer.MIN_VALUE || v > Integer.MAX_VALUE) throw err.error(t, "integer " + MessageText.quote(t.text(), "") + " is out of range for '" + key + "'");
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
        throw err.error(t, "expected " + SceneErrors.orList(choices) + " for '" + key + "', found " + t.describe() + hint);
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
                throw err.error(t, "expected " + SceneErrors.orList(choices) + " for '" + key + "', found " + t.describe() + hint);
            }
            if (out.contains(t.text())) throw err.error(t, MessageText.quote(t.text()) + " listed twice for '" + key + "'");
            out.add(t.text());
        }
    }

    private String string(String key) {
        Token t = lex.next();
        if (t.kind() == Kind.STRING) return t.text();
        throw err.error(t, "expected a string in double quotes for '" + key + "', found " + t.describe());
    }

    /** After an object's 'material' key: a name defined earlier, or an inline block. */
    private Material materialValue(Token keyToken) {
        Token t = lex.peek();
        if (t.kind() == Kind.OPEN) return values.material(block(SceneGrammar.MATERIAL, keyToken, null));
        lex.next();
        if (t.kind() != Kind.WORD) throw err.error(t, "expected a material name or '{' after '" + keyToken.text() + (keyToken.text().equals("material") ? "" : " NAME")
                + "', found " + t.describe());
        return values.material(t);
    }

    /** A texture name defined earlier. */
    private Texture textureValue(String key) {
        Token t = lex.next();
        if (t.kind() != Kind.WORD) throw err.error(t, "expected a texture name for '" + key + "', found " + t.describe());
        return values.texture(t);
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
        throw err.error(t, "expected x, y, z or an axis (3 numbers) for 'rotate', found " + t.describe());
    }

    private double rotationAngle() { return number("expected an angle in degrees for 'rotate'"); }

    /** A motion block's 'rotate' value. */
    record AxisAngle(Vec3 axis, double degrees) {}

    /** A keys block's 'key' value: the frame number as written, where it was, and the pose's block. */
    record KeyPose(double frame, Token frameAt, Props pose) {}

    private Transform transform(Token keyToken, java.util.function.Supplier<Transform> make) {
        try {
            return make.get();
        } catch (IllegalArgumentException e) {
            throw err.wrap(keyToken, "invalid '" + keyToken.text() + "': ", e);
        }
    }

    /**
     * An object statement nested in a CSG block: one of the block's operands. Shapes without an
     * inside are refused at their keyword, before their block is read.
     */
    private GObject operand(Token kw, Block b, Block parent) {
        if (!b.operand()) {
            throw err.error(kw, article(b.keyword()) + " cannot be " + article(parent.keyword()) + " operand: it is not a closed solid"
                    + " (operands are " + SceneErrors.orList(SceneGrammar.operandNames()) + ")");
        }
        return values.object(block(b, kw, null));
    }

    /** "a plane", "an intersection". */
    private static String article(String word) {
        return ("aeio".indexOf(word.charAt(0)) >= 0 ? "an " : "a ") + word;
    }
}
