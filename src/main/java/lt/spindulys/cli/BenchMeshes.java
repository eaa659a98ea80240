package lt.spindulys.cli;

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
 * rather than kept in the repository.
 */
final class BenchMeshes {
    /** A torus size: its name in file names and its quads around the ring and the tube. */
    record Size(String name, int nu, int nv) {
        long quads() { return (long) nu * nv; }
        long triangles() { return 2 * quads(); }
        String file() { return "torus_" + name + ".obj"; }
    }

    static final Size[] SIZES = {
        new Size("1k", 32, 32), new Size("16k", 128, 128), new Size("250k", 500, 500), new Size("1m", 1000, 1000)};

    static final double MAJOR = 1.0, MINOR = 0.4, GROUND_Y = -0.4, GROUND_HALF = 20.0;
    static final String GROUND_FILE = "ground.obj";

    private BenchMeshes() {}

    static Size size(String name) {
        for (Size s : SIZES) if (s.name().equals(name)) return s;
        throw new IllegalArgumentException("unknown torus size " + name);
    }

    /** Writes the ground and the torus of {@code size} into {@code dir} unless they are there already. */
    static void ensure(Path dir, Size size) throws IOException {
        Files.createDirectories(dir);
        Path ground = dir.resolve(GROUND_FILE);
        if (!Files.exists(ground)) AtomicFile.write(ground, BenchMeshes::writeGround);
        Path torus = dir.resolve(size.file());
        if (!Files.exists(torus)) AtomicFile.write(torus, out -> writeTorus(out, size));
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
