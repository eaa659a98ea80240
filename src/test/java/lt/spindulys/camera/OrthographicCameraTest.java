package lt.spindulys.camera;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.adaptive.ViewFootprint;
import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;

/** Parallel rays from the image plane, their pixel footprint, and what refuses them. */
class OrthographicCameraTest {
    private static final OrthographicCamera CAMERA = new OrthographicCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 4);

    @Test
    void raysAreParallelAndStartOnTheImagePlane() {
        Ray r = new Ray();
        // Aspect 2: 4 units wide, 2 high. Film (0, 0) is the top left, at +x looking along +z (as a pinhole's).
        CAMERA.generateRay(0, 0, 2, 0.7, -0.3, 0.25, r);
        assertArrayEquals(new double[] {2, 1, -5, 0, 0, 1}, new double[] {r.ox, r.oy, r.oz, r.dx, r.dy, r.dz}, 1e-12);
        assertEquals(0.25, r.time);
        CAMERA.generateRay(1, 1, 2, 0, 0, 0, r);
        assertArrayEquals(new double[] {-2, -1, -5, 0, 0, 1}, new double[] {r.ox, r.oy, r.oz, r.dx, r.dy, r.dz}, 1e-12);
        CAMERA.generateRay(0.5, 0.5, 2, 0, 0, 0, r);
        assertArrayEquals(new double[] {0, 0, -5}, new double[] {r.ox, r.oy, r.oz}, 1e-12);
        assertFalse(CAMERA.usesLens());
    }

    @Test
    void theFootprintIsThePixelsWidthAtEveryDistance() {
        PixelFootprint f = CAMERA.pixelFootprint(200, 100);
        assertEquals(0.02, f.width(), 1e-15);
        assertEquals(0, f.spread());
        assertEquals(0.02, f.at(0), 1e-15);
        assertEquals(0.02, f.at(1000), 1e-15);
    }

    @Test
    void aPinholesFootprintGrowsWithDistanceFromNothing() {
        PinholeCamera pinhole = new PinholeCamera(new Vec3(0, 0, -5), Vec3.ZERO, Vec3.Y, 90);
        PixelFootprint f = pinhole.pixelFootprint(200, 100);
        assertEquals(0, f.width());
        // 90 degrees across 100 rows is 4 units of film across 200 columns at distance 1, so about 0.02 radians.
        assertEquals(0.02, f.spread(), 1e-5);
        assertEquals(0.2, f.at(10), 1e-4);
    }

    @Test
    void keysCarryTheCameraAndKeepItsFootprint() {
        Keyframes keys = Keyframes.of(new double[] {0, 1},
                new Keyframes.Pose[] {new Keyframes.Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(1, 1, 1)), new Keyframes.Pose(new Vec3(2, 0, 0), Vec3.ZERO, new Vec3(1, 1, 1))},
                Keyframes.Interpolation.LINEAR, lt.spindulys.math.Transform.IDENTITY);
        AnimatedCamera moving = new AnimatedCamera(CAMERA, keys);
        Ray r = new Ray();
        moving.generateRay(0.5, 0.5, 1, 0, 0, 1, r);
        assertArrayEquals(new double[] {2, 0, -5, 0, 0, 1}, new double[] {r.ox, r.oy, r.oz, r.dx, r.dy, r.dz}, 1e-12);
        assertEquals(CAMERA.pixelFootprint(100, 100), moving.pixelFootprint(100, 100));
        assertEquals(CAMERA.pixelFootprint(100, 100), moving.at(0.5).pixelFootprint(100, 100), "frozen, it is still orthographic");
    }

    @Test
    void hasNoLensToChange() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> CAMERA.withLens(0.1, null));
        assertTrue(e.getMessage().contains("no lens"), e.getMessage());
    }

    @Test
    void adaptiveSubdivisionRefusesIt() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ViewFootprint.of(CAMERA, 64, 64));
        assertEquals(ViewFootprint.ORTHOGRAPHIC_REFUSAL, e.getMessage());
    }

    @Test
    void refusesADegenerateView() {
        assertThrows(IllegalArgumentException.class, () -> new OrthographicCamera(Vec3.ZERO, Vec3.ZERO, Vec3.Y, 1));
        assertThrows(IllegalArgumentException.class, () -> new OrthographicCamera(Vec3.ZERO, Vec3.Z, Vec3.Y, 0));
        assertThrows(IllegalArgumentException.class, () -> new OrthographicCamera(Vec3.ZERO, Vec3.Z, Vec3.Z, 1));
    }
}
