package lt.spindulys.light;

import static org.junit.jupiter.api.Assertions.*;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Uv;

class MeshEmitterTest {
    private static final Material GLOW = Material.builder().emission(new Color(3, 2, 1)).build();
    private static final Material DIM = Material.builder().emission(new Color(0.5, 0.5, 0.5)).build();

    /** Two quads at y = 2 and y = 3 (four triangles), the upper one dimmer, moved by a transform. */
    private static TriangleMesh twoQuads() {
        double[] p = {-1, 2, -1, 1, 2, -1, 1, 2, 1, -1, 2, 1, -0.5, 3, -0.5, 0.5, 3, -0.5, 0.5, 3, 0.5, -0.5, 3, 0.5};
        MeshData d = new MeshData(p, null, null, new int[] {4, 4}, new int[] {0, 1, 2, 3, 4, 5, 6, 7}, null, null, "quads")
                .withGroups(new int[] {0, 1}, new String[] {"low", "high"});
        TriangleMesh m = new TriangleMesh(d);
        m.groupMaterial("low", GLOW).groupMaterial("high", DIM);
        m.transform(Transform.translate(0.25, 0, 0));
        return m;
    }

    private static Lights lights(SceneBuilder b) { return Lights.withEmissiveMeshes(b.build()); }

    @Test
    void anEmittingMeshIsALightWhoseSamplesAgreeWithItsDensity() {
        lt.spindulys.scene.Scene scene = new SceneBuilder().add(twoQuads()).build();
        Lights lights = Lights.withEmissiveMeshes(scene);
        assertEquals(1, lights.all().length);
        MeshEmitter e = assertInstanceOf(MeshEmitter.class, lights.all()[0]);
        assertSame(e, lights.emitterOf(scene.objects().get(0)), "the scene's frozen mesh names its light");
        assertTrue(e.samples(GLOW) && e.samples(DIM) && !e.samples(Material.DEFAULT));
        LightSample s = new LightSample();
        SplittableRandom rnd = new SplittableRandom(3);
        int high = 0, n = 20000;
        for (int i = 0; i < n; i++) {
            assertTrue(e.sampleLi(0.1, 0, 0.2, rnd.nextDouble(), rnd.nextDouble(), s));
            assertTrue(s.x >= -0.75 && s.x <= 1.25, "within the moved quads: " + s.x);
            if (s.y > 2.5) {
                high++;
                assertEquals(0.5, s.r, 0);
            } else {
                assertEquals(3, s.r, 0);
                assertEquals(1, s.b, 0);
            }
            // The lower quad hides the upper one from below: pdfLi finds the nearest crossing.
            if (s.y < 2.5) assertEquals(s.pdf, e.pdfLi(0.1, 0, 0.2, s.wx, s.wy, s.wz), 1e-9 * s.pdf);
        }
        // Triangles are picked by area times brightness: 1 x 0.5 against 4 x 2.
        assertEquals(0.5 / 8.5, (double) high / n, 0.006);
    }

    @Test
    void movingTexturedAndDarkMeshesAreNotLights() {
        TriangleMesh moving = twoQuads();
        moving.motion(Motion.translation(new Vec3(1, 0, 0), 0, 1));
        assertEquals(0, lights(new SceneBuilder().add(moving)).all().length, "a moving mesh");
        TriangleMesh dark = twoQuads();
        dark.groupMaterial("low", Material.DEFAULT).groupMaterial("high", Material.DEFAULT);
        assertEquals(0, lights(new SceneBuilder().add(dark)).all().length, "no emission");
        TriangleMesh textured = twoQuads();
        Material varying = Material.builder().texture(Channel.EMISSION, new lt.spindulys.texture.Checker(Color.WHITE, Color.BLACK, 4, false), new Uv(1, 1)).build();
        textured.groupMaterial("low", varying).groupMaterial("high", varying);
        assertEquals(0, lights(new SceneBuilder().add(textured)).all().length, "emission a texture varies");
        assertEquals(0, Lights.of(new SceneBuilder().add(twoQuads()).build()).all().length, "the Whitted tracer's lights leave meshes out");
    }
}
