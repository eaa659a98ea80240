package lt.spindulys.camera;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.sampling.Rng;

class ThinLensCameraTest {
    private static final PinholeCamera VIEW = new PinholeCamera(new Vec3(1, 2, -6), new Vec3(0, 1, 0), new Vec3(0.1, 1, 0), 50);
    private static final Vec3 FORWARD = new Vec3(0, 1, 0).minus(new Vec3(1, 2, -6)).normalized();

    private static void assertSameRay(Ray a, Ray b) {
        assertArrayEquals(new double[] {a.ox, a.oy, a.oz, a.dx, a.dy, a.dz, a.tMin, a.tMax, a.time},
                new double[] {b.ox, b.oy, b.oz, b.dx, b.dy, b.dz, b.tMin, b.tMax, b.time});
    }

    @Test
    void apertureZeroAndTheLensCentreGiveThePinholeRay() {
        ThinLensCamera open = new ThinLensCamera(VIEW, 0.3, 4, LensPattern.CONCENTRIC), shut = open.withAperture(0);
        Ray p = new Ray(), t = new Ray();
        VIEW.generateRay(0.3, 0.7, 1.5, 0.2, -0.4, 0.25, p);
        shut.generateRay(0.3, 0.7, 1.5, 0.2, -0.4, 0.25, t);
        assertSameRay(p, t);
        open.generateRay(0.3, 0.7, 1.5, 0, 0, 0.25, t);
        assertSameRay(p, t);
    }

    /** Every lens ray starts on the lens and passes through the focal-plane point the pinhole ray reaches. */
    @Test
    void everyLensRayPassesThroughThePixelsFocalPoint() {
        double aperture = 0.4, focus = 7.5;
        ThinLensCamera cam = new ThinLensCamera(VIEW, aperture, focus, LensPattern.CONCENTRIC);
        Rng rng = new Rng().seed(9);
        Ray p = new Ray(), t = new Ray();
        for (int i = 0; i < 200; i++) {
            double fx = rng.nextDouble(), fy = rng.nextDouble();
            double r = Math.sqrt(rng.nextDouble()), a = 2 * Math.PI * rng.nextDouble();
            VIEW.generateRay(fx, fy, 1.5, 0, 0, 0.5, p);
            cam.generateRay(fx, fy, 1.5, r * Math.cos(a), r * Math.sin(a), 0.5, t);
            Vec3 d = new Vec3(p.dx, p.dy, p.dz);
            Vec3 focal = VIEW.eye().plus(d.times(focus / d.dot(FORWARD)));
            Vec3 origin = new Vec3(t.ox, t.oy, t.oz), dir = new Vec3(t.dx, t.dy, t.dz);
            Vec3 offset = origin.minus(VIEW.eye());
            assertEquals(0, offset.dot(FORWARD), 1e-12, "the lens lies in the image plane");
            assertEquals(aperture * r, offset.length(), 1e-12, "lens radius scales the sample");
            assertEquals(1, dir.length(), 1e-12);
            double s = focal.minus(origin).dot(dir);
            assertEquals(0, origin.plus(dir.times(s)).minus(focal).length(), 1e-9, "ray passes through the focal point");
            assertEquals(0.5, t.time);
        }
    }

    @Test
    void focusPointGivesItsDistanceAlongTheViewDirection() {
        // 3 ahead of the eye and 2 to the side: the sideways offset does not count.
        Vec3 point = VIEW.eye().plus(FORWARD.times(3)).plus(FORWARD.cross(Vec3.Y).normalized().times(2));
        assertEquals(3, ThinLensCamera.focusDistanceTo(VIEW, point), 1e-12);
        assertEquals(VIEW.lookAt().minus(VIEW.eye()).length(), new ThinLensCamera(VIEW, 0.1).focusDistance(), 1e-12);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> ThinLensCamera.focusDistanceTo(VIEW, VIEW.eye().minus(FORWARD)));
        assertTrue(e.getMessage().startsWith("camera focus point must be in front of the camera"), e.getMessage());
    }

    @Test
    void refusesBadLenses() {
        assertThrows(IllegalArgumentException.class, () -> new ThinLensCamera(VIEW, -0.1, 5, LensPattern.CONCENTRIC));
        assertThrows(IllegalArgumentException.class, () -> new ThinLensCamera(VIEW, Double.NaN, 5, LensPattern.CONCENTRIC));
        assertThrows(IllegalArgumentException.class, () -> new ThinLensCamera(VIEW, 0.1, 0, LensPattern.CONCENTRIC));
        assertThrows(IllegalArgumentException.class, () -> new ThinLensCamera(VIEW, 0.1, Double.POSITIVE_INFINITY, LensPattern.RING));
    }
}
