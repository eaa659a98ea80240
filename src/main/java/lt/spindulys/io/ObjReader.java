package lt.spindulys.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.atomic.AtomicInteger;

import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.limits.PartThreads;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivTags;

/**
 * Reads Wavefront OBJ meshes: {@code v} (x y z, an optional w and an optional r g b colour are
 * ignored), {@code vn}, {@code vt} (u, optional v and w), and {@code f} with polygons of any size
 * whose corners are {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn}, indices counted
 * from 1 or, when negative, back from the latest element. {@code usemtl NAME} starts a face group
 * (faces until the next {@code usemtl} belong to it; the name is the rest of the line), recorded in
 * {@link MeshData#faceGroups()}; {@code mtllib} names the material libraries (several file names
 * allowed), kept for the scene to read ({@link #readMesh}). {@code o}, {@code g}, {@code s} and
 * OpenSubdiv's {@code t} tags are skipped; {@code #} starts a comment; a backslash at the end of a
 * line continues it. Anything else is an error.
 *
 * <p>{@link #readSubdiv} reads the same files as the control mesh of a subdivision surface: then the
 * {@code t} tags are parsed (OpenSubdiv's grammar {@code t name nints/nfloats/nstrings ints...
 * floats... strings...}; see docs/mesh-formats.md) into {@link SubdivTags}, every index checked
 * against the mesh, and texture coordinates must be on every face or none.
 *
 * <p>The file is read as bytes and parsed in place, numbers by hand (exactly rounded: the fast
 * path is taken only where it is exact, other numbers go to {@link Double#parseDouble}), with no
 * allocation per token, because meshes run to tens of millions of numbers. A file of
 * {@link #PARALLEL_BYTES} or more is read and parsed in chunks on up to {@link #MAX_THREADS}
 * threads and merged in file order: the mesh, and every error with its line and column, are the
 * same as parsed in one piece. Errors are {@link SceneException}s naming the file, line and
 * column of the offending token.
 */
public final class ObjReader {
    private ObjReader() {}

    /**
     * Reads the file; malformed input throws {@link SceneException} naming file:line:column.
     *
     * @param file the file
     * @return the mesh
     * @throws IOException if the file cannot be read
     */
    public static MeshData read(Path file) throws IOException {
        return parse(readBytes(file), file.toString());
    }

    /**
     * Parses OBJ text; {@code fileName} is used in messages and as the mesh's source.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @return the mesh
     */
    public static MeshData parse(String text, String fileName) {
        return parse(text.getBytes(StandardCharsets.UTF_8), fileName);
    }

    /**
     * Reads the file as a subdivision control mesh with its {@code t} tags; malformed input,
     * unknown tags and tag indices that do not fit the mesh throw {@link SceneException} naming
     * file:line:column.
     *
     * @param file the file
     * @return the control mesh and its tags
     * @throws IOException if the file cannot be read
     */
    public static SubdivInput readSubdiv(Path file) throws IOException {
        return new Parser(readBytes(file), file.toString(), true).parseSubdiv();
    }

    /**
     * Parses OBJ text as a subdivision control mesh; see {@link #readSubdiv}.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @return the control mesh and its tags
     */
    public static SubdivInput parseSubdiv(String text, String fileName) {
        return new Parser(text.getBytes(StandardCharsets.UTF_8), fileName, true).parseSubdiv();
    }

    /** A name the file gives at a place (an mtllib file name, a usemtl name), for the scene's messages. */
    record Ref(String name, int line, int column) {}

    /**
     * An OBJ file read with what it says about materials: the mesh (its face groups are the
     * usemtl names), its tags when read as a subdivision control mesh (else null), the mtllib
     * file names in the order given, and per face group the place of its first usemtl.
     */
    record Read(MeshData mesh, SubdivInput subdiv, List<Ref> libraries, List<Ref> groups) {}

    /**
     * {@link #read}, with the mtllib and usemtl statements' places for the scene to resolve.
     *
     * @param file the file
     * @return the mesh and its material references
     * @throws IOException if the file cannot be read
     */
    static Read readMesh(Path file) throws IOException {
        byte[] bytes = readBytes(file);
        int chunks = bytes.length < PARALLEL_BYTES ? 1 : (int) Math.min(MAX_CHUNKS, (bytes.length + CHUNK_BYTES - 1) / CHUNK_BYTES);
        return read(bytes, file.toString(), chunks, parseThreads());
    }

    /**
     * {@link #readSubdiv}, with the mtllib and usemtl statements' places for the scene to resolve.
     *
     * @param file the file
     * @return the control mesh, its tags and its material references
     * @throws IOException if the file cannot be read
     */
    static Read readSubdivision(Path file) throws IOException {
        Parser p = new Parser(readBytes(file), file.toString(), true);
        SubdivInput in = p.parseSubdiv();
        return new Read(in.mesh(), in, List.copyOf(p.libraries), p.groupRefs());
    }

    /** Parses a file's bytes as {@link #read} does after reading them: in chunks on several threads when the file is large. */
    static MeshData parse(byte[] bytes, String fileName) {
        int chunks = bytes.length < PARALLEL_BYTES ? 1 : (int) Math.min(MAX_CHUNKS, (bytes.length + CHUNK_BYTES - 1) / CHUNK_BYTES);
        return parse(bytes, fileName, chunks, parseThreads());
    }

    /** Files smaller than this are parsed on the caller's thread in one piece: threads would cost more than they save. */
    static final int PARALLEL_BYTES = 4 << 20;
    /** The size of a chunk: small enough that threads share the work evenly, large enough that merging is cheap. */
    static final int CHUNK_BYTES = 4 << 20;
    private static final int MAX_CHUNKS = 1024;
    /** Parse threads at most: reading memory, more would wait on each other. */
    static final int MAX_THREADS = 4;

    private static int parseThreads() {
        return Math.max(1, Math.min(MAX_THREADS, Runtime.getRuntime().availableProcessors()));
    }

    /**
     * Parses in {@code chunks} pieces (about equal, split at line starts) on up to {@code threads}
     * threads, the caller's included. The mesh and every message are the same for any number of
     * chunks and threads.
     */
    static MeshData parse(byte[] bytes, String fileName, int chunks, int threads) {
        return read(bytes, fileName, chunks, threads).mesh();
    }

    /** {@link #parse(byte[], String, int, int)} with the material references. */
    static Read read(byte[] bytes, String fileName, int chunks, int threads) {
        int[] starts = ChunkedParse.split(bytes, chunks);
        if (starts.length == 2) {
            Parser p = new Parser(bytes, fileName, false);
            MeshData m = p.parse();
            return new Read(m, null, List.copyOf(p.libraries), p.groupRefs());
        }
        return new ChunkedParse(bytes, fileName, starts).run(threads);
    }

    /** The file's bytes, read on the parse threads; a missing, special or too large file is a {@link SceneException}. */
    static byte[] readBytes(Path file) throws IOException {
        String name = file.toString();
        // A pipe would block and a device never end: only regular files are opened.
        String problem = InputFiles.problem(file);
        if (problem != null) {
            throw new SceneException(name, 0, 0, "OBJ file " + problem + " (looked in " + file.toAbsolutePath().normalize() + ")");
        }
        try {
            // The parser works on the bytes in place; what it builds is checked as it grows.
            return InputFiles.readAllBytes(file, "OBJ file", 1, parseThreads());
        } catch (InsufficientMemoryException e) {
            throw new SceneException(name, 0, 0, e.getMessage(), e);
        } catch (NoSuchFileException e) {
            throw new SceneException(name, 0, 0, "OBJ file not found (looked in " + file.toAbsolutePath().normalize() + ")");
        } catch (IOException e) {
            throw new SceneException(name, 0, 0, "cannot read OBJ file: " + e.getMessage(), e);
        }
    }

    /** First block of a growable array; blocks double up to {@link #MAX_BLOCK} elements. */
    private static final int FIRST_BLOCK = 1024, MAX_BLOCK = 1 << 16;

    /**
     * Growable primitive arrays as a list of blocks: one allocation per block, none per element,
     * and nothing is copied until the exact-size array is made (a doubling array copies each
     * element about twice more, and the garbage it leaves is as large as the mesh).
     */
    private abstract static class BlockList<A> {
        /** The filled blocks (primitive arrays), in order. */
        private Object[] blocks = new Object[8];
        private int full, before;

        /** A new block of the given length. */
        abstract A block(int length);

        /** Keeps the filled block and returns the next, empty one. */
        final A next(A filled, int length) {
            if (full == blocks.length) blocks = Arrays.copyOf(blocks, 2 * full);
            blocks[full++] = filled;
            before += length;
            return block(Math.min(MAX_BLOCK, 2 * length));
        }

        /** Elements added: those of the filled blocks and {@code n} of the current one. */
        final int size(int n) { return before + n; }

        /** Copies the elements into {@code to} from {@code at}: the filled blocks, then n of {@code cur}. */
        final void copyTo(A cur, int n, A to, int at) {
            for (int i = 0; i < full; i++) {
                int len = java.lang.reflect.Array.getLength(blocks[i]);
                System.arraycopy(blocks[i], 0, to, at, len);
                at += len;
            }
            System.arraycopy(cur, 0, to, at, n);
        }
    }

    /** A growable array of doubles (see {@link BlockList}). */
    private static final class Doubles extends BlockList<double[]> {
        private double[] cur = new double[FIRST_BLOCK];
        private int n;

        @Override double[] block(int length) { return new double[length]; }

        void add(double v) {
            if (n == cur.length) {
                cur = next(cur, cur.length);
                n = 0;
            }
            cur[n++] = v;
        }

        int size() { return size(n); }

        void copyTo(double[] to, int at) { copyTo(cur, n, to, at); }

        double[] toArray() {
            double[] a = new double[size()];
            copyTo(a, 0);
            return a;
        }
    }

    /** A growable array of ints (see {@link BlockList}). */
    private static final class Ints extends BlockList<int[]> {
        private int[] cur = new int[FIRST_BLOCK];
        private int n;

        @Override int[] block(int length) { return new int[length]; }

        void add(int v) {
            if (n == cur.length) {
                cur = next(cur, cur.length);
                n = 0;
            }
            cur[n++] = v;
        }

        int size() { return size(n); }

        void copyTo(int[] to, int at) { copyTo(cur, n, to, at); }

        int[] toArray() {
            int[] a = new int[size()];
            copyTo(a, 0);
            return a;
        }
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

        /**
         * A chunk after the first, parsed before the counts of the elements before it are known:
         * indices are not checked against the counts but remembered ({@link #need}, {@link #relative}),
         * and checked and resolved when the chunks are merged.
         */
        private final boolean deferred;
        /** Vertices, texture coordinates and normals in the file before {@link #pos}'s chunk (0 for a whole file). */
        private final int[] base = new int[3];
        /** Deferred: per kind, the most elements before the chunk that an index needs (valid if the base is at least this). */
        private final long[] need = {Long.MIN_VALUE, Long.MIN_VALUE, Long.MIN_VALUE};
        /** Deferred: per kind, the corners whose negative index was resolved against this chunk alone (the base is added in the merge). */
        private final Ints[] relative;

        private final Doubles positions = new Doubles(), normals = new Doubles(), uvs = new Doubles();
        private final Ints faceSizes = new Ints(), vertexIndex = new Ints(), normalIndex = new Ints(), uvIndex = new Ints();
        private boolean anyNormalIndex, anyUvIndex;

        /** Reading a subdivision control mesh: parse {@code t} tags, require UVs on all faces or none. */
        private final boolean subdiv;
        /** Line of the first face, and whether it has texture coordinates (subdiv mode). */
        private int firstFaceLine;
        private boolean firstFaceUv;
        private final TagCollector tags = new TagCollector();

        /** The usemtl names in order of first use (a face group each), and each one's index. */
        private final List<String> groupNames = new ArrayList<>();
        private final java.util.Map<String, Integer> groupIndex = new java.util.HashMap<>();
        /** Line and column of each group's first usemtl (line counted in this parser's part of the file). */
        private final Ints groupLine = new Ints(), groupColumn = new Ints();
        /** Group per face; null until the first usemtl (then filled for the faces before it). */
        private Ints faceGroup;
        /** The group of the faces being read: -1 before any usemtl, {@link #INHERIT} in a deferred chunk before its first. */
        private int currentGroup;
        /** The mtllib file names, in order. */
        private final List<Ref> libraries = new ArrayList<>();

        Parser(byte[] bytes, String file, boolean subdiv) {
            this(bytes, 0, bytes.length, 1, file, subdiv, false);
        }

        /** Parses bytes {@code from..to}, starting on line {@code firstLine}; {@code from} must start a line. */
        Parser(byte[] bytes, int from, int to, int firstLine, String file, boolean subdiv, boolean deferred) {
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
    }

    /** The group of a deferred chunk's faces before its first usemtl: the group the chunks before it end in. */
    private static final int INHERIT = -2;
    /** Longest usemtl name or mtllib file name, in bytes. */
    static final int MAX_NAME = 4096;
    /** Most mtllib file names in one OBJ file. */
    static final int MAX_LIBRARIES = 1024;

    /** Index kinds, for {@link Parser#base} and the deferred checks. */
    private static final int VERTEX = 0, UV = 1, NORMAL = 2;

    /**
     * A large file parsed in chunks on several threads and merged in file order. Each chunk is
     * parsed on its own ({@link Parser#deferred}); the merge checks each chunk's indices against
     * the counts before it, adds those counts to its negative indices, and copies the arrays into
     * the mesh's. A chunk that failed, or whose indices reach past the file so far, is parsed
     * again as the whole file's parser would reach it (same line, same counts), which throws the
     * same error at the same place: the first failing chunk's, as a sequential parse would.
     */
    static final class ChunkedParse {
        private final byte[] b;
        private final String file;
        /** Chunk k is bytes starts[k]..starts[k + 1]. */
        private final int[] starts;
        private final Parser[] parsed;
        /** The first chunk that failed (no chunk after it is started), or the chunk count. */
        private final AtomicInteger failedAt;
        private final AtomicInteger nextChunk = new AtomicInteger();
        /**
         * The order in which chunks are taken: spread over the file first (0, n/2, n/4, 3n/4, ...)
         * so that every kind of statement is met, and compiled for, early. Files often hold all
         * vertices, then all texture coordinates, then all faces; in file order, the compiled
         * parse loop was thrown away and compiled again as each kind first appeared.
         */
        private final int[] order;

        ChunkedParse(byte[] bytes, String file, int[] starts) {
            this.b = bytes;
            this.file = file;
            this.starts = starts;
            this.parsed = new Parser[starts.length - 1];
            this.failedAt = new AtomicInteger(parsed.length);
            this.order = spread(parsed.length);
        }

        /** 0..n-1, multiples of the largest power of two first, then of each smaller one. */
        static int[] spread(int n) {
            int[] order = new int[n];
            boolean[] taken = new boolean[n];
            int m = 0;
            for (int step = Integer.highestOneBit(Math.max(1, n)); step >= 1; step >>= 1) {
                for (int k = 0; k < n; k += step) {
                    if (!taken[k]) {
                        taken[k] = true;
                        order[m++] = k;
                    }
                }
            }
            return order;
        }

        /**
         * Chunk starts for about {@code chunks} equal chunks, and the file's length last: each
         * start follows a line break that does not continue a statement (a backslash before it).
         */
        static int[] split(byte[] b, int chunks) {
            int[] starts = new int[Math.max(1, chunks) + 1];
            int n = 1;
            for (int k = 1; k < chunks; k++) {
                int at = Math.max(starts[n - 1] + 1, (int) ((long) b.length * k / chunks));
                while (at < b.length && !startsStatement(b, at)) at++;
                if (at >= b.length) break;
                starts[n++] = at;
            }
            starts[n++] = b.length;
            return Arrays.copyOf(starts, n);
        }

        /** Whether a statement starts at {@code at}: just after a '\n' that ends a line not continued by a backslash. */
        private static boolean startsStatement(byte[] b, int at) {
            if (b[at - 1] != '\n') return false;
            int lineEnd = at >= 2 && b[at - 2] == '\r' ? at - 2 : at - 1;
            return lineEnd == 0 || b[lineEnd - 1] != '\\';
        }

        Read run(int threads) {
            PartThreads.run(Math.max(1, Math.min(threads, parsed.length)), "spindulys-obj-parse", k -> {
                try {
                    work();
                } catch (RuntimeException | Error e) {
                    failedAt.set(-1); // the others stop at their next chunk
                    throw e;
                }
            });
            return merge();
        }

        /** Parses chunks in {@link #order} as they come, skipping those after a chunk that failed. */
        private void work() {
            for (int i; (i = nextChunk.getAndIncrement()) < order.length;) {
                int k = order[i];
                if (k >= failedAt.get()) continue;
                Parser p = new Parser(b, starts[k], starts[k + 1], 1, file, false, true);
                try {
                    p.statements();
                    parsed[k] = p;
                } catch (SceneException e) {
                    failedAt.accumulateAndGet(k, Math::min);
                }
            }
        }

        private Read merge() {
            int chunks = parsed.length;
            int[][] base = new int[chunks + 1][3];
            int[] firstLine = new int[chunks + 1];
            firstLine[0] = 1;
            long positions = 0, normals = 0, uvs = 0, faces = 0, corners = 0;
            boolean anyNormalIndex = false, anyUvIndex = false;
            for (int k = 0; k < chunks; k++) {
                Parser p = parsed[k];
                int[] at = base[k];
                if (p == null || p.need[VERTEX] > at[VERTEX] || p.need[UV] > at[UV] || p.need[NORMAL] > at[NORMAL]) {
                    throw failure(k, at, firstLine[k]);
                }
                base[k + 1][VERTEX] = at[VERTEX] + p.positions.size() / 3;
                base[k + 1][UV] = at[UV] + p.uvs.size() / 2;
                base[k + 1][NORMAL] = at[NORMAL] + p.normals.size() / 3;
                firstLine[k + 1] = firstLine[k] + p.line - 1;
                positions += p.positions.size();
                normals += p.normals.size();
                uvs += p.uvs.size();
                faces += p.faceSizes.size();
                corners += p.vertexIndex.size();
                anyNormalIndex |= p.anyNormalIndex;
                anyUvIndex |= p.anyUvIndex;
            }
            // Each chunk's arrays are under 2^31 elements; so are the file's, which has fewer numbers than bytes.
            double[] pos = new double[(int) positions], nor = normals > 0 ? new double[(int) normals] : null, uv = uvs > 0 ? new double[(int) uvs] : null;
            int[] sizes = new int[(int) faces], vi = new int[(int) corners];
            int[] ni = anyNormalIndex ? new int[(int) corners] : null, ti = anyUvIndex ? new int[(int) corners] : null;
            int p0 = 0, n0 = 0, t0 = 0, f0 = 0, c0 = 0;
            boolean anyGroups = false;
            for (Parser p : parsed) anyGroups |= p.faceGroup != null;
            int[] groups = anyGroups ? new int[(int) faces] : null;
            List<String> names = new ArrayList<>();
            java.util.Map<String, Integer> index = new java.util.HashMap<>();
            List<Ref> groupRefs = new ArrayList<>(), libraries = new ArrayList<>();
            int current = -1;
            for (int k = 0; k < chunks; k++) {
                Parser p = parsed[k];
                parsed[k] = null;
                // Groups: the chunk's names numbered as the whole file numbers them (by first use),
                // its faces before its first usemtl in the group the chunks before it end in.
                int lineOffset = firstLine[k] - 1;
                int[] global = new int[p.groupNames.size()];
                List<Ref> local = p.groupRefs();
                for (int g = 0; g < global.length; g++) {
                    Ref r = local.get(g);
                    Integer gi = index.get(r.name());
                    if (gi == null) {
                        if (names.size() == MeshData.MAX_GROUPS) {
                            throw new SceneException(file, r.line() + lineOffset, r.column(), "more than " + MeshData.MAX_GROUPS + " different usemtl names in one file");
                        }
                        gi = names.size();
                        names.add(r.name());
                        index.put(r.name(), gi);
                        groupRefs.add(new Ref(r.name(), r.line() + lineOffset, r.column()));
                    }
                    global[g] = gi;
                }
                for (Ref r : p.libraries) {
                    if (libraries.size() == MAX_LIBRARIES) {
                        throw new SceneException(file, r.line() + lineOffset, r.column(), "more than " + MAX_LIBRARIES + " material libraries in one file");
                    }
                    libraries.add(new Ref(r.name(), r.line() + lineOffset, r.column()));
                }
                if (groups != null) {
                    int nf = p.faceSizes.size();
                    if (p.faceGroup == null) {
                        Arrays.fill(groups, f0, f0 + nf, current);
                    } else {
                        p.faceGroup.copyTo(groups, f0);
                        for (int f = f0; f < f0 + nf; f++) groups[f] = groups[f] == INHERIT ? current : global[groups[f]];
                    }
                }
                if (p.currentGroup != INHERIT) current = global[p.currentGroup];
                p.positions.copyTo(pos, p0);
                if (nor != null) p.normals.copyTo(nor, n0);
                if (uv != null) p.uvs.copyTo(uv, t0);
                p.faceSizes.copyTo(sizes, f0);
                p.vertexIndex.copyTo(vi, c0);
                resolve(vi, c0, p.relative[VERTEX], base[k][VERTEX]);
                if (ni != null) {
                    p.normalIndex.copyTo(ni, c0);
                    resolve(ni, c0, p.relative[NORMAL], base[k][NORMAL]);
                }
                if (ti != null) {
                    p.uvIndex.copyTo(ti, c0);
                    resolve(ti, c0, p.relative[UV], base[k][UV]);
                }
                p0 += p.positions.size();
                n0 += p.normals.size();
                t0 += p.uvs.size();
                f0 += p.faceSizes.size();
                c0 += p.vertexIndex.size();
            }
            MeshData mesh = new MeshData(pos, nor, uv, sizes, vi, ni, ti, file, groups, groups != null ? names.toArray(String[]::new) : null);
            return new Read(mesh, null, List.copyOf(libraries), List.copyOf(groupRefs));
        }

        /** Adds the base to the chunk's negative indices, which were counted back from its own latest element. */
        private static void resolve(int[] index, int chunkStart, Ints corners, int base) {
            if (corners.size() == 0) return;
            for (int c : corners.toArray()) index[chunkStart + c] += base;
        }

        /** The error of chunk k, found by parsing from its start as the whole file's parser would. */
        private SceneException failure(int k, int[] counts, int line) {
            Parser p = new Parser(b, starts[k], b.length, line, file, false, false);
            System.arraycopy(counts, 0, p.base, 0, 3);
            try {
                p.statements();
            } catch (SceneException e) {
                return e;
            }
            throw new IllegalStateException("chunk " + k + " of " + file + " failed alone but not in order");
        }
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
