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
}
