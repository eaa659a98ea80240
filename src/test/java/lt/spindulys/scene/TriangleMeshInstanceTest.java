package lt.spindulys.scene;

import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.trace.ShadingData;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.io.SceneParser;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;

/** Mesh instances: several placements of one geometry, sharing its arrays and structure. */
class TriangleMeshInstanceTest {

    private static Scene scene(GObject... objects) {
        SceneBuilder b = new SceneBuilder().camera(new PinholeCamera(new Vec3(0, 0, -10), Vec3.ZERO, new Vec3(0, 1, 0), 40));
        for (GObject o : objects) b.add(o);
        return b.build();
    }

    private static Transform place(int k) {
        return Transform.rotate(new Vec3(1, 2, 3), 25 * k).then(Transform.translate(2.5 * k - 2.5, 0.3 * k, 0));
    }

    @Test
    void instancesTraceLikeIndependentCopiesAndShareEverything() {
        MeshData sphere = TestMeshes.icosphere(3, 1);
        TriangleMesh proto = new TriangleMesh(sphere);
        TriangleMesh a = proto.instance().transform(place(1));
        TriangleMesh b = a.instance().transform(place(2)); // an instance of an instance
        proto.transform(place(0));
        // Instances first: whichever is frozen first builds the shared structure.
        Scene shared = scene(b, a, proto);
        Scene copies = scene(new TriangleMesh(sphere).transform(place(2)), new TriangleMesh(sphere).transform(place(1)),
                new TriangleMesh(sphere).transform(place(0)));

        assertTrue(a.isInstance() && b.isInstance());
        assertFalse(proto.isInstance());
        // The scene's frozen copies (b, a, proto) share one structure and answer isInstance as their originals.
        TriangleMesh fb = (TriangleMesh) shared.objects().get(0), fa = (TriangleMesh) shared.objects().get(1), fp = (TriangleMesh) shared.objects().get(2);
        assertTrue(fa.isInstance() && fb.isInstance());
        assertFalse(fp.isInstance());
        assertNotNull(fp.accelerator());
        assertSame(fp.accelerator(), fa.accelerator());
        assertSame(fp.accelerator(), fb.accelerator());
        assertEquals(0, a.memoryBytes());
        assertEquals(0, fa.memoryBytes());
        assertTrue(proto.memoryBytes() > 0);
        assertEquals(proto.memoryBytes(), fp.memoryBytes());

        Random r = new Random(17);
        TraceContext ctx = new TraceContext();
        Hit hs = new Hit(), hc = new Hit();
        ShadingData ss = new ShadingData(), sc = new ShadingData();
        int hits = 0;
        for (int i = 0; i < 5_000; i++) {
            Ray ray = new Ray().set(r.nextGaussian() * 3, r.nextGaussian() * 2, -8, r.nextGaussian() * 0.3, r.nextGaussian() * 0.3, 1, 0,
                    Double.POSITIVE_INFINITY);
            boolean x = shared.intersect(ray, hs, ctx), y = copies.intersect(ray, hc, ctx);
            assertEquals(y, x);
            if (!x) continue;
            hits++;
            assertEquals(hc.t, hs.t, 1e-12 * hc.t);
            hs.object.shade(ray, hs, ss);
            hc.object.shade(ray, hc, sc);
            for (int k = 0; k < 3; k++) assertEquals(sc.ns[k], ss.ns[k], 1e-9);
            assertEquals(shared.occluded(ray, ctx), copies.occluded(ray, ctx));
        }
        assertTrue(hits > 300, "hits " + hits);
    }

    @Test
    void eachInstanceKeepsItsOwnShading() {
        TriangleMesh proto = new TriangleMesh(TestMeshes.icosphere(2, 1));
        TriangleMesh smooth = proto.instance().smooth(true);
        proto.smooth(false);
        Scene scene = scene(proto, smooth.transform(Transform.translate(3, 0, 0)));
        GObject flat = scene.objects().get(0);
        GObject built = scene.objects().get(1);
        Ray ray = new Ray().set(3.1, 0.2, -5, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
        TraceContext ctx = new TraceContext();
        Hit h = new Hit();
        assertTrue(built.intersect(ray, h.reset(ray.tMax), ctx));
        ShadingData sd = new ShadingData();
        built.shade(ray, h, sd);
        double dot = 0, nn = 0, gg = 0;
        for (int k = 0; k < 3; k++) {
            dot += sd.ns[k] * sd.ng[k];
            nn += sd.ns[k] * sd.ns[k];
            gg += sd.ng[k] * sd.ng[k];
        }
        assertTrue(dot / Math.sqrt(nn * gg) < 1 - 1e-6, "the smooth instance interpolates normals");
        Ray flatRay = new Ray().set(0.1, 0.2, -5, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
        assertTrue(flat.intersect(flatRay, h.reset(flatRay.tMax), ctx));
        flat.shade(flatRay, h, sd);
        for (int k = 0; k < 3; k++) assertEquals(sd.ng[k] / Math.sqrt(gg(sd)), sd.ns[k] / Math.sqrt(nn(sd)), 1e-12);
    }

    private static double gg(ShadingData sd) { return sd.ng[0] * sd.ng[0] + sd.ng[1] * sd.ng[1] + sd.ng[2] * sd.ng[2]; }
    private static double nn(ShadingData sd) { return sd.ns[0] * sd.ns[0] + sd.ns[1] * sd.ns[1] + sd.ns[2] * sd.ns[2]; }

    @Test
    void theSceneFileReadsAMeshFileOnceAndPlacesInstances(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("cube.obj"), TestMeshes.CUBE_OBJ);
        Path scene = dir.resolve("s.dat");
        Files.writeString(scene, """
                camera { eye 0 0 -10  lookat 0 0 0 }
                mesh { file "cube.obj" }
                mesh { file "cube.obj"  translate 3 0 0  shading smooth }
                mesh { file "./cube.obj"  translate -3 0 0 }
                """);
        Scene s = SceneParser.parse(scene).settings(lt.spindulys.scene.RenderSettings.builder().accelerator(AcceleratorKind.BVH).build()).build();
        TriangleMesh m0 = (TriangleMesh) s.objects().get(0), m1 = (TriangleMesh) s.objects().get(1), m2 = (TriangleMesh) s.objects().get(2);
        assertFalse(m0.isInstance());
        assertTrue(m1.isInstance() && m2.isInstance(), "the same file, however written, is read once");
        assertTrue(m1.isSmooth());
        assertSame(m0.accelerator(), m2.accelerator());
    }

    @Test
    void theSameSubdivisionSurfaceTwiceIsRefinedOnce(@TempDir Path dir) throws IOException {
        Files.writeString(dir.resolve("cube.obj"), TestMeshes.CUBE_OBJ);
        Path scene = dir.resolve("s.dat");
        Files.writeString(scene, """
                camera { eye 0 0 -10  lookat 0 0 0 }
                subdiv { file "cube.obj"  level 3 }
                subdiv { file "cube.obj"  level 3  translate 3 0 0 }
                subdiv { file "cube.obj"  level 2  translate -3 0 0 }
                subdiv { file "cube.obj"  level 3  shading flat  translate 0 3 0 }
                """);
        Scene s = SceneParser.parse(scene).build();
        SubdivisionSurface a = (SubdivisionSurface) s.objects().get(0), b = (SubdivisionSurface) s.objects().get(1);
        SubdivisionSurface otherLevel = (SubdivisionSurface) s.objects().get(2), flat = (SubdivisionSurface) s.objects().get(3);
        assertFalse(a.isInstance());
        assertTrue(b.isInstance());
        assertSame(a.refined(), b.refined());
        assertFalse(otherLevel.isInstance() || flat.isInstance(), "a different level or shading is another surface");
        TraceContext ctx = new TraceContext();
        Hit ha = new Hit(), hb = new Hit();
        Random r = new Random(3);
        for (int i = 0; i < 500; i++) {
            double x = r.nextDouble() * 1.6 - 0.8, y = r.nextDouble() * 1.6 - 0.8;
            Ray ra = new Ray().set(x, y, -10, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
            Ray rb = new Ray().set(x + 3, y, -10, 0, 0, 1, 0, Double.POSITIVE_INFINITY);
            boolean hitA = a.intersect(ra, ha.reset(ra.tMax), ctx), hitB = b.intersect(rb, hb.reset(rb.tMax), ctx);
            assertEquals(hitA, hitB);
            if (hitA) assertEquals(ha.t, hb.t, 1e-12);
        }
    }
}
