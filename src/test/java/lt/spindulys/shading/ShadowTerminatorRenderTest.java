package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.IntegratorKind;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.TestMeshes;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.ShadingData;
import lt.spindulys.trace.TraceContext;

/**
 * The shadow terminator offset in both integrators: a coarse smooth-shaded sphere lit from the
 * side loses most of its stair-stepped self-shadow where its shading says it is lit, and a closed
 * smooth mesh still lets no light from outside reach its inside.
 */
class ShadowTerminatorRenderTest {
    private static final int SIZE = 128;
    private static final Vec3 LIGHT = new Vec3(300, 40, -20);

    private static Scene sphereScene(IntegratorKind kind, boolean terminator) {
        TriangleMesh ball = new TriangleMesh(TestMeshes.icosphere(0, 1)).smooth(true);
        ball.shadowTerminator(terminator);
        ball.material(Material.builder().color(Color.WHITE).ka(0).kd(1).ks(0).build());
        return new SceneBuilder()
                .settings(RenderSettings.builder().size(SIZE, SIZE).samplesPerPixel(1).maxDepth(kind == IntegratorKind.PATH ? 1 : 0)
                        .ambient(Color.BLACK).background(Color.BLACK).srgb(false).integrator(kind).build())
                .camera(new OrthographicCamera(new Vec3(0, 0, 5), Vec3.ZERO, Vec3.Y, 2.2))
                .light(new PointLight(LIGHT, Color.WHITE))
                .add(ball).build();
    }

    /**
     * Pixels whose shading normal faces the light (n.l above 0.1) but which the render shows
     * shadowed (under a quarter of the unshadowed value, kd n.l, in both the lifted and the plain render's terms).
     */
    private static int shadowedButLit(IntegratorKind kind, boolean terminator) throws InterruptedException {
        Scene scene = sphereScene(kind, terminator);
        FrameBuffer image = Renderer.render(scene, 2, ProgressListener.NONE).frame();
        OrthographicCamera camera = new OrthographicCamera(new Vec3(0, 0, 5), Vec3.ZERO, Vec3.Y, 2.2);
        Ray ray = new Ray();
        Hit hit = new Hit();
        ShadingData sd = new ShadingData();
        TraceContext ctx = new TraceContext();
        int count = 0, lit = 0;
        for (int y = 0; y < SIZE; y++) {
            for (int x = 0; x < SIZE; x++) {
                camera.generateRay((x + 0.5) / SIZE, (y + 0.5) / SIZE, 1, 0.5, 0.5, 0, ray);
                if (!scene.intersect(ray, hit, ctx)) continue;
                hit.object.shade(ray, hit, sd);
                double lx = LIGHT.x() - sd.p[0], ly = LIGHT.y() - sd.p[1], lz = LIGHT.z() - sd.p[2];
                double l = Math.sqrt(lx * lx + ly * ly + lz * lz);
                double cos = (sd.ns[0] * lx + sd.ns[1] * ly + sd.ns[2] * lz) / l;
                if (cos <= 0.1) continue;
                lit++;
                // A Lambertian white surface under a white light: kd n.l (the path tracer's 1/pi aside).
                double expected = kind == IntegratorKind.PATH ? cos / Math.PI : cos;
                if (image.get(x, y, 1) < 0.25 * expected) count++;
            }
        }
        assertTrue(lit > 2000, "lit pixels " + lit);
        return count;
    }

    @ParameterizedTest
    @EnumSource(IntegratorKind.class)
    void theOffsetRemovesMostOfTheSelfShadowWhereTheShadingIsLit(IntegratorKind kind) throws InterruptedException {
        int before = shadowedButLit(kind, false), after = shadowedButLit(kind, true);
        System.out.println(kind + ": lit by the shading but shadowed: " + before + " pixels on the facets, " + after + " lifted");
        assertTrue(before > 50, "the coarse sphere shadows itself without the offset: " + before);
        assertTrue(after * 5 < before, "with the offset " + after + " of " + before);
    }

    @ParameterizedTest
    @EnumSource(IntegratorKind.class)
    void aClosedSmoothMeshLetsNoLightFromOutsideIn(IntegratorKind kind) throws InterruptedException {
        // Camera inside a coarse smooth sphere (and a smooth cube) whose surfaces the light outside lights from without.
        for (TriangleMesh shell : new TriangleMesh[] {
                new TriangleMesh(TestMeshes.icosphere(1, 2)).smooth(true), new TriangleMesh(TestMeshes.gridCube(2)).smooth(true)}) {
            shell.material(Material.builder().color(Color.WHITE).ka(0).kd(1).ks(0).build());
            Scene scene = new SceneBuilder()
                    .settings(RenderSettings.builder().size(48, 48).samplesPerPixel(kind == IntegratorKind.PATH ? 4 : 1).maxDepth(4)
                            .ambient(Color.BLACK).background(Color.BLACK).srgb(false).integrator(kind).build())
                    .camera(new PinholeCamera(new Vec3(0.1, 0.05, 0), new Vec3(1, 0.1, 0.2), Vec3.Y, 100))
                    .light(new PointLight(new Vec3(3, 0.5, 0.4), Color.WHITE))
                    .light(new PointLight(new Vec3(-2.5, 2.5, -2), Color.WHITE))
                    .add(shell).build();
            FrameBuffer image = Renderer.render(scene, 2, ProgressListener.NONE).frame();
            for (int y = 0; y < 48; y++)
                for (int x = 0; x < 48; x++)
                    for (int c = 0; c < 3; c++) assertEquals(0, image.get(x, y, c), 0, "pixel " + x + ", " + y);
        }
    }

    /**
     * The square [-1, 1]^2 in y = 0 facing up, an 8 x 8 grid whose vertex normals all lean 30
     * degrees towards +x; with {@code offPlane}, a tiny far triangle below makes the mesh not flat.
     */
    private static TriangleMesh leaningSquare(boolean offPlane) {
        int n = 8, v = (n + 1) * (n + 1);
        double[] pos = new double[3 * v + 9], normals = new double[pos.length];
        for (int j = 0; j <= n; j++)
            for (int i = 0; i <= n; i++) {
                int k = 3 * (j * (n + 1) + i);
                pos[k] = -1 + 2.0 * i / n; pos[k + 2] = -1 + 2.0 * j / n;
            }
        double[] far = {0, -50, 0, 0.01, -50, 0, 0, -50, 0.01};
        System.arraycopy(far, 0, pos, 3 * v, 9);
        for (int k = 0; k < pos.length / 3; k++) { normals[3 * k] = 0.5; normals[3 * k + 1] = Math.sqrt(0.75); }
        int cells = n * n, tris = 2 * cells + (offPlane ? 1 : 0);
        int[] idx = new int[3 * tris], sizes = new int[tris];
        java.util.Arrays.fill(sizes, 3);
        for (int j = 0, t = 0; j < n; j++)
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                // Wound to face +y.
                idx[t++] = a; idx[t++] = c; idx[t++] = b;
                idx[t++] = a; idx[t++] = d; idx[t++] = c;
            }
        if (offPlane) { idx[6 * cells] = v; idx[6 * cells + 1] = v + 1; idx[6 * cells + 2] = v + 2; }
        TriangleMesh square = new TriangleMesh(new lt.spindulys.mesh.MeshData(pos, normals, null, sizes, idx, idx, null, "leaning square")).smooth(true);
        square.material(Material.builder().color(Color.WHITE).ka(0).kd(1).ks(0).build());
        return square;
    }

    @ParameterizedTest
    @EnumSource(IntegratorKind.class)
    void aFlatMeshLitFromBehindIsLitAsTheSameMeshNotFlat(IntegratorKind kind) throws InterruptedException {
        // Lit only from below at a grazing angle that the leaning normals face, the lifted shadow
        // rays must still meet the square itself: a flat receiver's shadow rays otherwise skip it.
        // The lift is small beside the square (a fraction of a cell), so most rays cross it.
        FrameBuffer[] images = new FrameBuffer[2];
        for (int k = 0; k < 2; k++) {
            TriangleMesh square = leaningSquare(k == 1);
            assertEquals(k == 0, square.flat());
            Scene scene = new SceneBuilder()
                    .settings(RenderSettings.builder().size(32, 32).samplesPerPixel(1).maxDepth(1)
                            .ambient(Color.BLACK).background(Color.BLACK).srgb(false).integrator(kind).build())
                    .camera(new OrthographicCamera(new Vec3(0, 5, 0), Vec3.ZERO, Vec3.Z, 2))
                    .light(new PointLight(new Vec3(30, -2, 0), Color.WHITE))
                    .add(square).build();
            if (k == 0) {
                // The light does reach the leaning normals' side: the test is not vacuous.
                Ray ray = new Ray();
                Hit hit = new Hit();
                ShadingData sd = new ShadingData();
                ray.set(0.1, 5, 0.1, 0, -1, 0, 0, Double.POSITIVE_INFINITY);
                assertTrue(scene.intersect(ray, hit, new TraceContext()));
                hit.object.shade(ray, hit, sd);
                assertTrue(sd.lifted && sd.ns[0] * 30 + sd.ns[1] * -2 > 0, "the shading normal faces the light below");
            }
            images[k] = Renderer.render(scene, 2, ProgressListener.NONE).frame();
        }
        // Near the +x edge a lifted ray passes beside the square and the light is seen (an open
        // sheet does not block it); elsewhere the square blocks it, flat or not.
        int dark = 0;
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++) {
                if (images[1].get(x, y, 1) == 0) dark++;
                for (int c = 0; c < 3; c++) assertEquals(images[1].get(x, y, c), images[0].get(x, y, c), 1e-12, "pixel " + x + ", " + y);
            }
        assertTrue(dark > 32 * 32 / 2, "dark pixels " + dark);
    }

    @org.junit.jupiter.api.Test
    void theLiftedPointFollowsTheObjectsTransform() {
        // An icosahedron scaled by 2 about (1, 2, 3): its lifted points lie nearer the sphere of radius 2.
        TriangleMesh ball = new TriangleMesh(TestMeshes.icosphere(0, 1)).smooth(true);
        ball.transform(lt.spindulys.math.Transform.scale(2, 2, 2).then(lt.spindulys.math.Transform.translate(1, 2, 3)));
        Scene scene = new SceneBuilder().add(ball).build();
        Ray ray = new Ray();
        Hit hit = new Hit();
        ShadingData sd = new ShadingData();
        TraceContext ctx = new TraceContext();
        int lifted = 0;
        for (int i = 0; i < 100; i++) {
            double ox = 1 + 1.6 * (i % 10 / 9.0 - 0.5), oy = 2 + 1.6 * (i / 10 / 9.0 - 0.5);
            ray.set(ox, oy, 10, 0, 0, -1, 0, Double.POSITIVE_INFINITY);
            assertTrue(scene.intersect(ray, hit, ctx));
            hit.object.shade(ray, hit, sd);
            if (!sd.lifted) continue;
            lifted++;
            double[] p = sd.p, q = sd.shadowOrigin;
            double rp = Math.sqrt((p[0] - 1) * (p[0] - 1) + (p[1] - 2) * (p[1] - 2) + (p[2] - 3) * (p[2] - 3));
            double rq = Math.sqrt((q[0] - 1) * (q[0] - 1) + (q[1] - 2) * (q[1] - 2) + (q[2] - 3) * (q[2] - 3));
            // Blended tangent planes may overshoot a coarse sphere a little, never by as much as the facet lies inside it.
            assertTrue(rq > rp && Math.abs(2 - rq) < 2 - rp, "from " + rp + " to " + rq);
        }
        assertTrue(lifted > 80, "lifted " + lifted);
    }
}
