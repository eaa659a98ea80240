package lt.spindulys.bench;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.math.BigDecimal;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import lt.spindulys.files.AtomicFile;

/**
 * Writes the meshes of the shared peer benchmark scene (scenes/bench/torus-*.dat): a torus of
 * major radius 1 and minor radius 0.4 about +Y as a closed quad mesh with seam-split texture
 * coordinates, and a 40 x 40 ground quad at y = -0.4. The text is the same, byte for byte, as
 * the peer kit's generator writes, so every renderer reads identical numbers; quads are split
 * along their v0-v2 diagonal by every reader, ours included. Large sizes are generated on demand
 * rather than kept in the repository. Also the mesh of the mesh-filling view knot-1m:
 * a tube around a (2, 3) torus knot, resting on the same ground.
 */
final class BenchMeshes {
    /** A generated bench mesh: its file in scenes/bench/meshes/, its size, and how to write it. */
    interface Shape {
        String file();
        long quads();
        default long triangles() { return 2 * quads(); }
        void write(OutputStream out) throws IOException;
    }

    /** A torus size: its name in file names and its quads around the ring and the tube. */
    record Size(String name, int nu, int nv) implements Shape {
        @Override public long quads() { return (long) nu * nv; }
        @Override public String file() { return "torus_" + name + ".obj"; }
        @Override public void write(OutputStream out) throws IOException { writeTorus(out, this); }
    }

    /**
     * A closed tube of radius {@code tube} around the (p, q) torus knot that winds p times about
     * the +Y axis and q times through the hole of a torus of radii {@code major} and
     * {@code minor}, lifted so that its lowest points touch the ground; {@code nu} quads along
     * the knot, {@code nv} around the tube. Positions and faces only: the views it serves are
     * untextured, and a reader that skips no texture coordinates is not slowed by them.
     */
    record Knot(String name, int p, int q, double major, double minor, double tube, double phase, int nu, int nv) implements Shape {
        @Override public long quads() { return (long) nu * nv; }
        @Override public String file() { return "knot_" + name + ".obj"; }
        @Override public void write(OutputStream out) throws IOException { writeKnot(out, this); }
        /** The height of the knot's centre: its lowest points, minor + tube below it, touch the ground. */
        double centreY() { return GROUND_Y + minor + tube; }
    }

    /**
     * The knot of the knot-1m view: a trefoil whose strands are at least 0.89 apart (centre to
     * centre), so a tube of radius 0.25 leaves gaps the light and the camera see through; 3,125 x
     * 320 quads keep them roughly square (the knot is 15.3 long, the tube 1.57 round). The phase
     * turns a lobe towards the camera, so the view is balanced.
     */
    static final Knot KNOT_1M = new Knot("1m", 2, 3, 1.0, 0.45, 0.25, Math.PI / 2, 3125, 320);

    static final Size[] SIZES = {
        new Size("1k", 32, 32), new Size("16k", 128, 128), new Size("250k", 500, 500), new Size("1m", 1000, 1000)};

    static final double MAJOR = 1.0, MINOR = 0.4, GROUND_Y = -0.4, GROUND_HALF = 20.0;
    static final String GROUND_FILE = "ground.obj";
    /**
     * The material library the meshes name. Our reader skips it; the peers that read OBJ files
     * (Embree's tutorials, Blender) take the grey from it, so it is written beside the meshes.
     */
    static final String MATERIAL_FILE = "grey.mtl";
    static final String MATERIAL_TEXT = "newmtl grey\nKd 0.8 0.8 0.8\nKs 0 0 0\nNs 1\nd 1\n";

    private BenchMeshes() {}

    static Size size(String name) {
        for (Size s : SIZES) if (s.name().equals(name)) return s;
        throw new IllegalArgumentException("unknown torus size " + name);
    }

    /** Writes the ground, the material library and {@code shape} into {@code dir} unless they are there already. */
    static void ensure(Path dir, Shape shape) throws IOException {
        Files.createDirectories(dir);
        Path ground = dir.resolve(GROUND_FILE);
        if (!Files.exists(ground)) AtomicFile.write(ground, BenchMeshes::writeGround);
        Path mtl = dir.resolve(MATERIAL_FILE);
        if (!Files.exists(mtl)) AtomicFile.write(mtl, out -> out.write(MATERIAL_TEXT.getBytes(StandardCharsets.US_ASCII)));
        Path mesh = dir.resolve(shape.file());
        if (!Files.exists(mesh)) AtomicFile.write(mesh, shape::write);
    }

    static void writeGround(OutputStream raw) throws IOException {
        Text t = new Text(raw);
        double h = GROUND_HALF, y = GROUND_Y;
        t.s("# ground: 1 quads, 4 vertices\nmtllib grey.mtl\no ground\nusemtl grey\n");
        double[][] p = {{-h, y, h}, {h, y, h}, {h, y, -h}, {-h, y, -h}};
        for (double[] v : p) t.s("v ").num(v[0]).s(" ").num(v[1]).s(" ").num(v[2]).s("\n");
        double[][] uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (double[] v : uv) t.s("vt ").num(v[0]).s(" ").num(v[1]).s("\n");
        t.s("f 1/1 2/2 3/3 4/4\n");
        t.flush();
    }

    /**
     * The torus: vertex (i, j) at ring angle u = 2 pi i / nu and tube angle v = 2 pi j / nv is
     * ((R + r cos v) cos u, r sin v, -(R + r cos v) sin u); quads are wound so the geometric
     * normal points outward.
     */
    static void writeTorus(OutputStream raw, Size size) throws IOException {
        Text t = new Text(raw);
        int nu = size.nu(), nv = size.nv();
        String name = "torus_" + size.name();
        t.s("# " + name + ": " + size.quads() + " quads, " + (long) nu * nv + " vertices\n");
        t.s("mtllib grey.mtl\no " + name + "\nusemtl grey\n");
        double[] cv = new double[nv], sv = new double[nv];
        for (int j = 0; j < nv; j++) {
            double v = 2.0 * Math.PI * j / nv;
            cv[j] = Math.cos(v);
            sv[j] = Math.sin(v);
        }
        for (int i = 0; i < nu; i++) {
            double u = 2.0 * Math.PI * i / nu, cu = Math.cos(u), su = Math.sin(u);
            for (int j = 0; j < nv; j++) {
                double rr = MAJOR + MINOR * cv[j];
                t.s("v ").num(rr * cu).s(" ").num(MINOR * sv[j]).s(" ").num(-rr * su).s("\n");
            }
        }
        for (int i = 0; i <= nu; i++) {
            for (int j = 0; j <= nv; j++) t.s("vt ").num(i / (double) nu).s(" ").num(j / (double) nv).s("\n");
        }
        for (int i = 0; i < nu; i++) {
            for (int j = 0; j < nv; j++) {
                int i1 = (i + 1) % nu, j1 = (j + 1) % nv;
                long p0 = (long) i * nv + j + 1, p1 = (long) i1 * nv + j + 1, p2 = (long) i1 * nv + j1 + 1, p3 = (long) i * nv + j1 + 1;
                long t0 = (long) i * (nv + 1) + j + 1, t1 = (long) (i + 1) * (nv + 1) + j + 1;
                t.s("f ").i(p0).s("/").i(t0).s(" ").i(p1).s("/").i(t1).s(" ")
                        .i(p2).s("/").i(t1 + 1).s(" ").i(p3).s("/").i(t0 + 1).s("\n");
            }
        }
        t.flush();
    }

    /**
     * The knot's tube. Its frame at a point of the knot is the torus's surface normal there
     * (the knot lies on the torus, so the normal is square to the knot's tangent) and the
     * tangent crossed with it: periodic, never degenerate, and without the twist a
     * parallel-transported frame would need closing. Vertex (i, j) sits at angle 2 pi j / nv
     * round the tube at knot parameter t = 2 pi i / nu; quads are wound so the geometric normal
     * points out of the tube, and indices wrap in both directions, so the mesh is closed.
     */
    static void writeKnot(OutputStream raw, Knot k) throws IOException {
        Text t = new Text(raw);
        int nu = k.nu(), nv = k.nv();
        String name = "knot_" + k.name();
        t.s("# " + name + ": " + k.quads() + " quads, " + k.quads() + " vertices, tube around the (" + k.p() + ", " + k.q() + ") torus knot\n");
        t.s("mtllib " + MATERIAL_FILE + "\no " + name + "\nusemtl grey\n");
        double[] cv = new double[nv], sv = new double[nv];
        for (int j = 0; j < nv; j++) {
            double v = 2.0 * Math.PI * j / nv;
            cv[j] = Math.cos(v);
            sv[j] = Math.sin(v);
        }
        double big = k.major(), small = k.minor(), y0 = k.centreY();
        for (int i = 0; i < nu; i++) {
            double s = 2.0 * Math.PI * i / nu;
            double a = k.p() * s + k.phase(), b = k.q() * s;
            double ca = Math.cos(a), sa = Math.sin(a), cb = Math.cos(b), sb = Math.sin(b);
            double rr = big + small * cb;
            double cx = rr * ca, cy = small * sb + y0, cz = -rr * sa;
            // torus normal n and tangent d/ds of the centre line
            double nx = cb * ca, ny = sb, nz = -cb * sa;
            double tx = -small * k.q() * sb * ca - rr * k.p() * sa;
            double ty = small * k.q() * cb;
            double tz = small * k.q() * sb * sa - rr * k.p() * ca;
            double tl = Math.sqrt(tx * tx + ty * ty + tz * tz);
            tx /= tl;
            ty /= tl;
            tz /= tl;
            // m = t x n completes the frame (n, m) square to the tangent
            double mx = ty * nz - tz * ny, my = tz * nx - tx * nz, mz = tx * ny - ty * nx;
            for (int j = 0; j < nv; j++) {
                double ox = k.tube() * (cv[j] * nx + sv[j] * mx), oy = k.tube() * (cv[j] * ny + sv[j] * my), oz = k.tube() * (cv[j] * nz + sv[j] * mz);
                t.s("v ").num(cx + ox).s(" ").num(cy + oy).s(" ").num(cz + oz).s("\n");
            }
        }
        for (int i = 0; i < nu; i++) {
            int i1 = (i + 1) % nu;
            for (int j = 0; j < nv; j++) {
                int j1 = (j + 1) % nv;
                // (n, m, t) is right-handed, so stepping round the tube (j) then along the knot (i)
                // winds counter-clockwise seen from outside.
                long p0 = (long) i * nv + j + 1, p1 = (long) i * nv + j1 + 1, p2 = (long) i1 * nv + j1 + 1, p3 = (long) i1 * nv + j + 1;
                t.s("f ").i(p0).s(" ").i(p1).s(" ").i(p2).s(" ").i(p3).s("\n");
            }
        }
        t.flush();
    }

    /**
     * The peer kit's number format: six decimals of the exact binary value rounded half-even
     * (as C's printf), trailing zeros and a trailing point removed, and "0" for zero; a tiny
     * negative prints "-0" as printf's "-0.000000" does.
     */
    static String number(double x) {
        if (x == 0) return "0";
        BigDecimal d = new BigDecimal(x).setScale(6, RoundingMode.HALF_EVEN);
        String f = d.toPlainString();
        int end = f.length();
        while (f.charAt(end - 1) == '0') end--;
        if (f.charAt(end - 1) == '.') end--;
        // BigDecimal has no negative zero.
        return (d.signum() == 0 && x < 0 ? "-" : "") + f.substring(0, end);
    }

    /** Buffered ASCII output with the peer kit's number format. */
    private static final class Text {
        private final OutputStream out;
        private final StringBuilder sb = new StringBuilder(1 << 16);

        Text(OutputStream out) { this.out = new BufferedOutputStream(out, 1 << 16); }

        Text s(String v) { sb.append(v); return spill(); }
        Text i(long v) { sb.append(v); return spill(); }

        Text num(double x) {
            sb.append(number(x));
            return spill();
        }

        private Text spill() {
            if (sb.length() > 60000) flushText();
            return this;
        }

        private void flushText() {
            try {
                out.write(sb.toString().getBytes(StandardCharsets.US_ASCII));
            } catch (IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
            sb.setLength(0);
        }

        void flush() throws IOException {
            try {
                flushText();
            } catch (java.io.UncheckedIOException e) {
                throw e.getCause();
            }
            out.flush();
        }
    }
}
