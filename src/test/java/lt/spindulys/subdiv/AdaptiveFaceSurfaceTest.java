package lt.spindulys.subdiv;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicIntegerArray;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The irregular faces of Catmull-Clark and Loop by {@link AdaptiveFaceSurface}, against Bfr's
 * limit (the data of {@link FaceSurfaceTest}): every point, position and derivatives, to 1e-9
 * of the shape's size. Each face has one evaluator, made from its one-ring ({@link PatchRefiner#local}).
 */
class AdaptiveFaceSurfaceTest {
    /** Points checked, points in end patches (not evaluated yet), unsupported irregular points. */
    static final AtomicIntegerArray COUNTS = new AtomicIntegerArray(3);
    static volatile double worst;
    /** Per scheme: points checked and the worst error relative to the shape's size. */
    static final Map<String, double[]> WORST = new java.util.concurrent.ConcurrentHashMap<>();

    static java.util.stream.Stream<String> shapes() { return FaceSurfaceTest.shapes(); }

    @ParameterizedTest(name = "{0}")
    @MethodSource("shapes")
    void matchesBfrOnIrregularFaces(String shape) {
        ControlMesh cm = Corpus.load(shape);
        if (cm.options().scheme() == SubdivOptions.Scheme.BILINEAR) return;
        Corpus.Oracle o = Corpus.oracle("limit/" + shape + ".limit.txt", 0, false);
        int smooth = (int) o.section("options")[0][0], sharp = (int) o.section("options")[0][1];
        double size = FaceSurfaceTest.size(cm.positions());
        Map<Integer, double[]> faces = new TreeMap<>();
        for (double[] r : o.section("faces")) faces.put((int) r[0], r);
        PatchRefiner refiner = new PatchRefiner(cm);
        AdaptiveFaceSurface surface = null;
        int surfaceFace = -1;
        double[] p = new double[3], du = new double[3], dv = new double[3];
        List<String> bad = new ArrayList<>();
        for (double[] r : o.section("points")) {
            int f = (int) r[0];
            if (faces.get(f)[2] == 1) continue; // regular: FaceSurfaceTest
            if (!AdaptiveFaceSurface.supported(cm.base, cm.options(), f)) {
                COUNTS.incrementAndGet(2);
                continue;
            }
            // One evaluator per face, of the face's one-ring (all its descent needs).
            if (f != surfaceFace) {
                PatchRefiner.Local local = refiner.local(f);
                surface = AdaptiveFaceSurface.of(local.mesh(), local.face(), smooth, sharp);
                surfaceFace = f;
            }
            if (!surface.evaluate(r[1], r[2], p, du, dv)) {
                COUNTS.incrementAndGet(1);
                bad.add("face " + f + " at (" + r[1] + ", " + r[2] + ") not evaluated");
                continue;
            }
            COUNTS.incrementAndGet(0);
            double e = 0;
            for (int d = 0; d < 3; d++) {
                e = Math.max(e, Math.abs(p[d] - r[3 + d]));
                e = Math.max(e, Math.abs(du[d] - r[6 + d]));
                e = Math.max(e, Math.abs(dv[d] - r[9 + d]));
            }
            e /= size;
            synchronized (AdaptiveFaceSurfaceTest.class) {
                worst = Math.max(worst, e);
                WORST.merge(cm.options().scheme().keyword(), new double[] {1, e}, (a, b) -> new double[] {a[0] + b[0], Math.max(a[1], b[1])});
            }
            if (!(e <= FaceSurfaceTest.TOL)) bad.add("face " + f + " at (" + r[1] + ", " + r[2] + "): error " + e);
        }
        assertTrue(bad.isEmpty(), () -> shape + ": " + bad.size() + " mismatches:\n  " + String.join("\n  ", bad.subList(0, Math.min(10, bad.size()))));
    }

    @AfterAll
    static void report() {
        System.out.printf("AdaptiveFaceSurfaceTest catmark and loop: %d irregular points checked (worst error %.3g of the size), %d not evaluated, %d on unsupported faces%n",
                COUNTS.get(0), worst, COUNTS.get(1), COUNTS.get(2));
        WORST.forEach((k, v) -> System.out.printf("AdaptiveFaceSurfaceTest %s: %d irregular points, worst error %.3g of the size%n", k, (int) v[0], v[1]));
    }
}
