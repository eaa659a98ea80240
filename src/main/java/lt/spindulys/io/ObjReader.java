package lt.spindulys.io;

import static lt.spindulys.io.ObjParser.INHERIT;
import static lt.spindulys.io.ObjParser.NORMAL;
import static lt.spindulys.io.ObjParser.UV;
import static lt.spindulys.io.ObjParser.VERTEX;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.limits.PartThreads;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.SubdivInput;
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
        return new ObjParser(readBytes(file), file.toString(), true).parseSubdiv();
    }

    /**
     * Parses OBJ text as a subdivision control mesh; see {@link #readSubdiv}.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @return the control mesh and its tags
     */
    public static SubdivInput parseSubdiv(String text, String fileName) {
        return new ObjParser(text.getBytes(StandardCharsets.UTF_8), fileName, true).parseSubdiv();
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
        ObjParser p = new ObjParser(readBytes(file), file.toString(), true);
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
            ObjParser p = new ObjParser(bytes, fileName, false);
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

    /** Longest usemtl name or mtllib file name, in bytes. */
    static final int MAX_NAME = 4096;
    /** Most mtllib file names in one OBJ file. */
    static final int MAX_LIBRARIES = 1024;

    /**
     * A large file parsed in chunks on several threads and merged in file order. Each chunk is
     * parsed on its own ({@link ObjParser#deferred}); the merge checks each chunk's indices against
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
        private final ObjParser[] parsed;
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
            this.parsed = new ObjParser[starts.length - 1];
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
                ObjParser p = new ObjParser(b, starts[k], starts[k + 1], 1, file, false, true);
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
                ObjParser p = parsed[k];
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
            for (ObjParser p : parsed) anyGroups |= p.faceGroup != null;
            int[] groups = anyGroups ? new int[(int) faces] : null;
            List<String> names = new ArrayList<>();
            java.util.Map<String, Integer> index = new java.util.HashMap<>();
            List<Ref> groupRefs = new ArrayList<>(), libraries = new ArrayList<>();
            int current = -1;
            for (int k = 0; k < chunks; k++) {
                ObjParser p = parsed[k];
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
        private static void resolve(int[] index, int chunkStart, BlockList.Ints corners, int base) {
            if (corners.size() == 0) return;
            for (int c : corners.toArray()) index[chunkStart + c] += base;
        }

        /** The error of chunk k, found by parsing from its start as the whole file's parser would. */
        private SceneException failure(int k, int[] counts, int line) {
            ObjParser p = new ObjParser(b, starts[k], b.length, line, file, false, false);
            System.arraycopy(counts, 0, p.base, 0, 3);
            try {
                p.statements();
            } catch (SceneException e) {
                return e;
            }
            throw new IllegalStateException("chunk " + k + " of " + file + " failed alone but not in order");
        }
    }
}
