package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Motion;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.trace.TraceContext;

/**
 * The per-thread occluder cache of {@link Scene#occluded}: the object and part that last blocked
 * a slot's shadow ray are tested first, and that test says true only where the full query does,
 * so shadows (and images) are the same with and without it; a context carries no occluder from
 * one scene to another.
 */
class OccluderCacheTest {
    /** Meshes (one moving, one transformed), a subdivision surface, spheres, a box, a CSG difference and a plane. */
    private static Scene scene() {
        SceneBuilder b = new SceneBuilder().settings(RenderSettings.builder().shutter(0, 1).build());
        MeshData ico = TestMeshes.icosphere(2, 1);
        TriangleMesh still = new TriangleMesh(ico);
        still.transform(Transform.scale(1.5, 0.6, 1).then(Transform.translate(-2, 1, 0)));
        TriangleMesh moving = new TriangleMesh(ico);
        moving.transform(Transform.translate(2, 1, 0)).motion(Motion.translation(new Vec3(0, 0, 1.5), 0, 1));
        MeshData c = TestMeshes.cube();
        SubdivisionSurface subdiv = new SubdivisionSurface(ControlMesh.builder(c.positions(), c.faceSizes(), c.vertexIndex()).build(), 2);
        subdiv.transform(Transform.translate(0, 1.2, 2));
        Bool cut = new Bool(Bool.Op.DIFFERENCE, List.of(new Box(new Vec3(-1, 0, -1), new Vec3(1, 1.5, 1)), new Sphere(new Vec3(0, 1.5, 0), 0.9)));
        cut.transform(Transform.translate(0, 0, -2.5));
        b.add(still).add(moving).add(subdiv).add(cut)
                .add(new Sphere(new Vec3(0.5, 2.5, 0.5), 0.4)).add(new Box(new Vec3(-3, 2, 2), new Vec3(-2, 2.3, 3)))
                .add(new Plane(new Vec3(0, 1, 0), -3)); // unbounded, below the points the rays start from
        return b.build();
    }

    @Test
    void cachedOccluderBlocksOnlyWhereTheFullQueryDoes() {
        Scene scene = scene();
        Random r = new Random(2031);
        TraceContext warm = new TraceContext();
        Ray ray = new Ray();
        int blocked = 0, answeredByCache = 0;
        // Batches of shadow rays from neighbouring points towards neighbouring spots of a square
        // light above the objects, each spot its own slot, as the integrator sends them.
        for (int batch = 0; batch < 300; batch++) {
            double bx = 8 * r.nextDouble() - 4, bz = 8 * r.nextDouble() - 4;
            for (int k = 0; k < 64; k++) {
                int slot = k % 16;
                double ox = bx + 0.05 * r.nextGaussian(), oz = bz + 0.05 * r.nextGaussian(), oy = 0.01 * r.nextDouble();
                double lx = -1 + 0.5 * (slot % 4) + 0.5 * r.nextDouble(), lz = -1 + 0.5 * (slot / 4) + 0.5 * r.nextDouble();
                ray.set(ox, oy, oz, lx - ox, 6 - oy, lz - oz, 0, 1 - 1e-7);
                ray.time = r.nextDouble();
                warm.occluderSlot = slot;
                GObject cached = warm.occluderScene == scene ? (GObject) warm.occluders[slot] : null;
                boolean byCache = cached != null && cached.occludedByPart(ray, warm.occluderParts[slot], new TraceContext());
                boolean full = scene.occluded(ray, new TraceContext()); // a fresh context: no cache
                if (byCache) {
                    answeredByCache++;
                    assertTrue(full, "the cached occluder blocks a ray nothing blocks: " + ray);
                }
                assertEquals(full, scene.occluded(ray, warm), "with the cache: " + ray);
                if (full) blocked++;
            }
        }
        assertTrue(blocked > 1000, "blocked rays " + blocked);
        assertTrue(answeredByCache > blocked / 8, "the cache answered " + answeredByCache + " of " + blocked + " blocked rays");
    }

    /** Only objects that name a cheap part are kept: a mesh's triangle, a sphere; not a CSG node. */
    @Test
    void keepsTrianglesAndSimpleShapesButNotCsgNodes() {
        Scene scene = scene();
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        ctx.occluderSlot = 3;
        ray.set(-2, -1, 0, 0, 4, 0, 0, 1); // up through the still mesh
        assertTrue(scene.occluded(ray, ctx));
        assertTrue(ctx.occluders[3] instanceof TriangleMesh);
        int triangle = ctx.occluderParts[3];
        assertTrue(triangle >= 0 && triangle < ((TriangleMesh) ctx.occluders[3]).triangleCount());
        ctx.occluderSlot = 4;
        ray.set(0.5, 1.8, 0.5, 0, 1, 0, 0, 1); // up into the small sphere only
        assertTrue(scene.occluded(ray, ctx));
        assertTrue(ctx.occluders[4] instanceof Sphere);
        ctx.occluderSlot = 5;
        ray.set(0, 0.5, -4.5, 0, 0, 2, 0, 1); // into the CSG box's side, below the bite
        assertTrue(scene.occluded(ray, ctx));
        assertEquals(null, ctx.occluders[5]);
        assertNotNull(ctx.occluders[3], "other slots keep theirs");
    }

    @Test
    void aContextCarriesNoOccluderToAnotherScene() {
        Scene first = scene(), empty = new SceneBuilder().add(new Sphere(new Vec3(50, 50, 50), 1)).build();
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray().set(-2, -1, 0, 0, 4, 0, 0, 1);
        assertTrue(first.occluded(ray, ctx));
        assertFalse(empty.occluded(ray, ctx));
        assertTrue(first.occluded(ray, ctx));
    }

    @Test
    void motionAnywhereInTheTreeMakesTheSceneMove() {
        assertFalse(new SceneBuilder().add(new Sphere(Vec3.ZERO, 1)).build().hasMovingObjects());
        Sphere leaf = new Sphere(Vec3.ZERO, 1);
        leaf.motion(Motion.translation(new Vec3(1, 0, 0), 0, 1));
        Bool u = new Bool(Bool.Op.UNION, List.of(new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1)), leaf));
        assertTrue(new SceneBuilder().add(u).build().hasMovingObjects());
    }
}
