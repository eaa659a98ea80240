package lt.spindulys.io;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;

import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.RefinedMesh;

/**
 * Writes a refined subdivision mesh as Wavefront OBJ text that {@link ObjReader} (and other OBJ
 * readers) read back: {@code v} positions, {@code vt} face-varying UVs when the mesh has them,
 * {@code vn} limit normals when asked, and one {@code f} per face that is not a hole, with
 * {@code v/vt/vn} corners as present. Numbers are written so that they read back exactly.
 */
public final class ObjWriter {
    private ObjWriter() {}

    /**
     * Writes {@code mesh} to {@code out} (which is flushed, not closed).
     *
     * @param mesh the refined mesh
     * @param out the stream
     * @throws IOException if writing fails
     * @param limit   write the limit-surface positions and the limit normals ({@code vn}) instead of
     *                the refined positions
     * @param comment a comment for the first lines (may hold several lines), or null
     */
    public static void write(RefinedMesh mesh, boolean limit, String comment, OutputStream out) throws IOException {
        Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        if (comment != null) {
            for (String line : comment.split("\\R", -1)) w.write("# " + line + "\n");
        }
        double[] p = limit ? mesh.limitPositions() : mesh.positions();
        for (int i = 0; i < p.length; i += 3) triple(w, "v ", p, i);
        double[] uvs = mesh.uvs();
        int[] faceUvs = mesh.faceUvs();
        boolean withUv = uvs != null && faceUvs != null;
        if (withUv) {
            for (int i = 0; i < uvs.length; i += 2) {
                w.write("vt ");
                w.write(number(uvs[i]));
                w.write(' ');
                w.write(number(uvs[i + 1]));
                w.write('\n');
            }
        }
        if (limit) {
            double[] n = mesh.limitNormals();
            for (int i = 0; i < n.length; i += 3) triple(w, "vn ", n, i);
        }
        int[] sizes = mesh.faceSizes(), fv = mesh.faceVertices();
        StringBuilder line = new StringBuilder(64);
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            if (mesh.isHole(f)) continue;
            line.setLength(0);
            line.append('f');
            for (int j = 0; j < sizes[f]; j++) {
                int v = fv[c + j] + 1;
                line.append(' ').append(v);
                // Normals are per vertex, so a vertex's normal has the vertex's own index.
                if (withUv) line.append('/').append(faceUvs[c + j] + 1);
                if (limit) line.append(withUv ? "/" : "//").append(v);
            }
            line.append('\n');
            w.append(line);
        }
        w.flush();
    }

    /**
     * Writes a polygon mesh (an adaptive tessellation) to {@code out} (flushed, not closed):
     * {@code v}, then {@code vt} and {@code vn} when the mesh has them, and {@code f v/vt/vn}
     * corners with the indices the mesh gives each corner.
     *
     * @param mesh    the mesh; a corner's uv or normal index of -1 leaves that part out of every corner of its face
     * @param comment a comment for the first lines (may hold several lines), or null
     * @param out     the stream
     * @throws IOException if writing fails
     */
    public static void write(MeshData mesh, String comment, OutputStream out) throws IOException {
        Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        if (comment != null) {
            for (String line : comment.split("\\R", -1)) w.write("# " + line + "\n");
        }
        double[] p = mesh.positions();
        for (int i = 0; i < p.length; i += 3) triple(w, "v ", p, i);
        double[] uvs = mesh.uvs();
        if (uvs != null) {
            for (int i = 0; i < uvs.length; i += 2) {
                w.write("vt ");
                w.write(number(uvs[i]));
                w.write(' ');
                w.write(number(uvs[i + 1]));
                w.write('\n');
            }
        }
        double[] n = mesh.normals();
        if (n != null) for (int i = 0; i < n.length; i += 3) triple(w, "vn ", n, i);
        int[] sizes = mesh.faceSizes(), vi = mesh.vertexIndex(), ti = mesh.uvIndex(), ni = mesh.normalIndex();
        StringBuilder line = new StringBuilder(64);
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            // A face whose corners miss a uv or a normal is written without that part (OBJ wants all or none).
            boolean withUv = ti != null, withNormal = ni != null;
            for (int j = 0; j < sizes[f]; j++) {
                withUv &= ti != null && ti[c + j] >= 0;
                withNormal &= ni != null && ni[c + j] >= 0;
            }
            line.setLength(0);
            line.append('f');
            for (int j = 0; j < sizes[f]; j++) {
                line.append(' ').append(vi[c + j] + 1);
                if (withUv) line.append('/').append(ti[c + j] + 1);
                if (withNormal) line.append(withUv ? "/" : "//").append(ni[c + j] + 1);
            }
            line.append('\n');
            w.append(line);
        }
        w.flush();
    }

    private static void triple(Writer w, String keyword, double[] a, int i) throws IOException {
        w.write(keyword);
        w.write(number(a[i]));
        w.write(' ');
        w.write(number(a[i + 1]));
        w.write(' ');
        w.write(number(a[i + 2]));
        w.write('\n');
    }

    /** The shortest text that reads back as exactly this double; whole numbers without ".0". */
    static String number(double d) {
        if (d == 0) return 1 / d < 0 ? "-0" : "0";
        if (d == Math.rint(d) && Math.abs(d) < 1e15) return Long.toString((long) d);
        return Double.toString(d);
    }
}
