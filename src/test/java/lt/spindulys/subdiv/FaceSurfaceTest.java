package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Direct limit evaluation against OpenSubdiv Bfr's ({@code subdiv/limit/}, see its README): for
 * every shape, every sampled face Bfr evaluates, the face must be regular exactly when Bfr says so
 * (Catmull-Clark and Loop), and on regular and bilinear faces the position and both derivatives
 * must match Bfr's to 1e-9 of the shape's size (its bounding box's largest side).
 */
class FaceSurfaceTest {
    static final double TOL = 1e-9;

    /** Per scheme: points checked, and the worst error relative to the shape's size. */
    static final Map<String, double[]> WORST = new ConcurrentHashMap<>();

    static Stream<String> shapes() {
        try (Stream<Path> s = Files.list(Corpus.dir().resolve("limit"))) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".limit.txt.gz"))
                    .map(n -> n.substring(0, n.length() - ".limit.txt.gz".length())).sorted().toList().stream();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void everyShapeHasReferenceData() {
        assertEquals(123, shapes().count(), "shapes with limit data");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("shapes")
    void matchesBfrOnRegularAndBilinearFaces(String shape) {
        ControlMesh cm = Corpus.load(shape);
        Corpus.Oracle o = Corpus.oracle("limit/" + shape + ".limit.txt", 0, false);
        double[][] opts = o.section("options");
        assertEquals(2, opts[0][0], "approxLevelSmooth");
        assertEquals(6, opts[0][1], "approxLevelSharp");
        double size = size(cm.positions());
        boolean bilinear = cm.options().scheme() == SubdivOptions.Scheme.BILINEAR;
        Map<Integer, double[]> faces = new TreeMap<>();
        List<String> bad = new ArrayList<>();
        for (double[] r : o.section("faces")) {
            int f = (int) r[0];
            faces.put(f, r);
            if (r[1] == 0) continue;
            if (!bilinear) {
                boolean regular = FaceSurface.isRegular(cm.base, cm.options(), f);
                if (regular != (r[2] == 1)) bad.add("face " + f + ": regular " + regular + ", Bfr " + (r[2] == 1));
            }
        }
        double[] p = new double[3], du = new double[3], dv = new double[3];
        double worst = 0;
        int checked = 0;
        for (double[] r : o.section("points")) {
            int f = (int) r[0];
            double[] face = faces.get(f);
            if (!bilinear && (face[2] != 1 || !FaceSurface.isRegular(cm.base, cm.options(), f))) continue;
            FaceSurface s = FaceSurface.of(cm, f);
            s.evaluate(r[1], r[2], p, du, dv);
            double e = 0;
            for (int d = 0; d < 3; d++) {
                e = Math.max(e, Math.abs(p[d] - r[3 + d]));
                e = Math.max(e, Math.abs(du[d] - r[6 + d]));
                e = Math.max(e, Math.abs(dv[d] - r[9 + d]));
            }
            e /= size;
            if (!(e <= TOL)) bad.add("face " + f + " at (" + r[1] + ", " + r[2] + "): error " + e + " of the size");
            worst = Math.max(worst, e);
            checked++;
        }
        String scheme = cm.options().scheme().keyword();
        double w = worst;
        int c = checked;
        WORST.merge(scheme, new double[] {c, w}, (a, b) -> new double[] {a[0] + b[0], Math.max(a[1], b[1])});
        assertTrue(bad.isEmpty(), () -> shape + ": " + bad.size() + " mismatches:\n  " + String.join("\n  ", bad.subList(0, Math.min(10, bad.size()))));
    }

    @AfterAll
    static void report() {
        WORST.forEach((k, v) -> System.out.printf("FaceSurfaceTest %s: %d points, worst error %.3g of the size%n", k, (int) v[0], v[1]));
    }

    static double size(double[] pos) {
        double s = 0;
        for (int d = 0; d < 3; d++) {
            double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
            for (int i = d; i < pos.length; i += 3) {
                lo = Math.min(lo, pos[i]);
                hi = Math.max(hi, pos[i]);
            }
            s = Math.max(s, hi - lo);
        }
        return s;
    }

    /** Regular patches reproduce a planar lattice exactly (linear precision), with unit derivatives. */
    @Test
    void regularPatchesHaveLinearPrecision() {
        int n = 7;
        double[] pos = new double[3 * n * n];
        for (int j = 0; j < n; j++) for (int i = 0; i < n; i++) { pos[3 * (j * n + i)] = i; pos[3 * (j * n + i) + 1] = j; }
        int[] qs = new int[(n - 1) * (n - 1)], qv = new int[4 * qs.length];
        int[] ts = new int[2 * qs.length], tv = new int[3 * ts.length];
        for (int j = 0, q = 0; j < n - 1; j++) {
            for (int i = 0; i < n - 1; i++, q++) {
                int a = j * n + i, b = a + 1, c = a + n + 1, d = a + n;
                qs[q] = 4;
                System.arraycopy(new int[] {a, b, c, d}, 0, qv, 4 * q, 4);
                ts[2 * q] = ts[2 * q + 1] = 3;
                System.arraycopy(new int[] {a, b, d, b, c, d}, 0, tv, 6 * q, 6);
            }
        }
        ControlMesh quads = ControlMesh.builder(pos, qs, qv).build();
        ControlMesh tris = ControlMesh.builder(pos, ts, tv).options(SubdivOptions.DEFAULT.withScheme(SubdivOptions.Scheme.LOOP)).build();
        int quad = 3 * (n - 1) + 3, tri = 2 * quad;
        double[] p = new double[3], du = new double[3], dv = new double[3];
        for (double[] uv : new double[][] {{0.1, 0.2}, {0.5, 0.25}, {0.7, 0.05}, {0, 0}, {1, 0}, {0, 1}}) {
            FaceSurface.of(quads, quad).evaluate(uv[0], uv[1], p, du, dv);
            assertArrayEquals(new double[] {3 + uv[0], 3 + uv[1], 0}, p, 1e-14);
            assertArrayEquals(new double[] {1, 0, 0}, du, 1e-14);
            assertArrayEquals(new double[] {0, 1, 0}, dv, 1e-14);
            FaceSurface.of(tris, tri).evaluate(uv[0], uv[1], p, du, dv);
            assertArrayEquals(new double[] {3 + uv[0], 3 + uv[1], 0}, p, 1e-14);
            assertArrayEquals(new double[] {1, 0, 0}, du, 1e-14);
            assertArrayEquals(new double[] {0, 1, 0}, dv, 1e-14);
        }
    }
}
