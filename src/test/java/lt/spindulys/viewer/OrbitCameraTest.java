package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Bounds;
import lt.spindulys.math.Vec3;

class OrbitCameraTest {
    private static final double EPS = 1e-9;

    /** Screen x, y of p (pixels, y down) as the rasterizer projects it. */
    static double[] project(OrbitCamera c, Vec3 p, int w, int h) {
        Vec3 d = p.minus(c.eye());
        double z = d.dot(c.forward()), f = h / 2.0 / Math.tan(Math.toRadians(c.fovDegrees()) / 2);
        return new double[] {w / 2.0 + f * d.dot(c.right()) / z, h / 2.0 - f * d.dot(c.up()) / z, z};
    }

    @Test
    void frameIsOrthonormalAndLooksAtTheTarget() {
        OrbitCamera c = new OrbitCamera();
        c.set(new Vec3(1, 2, 3), 4, 0.7, -0.3);
        assertEquals(4, c.eye().minus(c.target()).length(), EPS);
        Vec3 toTarget = c.target().minus(c.eye()).normalized();
        assertEquals(1, toTarget.dot(c.forward()), EPS);
        assertEquals(0, c.forward().dot(c.up()), EPS);
        assertEquals(0, c.forward().dot(c.right()), EPS);
        assertEquals(0, c.up().dot(c.right()), EPS);
        assertEquals(1, c.up().length(), EPS);
        // right x up = backward: a right-handed frame.
        assertEquals(-1, c.right().cross(c.up()).dot(c.forward()), EPS);
        assertTrue(c.up().y() > 0, "up points up while the pitch is short of the poles");
    }

    @Test
    void orbitTurnsTheSurfaceWithTheMouseAndStopsShortOfThePoles() {
        OrbitCamera c = new OrbitCamera();
        c.set(Vec3.ZERO, 5, 0, 0);
        Vec3 right = c.right();
        c.orbit(10, 0);
        assertTrue(c.eye().dot(right) < 0, "dragging right moves the eye left around the target");
        assertEquals(5, c.eye().length(), 1e-9);
        c.orbit(0, 10);
        assertTrue(c.eye().y() > 0, "dragging down moves the eye up over the target");
        c.orbit(0, 1e6);
        assertEquals(OrbitCamera.MAX_PITCH, c.pitch(), EPS);
        assertTrue(c.pitch() < Math.PI / 2);
        c.orbit(0, -1e7);
        assertEquals(-OrbitCamera.MAX_PITCH, c.pitch(), EPS);
        assertTrue(c.up().isFinite() && Math.abs(c.up().length() - 1) < EPS);
        for (int i = 0; i < 1000; i++) c.orbit(1000, 0);
        assertTrue(Math.abs(c.yaw()) <= Math.PI + EPS, "yaw stays in one turn");
    }

    @Test
    void panMovesThePointAtTheTargetWithTheMouse() {
        OrbitCamera c = new OrbitCamera();
        c.set(new Vec3(0.5, -1, 2), 7, 0.4, 0.2);
        Vec3 old = c.target();
        c.pan(30, -12, 480);
        double[] s = project(c, old, 640, 480);
        assertEquals(320 + 30, s[0], 1e-6);
        assertEquals(240 - 12, s[1], 1e-6);
        assertEquals(7, c.distance(), EPS);
    }

    @Test
    void zoomChangesTheDistanceOnly() {
        OrbitCamera c = new OrbitCamera();
        c.set(Vec3.ZERO, 8, 0.1, 0.1);
        c.zoom(2);
        assertEquals(4, c.distance(), EPS);
        c.zoom(0.5);
        assertEquals(8, c.distance(), EPS);
        assertThrows(IllegalArgumentException.class, () -> c.zoom(0));
        assertThrows(IllegalArgumentException.class, () -> c.zoom(Double.NaN));
        c.zoom(1e300);
        assertTrue(c.distance() >= OrbitCamera.MIN_DISTANCE);
    }

    @Test
    void fitShowsEveryCornerOfTheBoxFromAnyDirection() {
        Bounds b = new Bounds(-3, 0, 10, 5, 1, 12);
        for (double aspect : new double[] {0.3, 1, 16 / 9.0, 4}) {
            for (double yaw = -3; yaw < 3; yaw += 0.7) {
                for (double pitch = -1.4; pitch < 1.5; pitch += 0.5) {
                    OrbitCamera c = new OrbitCamera();
                    c.set(new Vec3(100, 100, 100), 1, yaw, pitch);
                    c.fit(b, aspect);
                    int h = 400, w = (int) Math.round(h * aspect);
                    for (int k = 0; k < 8; k++) {
                        Vec3 p = new Vec3((k & 1) == 0 ? b.minX() : b.maxX(), (k & 2) == 0 ? b.minY() : b.maxY(), (k & 4) == 0 ? b.minZ() : b.maxZ());
                        double[] s = project(c, p, w, h);
                        assertTrue(s[2] > 0 && s[0] >= 0 && s[0] <= w && s[1] >= 0 && s[1] <= h,
                                "corner " + p + " at " + s[0] + "," + s[1] + " in " + w + "x" + h + " (yaw " + yaw + ", pitch " + pitch + ")");
                    }
                }
            }
        }
    }

    @Test
    void fitOfNothingLeavesTheCamera() {
        OrbitCamera c = new OrbitCamera();
        c.set(new Vec3(1, 1, 1), 3, 0, 0);
        c.fit(Bounds.EMPTY, 1.5);
        assertEquals(3, c.distance(), EPS);
        assertEquals(new Vec3(1, 1, 1), c.target());
    }
}
