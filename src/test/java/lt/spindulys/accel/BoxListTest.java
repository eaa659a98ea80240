package lt.spindulys.accel;

import static lt.spindulys.accel.BvhTest.around;
import static lt.spindulys.accel.BvhTest.compare;
import static lt.spindulys.accel.BvhTest.soup;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Random;
import java.util.Set;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.trace.Hit;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.scene.TriangleMesh;

/** The box list (a scene's few objects) against brute force, as every structure is. */
class BoxListTest {

    @Test
    void agreesWithBruteForceOnOneToFourPrimitives() {
        for (int n = 1; n <= 4; n++) {
            TriangleMesh m = new TriangleMesh(TestMeshes.soup(soup(new Random(300 + n), n, 0.05, 1)));
            compare(m, new BoxList(m), around(m), 20_000, 310 + n);
        }
    }

    @Test
    void agreesWithBruteForceOnFlatBoxes() {
        // Triangles in the plane y = 0 and in x = 0.25: boxes of zero thickness, which axis rays
        // in and beside those planes must still pass or miss exactly as brute force says.
        double[] c = soup(new Random(320), 4, 0.1, 1);
        for (int k = 1; k < 18; k += 3) c[k] = 0;
        for (int k = 18; k < c.length; k += 3) c[k] = 0.25;
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(c));
        compare(m, new BoxList(m), around(m), 20_000, 321);
    }

    @Test
    void visitOffersEveryPrimitiveTheRayHits() {
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(soup(new Random(330), 4, 0.1, 1)));
        BoxList list = new BoxList(m);
        Random r = new Random(331);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        int hits = 0;
        for (int i = 0; i < 5_000; i++) {
            ray.set(r.nextGaussian(), r.nextGaussian(), r.nextGaussian(), r.nextGaussian(), r.nextGaussian(), r.nextGaussian(),
                    Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY);
            Set<Integer> offered = new HashSet<>();
            list.visit(ray, ctx, (prim, ry, c) -> offered.add(prim));
            for (int p = 0; p < m.size(); p++) {
                if (m.intersect(p, ray, new Hit().reset(ray.tMax), ctx)) {
                    hits++;
                    assertTrue(offered.contains(p), "ray " + i + " hits " + p + " but it was not offered");
                }
            }
        }
        assertTrue(hits > 100, "rays should hit: " + hits);
    }

    @Test
    void aSceneOfAFewTransformedObjectsAgreesWithTestingEachObject() {
        // A transformed object leaves its own ray's per-direction constants in the context: the
        // boxes after it must still be tested with the world ray's.
        Random r = new Random(340);
        SceneBuilder b = new SceneBuilder();
        for (int i = 0; i < 4; i++) {
            TriangleMesh m = new TriangleMesh(TestMeshes.icosphere(1, 1));
            m.transform(Transform.scale(0.5 + r.nextDouble(), 0.3 + r.nextDouble(), 1).then(Transform.rotateY(90 * r.nextDouble()))
                    .then(Transform.translate(3 * r.nextDouble(), 3 * r.nextDouble(), 3 * r.nextDouble())));
            b.add(m);
        }
        Scene scene = b.build();
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit hit = new Hit(), each = new Hit();
        int hits = 0;
        for (int i = 0; i < 20_000; i++) {
            ray.set(-2 + 7 * r.nextDouble(), -2 + 7 * r.nextDouble(), -2 + 7 * r.nextDouble(), r.nextGaussian(), r.nextGaussian(), r.nextGaussian(),
                    0, Double.POSITIVE_INFINITY);
            double nearest = Double.POSITIVE_INFINITY;
            for (var o : scene.objects()) if (o.intersect(ray, each.reset(ray.tMax), ctx)) nearest = Math.min(nearest, each.t);
            boolean found = scene.intersect(ray, hit, ctx);
            assertEquals(nearest < Double.POSITIVE_INFINITY, found, "ray " + i);
            if (found) {
                hits++;
                assertEquals(nearest, hit.t, 1e-12 * nearest, "ray " + i);
            }
            assertEquals(found, scene.occluded(ray, ctx), "occluded, ray " + i);
        }
        assertTrue(hits > 1_000, "rays should hit: " + hits);
    }

    @Test
    void aRayEntersOnlyTheBoxesItCrosses() {
        // Two unit triangles far apart: a ray at the first one never tests the second.
        double[] c = {0, 0, 0, 1, 0, 0, 0, 1, 0, 10, 0, 0, 11, 0, 0, 10, 1, 0};
        int[] tested = new int[2];
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(c));
        PrimitiveSet counting = new PrimitiveSet() {
            @Override public int size() { return m.size(); }
            @Override public void bounds(int i, double[] out) { m.bounds(i, out); }
            @Override public boolean intersect(int i, Ray ray, PrimitiveHit hit, TraversalScratch ctx) {
                tested[i]++;
                return m.intersect(i, ray, hit, ctx);
            }
        };
        BoxList list = new BoxList(counting);
        Ray ray = new Ray().set(0.25, 0.25, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
        Hit hit = new Hit().reset(ray.tMax);
        assertTrue(list.intersect(ray, hit, new TraceContext()));
        assertEquals(0, hit.prim);
        assertEquals(1, tested[0]);
        assertEquals(0, tested[1]);
        assertFalse(list.occluded(ray.set(5, 0.25, 1, 0, 0, -1, 0, Double.POSITIVE_INFINITY), new TraceContext()));
        assertEquals(0, tested[1]);
    }
}
