package lt.spindulys.io;

import static lt.spindulys.io.ObjReader.MAX_LIBRARIES;
import static lt.spindulys.io.ObjReader.MAX_NAME;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import lt.spindulys.io.BlockList.Doubles;
import lt.spindulys.io.BlockList.Ints;
import lt.spindulys.io.ObjReader.Ref;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivTags;

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

    private final byte[] b;
    private final int end;
    private final String file;
    private int pos;
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
    private final TagCollector tags = new TagCollector();

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
                tag();
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

    // ---- OpenSubdiv tags (subdivision mode) ----

    /**
     * {@code t name nints/nfloats/nstrings ints... floats... strings...}. The counts are
     * checked against what each tag needs and against the arguments on the line; indices are
     * checked against the mesh once the whole file is read.
     */
    private void tag() {
        skipBlanks();
        int nameAt = pos;
        if (atLineEnd()) throw error(nameAt, "expected a tag name after 't', found " + describe(nameAt));
        skipToken();
        // A name far longer than any tag's is not decoded whole (it may be most of the file).
        String name = pos - nameAt <= 64 ? text(nameAt, pos) : null;
        if (name == null || !TAGS.contains(name)) {
            throw error(nameAt, "unknown tag " + quote(nameAt, pos, "'") + (name == null ? "" : SceneGrammar.didYouMean(name, TAGS))
                    + " (known: " + String.join(", ", TAGS) + ")");
        }
        skipBlanks();
        int countsAt = pos;
        int[] counts = tagCounts(name);
        int ni = counts[0], nf = counts[1], ns = counts[2];
        String countsText = ni + "/" + nf + "/" + ns;
        String shape = switch (name) {
            case "crease" -> ni >= 2 && ni % 2 == 0 && (nf == 1 || nf == ni / 2) && ns == 0 ? null
                    : "vertex pairs and one sharpness for all pairs or one per pair (such as 2/1/0 or 4/2/0)";
            case "corner" -> ni >= 1 && (nf == 1 || nf == ni) && ns == 0 ? null
                    : "vertices and one sharpness for all or one per vertex (such as 1/1/0 or 3/3/0)";
            case "hole" -> ni >= 1 && nf == 0 && ns == 0 ? null : "face indices only (such as 1/0/0 or 3/0/0)";
            case "interpolateboundary", "facevaryinginterpolateboundary", "facevaryingpropagatecorners" ->
                    ni == 1 && nf == 0 && ns == 0 ? null : "one integer (1/0/0)";
            case "creasemethod", "smoothtriangles", "scheme" -> ni == 0 && nf == 0 && ns == 1 ? null : "one string (0/0/1)";
            default -> null; // hierarchical edits: read and ignored, as OpenSubdiv's Far does
        };
        if (shape != null) throw error(countsAt, "tag '" + name + "' takes " + shape + ", found " + countsText);

        String argsSay = " (its counts " + countsText + " say " + plural(ni, "integer") + ", " + plural(nf, "float")
                + " and " + plural(ns, "string") + ")";
        // The counts are the file's word: the arrays grow as the arguments arrive (to exactly the
        // counts once all are read), so a tag that announces 10^9 of them costs nothing.
        long[] ints = new long[Math.min(ni, FIRST_ARGS)];
        int[] intLine = new int[ints.length], intColumn = new int[ints.length];
        for (int i = 0; i < ni; i++) {
            if (i == ints.length) {
                int n = grown(i, ni);
                ints = Arrays.copyOf(ints, n);
                intLine = Arrays.copyOf(intLine, n);
                intColumn = Arrays.copyOf(intColumn, n);
            }
            skipBlanks();
            intLine[i] = line;
            intColumn[i] = column(pos);
            ints[i] = tagInteger(name, "integer " + (i + 1) + " of " + ni + argsSay);
        }
        float[] floats = new float[Math.min(nf, FIRST_ARGS)];
        for (int i = 0; i < nf; i++) {
            if (i == floats.length) floats = Arrays.copyOf(floats, grown(i, nf));
            skipBlanks();
            int at = pos;
            boolean sharpness = name.equals("crease") || name.equals("corner");
            double v = number((sharpness ? "sharpness " : "float ") + (i + 1) + " of " + nf + " of tag '" + name + "'" + argsSay);
            if (sharpness && v < 0) throw error(at, name + " sharpness must not be negative, found " + quote(at, pos, ""));
            floats[i] = (float) v; // OpenSubdiv keeps sharpness as float
        }
        String[] strings = new String[Math.min(ns, FIRST_ARGS)];
        int[] stringAt = new int[strings.length];
        for (int i = 0; i < ns; i++) {
            if (i == strings.length) {
                strings = Arrays.copyOf(strings, grown(i, ns));
                stringAt = Arrays.copyOf(stringAt, strings.length);
            }
            skipBlanks();
            stringAt[i] = pos;
            if (atLineEnd()) {
                throw error(pos, "expected string " + (i + 1) + " of " + ns + " of tag '" + name + "'" + argsSay + ", found " + describe(pos));
            }
            strings[i] = token();
        }
        skipBlanks();
        if (!atLineEnd()) {
            throw error(pos, "unexpected " + describe(pos) + " after the arguments of tag '" + name + "'" + argsSay);
        }

        switch (name) {
            case "crease" -> {
                for (int i = 0; i < ni; i += 2) {
                    float s = floats[nf == 1 ? 0 : i / 2];
                    tags.creases.add(new TagIndex(ints[i], intLine[i], intColumn[i]));
                    tags.creases.add(new TagIndex(ints[i + 1], intLine[i + 1], intColumn[i + 1]));
                    tags.creaseSharpness.add(s);
                }
            }
            case "corner" -> {
                for (int i = 0; i < ni; i++) {
                    tags.corners.add(new TagIndex(ints[i], intLine[i], intColumn[i]));
                    tags.cornerSharpness.add(floats[nf == 1 ? 0 : i]);
                }
            }
            case "hole" -> {
                for (int i = 0; i < ni; i++) tags.holes.add(new TagIndex(ints[i], intLine[i], intColumn[i]));
            }
            case "interpolateboundary" -> {
                SubdivOptions.Boundary[] modes = {SubdivOptions.Boundary.NONE, SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.Boundary.EDGE_ONLY};
                long v = ints[0];
                if (v < 0 || v > 2) {
                    throw new SceneException(file, intLine[0], intColumn[0],
                            "expected 0 (none), 1 (edge and corner) or 2 (edge only) for tag 'interpolateboundary', found " + v);
                }
                tags.options = tags.options.withBoundary(modes[(int) v]);
            }
            case "facevaryinginterpolateboundary" -> {
                SubdivOptions.FaceVarying[] modes = SubdivOptions.FaceVarying.values();
                long v = ints[0];
                if (v < 0 || v >= modes.length) {
                    throw new SceneException(file, intLine[0], intColumn[0],
                            "expected 0 (none), 1 (corners only), 2 (corners plus1), 3 (corners plus2), 4 (boundaries) or 5 (all)"
                                    + " for tag 'facevaryinginterpolateboundary', found " + v);
                }
                tags.options = tags.options.withFaceVarying(modes[(int) v]);
            }
            case "creasemethod" -> {
                tags.options = tags.options.withCreasing(switch (strings[0]) {
                    case "normal" -> SubdivOptions.Creasing.UNIFORM;
                    case "chaikin" -> SubdivOptions.Creasing.CHAIKIN;
                    default -> throw error(stringAt[0], "expected normal or chaikin for tag 'creasemethod', found " + MessageText.quote(strings[0])
                            + SceneGrammar.didYouMean(strings[0], List.of("normal", "chaikin")));
                });
            }
            case "smoothtriangles" -> {
                tags.options = tags.options.withTriangles(switch (strings[0]) {
                    case "catmark" -> SubdivOptions.Triangles.CATMARK;
                    case "smooth" -> SubdivOptions.Triangles.SMOOTH;
                    default -> throw error(stringAt[0], "expected catmark or smooth for tag 'smoothtriangles', found " + MessageText.quote(strings[0])
                            + SceneGrammar.didYouMean(strings[0], List.of("catmark", "smooth")));
                });
            }
            case "scheme" -> {
                SubdivOptions.Scheme s = SubdivOptions.Scheme.ofKeyword(strings[0]);
                if (s == null) {
                    throw error(stringAt[0], "expected catmark, loop or bilinear for tag 'scheme', found " + MessageText.quote(strings[0])
                            + SceneGrammar.didYouMean(strings[0], List.of("catmark", "loop", "bilinear")));
                }
                tags.options = tags.options.withScheme(s);
            }
            default -> {
                if (!tags.ignored.contains(name)) tags.ignored.add(name);
            }
        }
    }

    /** "nints/nfloats/nstrings": three counts from 0, separated by slashes. */
    /** Tag arguments allocated before any is read; the arrays double from there. */
    private static final int FIRST_ARGS = 16;

    /** The next length of an argument array that is full at {@code length} of {@code count}. */
    private static int grown(int length, int count) {
        return (int) Math.min(count, 2L * length);
    }

    private int[] tagCounts(String name) {
        int start = pos;
        int[] counts = new int[3];
        for (int k = 0; k < 3; k++) {
            if (k > 0) {
                if (pos >= end || b[pos] != '/') { pos = start; counts = null; break; }
                pos++;
            }
            int digits = 0;
            long v = 0;
            while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
                if (v < 1L << 40) v = v * 10 + (b[pos] - '0');
                digits++;
                pos++;
            }
            if (digits == 0 || v > 1_000_000_000) { pos = start; counts = null; break; }
            counts[k] = (int) v;
        }
        if (counts == null || !atTokenEnd()) {
            pos = start;
            throw error(start, "expected the argument counts nints/nfloats/nstrings (such as 2/1/0) after 't " + name + "', found " + describe(start));
        }
        return counts;
    }

    /** A decimal integer argument of a tag. */
    private long tagInteger(String name, String what) {
        int start = pos;
        if (atLineEnd()) throw error(start, "expected " + what + " of tag '" + name + "', found " + describe(start));
        boolean neg = false;
        if (b[pos] == '-' || b[pos] == '+') neg = b[pos++] == '-';
        long v = 0;
        int digits = 0;
        while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
            if (v < 1L << 40) v = v * 10 + (b[pos] - '0');
            digits++;
            pos++;
        }
        if (digits == 0 || !atTokenEnd()) {
            pos = start;
            throw error(start, "expected " + what + " of tag '" + name + "', found " + describe(start));
        }
        return neg ? -v : v;
    }

    /** The token at pos (up to a blank, a comment or the line's end), consumed. */
    private String token() {
        int start = pos;
        skipToken();
        return text(start, pos);
    }

    private void skipToken() {
        while (pos < end && !isBlank(b[pos]) && !isLineEnd(b[pos]) && b[pos] != '#') pos++;
    }

    private static String plural(int n, String word) {
        return n + " " + word + (n == 1 ? "" : "s");
    }

    /** The mesh and its tags, the tags' indices checked against the whole file's vertices, faces and edges. */
    SubdivInput parseSubdiv() {
        MeshData mesh = parse();
        int nv = mesh.vertexCount(), nf = mesh.faceCount();
        int[] creases = new int[tags.creases.size()];
        Set<Long> edges = null;
        for (int i = 0; i < creases.length; i += 2) {
            TagIndex a = tags.creases.get(i), c = tags.creases.get(i + 1);
            creases[i] = checkIndex(a, nv, "crease vertex", "vertices");
            creases[i + 1] = checkIndex(c, nv, "crease vertex", "vertices");
            if (creases[i] == creases[i + 1]) {
                throw new SceneException(file, c.line, c.column, "crease from vertex " + a.value + " to itself (a crease is an edge: two different vertices)");
            }
            if (edges == null) edges = edges(mesh);
            if (!edges.contains(edgeKey(creases[i], creases[i + 1]))) {
                throw new SceneException(file, a.line, a.column, "crease " + a.value + " " + c.value + " is not an edge of the mesh (no face has vertices "
                        + a.value + " and " + c.value + " next to each other; tag indices count from 0)");
            }
        }
        int[] corners = new int[tags.corners.size()];
        for (int i = 0; i < corners.length; i++) corners[i] = checkIndex(tags.corners.get(i), nv, "corner vertex", "vertices");
        int[] holes = new int[tags.holes.size()];
        for (int i = 0; i < holes.length; i++) holes[i] = checkIndex(tags.holes.get(i), nf, "hole face", "faces");
        float[] cs = new float[tags.creaseSharpness.size()], ks = new float[tags.cornerSharpness.size()];
        for (int i = 0; i < cs.length; i++) cs[i] = tags.creaseSharpness.get(i);
        for (int i = 0; i < ks.length; i++) ks[i] = tags.cornerSharpness.get(i);
        return new SubdivInput(mesh, new SubdivTags(creases, cs, corners, ks, holes, tags.options, tags.ignored));
    }

    private int checkIndex(TagIndex t, int count, String what, String plural) {
        if (t.value < 0 || t.value >= count) {
            throw new SceneException(file, t.line, t.column, what + " " + t.value + " out of range (the file has " + count + " " + plural
                    + "; tag indices count from 0)");
        }
        return (int) t.value;
    }

    private static long edgeKey(int a, int c) {
        return ((long) Math.min(a, c) << 32) | Math.max(a, c);
    }

    private static Set<Long> edges(MeshData m) {
        Set<Long> set = new HashSet<>();
        int[] sizes = m.faceSizes(), vi = m.vertexIndex();
        int corner = 0;
        for (int size : sizes) {
            for (int j = 0; j < size; j++) set.add(edgeKey(vi[corner + j], vi[corner + (j + 1) % size]));
            corner += size;
        }
        return set;
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
        return new SceneException(file, line, column(at), message);
    }

    /** Column of {@code at} on the current line; columns count characters, not bytes (UTF-8 continuation bytes are skipped). */
    private int column(int at) {
        int column = 1;
        for (int i = lineStart; i < at && i < end; i++) if ((b[i] & 0xC0) != 0x80) column++;
        return column;
    }

    private String text(int from, int to) {
        return new String(b, from, to - from, StandardCharsets.UTF_8);
    }

    /**
     * Bytes {@code from..to} as a message quotes them ({@link MessageText#quote(String, long, String)}):
     * only the start of a long token is decoded, since a token may be most of the file.
     */
    private String quote(int from, int to, String mark) {
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
    private String describe(int at) {
        if (at >= end) return "end of file";
        byte c = b[at];
        if (isLineEnd(c)) return "end of line";
        if (c == '#') return "a comment";
        if (isBlank(c)) return "a space";
        int e = at;
        while (e < end && !isBlank(b[e]) && !isLineEnd(b[e])) e++;
        return quote(at, e, "'");
    }

    /** The tag names OpenSubdiv's shape files use; any other name is an error. */
    private static final List<String> TAGS = List.of("crease", "corner", "hole", "interpolateboundary",
            "facevaryinginterpolateboundary", "facevaryingpropagatecorners", "creasemethod", "smoothtriangles",
            "scheme", "vertexedit", "edgeedit", "faceedit");

    /** An index given in a tag, with where it was written, checked once the mesh is complete. */
    private record TagIndex(long value, int line, int column) {}

    /** Tags as they are read; tags are few, so plain lists do. */
    private static final class TagCollector {
        final List<TagIndex> creases = new ArrayList<>(), corners = new ArrayList<>(), holes = new ArrayList<>();
        final List<Float> creaseSharpness = new ArrayList<>(), cornerSharpness = new ArrayList<>();
        final List<String> ignored = new ArrayList<>();
        SubdivOptions options = SubdivOptions.DEFAULT;
    }
}
