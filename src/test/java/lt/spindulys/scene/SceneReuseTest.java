package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.Camera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.io.ObjReader;
import lt.spindulys.material.Material;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;

/**
 * Objects are descriptions that building never changes: one object in several scenes, a builder
 * that builds again after a change, shared mesh structures, and the build context that tells an
 * object the view.
 */
class SceneReuseTest {
    private static final Camera CAMERA = new PinholeCamera(new Vec3(0, 1, -6), new Vec3(0, 0.5, 0), Vec3.Y, 45);
    private static final Material RED = Material.builder().color(new Color(0.9, 0.2, 0.1)).kd(0.8).ks(0.3).shininess(20).build();

    private static SceneBuilder builder() {
        return new SceneBuilder().settings(RenderSettings.builder().size(48, 36).build()).camera(CAMERA)
                .light(new PointLight(new Vec3(4, 6, -5), Color.WHITE));
    }

    private static double[] render(Scene s) throws InterruptedException {
        return Renderer.render(s, 1, ProgressListener.NONE).frame().data().clone();
    }

    private static double hitT(Scene s, double ox, double oy, double oz) {
        Ray r = new Ray().set(ox, oy, oz, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
        Hit h = new Hit();
        return s.intersect(r, h, new TraceContext()) ? h.t : Double.NaN;
    }

    @Test
    void anObjectInTwoScenesRendersIdenticallyInBoth() throws InterruptedException {
        Sphere ball = new Sphere(new Vec3(0, 1, 0), 1).material(RED);
        TriangleMesh mesh = new TriangleMesh(TestMeshes.icosphere(2, 0.5)).transform(Transform.translate(1.5, 0.5, 0));
        Plane floor = new Plane(Vec3.Y, 0);
        Scene a = builder().add(ball).add(mesh).add(floor).build();
        Scene b = builder().add(floor).add(ball).add(mesh).build();
        // Another order of adding gives other ids and another order of tests, the same picture.
        assertArrayEquals(render(a), render(b));
        assertEquals(List.of(0, 1, 2), a.objects().stream().map(GObject::id).toList());
        assertSame(Sphere.class, b.objects().get(1).getClass());
        assertEquals(1, b.objects().get(1).id());
        // The caller's objects are untouched descriptions; the scenes hold frozen copies.
        for (GObject o : List.<GObject>of(ball, mesh, floor)) {
            assertFalse(o.isFrozen(), o.name());
            assertEquals(-1, o.id());
            assertTrue(a.objects().stream().noneMatch(f -> f == o));
        }
        assertTrue(a.objects().stream().allMatch(GObject::isFrozen));
        assertNotSame(a.objects().get(0), b.objects().get(1));
    }

    @Test
    void changingATransformAndBuildingAgainMovesTheObjectAndLeavesTheFirstSceneAlone() throws InterruptedException {
        Sphere ball = new Sphere(Vec3.ZERO, 1);
        SceneBuilder b = builder().add(ball);
        Scene first = b.build();
        double[] firstImage = render(first);
        assertEquals(4, hitT(first, 0, 0, -5), 1e-12);

        ball.transform(Transform.translate(0, 0, 2)); // the next frame
        Scene second = b.build();                      // the same builder builds again
        assertEquals(6, hitT(second, 0, 0, -5), 1e-12);
        assertEquals(4, hitT(first, 0, 0, -5), 1e-12, "the first scene keeps its own copy");
        assertArrayEquals(firstImage, render(first));
        assertFalse(java.util.Arrays.equals(firstImage, render(second)));

        // A material and a motion given after a build are in the next one only.
        ball.material(RED).motion(Motion.linear(Vec3.X, 1, Double.NaN, Double.NaN)); // open: the shutter's times
        Scene third = b.build();
        assertSame(RED, third.objects().get(0).material());
        assertTrue(third.objects().get(0).isMoving());
        assertSame(Material.DEFAULT, second.objects().get(0).material());
        assertFalse(second.objects().get(0).isMoving());
        assertFalse(ball.isFrozen());
        assertFalse(ball.motion().isResolved(), "the caller's motion is not resolved in place");
        assertTrue(third.objects().get(0).motion().isResolved());
    }

    @Test
    void oneObjectMayBeAddedTwiceAndBeAnOperandOfTwoBools() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        Bool u = new Bool(Bool.Op.UNION, List.of(s, new Sphere(new Vec3(0.5, 0, 0), 1))).transform(Transform.translate(-3, 0, 0));
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(new Box(new Vec3(-1, -1, -1), new Vec3(1, 1, 1)), s)).transform(Transform.translate(3, 0, 0));
        Scene scene = builder().add(s).add(s).add(u).add(d).build();
        assertEquals(2 + 3 + 3, scene.objectIdCount());
        Bool fu = (Bool) scene.objects().get(2), fd = (Bool) scene.objects().get(3);
        // Each place has its own frozen copy, each marked with its own solid.
        assertNotSame(fu.operands().get(0), fd.operands().get(1));
        assertSame(fu, fu.operands().get(0).solid());
        assertSame(fd, fd.operands().get(1).solid());
        assertSame(s, s.solid());
        // The sphere as itself at the origin, in the union at x = -3, cut out of the box at x = 3.
        assertEquals(4, hitT(scene, 0, 0, -5), 1e-12);
        assertEquals(4, hitT(scene, -3, 0, -5), 1e-12);
        assertEquals(4, hitT(scene, 3, 0.5, -5), 1e-12, "the box's face");
        // From inside the hollow the sphere cut, the first surface is where the sphere leaves the box.
        assertEquals(0.5 + Math.sqrt(0.75), hitT(scene, 3, 0.5, -0.5), 1e-9);
    }

    @Test
    void aSceneObjectCannotBeAddedAgainAndRefusesChanges() {
        Scene scene = builder().add(new Sphere(Vec3.ZERO, 1).name("ball")).build();
        GObject frozen = scene.objects().get(0);
        assertEquals("ball is an object of a built scene; add the object it was built from",
                assertThrows(IllegalArgumentException.class, () -> builder().add(frozen)).getMessage());
        assertThrows(IllegalStateException.class, () -> frozen.transform(Transform.translate(1, 0, 0)));
    }

    @Test
    void aMeshInTwoScenesSharesItsStructureBuiltOnce() throws Exception {
        TriangleMesh mesh = new TriangleMesh(TestMeshes.icosphere(3, 1));
        Scene a = builder().add(mesh).build();
        mesh.transform(Transform.translate(0, 1, 0));
        Scene b = builder().add(mesh).add(mesh).build();
        TriangleMesh fa = (TriangleMesh) a.objects().get(0), fb = (TriangleMesh) b.objects().get(0), fc = (TriangleMesh) b.objects().get(1);
        assertNotNull(fa.accelerator());
        assertSame(fa.accelerator(), fb.accelerator());
        assertSame(fa.accelerator(), fc.accelerator());
        assertFalse(fa.isInstance(), "a copy answers as the mesh it was made from");
        assertEquals(mesh.memoryBytes(), fa.memoryBytes());
        // Another kind of structure is another (shared) structure.
        Scene brute = builder().settings(RenderSettings.builder().size(48, 36).accelerator(AcceleratorKind.OCTREE).build()).add(mesh).build();
        assertNotSame(fa.accelerator(), ((TriangleMesh) brute.objects().get(0)).accelerator());

        // A subdivision surface's triangles are shared the same way.
        SubdivisionSurface surface = new SubdivisionSurface(ObjReader.parseSubdiv(TestMeshes.CUBE_OBJ, "cube.obj").toControlMesh(), 2);
        Scene s1 = builder().add(surface).build(), s2 = builder().add(surface.transform(Transform.rotateY(30))).build();
        SubdivisionSurface f1 = (SubdivisionSurface) s1.objects().get(0), f2 = (SubdivisionSurface) s2.objects().get(0);
        assertSame(f1.refined(), f2.refined());
        assertFalse(f1.isInstance());
        assertTrue(hitT(s2, 0, 0, -5) > 0);

        // Scenes built at once on several threads from a new mesh still build its structure once.
        TriangleMesh fresh = new TriangleMesh(TestMeshes.icosphere(4, 1));
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<Scene>> builds = new ArrayList<>();
            for (int i = 0; i < 8; i++) builds.add(pool.submit(() -> builder().add(fresh).build()));
            Object first = null;
            for (Future<Scene> f : builds) {
                Object structure = ((TriangleMesh) f.get().objects().get(0)).accelerator();
                if (first == null) first = structure;
                assertSame(first, structure);
            }
        } finally {
            pool.shutdownNow();
        }
    }

    /** A test object that records what its build context says. */
    private static final class ViewProbe extends GObject {
        BuildContext seen;

        @Override public String kind() { return "probe"; }
        @Override public Bounds localBounds() { return new Bounds(-1, -1, -1, 1, 1, 1); }
        @Override public boolean isClosed() { return true; }
        @Override protected boolean intersectLocal(Ray ray, Hit hit, TraceContext ctx) { return false; }
        @Override protected void spansLocal(Ray ray, lt.spindulys.trace.SpanBuffer out, TraceContext ctx) {}
        @Override protected void shadeLocal(double x, double y, double z, Hit hit, ShadingData sd) {}

        @Override
        protected int freeze(BuildContext context, int ids) {
            seen = context;
            return super.freeze(context, ids);
        }
    }

    @Test
    void anObjectSeesTheCameraFilmAndShutterWhenTheSceneIsBuilt() {
        ViewProbe top = new ViewProbe(), operand = new ViewProbe();
        Material blue = Material.builder().color(new Color(0.1, 0.2, 0.9)).build();
        Bool holder = new Bool(Bool.Op.UNION, List.of(operand, new Sphere(Vec3.ZERO, 1))).material(blue).transform(Transform.translate(0, 2, 0));
        RenderSettings settings = RenderSettings.builder().size(320, 200).shutter(0.25, 0.75).accelerator(AcceleratorKind.BVH).build();
        Scene scene = new SceneBuilder().settings(settings).camera(CAMERA).add(top).add(holder).build();
        assertNull(top.seen, "the caller's object is not the one built");

        BuildContext atTop = ((ViewProbe) scene.objects().get(0)).seen;
        assertSame(CAMERA, atTop.camera());
        assertEquals(320, atTop.width());
        assertEquals(200, atTop.height());
        assertEquals(0.25, atTop.shutterOpen());
        assertEquals(0.75, atTop.shutterClose());
        assertSame(AcceleratorKind.BVH, atTop.accelerator());
        assertSame(Material.DEFAULT, atTop.material());
        assertEquals(Transform.IDENTITY, atTop.placement().staticTransform());

        // An operand gets a derived context: the Bool's placement and material, the same view.
        BuildContext inside = ((ViewProbe) ((Bool) scene.objects().get(1)).operands().get(0)).seen;
        assertSame(CAMERA, inside.camera());
        assertEquals(320, inside.width());
        assertEquals(200, inside.height());
        assertEquals(0.25, inside.shutterOpen());
        assertEquals(0.75, inside.placement().close());
        assertSame(blue, inside.material());
        assertEquals(Transform.translate(0, 2, 0), inside.placement().staticTransform());
    }
}
