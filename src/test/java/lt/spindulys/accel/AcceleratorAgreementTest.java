package lt.spindulys.accel;

import static lt.spindulys.accel.BvhTest.compare;
import static lt.spindulys.accel.BvhTest.soup;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.scene.GObject;
import lt.spindulys.trace.TracedObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.scene.TriangleMesh;

/**
 * Every real structure against brute force, 100,000 seeded rays per input: a random soup, a
 * closed mesh with faces on axis planes, and the two levels of a scene together. The inputs that
 * break naive builds are in {@link AcceleratorDegenerateInputTest}.
 */
class AcceleratorAgreementTest {

    static void mesh(AcceleratorKind kind, double[] coords, long seed) {
        TriangleMesh m = new TriangleMesh(TestMeshes.soup(coords));
        compare(m, build(kind, m), BvhTest.around(m), 100_000, seed);
    }

    /**
     * The structure {@code kind} names, as the scene builds it ({@code AcceleratorKind.build} is
     * the scene package's own; scene.AcceleratorKindTest checks that it agrees with this).
     */
    static Accelerator build(AcceleratorKind kind, PrimitiveSet set) {
        return switch (kind) {
            case BVH -> WideBvh.build(set, true);
            case BVH_COMPACT -> WideBvh.widen(new Bvh(set));
            case BVH2 -> new Bvh(set);
            case OCTREE -> new Octree(set);
            case BRUTE_FORCE -> new BruteForce(set);
        };
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH_COMPACT", "BVH2", "OCTREE"})
    void randomSoup(AcceleratorKind kind) {
        mesh(kind, soup(new Random(101), 150, 0.005, 0.2), 102);
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH_COMPACT", "BVH2", "OCTREE"})
    void closedGridWithFacesOnCellPlanes(AcceleratorKind kind) {
        // Faces at multiples of 1/2 from the low corner: exactly on octree cell planes from level 2 on.
        TriangleMesh m = new TriangleMesh(TestMeshes.gridCube(4));
        compare(m, build(kind, m), new Bounds(-2, -2, -2, 2, 2, 2), 100_000, 109);
    }

    /** A scene of transformed meshes: the object level and the triangle level both of one kind. */
    private static Scene scene(AcceleratorKind kind, long seed) {
        Random r = new Random(seed);
        SceneBuilder b = new SceneBuilder().settings(RenderSettings.builder().accelerator(kind).build());
        MeshData sphere = TestMeshes.icosphere(2, 1);
        for (int i = 0; i < 30; i++) {
            TriangleMesh m = new TriangleMesh(sphere);
            double s = 0.2 + r.nextDouble();
            m.transform(Transform.scale(s, s * (0.5 + r.nextDouble()), s).then(Transform.translate(r.nextDouble() * 10, r.nextDouble() * 10, r.nextDouble() * 10)));
            b.add(m);
        }
        for (int i = 0; i < 5; i++) {
            // Flat soups: a mesh whose own structure faces the one-plane case inside the scene.
            double[] c = soup(r, 100, 0.05, 0.5);
            for (int k = 1; k < c.length; k += 3) c[k] = 0;
            TriangleMesh m = new TriangleMesh(TestMeshes.soup(c));
            m.transform(Transform.scale(5, 1, 5).then(Transform.translate(r.nextDouble() * 5, r.nextDouble() * 10, r.nextDouble() * 5)));
            b.add(m);
        }
        return b.build();
    }

    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH_COMPACT", "BVH2", "OCTREE"})
    void twoLevelSceneAgreesWithBruteForceAtBothLevels(AcceleratorKind kind) {
        Scene fast = scene(kind, 110), slow = scene(AcceleratorKind.BRUTE_FORCE, 110);
        Random r = new Random(111);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit hf = new Hit(), hs = new Hit();
        int hits = 0;
        for (int i = 0; i < 8_000; i++) {
            double dx = r.nextGaussian(), dy = r.nextGaussian(), dz = r.nextGaussian();
            if (i % 4 == 1) { dx = 0; dz = 0; } // axis-parallel, through the flat meshes' plane normal
            ray.set(r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2, dx, dy, dz, 0, Double.POSITIVE_INFINITY);
            boolean s = slow.intersect(ray, hs, ctx);
            boolean f = fast.intersect(ray, hf, ctx);
            final int n = i;
            assertEquals(s, f, () -> "ray " + n + " " + ray);
            assertEquals(0, ctx.stackTop);
            if (s) {
                hits++;
                assertEquals(hs.t, hf.t, 1e-12 * hs.t, () -> "ray " + n + " " + ray);
                TracedObject os = hs.object, of = hf.object;
                if (os.id() != of.id() || hs.prim != hf.prim) assertEquals(hs.t, hf.t, () -> "a different hit must be a tie, ray " + n);
            }
            assertEquals(s, fast.occluded(ray, ctx), () -> "occluded, ray " + n + " " + ray);
            assertEquals(0, ctx.stackTop);
        }
        assertTrue(hits > 800, "hits " + hits);
    }

    /**
     * Moving objects (the thesis's octree missed them, its figure 49): the structures index each
     * object by its bounds over the whole shutter, so at any ray time they find what brute force,
     * which asks every object, finds.
     */
    @ParameterizedTest
    @EnumSource(value = AcceleratorKind.class, names = {"BVH", "BVH_COMPACT", "BVH2", "OCTREE"})
    void movingObjectsAreFoundAtEveryTime(AcceleratorKind kind) {
        Scene fast = movingScene(kind, 120), slow = movingScene(AcceleratorKind.BRUTE_FORCE, 120);
        Random r = new Random(121);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit hf = new Hit(), hs = new Hit();
        int hits = 0;
        for (int i = 0; i < 8_000; i++) {
            ray.set(r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2, r.nextDouble() * 14 - 2, r.nextGaussian(), r.nextGaussian(), r.nextGaussian(),
                    0, Double.POSITIVE_INFINITY);
            ray.time = r.nextDouble();
            boolean s = slow.intersect(ray, hs, ctx), f = fast.intersect(ray, hf, ctx);
            final int n = i;
            assertEquals(s, f, () -> "ray " + n + " " + ray);
            if (s) {
                hits++;
                assertEquals(hs.t, hf.t, 1e-12 * hs.t, () -> "ray " + n + " " + ray);
            }
            assertEquals(s, fast.occluded(ray, ctx), () -> "occluded, ray " + n + " " + ray);
        }
        assertTrue(hits > 400, "hits " + hits);
    }

    /** Spheres and meshes that travel several times their size, turn and grow during the shutter. */
    private static Scene movingScene(AcceleratorKind kind, long seed) {
        Random r = new Random(seed);
        SceneBuilder b = new SceneBuilder().settings(RenderSettings.builder().accelerator(kind).build());
        MeshData sphere = TestMeshes.icosphere(1, 1);
        for (int i = 0; i < 30; i++) {
            GObject o = i % 2 == 0 ? new lt.spindulys.scene.Sphere(lt.spindulys.math.Vec3.ZERO, 1) : new TriangleMesh(sphere);
            o.transform(Transform.scale(0.6, 0.9, 0.6).then(Transform.translate(r.nextDouble() * 10, r.nextDouble() * 10, r.nextDouble() * 10)));
            double start = 0.6 * r.nextDouble();
            o.motion(lt.spindulys.math.Motion.of(new lt.spindulys.math.Vec3(1 + r.nextDouble(), 1, 1), lt.spindulys.math.Vec3.Z, 180 * r.nextDouble(),
                    new lt.spindulys.math.Vec3(4 * r.nextGaussian(), 4 * r.nextGaussian(), 4 * r.nextGaussian()), lt.spindulys.math.Vec3.ZERO,
                    start, start + 0.1 + 0.3 * r.nextDouble()));
            b.add(o);
        }
        return b.build();
    }
}
