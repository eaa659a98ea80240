package lt.spindulys.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Objects;

import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.camera.Camera;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.files.AtomicFile;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.math.Vec3;

/**
 * A scene file's {@code camera} statement as text: a camera written as the block that reads back
 * as the same camera ({@link #format}), where that block is in a scene file's text
 * ({@link #locate}), and the file with its block replaced and everything else kept byte for byte
 * ({@link #save}). For a viewer that lets the user move the camera and keep the view.
 *
 * <p>Numbers are written in the shortest form that reads back as exactly the same double, so the
 * camera parsed from the text renders exactly the pictures the camera given renders. The keys or
 * turntable of an animated camera are not made from the camera: they are kept as the file's own
 * text ({@link Located#keysText()}).
 */
public final class CameraBlock {
    private CameraBlock() {}

    /**
     * Where a scene file's camera statement is, in the file's text (a leading byte-order mark counts as one character).
     *
     * @param start     the index of the statement's first character (of the word {@code camera})
     * @param end       one past the index of its closing brace
     * @param line      the line of the word {@code camera}, from 1
     * @param column    its column, from 1
     * @param keysText  the text of its {@code keys { ... }} or {@code turntable { ... }} value with the key, or null
     * @param tokens    the statement's tokens, space separated (strings as they are written): equal for blocks
     *                  that differ only in spacing and comments
     */
    public record Located(int start, int end, int line, int column, String keysText, String tokens) {}

    /**
     * The camera written as a {@code camera} block on one line, such as
     * {@code camera { eye 0 2 -6  lookat 0 1 0  up 0 1 0  fov 45 }}; a thin lens adds its
     * {@code aperture} and {@code focus} (left out when it is the look-at distance, the default)
     * and a ring {@code lens}; an orthographic one {@code projection orthographic  width W}.
     *
     * @param camera   a pinhole, thin-lens or orthographic camera, or an animated one carrying one of them
     * @param keysText for an animated camera, its {@code keys} or {@code turntable} value as the file
     *                 writes it ({@link Located#keysText()}), written at the end of the block; else ignored
     * @return the block, without a line end
     * @throws IllegalArgumentException for an animated camera without {@code keysText}, or a kind of camera a scene file cannot write
     */
    public static String format(Camera camera, String keysText) {
        Objects.requireNonNull(camera, "camera");
        StringBuilder s = new StringBuilder("camera {");
        Camera still = camera;
        if (camera instanceof AnimatedCamera a) {
            if (keysText == null) throw new IllegalArgumentException("an animated camera is written with its keys' text, and none was given");
            still = a.base();
        }
        if (still instanceof PinholeCamera p) {
            view(s, p.eye(), p.lookAt(), p.up());
            s.append("  fov ").append(number(p.fovDegrees()));
        } else if (still instanceof ThinLensCamera t) {
            PinholeCamera p = t.view();
            view(s, p.eye(), p.lookAt(), p.up());
            s.append("  fov ").append(number(p.fovDegrees()));
            s.append("  aperture ").append(number(t.aperture()));
            // The parser's default focus is computed the same way, so leaving it out reads back exactly.
            if (t.focusDistance() != ThinLensCamera.lookAtDistance(p)) s.append("  focus ").append(number(t.focusDistance()));
            if (t.lensPattern() != LensPattern.CONCENTRIC) s.append("  lens ").append(t.lensPattern().keyword());
        } else if (still instanceof OrthographicCamera o) {
            view(s, o.eye(), o.lookAt(), o.up());
            s.append("  projection orthographic  width ").append(number(o.viewWidth()));
        } else {
            throw new IllegalArgumentException("a scene file has no camera block for a " + still.getClass().getSimpleName());
        }
        if (camera instanceof AnimatedCamera) s.append("  ").append(keysText);
        return s.append(" }").toString();
    }

    private static void view(StringBuilder s, Vec3 eye, Vec3 lookAt, Vec3 up) {
        s.append(" eye ").append(vector(eye)).append("  lookat ").append(vector(lookAt)).append("  up ").append(vector(up));
    }

    private static String vector(Vec3 v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

    /** The shortest text the scene lexer reads back as exactly this double. */
    static String number(double d) { return ObjWriter.number(d); }

    /**
     * Finds the camera statement of a scene file's text by its tokens (so a material named
     * {@code camera}, or the word in a comment or a string, is not taken for it).
     *
     * @param text the file's text
     * @param file its name, for messages
     * @return where the statement is, or null when the file has none
     * @throws SceneException if the text does not read as statements (an unclosed block, a bad
     *         token), or has two camera statements, at the place that shows it
     */
    public static Located locate(String text, String file) {
        int bom = text.startsWith("\uFEFF") ? 1 : 0;
        SceneLexer lex = new SceneLexer(text, file);
        Offsets at = new Offsets(text, bom);
        Located found = null;
        while (true) {
            SceneLexer.Token t = lex.next();
            if (t.kind() == SceneLexer.Kind.EOF) return found;
            if (t.kind() != SceneLexer.Kind.WORD) throw lex.error(t.line(), t.column(), "expected a statement, found " + t.describe());
            if (t.isWord("material") || t.isWord("texture")) {
                SceneLexer.Token name = lex.next();
                if (name.kind() != SceneLexer.Kind.WORD) throw lex.error(name.line(), name.column(), "expected a name after '" + t.text() + "', found " + name.describe());
            }
            SceneLexer.Token open = lex.next();
            if (open.kind() != SceneLexer.Kind.OPEN) throw lex.error(open.line(), open.column(), "expected '{' after '" + t.text() + "', found " + open.describe());
            boolean camera = t.isWord("camera");
            if (camera && found != null) throw lex.error(t.line(), t.column(), "camera is already defined at " + found.line() + ":" + found.column());
            StringBuilder tokens = new StringBuilder("camera {");
            String keys = null;
            int depth = 1;
            SceneLexer.Token keysStart = null;
            SceneLexer.Token last = open;
            while (depth > 0) {
                SceneLexer.Token u = lex.next();
                switch (u.kind()) {
                    case EOF -> throw lex.error(open.line(), open.column(), "this '{' of '" + t.text() + "' is never closed");
                    case OPEN -> depth++;
                    case CLOSE -> depth--;
                    default -> { }
                }
                if (!camera) continue;
                if (depth == 1 && u.kind() == SceneLexer.Kind.WORD && (u.isWord("keys") || u.isWord("turntable"))) {
                    keysStart = u;
                } else if (keysStart != null && u.kind() == SceneLexer.Kind.CLOSE && depth == 1) {
                    keys = text.substring(at.of(keysStart), at.of(u) + 1);
                    keysStart = null;
                }
                tokens.append(' ').append(u.kind() == SceneLexer.Kind.STRING ? '"' + u.text() + '"' : u.text());
                last = u;
            }
            if (camera) found = new Located(at.of(t), at.of(last) + 1, t.line(), t.column(), keys, tokens.toString());
        }
    }

    /**
     * The text with its camera statement replaced by {@code block}; every other character kept.
     * A text without a camera statement gets the block before its first statement, on a line of
     * its own (after the comments that head the file).
     *
     * @param text  the scene file's text
     * @param file  its name, for messages
     * @param block the new statement ({@link #format})
     * @return the new text
     * @throws SceneException as {@link #locate} does
     */
    public static String replace(String text, String file, String block) {
        Located l = locate(text, file);
        if (l != null) return text.substring(0, l.start()) + block + text.substring(l.end());
        int first = firstStatement(text, file);
        String eol = text.contains("\r\n") ? "\r\n" : "\n";
        return text.substring(0, first) + block + eol + text.substring(first);
    }

    /** Where the first token is, or the end of the text. */
    private static int firstStatement(String text, String file) {
        int bom = text.startsWith("\uFEFF") ? 1 : 0;
        SceneLexer.Token t = new SceneLexer(text, file).next();
        return t.kind() == SceneLexer.Kind.EOF ? text.length() : new Offsets(text, bom).of(t);
    }

    /**
     * Writes {@code camera} into a scene file in place of its camera statement ({@link #replace},
     * keeping an animated camera's keys as the file has them): every byte outside the statement
     * stays as it was. Written atomically, through a temporary file in the same folder renamed
     * over the file (a link is followed, so the file it leads to is replaced and the link kept).
     *
     * @param file   the scene file
     * @param camera the camera to write
     * @return the block written
     * @throws IOException if the file cannot be read or written
     * @throws SceneException if the file is not UTF-8 or does not read as statements ({@link #locate})
     * @throws IllegalArgumentException if the camera is animated and the file's camera has no keys to keep
     */
    public static String save(Path file, Camera camera) throws IOException {
        // Checked against the heap first: the bytes, the text (two bytes a character), the pieces cut from it.
        byte[] bytes = InputFiles.readAllBytes(file, "scene file", 6);
        String name = file.toString();
        String text = SceneLexer.decodeUtf8(bytes, name, "the file");
        Located l = locate(text, name);
        String block = format(camera, l != null ? l.keysText() : null);
        int start, end;
        String insert;
        if (l != null) {
            start = l.start();
            end = l.end();
            insert = block;
        } else {
            start = end = firstStatement(text, name);
            insert = block + (text.contains("\r\n") ? "\r\n" : "\n");
        }
        // Spliced in bytes, so nothing outside the statement is re-encoded.
        int byteStart = text.substring(0, start).getBytes(StandardCharsets.UTF_8).length;
        int byteEnd = byteStart + text.substring(start, end).getBytes(StandardCharsets.UTF_8).length;
        byte[] middle = insert.getBytes(StandardCharsets.UTF_8);
        Path target = Files.isSymbolicLink(file) ? file.toRealPath() : file;
        AtomicFile.write(target, out -> {
            out.write(bytes, 0, byteStart);
            out.write(middle);
            out.write(bytes, byteEnd, bytes.length - byteEnd);
        });
        return block;
    }

    /** Character indices of tokens, from their line and column (columns count characters, as the lexer's do). */
    private static final class Offsets {
        private final int[] lineStarts;

        Offsets(String text, int bom) {
            int lines = 1;
            for (int i = bom; i < text.length(); i++) if (endsLine(text, i)) lines++;
            lineStarts = new int[lines];
            int l = 1;
            for (int i = bom; i < text.length(); i++) if (endsLine(text, i)) lineStarts[l++] = i + 1;
            lineStarts[0] = bom;
        }

        /** A line ends at \n, and at \r not followed by \n (\r\n is one line end, at its \n). */
        private static boolean endsLine(String text, int i) {
            char c = text.charAt(i);
            return c == '\n' || c == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n');
        }

        int of(SceneLexer.Token t) { return lineStarts[t.line() - 1] + t.column() - 1; }
    }
}
