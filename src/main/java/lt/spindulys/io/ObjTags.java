package lt.spindulys.io;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import lt.spindulys.limits.MessageText;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivTags;

/**
 * OpenSubdiv's {@code t} tags of an OBJ file read as a subdivision control mesh (grammar
 * {@code t name nints/nfloats/nstrings ints... floats... strings...}; see docs/mesh-formats.md).
 * Each tag is read from the {@link ObjParser}'s statement and checked as it comes: a known name,
 * counts of the shape the tag takes, arguments that match the counts, values in range
 * ({@link #read}). The indices are kept with where they were written and checked against the
 * complete mesh at the end ({@link #resolve}), which makes the {@link SubdivTags}.
 */
final class ObjTags {
    /** The tag names OpenSubdiv's shape files use; any other name is an error. */
    private static final List<String> TAGS = List.of("crease", "corner", "hole", "interpolateboundary",
            "facevaryinginterpolateboundary", "facevaryingpropagatecorners", "creasemethod", "smoothtriangles",
            "scheme", "vertexedit", "edgeedit", "faceedit");

    /** Tag arguments allocated before any is read; the arrays double from there. */
    private static final int FIRST_ARGS = 16;

    /** An index given in a tag, with where it was written, checked once the mesh is complete. */
    private record TagIndex(long value, int line, int column) {}

    private final String file;
    // Tags as they are read; tags are few, so plain lists do.
    private final List<TagIndex> creases = new ArrayList<>(), corners = new ArrayList<>(), holes = new ArrayList<>();
    private final List<Float> creaseSharpness = new ArrayList<>(), cornerSharpness = new ArrayList<>();
    private final List<String> ignored = new ArrayList<>();
    private SubdivOptions options = SubdivOptions.DEFAULT;

    /** Tags of {@code file} (the name used in messages). */
    ObjTags(String file) {
        this.file = file;
    }

    /**
     * Reads one tag, {@code p} just past its {@code t}:
     * {@code t name nints/nfloats/nstrings ints... floats... strings...}. The counts are
     * checked against what each tag needs and against the arguments on the line; indices are
     * checked against the mesh once the whole file is read.
     */
    void read(ObjParser p) {
        p.skipBlanks();
        int nameAt = p.pos;
        if (p.atLineEnd()) throw p.error(nameAt, "expected a tag name after 't', found " + p.describe(nameAt));
        p.skipToken();
        // A name far longer than any tag's is not decoded whole (it may be most of the file).
        String name = p.pos - nameAt <= 64 ? p.text(nameAt, p.pos) : null;
        if (name == null || !TAGS.contains(name)) {
            throw p.error(nameAt, "unknown tag " + p.quote(nameAt, p.pos, "'") + (name == null ? "" : SceneGrammar.didYouMean(name, TAGS))
                    + " (known: " + String.join(", ", TAGS) + ")");
        }
        p.skipBlanks();
        int countsAt = p.pos;
        int[] counts = counts(p, name);
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
        if (shape != null) throw p.error(countsAt, "tag '" + name + "' takes " + shape + ", found " + countsText);

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
            p.skipBlanks();
            intLine[i] = p.line;
            intColumn[i] = p.column(p.pos);
            ints[i] = integer(p, name, "integer " + (i + 1) + " of " + ni + argsSay);
        }
        float[] floats = new float[Math.min(nf, FIRST_ARGS)];
        for (int i = 0; i < nf; i++) {
            if (i == floats.length) floats = Arrays.copyOf(floats, grown(i, nf));
            p.skipBlanks();
            int at = p.pos;
            boolean sharpness = name.equals("crease") || name.equals("corner");
            double v = p.number((sharpness ? "sharpness " : "float ") + (i + 1) + " of " + nf + " of tag '" + name + "'" + argsSay);
            if (sharpness && v < 0) throw p.error(at, name + " sharpness must not be negative, found " + p.quote(at, p.pos, ""));
            floats[i] = (float) v; // OpenSubdiv keeps sharpness as float
        }
        String[] strings = new String[Math.min(ns, FIRST_ARGS)];
        int[] stringAt = new int[strings.length];
        for (int i = 0; i < ns; i++) {
            if (i == strings.length) {
                strings = Arrays.copyOf(strings, grown(i, ns));
                stringAt = Arrays.copyOf(stringAt, strings.length);
            }
            p.skipBlanks();
            stringAt[i] = p.pos;
            if (p.atLineEnd()) {
                throw p.error(p.pos, "expected string " + (i + 1) + " of " + ns + " of tag '" + name + "'" + argsSay + ", found " + p.describe(p.pos));
            }
            strings[i] = p.token();
        }
        p.skipBlanks();
        if (!p.atLineEnd()) {
            throw p.error(p.pos, "unexpected " + p.describe(p.pos) + " after the arguments of tag '" + name + "'" + argsSay);
        }

        switch (name) {
            case "crease" -> {
                for (int i = 0; i < ni; i += 2) {
                    float s = floats[nf == 1 ? 0 : i / 2];
                    creases.add(new TagIndex(ints[i], intLine[i], intColumn[i]));
                    creases.add(new TagIndex(ints[i + 1], intLine[i + 1], intColumn[i + 1]));
                    creaseSharpness.add(s);
                }
            }
            case "corner" -> {
                for (int i = 0; i < ni; i++) {
                    corners.add(new TagIndex(ints[i], intLine[i], intColumn[i]));
                    cornerSharpness.add(floats[nf == 1 ? 0 : i]);
                }
            }
            case "hole" -> {
                for (int i = 0; i < ni; i++) holes.add(new TagIndex(ints[i], intLine[i], intColumn[i]));
            }
            case "interpolateboundary" -> {
                SubdivOptions.Boundary[] modes = {SubdivOptions.Boundary.NONE, SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.Boundary.EDGE_ONLY};
                long v = ints[0];
                if (v < 0 || v > 2) {
                    throw new SceneException(file, intLine[0], intColumn[0],
                            "expected 0 (none), 1 (edge and corner) or 2 (edge only) for tag 'interpolateboundary', found " + v);
                }
                options = options.withBoundary(modes[(int) v]);
            }
            case "facevaryinginterpolateboundary" -> {
                SubdivOptions.FaceVarying[] modes = SubdivOptions.FaceVarying.values();
                long v = ints[0];
                if (v < 0 || v >= modes.length) {
                    throw new SceneException(file, intLine[0], intColumn[0],
                            "expected 0 (none), 1 (corners only), 2 (corners plus1), 3 (corners plus2), 4 (boundaries) or 5 (all)"
                                    + " for tag 'facevaryinginterpolateboundary', found " + v);
                }
                options = options.withFaceVarying(modes[(int) v]);
            }
            case "creasemethod" -> {
                options = options.withCreasing(switch (strings[0]) {
                    case "normal" -> SubdivOptions.Creasing.UNIFORM;
                    case "chaikin" -> SubdivOptions.Creasing.CHAIKIN;
                    default -> throw p.error(stringAt[0], "expected normal or chaikin for tag 'creasemethod', found " + MessageText.quote(strings[0])
                            + SceneGrammar.didYouMean(strings[0], List.of("normal", "chaikin")));
                });
            }
            case "smoothtriangles" -> {
                options = options.withTriangles(switch (strings[0]) {
                    case "catmark" -> SubdivOptions.Triangles.CATMARK;
                    case "smooth" -> SubdivOptions.Triangles.SMOOTH;
                    default -> throw p.error(stringAt[0], "expected catmark or smooth for tag 'smoothtriangles', found " + MessageText.quote(strings[0])
                            + SceneGrammar.didYouMean(strings[0], List.of("catmark", "smooth")));
                });
            }
            case "scheme" -> {
                SubdivOptions.Scheme s = SubdivOptions.Scheme.ofKeyword(strings[0]);
                if (s == null) {
                    throw p.error(stringAt[0], "expected catmark, loop or bilinear for tag 'scheme', found " + MessageText.quote(strings[0])
                            + SceneGrammar.didYouMean(strings[0], List.of("catmark", "loop", "bilinear")));
                }
                options = options.withScheme(s);
            }
            default -> {
                if (!ignored.contains(name)) ignored.add(name);
            }
        }
    }

    /** The next length of an argument array that is full at {@code length} of {@code count}. */
    private static int grown(int length, int count) {
        return (int) Math.min(count, 2L * length);
    }

    /** "nints/nfloats/nstrings": three counts from 0, separated by slashes. */
    private static int[] counts(ObjParser p, String name) {
        byte[] b = p.b;
        int start = p.pos, end = p.end, pos = start;
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
        p.pos = pos;
        if (counts == null || !p.atTokenEnd()) {
            p.pos = start;
            throw p.error(start, "expected the argument counts nints/nfloats/nstrings (such as 2/1/0) after 't " + name + "', found " + p.describe(start));
        }
        return counts;
    }

    /** A decimal integer argument of a tag. */
    private static long integer(ObjParser p, String name, String what) {
        int start = p.pos;
        if (p.atLineEnd()) throw p.error(start, "expected " + what + " of tag '" + name + "', found " + p.describe(start));
        byte[] b = p.b;
        int end = p.end, pos = start;
        boolean neg = false;
        if (b[pos] == '-' || b[pos] == '+') neg = b[pos++] == '-';
        long v = 0;
        int digits = 0;
        while (pos < end && b[pos] >= '0' && b[pos] <= '9') {
            if (v < 1L << 40) v = v * 10 + (b[pos] - '0');
            digits++;
            pos++;
        }
        p.pos = pos;
        if (digits == 0 || !p.atTokenEnd()) {
            p.pos = start;
            throw p.error(start, "expected " + what + " of tag '" + name + "', found " + p.describe(start));
        }
        return neg ? -v : v;
    }

    private static String plural(int n, String word) {
        return n + " " + word + (n == 1 ? "" : "s");
    }

    /** The tags read, their indices checked against the whole file's vertices, faces and edges. */
    SubdivTags resolve(MeshData mesh) {
        int nv = mesh.vertexCount(), nf = mesh.faceCount();
        int[] creases = new int[this.creases.size()];
        Set<Long> edges = null;
        for (int i = 0; i < creases.length; i += 2) {
            TagIndex a = this.creases.get(i), c = this.creases.get(i + 1);
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
        int[] corners = new int[this.corners.size()];
        for (int i = 0; i < corners.length; i++) corners[i] = checkIndex(this.corners.get(i), nv, "corner vertex", "vertices");
        int[] holes = new int[this.holes.size()];
        for (int i = 0; i < holes.length; i++) holes[i] = checkIndex(this.holes.get(i), nf, "hole face", "faces");
        float[] cs = new float[this.creaseSharpness.size()], ks = new float[this.cornerSharpness.size()];
        for (int i = 0; i < cs.length; i++) cs[i] = this.creaseSharpness.get(i);
        for (int i = 0; i < ks.length; i++) ks[i] = this.cornerSharpness.get(i);
        return new SubdivTags(creases, cs, corners, ks, holes, options, ignored);
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
}
