package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.io.ObjReader;

/**
 * {@link FaceVaryingSurface} against Bfr's face-varying limit (subdiv/fvar/fvar_limit.txt.gz, see
 * the README there): the UV of every sampled point under each of the six face-varying options,
 * to 1e-9 of the shape's UV range; and under {@code ALL}, the UV is the bilinear interpolation
 * of the face's corner UVs, computed here independently.
 */
class FaceVaryingSurfaceTest {
    static final double TOL = 1e-9;
    static final int SMOOTH = 2, SHARP = 6;
    private static final SubdivOptions.FaceVarying[] MODES = SubdivOptions.FaceVarying.values();
    /** Per mode: points checked; and the worst error (of the UV range) over all modes. */
    private static final int[] CHECKED = new int[MODES.length];
    private static double worst;

    /** The reference rows of each shape: face, u, v, then per mode the UV (NaN where Bfr has none). */
    private static final Map<String, List<double[]>> DATA = parse();

    private static Map<String, List<double[]>> parse() {
        Map<String, List<double[]>> out = new LinkedHashMap<>();
        List<double[]> rows = null;
        for (String line : Corpus.text("fvar/fvar_limit.txt").split("\n")) {
            if (line.isEmpty() || line.startsWith("#") || line.startsWith("end")) continue;
            String[] t = line.trim().split("\\s+");
            if (t[0].equals("shape")) {
                rows = new ArrayList<>();
                out.put(t[1], rows);
                continue;
            }
            double[] r = new double[3 + 2 * MODES.length];
            for (int i = 0; i < 3; i++) r[i] = Double.parseDouble(t[i]);
            // Per mode "U V", "x" (no surface) or "=" (the previous mode's value).
            for (int m = 0, k = 3; m < MODES.length; m++) {
                String a = t[k++];
                if (a.equals("=")) {
                    r[3 + 2 * m] = r[1 + 2 * m];
                    r[4 + 2 * m] = r[2 + 2 * m];
                } else if (a.equals("x")) {
                    r[3 + 2 * m] = r[4 + 2 * m] = Double.NaN;
                } else {
                    r[3 + 2 * m] = Double.parseDouble(a);
                    r[4 + 2 * m] = Double.parseDouble(t[k++]);
                }
            }
            rows.add(r);
        }
        return out;
    }

    static Stream<String> shapes() { return DATA.keySet().stream(); }

    @ParameterizedTest(name = "{0}")
    @MethodSource("shapes")
    void matchesBfr(String shape) {
        List<String> bad = new ArrayList<>();
        double[] uv = new double[2];
        // Read once; each mode only changes the options.
        SubdivInput in = ObjReader.parseSubdiv(Corpus.text(shape + ".obj"), shape + ".obj");
        SubdivOptions options = in.options().withScheme(Corpus.scheme(shape));
        for (SubdivOptions.FaceVarying mode : MODES) {
            ControlMesh cm = in.withOptions(options.withFaceVarying(mode)).toControlMesh();
            double range = uvRange(cm.uvs());
            PatchRefiner refiner = new PatchRefiner(cm);
            int m = mode.ordinal(), surfaceFace = -1;
            FaceVaryingSurface surface = null;
            for (double[] r : DATA.get(shape)) {
                int f = (int) r[0];
                if (f != surfaceFace) {
                    surface = FaceVaryingSurface.of(refiner, f, SMOOTH, SHARP);
                    surfaceFace = f;
                }
                double eu = r[3 + 2 * m], ev = r[4 + 2 * m];
                boolean ok = surface.evaluate(r[1], r[2], uv);
                if (Double.isNaN(eu)) {
                    if (ok) bad.add(mode + " face " + f + ": evaluated where Bfr has no surface");
                    continue;
                }
                if (!ok) {
                    bad.add(mode + " face " + f + " at (" + r[1] + ", " + r[2] + "): not evaluated");
                    continue;
                }
                double e = Math.max(Math.abs(uv[0] - eu), Math.abs(uv[1] - ev)) / range;
                synchronized (FaceVaryingSurfaceTest.class) {
                    CHECKED[m]++;
                    worst = Math.max(worst, e);
                }
                if (!(e <= TOL)) bad.add(mode + " face " + f + " at (" + r[1] + ", " + r[2] + "): (" + uv[0] + ", " + uv[1] + ") vs Bfr (" + eu + ", " + ev + "), error " + e);
            }
        }
        assertTrue(bad.isEmpty(), () -> shape + ": " + bad.size() + " mismatches:\n  " + String.join("\n  ", bad.subList(0, Math.min(12, bad.size()))));
    }

    /** Under ALL (and with the bilinear scheme, whatever the option) a face's UVs are bilinear in its corners. */
    @Test
    void linearAllIsBilinear() {
        double[] uv = new double[2];
        int checked = 0;
        for (String shape : DATA.keySet()) {
            ControlMesh cm = Corpus.load(shape, o -> o.withFaceVarying(SubdivOptions.FaceVarying.ALL));
            double range = uvRange(cm.uvs());
            boolean loop = cm.options().scheme() == SubdivOptions.Scheme.LOOP;
            int[] sizes = cm.faceSizes(), fuv = cm.faceUvIndices();
            double[] uvs = cm.uvs();
            int[] start = new int[sizes.length + 1];
            for (int f = 0; f < sizes.length; f++) start[f + 1] = start[f] + sizes[f];
            for (double[] r : DATA.get(shape)) {
                int f = (int) r[0], n = sizes[f];
                if (!FaceVaryingSurface.of(cm, f, SMOOTH, SHARP).evaluate(r[1], r[2], uv)) continue; // a hole
                double[] expected = new double[2];
                for (int d = 0; d < 2; d++) {
                    double[] c = new double[n];
                    for (int k = 0; k < n; k++) c[k] = uvs[2 * fuv[start[f] + k] + d];
                    expected[d] = bilinear(c, r[1], r[2], loop);
                }
                assertEquals(expected[0], uv[0], 1e-12 * range, shape + " face " + f);
                assertEquals(expected[1], uv[1], 1e-12 * range, shape + " face " + f);
                checked++;
            }
        }
        assertTrue(checked > 900, "points checked: " + checked);
    }

    /** Bfr's linear patch of a face's corner values c at (u,v): bilinear, linear on a Loop triangle, else per sub-face. */
    private static double bilinear(double[] c, double u, double v, boolean loop) {
        int n = c.length;
        if (loop) return (1 - u - v) * c[0] + u * c[1] + v * c[2];
        if (n == 4) return (1 - u) * (1 - v) * c[0] + u * (1 - v) * c[1] + u * v * c[2] + (1 - u) * v * c[3];
        int columns = n < 5 ? 2 : n < 10 ? 3 : 1 + (int) Math.sqrt(n - 1);
        int q = columns * (int) Math.floor(v) + (int) Math.floor(u);
        double s = 2 * (u - Math.floor(u)), t = 2 * (v - Math.floor(v));
        double centre = 0;
        for (double x : c) centre += x / n;
        double corner = c[q], next = (c[q] + c[(q + 1) % n]) / 2, prev = (c[q] + c[(q + n - 1) % n]) / 2;
        return (1 - s) * (1 - t) * corner + s * (1 - t) * next + s * t * centre + (1 - s) * t * prev;
    }

    private static double uvRange(double[] uvs) {
        double lu = Double.MAX_VALUE, hu = -Double.MAX_VALUE, lv = Double.MAX_VALUE, hv = -Double.MAX_VALUE;
        for (int i = 0; i < uvs.length; i += 2) {
            lu = Math.min(lu, uvs[i]);
            hu = Math.max(hu, uvs[i]);
            lv = Math.min(lv, uvs[i + 1]);
            hv = Math.max(hv, uvs[i + 1]);
        }
        return Math.max(Math.max(hu - lu, hv - lv), 1e-300);
    }

    @AfterAll
    static void report() {
        StringBuilder s = new StringBuilder("FaceVaryingSurfaceTest: points checked per mode");
        for (SubdivOptions.FaceVarying m : MODES) s.append(' ').append(m).append(' ').append(CHECKED[m.ordinal()]);
        System.out.println(s.append(String.format("; worst error %.3g of the UV range", worst)));
    }
}
