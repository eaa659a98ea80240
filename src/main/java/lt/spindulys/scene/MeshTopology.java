package lt.spindulys.scene;

import java.util.Arrays;

import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;

/**
 * The structural checks of a mesh: that polygon data is consistent (face sizes, index ranges,
 * finite positions) before it is triangulated, and the edge census of indexed triangles (three
 * position indices per triangle in {@code tri}, x, y, z per position in {@code pos}) that says
 * whether they close a solid. Vertices at the same position are welded into one for the census,
 * so a mesh whose file repeats a position (split at a texture seam, say) still counts as closed:
 * the watertight ray test sees such copies as the same point.
 */
final class MeshTopology {
    private MeshTopology() {}

    /**
     * Checks {@code d} before it is triangulated; messages start with its source.
     *
     * @throws IllegalArgumentException if the arrays are inconsistent, an index is out of range or a position is not finite
     */
    static void validate(MeshData d) {
        String w = d.source() == null ? "mesh: " : d.source() + ": ";
        double[] p = d.positions();
        if (p == null || p.length % 3 != 0) throw new IllegalArgumentException(w + "positions must hold three numbers per vertex");
        for (double v : p) if (!Ranges.isModest(v)) throw new IllegalArgumentException(w + "vertex positions must be finite and at most " + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude, found " + v);
        int[] sizes = d.faceSizes(), vi = d.vertexIndex();
        long corners = 0;
        for (int f = 0; f < sizes.length; f++) {
            if (sizes[f] < 3) throw new IllegalArgumentException(w + "face " + (f + 1) + " has " + sizes[f] + " vertices, expected at least 3");
            corners += sizes[f];
        }
        if (corners != vi.length) throw new IllegalArgumentException(w + "face sizes add up to " + corners + " corners but there are " + vi.length + " vertex indices");
        checkIndices(w, "vertex", vi, p.length / 3, false);
        checkOptional(w, "normal", d.normalIndex(), d.normals(), vi.length);
        checkOptional(w, "texture coordinate", d.uvIndex(), d.uvs(), vi.length);
        if (d.uvs() != null && d.uvs().length % 2 != 0) throw new IllegalArgumentException(w + "texture coordinates must hold two numbers each");
        checkGroups(w, d.faceGroups(), d.groupNames(), sizes.length);
    }

    /** Face groups: one per face, each -1 or a name's index; names given exactly when groups are. */
    static void checkGroups(String w, int[] groups, String[] names, int faces) {
        if ((groups == null) != (names == null)) throw new IllegalArgumentException(w + "face groups and group names must be given together");
        if (groups == null) return;
        if (groups.length != faces) throw new IllegalArgumentException(w + groups.length + " face groups for " + faces + " faces");
        if (names.length > MeshData.MAX_GROUPS) throw new IllegalArgumentException(w + names.length + " face groups, more than the " + MeshData.MAX_GROUPS + " allowed");
        for (int f = 0; f < faces; f++) {
            if (groups[f] < -1 || groups[f] >= names.length) {
                throw new IllegalArgumentException(w + "face " + (f + 1) + " has group " + groups[f] + ", but there are " + names.length + " groups");
            }
        }
    }

    private static void checkOptional(String w, String what, int[] index, double[] values, int corners) {
        if (index == null) return;
        if (index.length != corners) throw new IllegalArgumentException(w + what + " indices: " + index.length + " for " + corners + " corners");
        int stride = what.equals("normal") ? 3 : 2;
        checkIndices(w, what, index, values == null ? 0 : values.length / stride, true);
    }

    private static void checkIndices(String w, String what, int[] index, int count, boolean optional) {
        for (int i = 0; i < index.length; i++) {
            int v = index[i];
            if (v >= count || v < (optional ? -1 : 0)) {
                throw new IllegalArgumentException(w + what + " index " + v + " at corner " + i + " is out of range (there are " + count + ")");
            }
        }
    }

    /** True if every undirected edge of the triangles, vertices welded by position, is used by exactly two of them. */
    static boolean everyEdgeTwice(int[] tri, int triangleCount, double[] pos) {
        return edgeUse(tri, triangleCount, pos, true) == 0;
    }

    /**
     * Edges used by exactly one triangle, vertices welded by position: the edges along the holes
     * of an open mesh (0 for a closed one; an edge shared by three or more triangles also keeps a
     * mesh from being closed but is not a boundary edge).
     */
    static int boundaryEdgeCount(int[] tri, int triangleCount, double[] pos) {
        return edgeUse(tri, triangleCount, pos, false);
    }

    /**
     * The one edge census behind {@link #everyEdgeTwice} and {@link #boundaryEdgeCount}:
     * undirected edges between welded vertices, sorted, counted by use. Returns the number of
     * edges used once; with {@code stopAtFirstBad} it returns 1 as soon as any edge is used other
     * than twice, 0 if none is.
     */
    private static int edgeUse(int[] tri, int triangleCount, double[] pos, boolean stopAtFirstBad) {
        int[] id = weld(pos);
        long[] keys = new long[3 * triangleCount];
        for (int t = 0; t < triangleCount; t++) {
            for (int e = 0; e < 3; e++) {
                int a = id[tri[3 * t + e]], b = id[tri[3 * t + (e + 1) % 3]];
                keys[3 * t + e] = ((long) Math.min(a, b) << 32) | Math.max(a, b);
            }
        }
        Arrays.parallelSort(keys); // millions of edges on large meshes; the sorted result is the same
        int once = 0;
        for (int i = 0; i < keys.length; ) {
            int j = i + 1;
            while (j < keys.length && keys[j] == keys[i]) j++;
            if (j - i != 2 && stopAtFirstBad) return 1;
            if (j - i == 1) once++;
            i = j;
        }
        return once;
    }

    /** For each vertex, the lowest index of a vertex at the same position (open-addressing hash). */
    static int[] weld(double[] p) {
        int n = p.length / 3;
        int cap = 16;
        while (cap < 2 * n) cap <<= 1;
        int mask = cap - 1;
        int[] table = new int[cap];
        Arrays.fill(table, -1);
        int[] id = new int[n];
        for (int v = 0; v < n; v++) {
            double x = p[3 * v], y = p[3 * v + 1], z = p[3 * v + 2];
            // + 0.0 turns -0.0 into 0.0, which compare equal and must hash alike.
            long h = Double.doubleToLongBits(x + 0.0) * 0x9E3779B97F4A7C15L
                    ^ Double.doubleToLongBits(y + 0.0) * 0xC2B2AE3D27D4EB4FL
                    ^ Double.doubleToLongBits(z + 0.0) * 0x165667B19E3779F9L;
            int slot = (int) (h ^ (h >>> 29) ^ (h >>> 47)) & mask;
            while (true) {
                int u = table[slot];
                if (u < 0) {
                    table[slot] = v;
                    id[v] = v;
                    break;
                }
                if (p[3 * u] == x && p[3 * u + 1] == y && p[3 * u + 2] == z) {
                    id[v] = u;
                    break;
                }
                slot = (slot + 1) & mask;
            }
        }
        return id;
    }
}

