package lt.spindulys.subdiv;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;
import java.util.Objects;

import lt.spindulys.mesh.MeshData;

/**
 * A control mesh as read from a file, before it is frozen into a {@link ControlMesh}: the polygons
 * (with texture coordinates as face-varying UVs, normals unused) and the subdivision tags. The
 * {@code with*} methods make changed copies, for the settings a scene or the command line
 * overrides.
 *
 * @param mesh the polygons; where {@code uvIndex} is given, every corner has one
 * @param tags creases, corners, holes and options
 */
public record SubdivInput(MeshData mesh, SubdivTags tags) {
    /**
     * Checks that both are given.
     *
     * @param mesh the polygons
     * @param tags creases, corners, holes and options
     * @throws NullPointerException if one is null
     */
    public SubdivInput {
        Objects.requireNonNull(mesh, "mesh");
        Objects.requireNonNull(tags, "tags");
    }

    /**
     * The mesh without tags and with the default options.
     *
     * @param mesh the polygons
     * @return the input
     */
    public static SubdivInput of(MeshData mesh) {
        return new SubdivInput(mesh, SubdivTags.NONE);
    }

    /** {@return the scheme options of the tags} */
    public SubdivOptions options() { return tags.options(); }

    /**
     * A copy with other scheme options.
     *
     * @param o the options
     * @return the input
     */
    public SubdivInput withOptions(SubdivOptions o) {
        return new SubdivInput(mesh, tags.withOptions(o));
    }

    /**
     * The same mesh with face-varying UVs: (u, v) pairs and an index into them per face corner.
     *
     * @param uvs (u, v) pairs
     * @param uvIndex index of a pair per face corner
     * @return the input
     */
    public SubdivInput withUvs(double[] uvs, int[] uvIndex) {
        MeshData m = mesh;
        return new SubdivInput(new MeshData(m.positions(), m.normals(), uvs, m.faceSizes(), m.vertexIndex(), m.normalIndex(),
                uvIndex, m.source(), m.faceGroups(), m.groupNames()), tags);
    }

    /**
     * The same mesh with one (u, v) per face corner, face after face (as an unwrap file lists
     * them). Corners of one vertex with exactly the same (u, v) share a face-varying value, so
     * only real seams, where the same vertex has different UVs in different faces, split the UV
     * layout; smooth UV interpolation then behaves as it would for the same mesh with shared OBJ
     * {@code vt} indices.
     *
     * @param cornerUvs two doubles per face corner
     * @return the input
     * @throws IllegalArgumentException if there is not exactly one pair per corner
     */
    public SubdivInput withCornerUvs(double[] cornerUvs) {
        int[] vi = mesh.vertexIndex();
        if (cornerUvs.length != 2 * vi.length) {
            throw new IllegalArgumentException("expected " + vi.length + " UV pairs, one per face corner, found " + cornerUvs.length / 2.0);
        }
        Map<UvKey, Integer> ids = new HashMap<>();
        double[] uvs = new double[cornerUvs.length];
        int[] index = new int[vi.length];
        int n = 0;
        for (int c = 0; c < vi.length; c++) {
            double u = cornerUvs[2 * c], v = cornerUvs[2 * c + 1];
            // + 0.0 so that -0.0 and 0.0, which are the same coordinate, weld.
            UvKey k = new UvKey(vi[c], Double.doubleToLongBits(u + 0.0), Double.doubleToLongBits(v + 0.0));
            Integer id = ids.get(k);
            if (id == null) {
                id = n++;
                ids.put(k, id);
                uvs[2 * id] = u;
                uvs[2 * id + 1] = v;
            }
            index[c] = id;
        }
        return withUvs(Arrays.copyOf(uvs, 2 * n), index);
    }

    private record UvKey(int vertex, long u, long v) {}

    /**
     * Faces the mesh has after {@code level} uniform refinements with its scheme (see
     * {@link ControlMesh#refinedFaceCount(SubdivOptions.Scheme, int, long, int)}). For refusing
     * levels too deep for memory.
     *
     * @param level refinements, at least 0
     * @return the face count; past 2^60 it stops growing (already far too many)
     */
    public long refinedFaceCount(int level) {
        return ControlMesh.refinedFaceCount(tags.options().scheme(), mesh.faceCount(), mesh.vertexIndex().length, level);
    }

    /**
     * Builds the control mesh: positions, faces, UVs (when the mesh has them), the tags and the
     * options. {@link ControlMesh.Builder#build()} validates the topology.
     *
     * @return the control mesh
     * @throws IllegalArgumentException naming the mesh's source and the face or vertex at fault
     */
    public ControlMesh toControlMesh() {
        ControlMesh.Builder b = ControlMesh.builder(mesh.positions(), mesh.faceSizes(), mesh.vertexIndex());
        if (mesh.source() != null) b.source(mesh.source());
        if (mesh.faceGroups() != null) b.faceGroups(mesh.faceGroups(), mesh.groupNames());
        int[] uvIndex = mesh.uvIndex();
        if (uvIndex != null && mesh.uvs() != null) {
            for (int c = 0; c < uvIndex.length; c++) {
                if (uvIndex[c] < 0) {
                    throw new IllegalArgumentException((mesh.source() == null ? "" : mesh.source() + ": ")
                            + "corner " + c + " has no texture coordinate, but others have (a subdivision surface needs them on every corner or none)");
                }
            }
            b.uvs(mesh.uvs(), uvIndex);
        }
        return tags.applyTo(b).build();
    }
}
