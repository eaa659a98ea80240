package lt.spindulys.io;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.util.function.DoubleConsumer;

import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivTags;

/**
 * Writes meshes as Wavefront OBJ text that {@link ObjReader} (and other OBJ readers) read back.
 * A refined subdivision mesh: {@code v} positions, {@code vt} face-varying UVs when the mesh has
 * them, {@code vn} limit normals when asked, and one {@code f} per face that is not a hole, with
 * {@code v/vt/vn} corners as present. A control mesh ({@link #write(ControlMesh, String, String,
 * OutputStream)}): the same with OpenSubdiv's {@code t} tags, so that {@link ObjReader#readSubdiv}
 * gives back an equal control mesh. Numbers are written so that they read back exactly.
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
        ObjectFile file = new ObjectFile(out, comment);
        file.add(null, mesh, limit, null);
        file.finish();
    }

    /**
     * Several refined meshes in one OBJ file, each an object ({@code o NAME}) with its own
     * vertices, uvs, normals and faces, as {@link #write(RefinedMesh, boolean, String, OutputStream)}
     * writes one: OBJ's indices count through the whole file, so each object's faces index past
     * the elements of the objects before it. Meshes are added one at a time, so only the one being
     * written need be in memory. (Subdivision tags cannot be given per object: they and the scheme
     * options belong to the whole file; a control mesh with tags is written one per file by
     * {@link ObjWriter#write(ControlMesh, String, String, OutputStream)}.)
     */
    public static final class ObjectFile {
        private final Writer w;
        private final StringBuilder line = new StringBuilder(64);
        /** Elements written so far: the next object's indices start after them. */
        private long vertices, uvs, normals;

        /**
         * Starts the file with a comment.
         *
         * @param out     the stream (flushed by {@link #finish()}, not closed)
         * @param comment a comment for the first lines (may hold several lines), or null
         * @throws IOException if writing fails
         */
        public ObjectFile(OutputStream out, String comment) throws IOException {
            w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
            header(w, comment, null);
        }

        /**
         * Writes one mesh as an object: {@code o NAME}, {@code v} (refined or limit positions),
         * {@code vt} when the mesh has UVs, {@code vn} limit normals with {@code limit}, one
         * {@code f} per face that is not a hole, and {@code t scheme 0/0/1 loop|bilinear} when the
         * mesh was refined with a scheme other than Catmull-Clark ({@code t} tags belong to a whole
         * file for {@link ObjReader#readSubdiv}, so a file whose objects have different schemes
         * reads back with the last object's).
         *
         * @param name     the object's name, or null for no {@code o} line
         * @param mesh     the refined mesh
         * @param limit    write the limit positions and limit normals instead of the refined positions
         * @param progress told the fraction of this mesh written (0 to 1, every few thousand lines),
         *                 may throw an unchecked exception (a cancellation) to stop; or null
         * @throws IOException              if writing fails
         * @throws IllegalArgumentException if a number is beyond {@link Ranges#MAX_NUMBER} (OBJ readers
         *                                  here refuse it), naming the object and the vertex
         */
        public void add(String name, RefinedMesh mesh, boolean limit, DoubleConsumer progress) throws IOException {
            double[] p = limit ? mesh.limitPositions() : mesh.positions();
            String source = name != null ? name : mesh.controlMesh().source();
            checkRange(p, "vertex", 3, source);
            double[] uv = mesh.uvs();
            int[] faceUvs = mesh.faceUvs();
            boolean withUv = uv != null && faceUvs != null;
            if (withUv) checkRange(uv, "uv", 2, source);
            int[] sizes = mesh.faceSizes(), fv = mesh.faceVertices();
            int nv = p.length / 3;
            SubdivOptions.Scheme scheme = mesh.controlMesh().options().scheme();
            boolean schemeTag = scheme != SubdivOptions.Scheme.CATMARK;
            Lines lines = new Lines((limit ? 2L : 1L) * nv + (withUv ? uv.length / 2 : 0) + sizes.length + (schemeTag ? 1 : 0), progress);
            if (name != null) w.write("o " + objectName(name) + "\n");
            for (int i = 0; i < p.length; i += 3) {
                triple(w, "v ", p, i);
                lines.done();
            }
            if (withUv) {
                for (int i = 0; i < uv.length; i += 2) {
                    pair(w, uv, i);
                    lines.done();
                }
            }
            if (limit) {
                double[] n = mesh.limitNormals();
                for (int i = 0; i < n.length; i += 3) {
                    triple(w, "vn ", n, i);
                    lines.done();
                }
            }
            long vBase = vertices + 1, tBase = uvs + 1, nBase = normals + 1;
            for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
                if (mesh.isHole(f)) {
                    lines.done();
                    continue;
                }
                line.setLength(0);
                line.append('f');
                for (int j = 0; j < sizes[f]; j++) {
                    line.append(' ').append(fv[c + j] + vBase);
                    // Normals are per vertex, so a vertex's normal has the vertex's own index in this object.
                    if (withUv) line.append('/').append(faceUvs[c + j] + tBase);
                    if (limit) line.append(withUv ? "/" : "//").append(fv[c + j] + nBase);
                }
                line.append('\n');
                w.append(line);
                lines.done();
            }
            if (schemeTag) {
                // The scheme the mesh was refined with, so that reading the file back as a control
                // mesh refines it further with the same rules (Catmull-Clark, the default, is not written).
                w.write("t scheme 0/0/1 " + scheme.keyword() + "\n");
                lines.done();
            }
            vertices += nv;
            if (withUv) uvs += uv.length / 2;
            if (limit) normals += nv;
            lines.finish();
        }

        /**
         * Flushes what was written.
         *
         * @throws IOException if writing fails
         */
        public void finish() throws IOException {
            w.flush();
        }
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

    /**
     * Writes a subdivision control mesh with its tags (flushed, not closed), in the dialect
     * {@link ObjReader#readSubdiv} and OpenSubdiv's shape files use: {@code v}; {@code vt} and
     * {@code f v/vt} corners with the face-varying UVs' own indices where the mesh has UVs, else
     * {@code f v}; then one {@code t crease 2/1/0 a b sharpness} per crease, {@code t corner 1/1/0
     * v sharpness} per corner and {@code t hole 1/0/0 face} per hole, in the order the mesh was
     * given them (tag indices count from 0), and the four scheme options, always, so the file
     * does not depend on a reader's defaults: {@code t interpolateboundary 1/0/0 N} (0 none, 1
     * edge and corner, 2 edge only), {@code t facevaryinginterpolateboundary 1/0/0 N} (0 none ...
     * 5 all, as {@link SubdivOptions.FaceVarying} in order), {@code t creasemethod 0/0/1
     * normal|chaikin} and {@code t smoothtriangles 0/0/1 catmark|smooth}; before them
     * {@code t scheme 0/0/1 loop|bilinear} when the scheme is not Catmull-Clark (the reader's
     * default, and the only scheme OpenSubdiv's shape files know).
     *
     * <p>A sharpness is written so that it reads back as the same {@code float}; one the OBJ
     * reader cannot take is written as the value with the same effect: a negative sharpness as 0
     * (smooth) and an infinite or huge one as {@link ControlMesh#INFINITELY_SHARP}.
     *
     * @param mesh    the control mesh
     * @param name    the object's name for an {@code o} line (readers that split objects use it), or null for none
     * @param comment a comment for the first lines (may hold several lines), or null
     * @param out     the stream
     * @throws IOException              if writing fails
     * @throws IllegalArgumentException if a coordinate or uv is beyond {@link Ranges#MAX_NUMBER} in
     *                                  magnitude (OBJ readers here refuse it), naming the mesh's source and the vertex
     */
    public static void write(ControlMesh mesh, String name, String comment, OutputStream out) throws IOException {
        write(mesh, name, comment, out, null);
    }

    /**
     * {@link #write(ControlMesh, String, String, OutputStream)}, telling {@code progress} how far it
     * has come (a fraction from 0 to 1, every few thousand lines); {@code progress} may throw an
     * unchecked exception (a cancellation) to stop the writing.
     *
     * @param mesh     the control mesh
     * @param name     the object's name for an {@code o} line, or null for none
     * @param comment  a comment for the first lines, or null
     * @param out      the stream
     * @param progress receives the fraction written, or null
     * @throws IOException if writing fails
     */
    public static void write(ControlMesh mesh, String name, String comment, OutputStream out, DoubleConsumer progress) throws IOException {
        checkRange(mesh.positions(), "vertex", 3, mesh.source());
        double[] uvs = mesh.uvs();
        int[] faceUvs = mesh.faceUvIndices();
        boolean withUv = uvs != null && faceUvs != null;
        if (withUv) checkRange(uvs, "uv", 2, mesh.source());
        SubdivTags tags = mesh.tags();
        int[] sizes = mesh.faceSizes(), fv = mesh.faceVertices();
        long total = (long) mesh.vertexCount() + (withUv ? uvs.length / 2 : 0) + sizes.length
                + tags.creaseCount() + tags.corners().length + tags.holes().length + 4
                + (mesh.options().scheme() == SubdivOptions.Scheme.CATMARK ? 0 : 1);
        Lines lines = new Lines(total, progress);
        Writer w = new BufferedWriter(new OutputStreamWriter(out, StandardCharsets.UTF_8), 1 << 16);
        header(w, comment, name);
        double[] p = mesh.positions();
        for (int i = 0; i < p.length; i += 3) {
            triple(w, "v ", p, i);
            lines.done();
        }
        if (withUv) {
            for (int i = 0; i < uvs.length; i += 2) {
                pair(w, uvs, i);
                lines.done();
            }
        }
        StringBuilder line = new StringBuilder(64);
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            line.setLength(0);
            line.append('f');
            for (int j = 0; j < sizes[f]; j++) {
                line.append(' ').append(fv[c + j] + 1);
                if (withUv) line.append('/').append(faceUvs[c + j] + 1);
            }
            line.append('\n');
            w.append(line);
            lines.done();
        }
        int[] creases = tags.creases(), corners = tags.corners();
        float[] creaseSharp = tags.creaseSharpness(), cornerSharp = tags.cornerSharpness();
        for (int i = 0; i < creaseSharp.length; i++) {
            w.write("t crease 2/1/0 " + creases[2 * i] + " " + creases[2 * i + 1] + " " + sharpness(creaseSharp[i]) + "\n");
            lines.done();
        }
        for (int i = 0; i < corners.length; i++) {
            w.write("t corner 1/1/0 " + corners[i] + " " + sharpness(cornerSharp[i]) + "\n");
            lines.done();
        }
        for (int h : tags.holes()) {
            w.write("t hole 1/0/0 " + h + "\n");
            lines.done();
        }
        SubdivOptions o = mesh.options();
        int boundary = switch (o.boundary()) {
            case NONE -> 0;
            case EDGE_AND_CORNER -> 1;
            case EDGE_ONLY -> 2;
        };
        // Only a scheme other than Catmull-Clark is written: catmark files stay as they were, and
        // OpenSubdiv's shape files (which have no scheme tag) read as Catmull-Clark too.
        if (o.scheme() != SubdivOptions.Scheme.CATMARK) w.write("t scheme 0/0/1 " + o.scheme().keyword() + "\n");
        w.write("t interpolateboundary 1/0/0 " + boundary + "\n");
        w.write("t facevaryinginterpolateboundary 1/0/0 " + o.fvar().ordinal() + "\n");
        w.write("t creasemethod 0/0/1 " + (o.creasing() == SubdivOptions.Creasing.CHAIKIN ? "chaikin" : "normal") + "\n");
        w.write("t smoothtriangles 0/0/1 " + (o.triangles() == SubdivOptions.Triangles.SMOOTH ? "smooth" : "catmark") + "\n");
        w.flush();
        lines.finish();
    }

    /**
     * A sharpness as text that reads back (as a double, then rounded to float, as the reader does)
     * to the same float: Float's shortest form where that survives the double rounding, else the
     * float's exact double value. Negative and unreadably large values become what they mean.
     */
    static String sharpness(float s) {
        if (!(s > 0)) return "0"; // negative sharpness is smooth, as 0 is (Crease.isSharp)
        if (!(s <= Ranges.MAX_NUMBER)) return number(ControlMesh.INFINITELY_SHARP); // infinitely sharp either way
        if (s == Math.rint(s)) return Long.toString((long) s);
        String t = Float.toString(s);
        return (float) Double.parseDouble(t) == s ? t : Double.toString(s);
    }

    /** Refuses numbers the OBJ reader refuses, before anything is written. */
    private static void checkRange(double[] a, String what, int stride, String source) {
        for (int i = 0; i < a.length; i++) {
            if (!(Math.abs(a[i]) <= Ranges.MAX_NUMBER)) {
                throw new IllegalArgumentException((source == null ? "" : source + ": ") + what + " " + i / stride + " has the number "
                        + a[i] + ", beyond the " + Ranges.show(Ranges.MAX_NUMBER) + " an OBJ file may hold");
            }
        }
    }

    private static void header(Writer w, String comment, String name) throws IOException {
        if (comment != null) {
            for (String line : comment.split("\\R", -1)) w.write("# " + line + "\n");
        }
        if (name != null) w.write("o " + objectName(name) + "\n");
    }

    /** An {@code o} name on one line: OBJ names end at the line, so line breaks become spaces. */
    static String objectName(String name) {
        String n = name.replaceAll("[\\r\\n\\\\#]", " ").strip();
        return n.isEmpty() ? "unnamed" : n;
    }

    private static void pair(Writer w, double[] a, int i) throws IOException {
        w.write("vt ");
        w.write(number(a[i]));
        w.write(' ');
        w.write(number(a[i + 1]));
        w.write('\n');
    }

    /** Counts written lines and reports the fraction every {@link #EVERY} of them. */
    private static final class Lines {
        static final int EVERY = 4096;
        final long total;
        final DoubleConsumer progress;
        long done;

        Lines(long total, DoubleConsumer progress) {
            this.total = Math.max(1, total);
            this.progress = progress;
            if (progress != null) progress.accept(0);
        }

        void done() {
            if (++done % EVERY == 0 && progress != null) progress.accept(Math.min(1, (double) done / total));
        }

        void finish() {
            if (progress != null) progress.accept(1);
        }
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
