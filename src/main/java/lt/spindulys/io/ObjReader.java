package lt.spindulys.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.List;

import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.InsufficientMemoryException;
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
    // The front: reading the file and choosing the parse. The statements are parsed by ObjParser,
    // the t tags of a control mesh by ObjTags, and a large file's chunks by ObjChunks.

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
        return read(bytes, file.toString(), chunks(bytes.length), parseThreads());
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
        return parse(bytes, fileName, chunks(bytes.length), parseThreads());
    }

    /** Files smaller than this are parsed on the caller's thread in one piece: threads would cost more than they save. */
    static final int PARALLEL_BYTES = 4 << 20;
    /** The size of a chunk: small enough that threads share the work evenly, large enough that merging is cheap. */
    static final int CHUNK_BYTES = 4 << 20;
    private static final int MAX_CHUNKS = 1024;
    /** Parse threads at most: reading memory, more would wait on each other. */
    static final int MAX_THREADS = 4;

    /** The chunks a file of {@code length} bytes is parsed in: one below {@link #PARALLEL_BYTES}, else {@link #CHUNK_BYTES} each. */
    private static int chunks(int length) {
        return length < PARALLEL_BYTES ? 1 : (int) Math.min(MAX_CHUNKS, (length + CHUNK_BYTES - 1) / CHUNK_BYTES);
    }

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
        int[] starts = ObjChunks.split(bytes, chunks);
        if (starts.length == 2) {
            ObjParser p = new ObjParser(bytes, fileName, false);
            MeshData m = p.parse();
            return new Read(m, null, List.copyOf(p.libraries), p.groupRefs());
        }
        return new ObjChunks(bytes, fileName, starts).run(threads);
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
}
