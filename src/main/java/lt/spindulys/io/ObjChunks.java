package lt.spindulys.io;

import static lt.spindulys.io.ObjParser.INHERIT;
import static lt.spindulys.io.ObjParser.NORMAL;
import static lt.spindulys.io.ObjParser.UV;
import static lt.spindulys.io.ObjParser.VERTEX;
import static lt.spindulys.io.ObjReader.MAX_LIBRARIES;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

import lt.spindulys.io.BlockList.Ints;
import lt.spindulys.io.ObjReader.Read;
import lt.spindulys.io.ObjReader.Ref;
import lt.spindulys.limits.PartThreads;
import lt.spindulys.mesh.MeshData;

/**
 * A large file parsed in chunks on several threads and merged in file order. Each chunk is
 * parsed on its own ({@link ObjParser#deferred}); the merge checks each chunk's indices against
 * the counts before it, adds those counts to its negative indices, and copies the arrays into
 * the mesh's. A chunk that failed, or whose indices reach past the file so far, is parsed
 * again as the whole file's parser would reach it (same line, same counts), which throws the
 * same error at the same place: the first failing chunk's, as a sequential parse would.
 */
final class ObjChunks {
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

    ObjChunks(byte[] bytes, String file, int[] starts) {
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
    private static void resolve(int[] index, int chunkStart, Ints corners, int base) {
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
