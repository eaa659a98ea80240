package lt.spindulys.shading;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.Camera;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.trace.ShadingData;

/** The width of a texture lookup: the camera's pixel at the hit, widened on surfaces seen obliquely. */
class TextureFootprintTest {
    private static FirstHits firstHits(Camera camera) {
        return new FirstHits(new SceneBuilder().settings(RenderSettings.builder().width(200).height(100).build())
                .camera(camera).add(new Sphere(Vec3.ZERO, 1)).build());
    }

    private static ShadingData facing(double nx, double ny, double nz) {
        ShadingData sd = new ShadingData();
        sd.ng[0] = nx; sd.ng[1] = ny; sd.ng[2] = nz;
        return sd;
    }

    @Test
    void anOrthographicPixelIsAsWideNearAsFar() {
        FirstHits h = firstHits(new OrthographicCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 4));
        ShadingData sd = facing(0, 0, -1);
        assertEquals(0.02, h.footprint(sd, 1, 0, 0, 1), 1e-15);
        assertEquals(0.02, h.footprint(sd, 100, 0, 0, 1), 1e-15);
        // Seen at 60 degrees the pixel covers twice as much surface.
        assertEquals(0.04, h.footprint(facing(0, Math.sqrt(3) / 2, -0.5), 100, 0, 0, 1), 1e-12);
    }

    @Test
    void aPinholePixelGrowsWithDistance() {
        FirstHits h = firstHits(new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 90));
        ShadingData sd = facing(0, 0, -1);
        assertEquals(0.02, h.footprint(sd, 1, 0, 0, 1), 1e-5);
        assertEquals(2.0, h.footprint(sd, 100, 0, 0, 1), 1e-3);
    }
}
