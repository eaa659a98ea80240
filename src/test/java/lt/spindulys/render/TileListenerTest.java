package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/** RenderJob.tiles: every tile once, its pixels final when reported, in the last time step only. */
class TileListenerTest {
    private static SceneBuilder scene(int timeSteps) {
        return new SceneBuilder()
                .settings(RenderSettings.builder().size(40, 30).samplesPerPixel(2).timeSteps(timeSteps).build())
                .camera(new PinholeCamera(new Vec3(0, 1, -4), new Vec3(0, 0.5, 0), Vec3.Y, 45))
                .light(new PointLight(new Vec3(3, 5, -3), Color.WHITE))
                .add(new Sphere(new Vec3(0, 0.5, 0), 0.7))
                .add(new Plane(Vec3.Y, 0));
    }

    @Test
    void everyTileIsReportedOnceWithItsFinalPixels() throws Exception {
        for (int steps : new int[] {1, 2}) {
            int[] reported = new int[40 * 30];
            double[] seen = new double[3 * 40 * 30];
            RenderResult r = RenderJob.of(scene(steps)).threads(2).tiles((frame, x0, y0, x1, y1) -> {
                synchronized (reported) {
                    for (int y = y0; y < y1; y++) {
                        for (int x = x0; x < x1; x++) {
                            reported[y * 40 + x]++;
                            for (int c = 0; c < 3; c++) seen[3 * (y * 40 + x) + c] = frame.get(x, y, c);
                        }
                    }
                }
            }).run();
            int[] once = new int[40 * 30];
            Arrays.fill(once, 1);
            assertArrayEquals(once, reported, "each pixel in exactly one reported tile, with " + steps + " time steps");
            assertArrayEquals(r.frame().data(), seen, "pixels are final when their tile is reported");
            assertEquals(40, r.width());
        }
    }
}
