package lt.spindulys.io;

import static lt.spindulys.io.ObjReader.MAX_LIBRARIES;
import static lt.spindulys.io.ObjReader.MAX_NAME;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

import lt.spindulys.io.BlockList.Doubles;
import lt.spindulys.io.BlockList.Ints;
import lt.spindulys.io.ObjReader.Ref;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.SubdivInput;

/**
 * The statements of an OBJ file, or of a part of one that starts a line, parsed from its bytes in
 * place: numbers by hand, with no allocation per token (see {@link ObjReader}). A whole file is
 * checked as it is read; a chunk of a large one ({@link ObjChunks}) is parsed {@link #deferred}
 * and checked when the chunks are merged. Errors are {@link SceneException}s naming the file, line
 * and column of the offending token.
 */
final class ObjParser {
    private static final double[] POW10 = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22
    };

    /** The group of a deferred chunk's faces before its first usemtl: the group the chunks before it end in. */
    static final int INHERIT = -2;
    /** Index kinds, for {@link #base} and the deferred checks. */
    static final int VERTEX = 0, UV = 1, NORMAL = 2;

    // The bytes, the end of the part parsed and the position reached; ObjTags reads a tag's
    // arguments through them and the token methods below (skipBlanks, number, error, ...).
    final byte[] b;
    final int end;
    private final String file;
    int pos;
    /** 1-based line number of {@link #pos} and where that line starts, for messages. */
    int line = 1, lineStart;

    /**
     * A chunk after the first, parsed before the counts of the elements before it are known:
     * indices are not checked against the counts but remembered ({@link #need}, {@link #relative}),
     * and checked and resolved when the chunks are merged.
     */
    private final boolean deferred;
    /** Vertices, texture coordinates and normals in the file before {@link #pos}'s chunk (0 for a whole file). */
    final int[] base = new int[3];
    /** Deferred: per kind, the most elements before the chunk that an index needs (valid if the base is at least this). */
    final long[] need = {Long.MIN_VALUE, Long.MIN_VALUE, Long.MIN_VALUE};
    /** Deferred: per kind, the corners whose negative index was resolved against this chunk alone (the base is added in the merge). */
    final Ints[] relative;

    final Doubles positions = new Doubles(), normals = new Doubles(), uvs = new Doubles();
    final Ints faceSizes = new Ints(), vertexIndex = new Ints(), normalIndex = new Ints(), uvIndex = new Ints();
    boolean anyNormalIndex, anyUvIndex;

    /** Reading a subdivision control mesh: parse {@code t} tags, require UVs on all faces or none. */
    private final boolean subdiv;
    /** Line of the first face, and whether it has texture coordinates (subdiv mode). */
    private int firstFaceLine;
    private boolean firstFaceUv;
    /** The {@code t} tags read (subdivision mode only). */
    private final ObjTags tags;

    /** The usemtl names in order of first use (a face group each), and each one's index. */
    final List<String> groupNames = new ArrayList<>();
    private final java.util.Map<String, Integer> groupIndex = new java.util.HashMap<>();
    /** Line and column of each group's first usemtl (line counted in this parser's part of the file). */
    private final Ints groupLine = new Ints(), groupColumn = new Ints();
    /** Group per face; null until the first usemtl (then filled for the faces before it). */
    Ints faceGroup;
    /** The group of the faces being read: -1 before any usemtl, {@link #INHERIT} in a deferred chunk before its first. */
    int currentGroup;
    /** The mtllib file names, in order. */
    final List<Ref> libraries = new ArrayList<>();

    ObjParser(byte[] bytes, String file, boolean subdiv) {
        this(bytes, 0, bytes.length, 1, file, subdiv, false);
    }

    /** Parses bytes {@code from..to}, starting on line {@code firstLine}; {@code from} must start a line. */
    ObjParser(byte[] bytes, int from, int to, int firstLine, String file, boolean subdiv, boolean deferred) {
        this.b = bytes;
        this.end = to;
        this.file = file;
        this.subdiv = subdiv;
        this.tags = subdiv ? new ObjTags(file) : null;
        this.deferred = deferred;
        this.relative = deferred ? new Ints[] {new Ints(), new Ints(), new Ints()} : null;
        this.currentGroup = deferred ? INHERIT : -1;
        pos = lineStart = from;
        line = firstLine;
        // A UTF-8 byte order mark is not part of the first statement.
        if (from == 0 && end >= 3 && (bytes[0] & 0xff) == 0xEF && (bytes[1] & 0xff) == 0xBB && (bytes[2] & 0xff) == 0xBF) {
            pos = lineStart = 3;
        }
    }

    MeshData parse() {
        statements();
        return new MeshData(positions.toArray(),
                normals.size() > 0 ? normals.toArray() : null,
                uvs.size() > 0 ? uvs.toArray() : null,
                faceSizes.toArray(), vertexIndex.toArray(),
                anyNormalIndex ? normalIndex.toArray() : null,
                anyUvIndex ? uvIndex.toArray() : null,
                file,
                faceGroup != null ? faceGroup.toArray() : null,
                faceGroup != null ? groupNames.toArray(String[]::new) : null);
    }

    /** Each group's first usemtl, in group order. */
    List<Ref> groupRefs() {
        List<Ref> out = new ArrayList<>(groupNames.size());
        int[] lines = groupLine.toArray(), columns = groupColumn.toArray();
        for (int g = 0; g < groupNames.size(); g++) out.add(new Ref(groupNames.get(g), lines[g], columns[g]));
        return List.copyOf(out);
    }

    /** Reads every statement up to the end. */
    void statements() {
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
            } else if (subdiv && len == 1 && c0 == 't') {
                tags.read(this);
            } else if (matches(start, len, "usemtl")) {
                usemtl();
            } else if (matches(start, len, "mtllib")) {
                mtllib();
            } else if (isSkipped(start, len)) {
                skipStatement();
            } else {
                String what = len <= 16 ? unsupported(text(start, pos)) : null;
                throw error(start, what != null ? "OBJ statement '" + text(start, pos) + "' (" + what + ") is not supported"
                        : "unknown OBJ statement " + quote(start, pos, "'"));
            }
            nextLine();
        }
    }

    /** Statements that carry nothing a ray tracer's mesh needs: o g s, and t outside a control mesh. */
    private boolean isSkipped(int s, int len) {
        return len == 1 && (b[s] == 'o' || b[s] == 'g' || b[s] == 's' || b[s] == 't');
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
            int v = index(VERTEX, "vertex", positions.size() / 3, "vertex", "vertices");
            int t = -1, n = -1;
            boolean hasUv = false, hasNormal = false;
            if (pos < end && b[pos] == '/') {
                pos++;
                if (pos < end && b[pos] != '/') {
                    t = index(UV, "texture coordinate", uvs.size() / 2, "texture coordinate", "texture coordinates");
                    hasUv = true;
                }
                if (pos < end && b[pos] == '/') {
                    pos++;
                    n = index(NORMAL, "normal", normals.size() / 3, "normal", "normals");
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
        if (subdiv) {
            // Face-varying UVs need a value at every corner of the surface.
            if (faceSizes.size() == 0) {
                firstFaceLine = line;
                firstFaceUv = withUv;
            } else if (withUv != firstFaceUv) {
                throw error(keyword, (withUv ? "face has texture coordinates, but the face on line " + firstFaceLine + " has none"
                        : "face has no texture coordinates, but the face on line " + firstFaceLine + " has")
                        + " (a subdivision surface needs them on every face or none)");
            }
        }
        faceSizes.add(corners);
        if (faceGroup != null) faceGroup.add(currentGroup);
        anyUvIndex |= withUv;
        anyNormalIndex |= withNormal;
    }

    // ---- materials ----

    /**
     * {@code usemtl NAME}: the faces that follow belong to the group NAME (the rest of the
     * line, blanks around it dropped, as .mtl files write it after newmtl).
     */
    private void usemtl() {
        skipBlanks();
        int start = pos;
        if (atLineEnd()) throw error(start, "expected a material name after 'usemtl', found " + describe(start));
        int last = start;
        while (pos < end && !isLineEnd(b[pos]) && b[pos] != '#') {
            if (!isBlank(b[pos])) last = pos + 1;
            pos++;
        }
        if (last - start > MAX_NAME) {
            throw error(start, "material name " + quote(start, last, "'") + " is longer than " + MAX_NAME + " characters");
        }
        String name = text(start, last);
        Integer g = groupIndex.get(name);
        if (g == null) {
            if (groupNames.size() == MeshData.MAX_GROUPS) {
                throw error(start, "more than " + MeshData.MAX_GROUPS + " different usemtl names in one file");
            }
            g = groupNames.size();
            groupNames.add(name);
            groupIndex.put(name, g);
            groupLine.add(line);
            groupColumn.add(column(start));
        }
        if (faceGroup == null) {
            faceGroup = new Ints();
            for (int f = faceSizes.size(); f > 0; f--) faceGroup.add(currentGroup);
        }
        currentGroup = g;
    }

    /** {@code mtllib FILE...}: material libraries, read by the scene relative to this file. */
    private void mtllib() {
        int n = 0;
        while (true) {
            skipBlanks();
            if (atLineEnd()) break;
            int start = pos;
            skipToken();
            if (pos - start > MAX_NAME) throw error(start, "file name " + quote(start, pos, "'") + " is longer than " + MAX_NAME + " characters");
            if (libraries.size() == MAX_LIBRARIES) throw error(start, "more than " + MAX_LIBRARIES + " material libraries in one file");
            libraries.add(new Ref(text(start, pos), line, column(start)));
            n++;
        }
        if (n == 0) throw error(pos, "expected a material library file name after 'mtllib', found " + describe(pos));
    }

    /** The mesh and its tags, the tags' indices checked against the whole file's vertices, faces and edges. */
    SubdivInput parseSubdiv() {
        MeshData mesh = parse();
        return new SubdivInput(mesh, tags.resolve(mesh));
    }

    /**
     * A face index, resolved to 0-based: positive counts from the first element, negative
     * back from the latest ({@code -1} is the element just read).
     */
    private int index(int kind, String what, int local, String singular, String plural) {
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
        if (deferred) {
            // Valid if the chunks before hold at least v - local; a negative index counts back
            // from this chunk's latest element, so the merge adds the base to it.
            need[kind] = Math.max(need[kind], v - local);
            if (!neg) return (int) (v - 1);
            relative[kind].add(vertexIndex.size());
            return (int) (local - v);
        }
        int have = base[kind] + local;
        String which = what.equals("vertex") ? "f index " : "f " + what + " index ";
        if (v > have) {
            throw error(start, which + quote(start, pos, "") + " out of range (the file has " + have + " " + (have == 1 ? singular : plural) + " so far)");
        }
        return neg ? (int) (have - v) : (int) (v - 1);
    }

    /** A decimal number ([+-] digits [. digits] [e [+-] digits]) ending at a blank, a comment or the line's end. */
    double number(String what) {
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
        // Bounded so that squares and products of coordinates cannot overflow (see Ranges).
        if (!(value <= Ranges.MAX_NUMBER)) {
            throw error(start, "number " + quote(start, pos, "") + " is too large for " + what + " (mesh numbers are at most "
                    + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude)");
        }
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
    void skipBlanks() {
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
    boolean atLineEnd() {
        return pos >= end || isLineEnd(b[pos]) || b[pos] == '#';
    }

    boolean atTokenEnd() {
        return pos >= end || isBlank(b[pos]) || isLineEnd(b[pos]) || b[pos] == '#'
                || b[pos] == '\\' && pos + 1 < end && isLineEnd(b[pos + 1]);
    }

    /** The token at pos (up to a blank, a comment or the line's end), consumed. */
    String token() {
        int start = pos;
        skipToken();
        return text(start, pos);
    }

    void skipToken() {
        while (pos < end && !isBlank(b[pos]) && !isLineEnd(b[pos]) && b[pos] != '#') pos++;
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

    SceneException error(int at, String message) {
        return new SceneException(file, line, column(at), message);
    }

    /** Column of {@code at} on the current line; columns count characters, not bytes (UTF-8 continuation bytes are skipped). */
    int column(int at) {
        int column = 1;
        for (int i = lineStart; i < at && i < end; i++) if ((b[i] & 0xC0) != 0x80) column++;
        return column;
    }

    String text(int from, int to) {
        return new String(b, from, to - from, StandardCharsets.UTF_8);
    }

    /**
     * Bytes {@code from..to} as a message quotes them ({@link MessageText#quote(String, long, String)}):
     * only the start of a long token is decoded, since a token may be most of the file.
     */
    String quote(int from, int to, String mark) {
        long characters = 0;
        int headEnd = to;
        for (int i = from; i < to; i++) {
            if ((b[i] & 0xC0) == 0x80) continue; // a UTF-8 continuation byte
            if (characters == MessageText.SHOWN + 1 && headEnd == to) headEnd = i;
            characters++;
        }
        return MessageText.quote(text(from, characters > MessageText.SHOWN + MessageText.SLACK ? headEnd : to), characters, mark);
    }

    /** What is at {@code at}, for "found ..." in messages: a quoted token or a description. */
    String describe(int at) {
        if (at >= end) return "end of file";
        byte c = b[at];
        if (isLineEnd(c)) return "end of line";
        if (c == '#') return "a comment";
        if (isBlank(c)) return "a space";
        int e = at;
        while (e < end && !isBlank(b[e]) && !isLineEnd(b[e])) e++;
        return quote(at, e, "'");
    }
}
