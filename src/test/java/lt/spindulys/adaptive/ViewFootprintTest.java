package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.Camera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.math.Vec3;

/** The footprint of every field of view a scene may give (0 < fov < 180), however small. */
class ViewFootprintTest {
    private static final double[] FOVS = {45, 1e-14, 1e-20, 1e-100, 1e-300, Double.MIN_VALUE};

    private static Camera[] cameras(double fov) {
        PinholeCamera straight = new PinholeCamera(new Vec3(0, 0, -5), new Vec3(0, 0, 0), new Vec3(0, 1, 0), fov);
        PinholeCamera diagonal = new PinholeCamera(new Vec3(3, 4, -5), new Vec3(0, 0, 0), new Vec3(0, 1, 0), fov);
        return new Camera[] {straight, diagonal, new ThinLensCamera(diagonal, 0.1)};
    }

    @Test
    void anyAcceptedFieldOfViewGivesAPositivePixelSizeAndFiniteLevels() {
        for (double fov : FOVS) {
            for (Camera c : cameras(fov)) {
                ViewFootprint v = ViewFootprint.of(c, 12, 9);
                double k = v.centrePixelsPerRadian();
                assertTrue(k > 0 && !Double.isNaN(k), fov + ": " + v);
                // An edge at the centre of the view: many pixels long (the view is narrow), never NaN.
                double px = v.pixels(-0.5, 0, 0, 0.5, 0, 0, 4);
                assertTrue(px >= 1 && !Double.isNaN(px), fov + ": " + px + " pixels, " + v);
                if (fov < 1) assertEquals(8, EdgeLevels.levelFor(px, 1, 8), fov + ": " + v);
            }
        }
    }

    @Test
    void anOrdinaryFieldOfViewKeepsItsMeasuredPixelSize() {
        // 9 pixels over a film 2 tan(22.5 degrees) high: about 10.9 pixels per radian at the centre.
        ViewFootprint v = ViewFootprint.of(cameras(45)[0], 12, 9);
        double expected = 9 / (2 * Math.tan(Math.toRadians(22.5)));
        assertEquals(expected, v.centrePixelsPerRadian(), expected * 1e-2);
    }
}
