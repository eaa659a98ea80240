package lt.spindulys.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Arrays;

import lt.spindulys.scene.MeshData;

/**
 * Reads Wavefront OBJ meshes: {@code v} (x y z, an optional w and an optional r g b colour are
 * ignored), {@code vn}, {@code vt} (u, optional v and w), and {@code f} with polygons of any size
 * whose corners are {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn}, indices counted
 * from 1 or, when negative, back from the latest element. {@code o}, {@code g}, {@code s},
 * {@code usemtl}, {@code mtllib} and OpenSubdiv's {@code t} tags are skipped; {@code #} starts a
 * comment; a backslash at the end of a line continues it. Anything else is an error.
 *
 * <p>The file is read as bytes and parsed in place, numbers by hand (exactly rounded: the fast
 * path is taken only where it is exact, other numbers go to {@link Double#parseDouble}), with no
 * allocation per token, because meshes run to tens of millions of numbers. Errors are
 * {@link SceneException}s naming the file, line and column of the offending token.
 */
public final class ObjReader {
    private ObjReader() {}

    /** Reads the file; malformed input throws {@link SceneException} naming file:line:column. */
    public static MeshData read(Path file) throws IOException {
        String name = file.toString();
        byte[] bytes;
        try {
            bytes = Files.readAllBytes(file);
        } catch (NoSuchFileException e) {
            throw new SceneException(name, 0, 0, "OBJ file not found (looked in " + file.toAbsolutePath().normalize() + ")");
        } catch (IOException e) {
            throw new SceneException(name, 0, 0, "cannot read OBJ file: " + e.getMessage(), e);
        }
        return new Parser(bytes, name).parse();
    }

    /** Parses OBJ text; {@code fileName} is used in messages and as the mesh's source. */
    public static MeshData parse(String text, String fileName) {
        return new Parser(text.getBytes(StandardCharsets.UTF_8), fileName).parse();
    }

    /** Growable primitive arrays: one allocation per doubling, none per element. */
    private static final class Doubles {
        double[] a = new double[1024];
        int n;

        void add(double v) {
            if (n == a.length) a = Arrays.copyOf(a, 2 * n);
            a[n++] = v;
        }

        double[] toArray() { return Arrays.copyOf(a, n); }
    }

    private static final class Ints {
        int[] a = new int[1024];
        int n;

        void add(int v) {
            if (n == a.length) a = Arrays.copyOf(a, 2 * n);
            a[n++] = v;
        }

        int[] toArray() { return Arrays.copyOf(a, n); }
    }

    private static final double[] POW10 = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
    };

    private static final class Parser {
        private final byte[] b;
        private final int end;
        private final String file;
        private int pos;
        /** 1-based line number of {@link #pos} and where that line starts, for messages. */
        private int line = 1, lineStart;

        private final Doubles positions = new Doubles(), normals = new Doubles(), uvs = new Doubles();
        private final Ints faceSizes = new Ints(), vertexIndex = new Ints(), normalIndex = new Ints(), uvIndex = new Ints();
        private boolean anyNormalIndex, anyUvIndex;

        Parser(byte[] bytes, String file) {
            this.b = bytes;
            this.end = bytes.length;
            this.file = file;
            // A UTF-8 byte order mark is not part of the first statement.
            if (end >= 3 && (bytes[0] & 0xff) == 0xEF && (bytes[1] & 0xff) == 0xBB && (bytes[2] & 0xff) == 0xBF) {
                pos = lineStart = 3;
            }
        }

        MeshData parse() {
            while (pos < end) {
                skipBlanks();
                if (atLineEnd()) {
                    nextLine();
                    continue;
                }
                int start = pos;
                while (pos < end && !isBlank(b[pos]) && !isLineEnd(b[pos]) && b[pos] != '#') pos++;
                int len = pos - start;
                byte c0 = b[start];
                if (len == 1 && c0 == 'v') {
                    vertex();
                } else if (len == 1 && c0 == 'f') {
                    face(start);
                } else if (len == 2 && c0 == 'v' && b[start + 1] == 'n') {
                    normal();
                } else if (len == 2 && c0 == 'v' && b[start + 1] == 't') {
                    texture();
                } else if (isSkipped(start, len)) {
                    skipStatement();
                } else {
                    String word = new String(b, start, len, StandardCharsets.UTF_8);
                    String what = unsupported(word);
                    throw error(start, what != null ? "OBJ statement '" + word + "' (" + what + ") is not supported"
                            : "unknown OBJ statement '" + word + "'");
                }
                nextLine();
            }
            return new MeshData(positions.toArray(),
                    normals.n > 0 ? normals.toArray() : null,
                    uvs.n > 0 ? uvs.toArray() : null,
                    faceSizes.toArray(), vertexIndex.toArray(),
                    anyNormalIndex ? normalIndex.toArray() : null,
                    anyUvIndex ? uvIndex.toArray() : null,
                    file);
        }

        /** Statements that carry nothing a ray tracer's mesh needs (yet): o g s usemtl mtllib t. */
        private boolean isSkipped(int s, int len) {
            return len == 1 && (b[s] == 'o' || b[s] == 'g' || b[s] == 's' || b[s] == 't')
                    || matches(s, len, "usemtl") || matches(s, len, "mtllib");
        }

        private boolean matches(int s, int len, String word) {
            if (len != word.length()) return false;
            for (int i = 0; i < len; i++) if (b[s + i] != word.charAt(i)) return false;
            return true;
        }

        private static String unsupported(String word) {
            return switch (word) {
                case "l" -> "polylines";
                case "p" -> "points";
                case "vp", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole",
                        "scrv", "sp", "end", "con" -> "free-form geometry";
                case "mg", "lod", "usemap", "maplib", "shadow_obj", "trace_obj", "ctech", "stech", "bevel",
                        "c_interp", "d_interp" -> "display and render attribute";
                default -> null;
            };
        }

        // ---- statements ----

        private void vertex() {
            positions.add(number("vertex x"));
            positions.add(number("vertex y"));
            positions.add(number("vertex z"));
            // Optional w (rational curves only, meaningless for a mesh) or a per-vertex colour
            // r g b as written by MeshLab and others; both are read and dropped.
            int extra = 0, extraStart = -1;
            while (true) {
                skipBlanks();
                if (atLineEnd()) break;
                if (extra == 3) throw error(pos, "unexpected " + describe(pos) + " after the vertex (expected x y z, x y z w or x y z r g b)");
                if (extra == 0) extraStart = pos;
                number(extra == 0 ? "vertex w or colour red" : extra == 1 ? "vertex colour green" : "vertex colour blue");
                extra++;
            }
            if (extra == 2) throw error(extraStart, "vertex has 5 numbers, expected 3 (x y z), 4 (x y z w) or 6 (x y z r g b)");
        }

        private void normal() {
            normals.add(number("normal x"));
            normals.add(number("normal y"));
            normals.add(number("normal z"));
            expectLineEnd("the normal (expected x y z)");
        }

        private void texture() {
            uvs.add(number("texture u"));
            double v = 0; // OBJ: v defaults to 0
            skipBlanks();
            if (!atLineEnd()) {
                v = number("texture v");
                skipBlanks();
                if (!atLineEnd()) number("texture w");
            }
            uvs.add(v);
            expectLineEnd("the texture coordinate (expected u, u v or u v w)");
        }

        private void face(int keyword) {
            int corners = 0;
            boolean withUv = false, withNormal = false;
            while (true) {
                skipBlanks();
                if (atLineEnd()) break;
                int cornerStart = pos;
                int v = index("vertex", positions.n / 3, "vertex", "vertices");
                int t = -1, n = -1;
                boolean hasUv = false, hasNormal = false;
                if (pos < end && b[pos] == '/') {
                    pos++;
                    if (pos < end && b[pos] != '/') {
                        t = index("texture coordinate", uvs.n / 2, "texture coordinate", "texture coordinates");
                        hasUv = true;
                    }
                    if (pos < end && b[pos] == '/') {
                        pos++;
                        n = index("normal", normals.n / 3, "normal", "normals");
                        hasNormal = true;
                    }
                }
                if (!atTokenEnd()) throw error(pos, "unexpected " + describe(pos) + " in face corner (expected v, v/vt, v//vn or v/vt/vn)");
                if (corners == 0) {
                    withUv = hasUv;
                    withNormal = hasNormal;
                } else if (hasUv != withUv) {
                    throw error(cornerStart, "face mixes corners with and without texture coordinates");
                } else if (hasNormal != withNormal) {
                    throw error(cornerStart, "face mixes corners with and without normals");
                }
                vertexIndex.add(v);
                uvIndex.add(t);
                normalIndex.add(n);
                corners++;
            }
            if (corners < 3) throw error(keyword, "face has " + corners + (corners == 1 ? " vertex" : " vertices") + ", expected at least 3");
            faceSizes.add(corners);
            anyUvIndex |= withUv;
            anyNormalIndex |= withNormal;
        }

        /**
         * A face index, resolved to 0-based: positive counts from the first element, negative
         * back from the latest ({@code -1} is the element just read).
         */
        private int index(String what, int have, String singular, String plural) {
            int start = pos;
            boolean neg = false;
            if (pos < end && (b[pos] == '-' || b[pos] == '+')) neg = b[pos++] == '-';
            long v = 0;
            int digits = 0;
            while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
                if (v < 1L << 40) v = v * 10 + (b[pos] - '0');
                digits++;
                pos++;
            }
            if (digits == 0) {
                pos = start;
                throw error(start, "expected a " + what + " index, found " + describe(start));
            }
            if (v == 0) throw error(start, "index 0 is not valid (OBJ indices start at 1)");
            String which = what.equals("vertex") ? "f index " : "f " + what + " index ";
            if (v > have) {
                throw error(start, which + text(start, pos) + " out of range (the file has " + have + " " + (have == 1 ? singular : plural) + " so far)");
            }
            return neg ? (int) (have - v) : (int) (v - 1);
        }

        /** A decimal number ([+-] digits [. digits] [e [+-] digits]) ending at a blank, a comment or the line's end. */
        private double number(String what) {
            skipBlanks();
            int start = pos;
            if (atLineEnd()) throw error(start, "expected a number for " + what + ", found " + describe(start));
            boolean neg = false;
            if (b[pos] == '-' || b[pos] == '+') neg = b[pos++] == '-';
            long mantissa = 0;
            int significant = 0, exp10 = 0;
            boolean anyDigit = false, exact = true;
            while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
                int d = b[pos++] - '0';
                anyDigit = true;
                if (significant < 19) {
                    if (mantissa != 0 || d != 0) {
                        mantissa = mantissa * 10 + d;
                        significant++;
                    }
                } else {
                    exp10++;
                    if (d != 0) exact = false;
                }
            }
            if (pos < end && b[pos] == '.') {
                pos++;
                while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
                    int d = b[pos++] - '0';
                    anyDigit = true;
                    if (significant < 19) {
                        if (mantissa != 0 || d != 0) {
                            mantissa = mantissa * 10 + d;
                            significant++;
                        }
                        exp10--;
                    } else if (d != 0) {
                        exact = false;
                    }
                }
            }
            if (anyDigit && pos < end && (b[pos] == 'e' || b[pos] == 'E')) {
                pos++;
                boolean eneg = false;
                if (pos < end && (b[pos] == '-' || b[pos] == '+')) eneg = b[pos++] == '-';
                int e = 0, edigits = 0;
                while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
                    if (e < 100_000) e = e * 10 + (b[pos] - '0');
                    pos++;
                    edigits++;
                }
                if (edigits == 0) anyDigit = false;
                exp10 += eneg ? -e : e;
            }
            if (!anyDigit || !atTokenEnd()) {
                pos = start;
                throw error(start, "expected a number for " + what + ", found " + describe(start));
            }
            double value;
            if (exact && significant <= 15 && exp10 >= -22 && exp10 <= 22) {
                // Both operands exact, one rounding: the correctly rounded result (Clinger's fast path).
                value = exp10 >= 0 ? mantissa * POW10[exp10] : mantissa / POW10[-exp10];
            } else {
                value = Math.abs(Double.parseDouble(new String(b, start, pos - start, StandardCharsets.ISO_8859_1)));
            }
            if (!Double.isFinite(value)) throw error(start, "number " + text(start, pos) + " is too large for " + what);
            return neg ? -value : value;
        }

        private void expectLineEnd(String after) {
            skipBlanks();
            if (!atLineEnd()) throw error(pos, "unexpected " + describe(pos) + " after " + after);
        }

        // ---- characters and lines ----

        private static boolean isBlank(byte c) { return c == ' ' || c == '\t' || c == '\f' || c == 0x0B; }
        private static boolean isLineEnd(byte c) { return c == '\n' || c == '\r'; }

        /** Skips spaces and tabs, and a backslash-newline (a continued line). */
        private void skipBlanks() {
            while (pos < end) {
                byte c = b[pos];
                if (isBlank(c)) {
                    pos++;
                } else if (c == '\\' && pos + 1 < end && isLineEnd(b[pos + 1])) {
                    pos++;
                    consumeNewline();
                } else {
                    break;
                }
            }
        }

        /** At the end of the statement: end of file, end of line, or a comment. */
        private boolean atLineEnd() {
            return pos >= end || isLineEnd(b[pos]) || b[pos] == '#';
        }

        private boolean atTokenEnd() {
            return pos >= end || isBlank(b[pos]) || isLineEnd(b[pos]) || b[pos] == '#'
                    || b[pos] == '\\' && pos + 1 < end && isLineEnd(b[pos + 1]);
        }

        /** Skips the rest of the statement, continuation lines included, up to its line end. */
        private void skipStatement() {
            while (pos < end && !isLineEnd(b[pos])) {
                if (b[pos] == '\\' && pos + 1 < end && isLineEnd(b[pos + 1])) {
                    pos++;
                    consumeNewline();
                } else {
                    pos++;
                }
            }
        }

        /** Moves past the comment (if any) and the line break at the end of the current statement. */
        private void nextLine() {
            while (pos < end && !isLineEnd(b[pos])) pos++;
            consumeNewline();
        }

        /** At a line break (\n, \r\n or a lone \r): consumes it and starts the next line. */
        private void consumeNewline() {
            if (pos >= end) return;
            if (b[pos] == '\r' && pos + 1 < end && b[pos + 1] == '\n') pos++;
            pos++;
            line++;
            lineStart = pos;
        }

        // ---- messages ----

        private SceneException error(int at, String message) {
            // Columns count characters, not bytes: skip UTF-8 continuation bytes.
            int column = 1;
            for (int i = lineStart; i < at && i < end; i++) if ((b[i] & 0xC0) != 0x80) column++;
            return new SceneException(file, line, column, message);
        }

        private String text(int from, int to) {
            return new String(b, from, to - from, StandardCharsets.UTF_8);
        }

        /** What is at {@code at}, for "found ..." in messages: a quoted token or a description. */
        private String describe(int at) {
            if (at >= end) return "end of file";
            byte c = b[at];
            if (isLineEnd(c)) return "end of line";
            if (c == '#') return "a comment";
            if (isBlank(c)) return "a space";
            int e = at;
            while (e < end && !isBlank(b[e]) && !isLineEnd(b[e]) && e - at < 40) e++;
            return "'" + text(at, e) + "'";
        }
    }
}
