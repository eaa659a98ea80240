package lt.spindulys.scene;

import lt.spindulys.material.Material;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.SpanBuffer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.mesh.MeshData;

/**
 * Rays from inside a closed mesh must hit it, whatever they pass through: shared edges and
 * vertices included, through each real acceleration structure. Every count below is exact.
 */
class MeshWatertightTest {

    /** A point strictly inside: inside the inscribed radius of the sphere or inside the cube. */
    private interface Interior {
        void sample(Random r, double[] out);
    }

    /**
     * Shoots {@code rays} rays from interior points: a third aimed exactly at vertices, a third at
     * points of edges (midpoints and random points along them), a third in random directions.
     * Returns the number of rays that found no hit or no span around their origin.
     */
    private static int misses(TriangleMesh m, Interior inside, int rays, long seed) {
        double[] p = m.data().positions();
        Random r = new Random(seed);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit h = new Hit();
        SpanBuffer spans = new SpanBuffer();
        double[] o = new double[3];
        Transform toWorld = m.transform();
        int misses = 0;
        for (int i = 0; i < rays; i++) {
            inside.sample(r, o);
            double dx, dy, dz;
            if (i % 3 == 2) {
                dx = r.nextGaussian(); dy = r.nextGaussian(); dz = r.nextGaussian();
            } else {
                int t = r.nextInt(m.triangleCount()), c = r.nextInt(3);
                int a = 3 * m.triangleVertex(t, c), b = 3 * m.triangleVertex(t, (c + 1) % 3);
                double f = i % 3 == 0 ? 0 : r.nextBoolean() ? 0.5 : r.nextDouble();
                dx = p[a] + f * (p[b] - p[a]) - o[0];
                dy = p[a + 1] + f * (p[b + 1] - p[a + 1]) - o[1];
                dz = p[a + 2] + f * (p[b + 2] - p[a + 2]) - o[2];
            }
            // Object-space ray mapped to world space, so transformed meshes are tested through their transform.
            var wo = toWorld.point(new lt.spindulys.math.Vec3(o[0], o[1], o[2]));
            var wd = toWorld.vector(new lt.spindulys.math.Vec3(dx, dy, dz));
            ray.set(wo.x(), wo.y(), wo.z(), wd.x(), wd.y(), wd.z(), 0, Double.POSITIVE_INFINITY);
            boolean hit = m.intersect(ray, h.reset(ray.tMax), ctx) && h.t > 0;
            spans.clear();
            m.spans(ray, spans, ctx);
            boolean around = spans.size() == 1 && spans.entry(0) < 0 && spans.exit(0) > 0;
            if (!hit || !around) misses++;
        }
        return misses;
    }

    private static TriangleMesh frozen(TriangleMesh m, AcceleratorKind kind) {
        TestBuild.freeze(m, Transform.IDENTITY, Material.DEFAULT, 0, kind);
        return m;
    }

    /** Inside the sphere of radius 0.9 (the icosphere's faces are all farther from its centre). */
    private static final Interior BALL = (r, out) -> {
        double x, y, z;
        do {
            x = 2 * r.nextDouble() - 1; y = 2 * r.nextDouble() - 1; z = 2 * r.nextDouble() - 1;
        } while (x * x + y * y + z * z > 0.81);
        out[0] = x; out[1] = y; out[2] = z;
    };

    /** Inside the cube, half of the time on a dyadic grid so rays pass exactly through grid vertices and edges. */
    private static final Interior BOX = (r, out) -> {
        for (int k = 0; k < 3; k++) out[k] = r.nextBoolean() ? (r.nextInt(127) - 63) / 64.0 : 1.98 * r.nextDouble() - 0.99;
    };

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void everyRayFromInsideAnIcosphereHitsIt(AcceleratorKind kind) {
        TriangleMesh m = frozen(new TriangleMesh(TestMeshes.icosphere(4, 1)), kind);
        assertTrue(m.isClosed());
        assertEquals(0, misses(m, BALL, 100_000, 1));
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void everyRayFromInsideAGridCubeHitsIt(AcceleratorKind kind) {
        TriangleMesh m = frozen(new TriangleMesh(TestMeshes.gridCube(8)), kind);
        assertTrue(m.isClosed());
        assertEquals(0, misses(m, BOX, 100_000, 2));
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void everyRayFromInsideATransformedMeshHitsIt(AcceleratorKind kind) {
        TriangleMesh m = new TriangleMesh(TestMeshes.icosphere(3, 1));
        m.transform(Transform.scale(3, 0.5, 1.5).then(Transform.rotate(new lt.spindulys.math.Vec3(1, 2, 3), 37)).then(Transform.translate(5, -2, 7)));
        frozen(m, kind);
        assertEquals(0, misses(m, BALL, 30_000, 3));
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH2", "OCTREE"})
    void raysFromTheCentreThroughEveryVertexAndEdgeMidpointHit(AcceleratorKind kind) {
        for (MeshData d : new MeshData[] {TestMeshes.icosphere(3, 1), TestMeshes.gridCube(16)}) {
            TriangleMesh m = frozen(new TriangleMesh(d), kind);
            double[] p = m.data().positions(); // the frozen mesh numbers its vertices in its own order
            TraceContext ctx = new TraceContext();
            Ray ray = new Ray();
            Hit h = new Hit();
            int misses = 0, rays = 0;
            for (int t = 0; t < m.triangleCount(); t++) {
                for (int c = 0; c < 3; c++) {
                    int a = 3 * m.triangleVertex(t, c), b = 3 * m.triangleVertex(t, (c + 1) % 3);
                    for (double f : new double[] {0, 0.5, 0.25}) {
                        ray.set(0, 0, 0, p[a] + f * (p[b] - p[a]), p[a + 1] + f * (p[b + 1] - p[a + 1]), p[a + 2] + f * (p[b + 2] - p[a + 2]),
                                0, Double.POSITIVE_INFINITY);
                        rays++;
                        if (!m.intersect(ray, h.reset(ray.tMax), ctx)) misses++;
                        else assertEquals(1, h.t, 1e-9);
                    }
                }
            }
            assertEquals(0, misses, d.source() + ": " + misses + " of " + rays);
        }
    }
}
