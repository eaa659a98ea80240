package lt.spindulys.camera;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

class AnimatedCameraTest {
    private static final PinholeCamera VIEW = new PinholeCamera(new Vec3(0, 2, -6), new Vec3(0, 0.5, 0), Vec3.Y, 40);

    /** A camera on a turntable sees what a still camera at the turned eye, look-at point and up sees, lens included. */
    @Test
    void aTurnedCameraIsTheStillCameraTurned() {
        Keyframes turn = Keyframes.turntable(Vec3.Y, new Vec3(0, 0, 1), 1, 0, 4);
        for (double time : new double[] {0, 0.5, 1, 2.75, 4.2}) {
            Transform at = turn.at(time);
            PinholeCamera still = new PinholeCamera(at.point(VIEW.eye()), at.point(VIEW.lookAt()), at.vector(VIEW.up()), 40);
            Camera[][] pairs = {{new AnimatedCamera(VIEW, turn), still},
                    {new AnimatedCamera(new ThinLensCamera(VIEW, 0.2, 5, LensPattern.CONCENTRIC), turn), new ThinLensCamera(still, 0.2, 5, LensPattern.CONCENTRIC)}};
            for (Camera[] pair : pairs) {
                Ray a = new Ray(), b = new Ray();
                pair[0].generateRay(0.3, 0.8, 1.5, 0.4, -0.2, time, a);
                pair[1].generateRay(0.3, 0.8, 1.5, 0.4, -0.2, time, b);
                assertEquals(b.ox, a.ox, 1e-12);
                assertEquals(b.oy, a.oy, 1e-12);
                assertEquals(b.oz, a.oz, 1e-12);
                assertEquals(b.dx, a.dx, 1e-12);
                assertEquals(b.dy, a.dy, 1e-12);
                assertEquals(b.dz, a.dz, 1e-12);
                assertEquals(time, a.time);
            }
        }
    }

    @Test
    void standingStillAtATimeIgnoresTheRaysTime() {
        AnimatedCamera c = new AnimatedCamera(VIEW, Keyframes.turntable(Vec3.Y, Vec3.ZERO, 1, 0, 1));
        Ray a = new Ray(), b = new Ray();
        c.at(0.25).generateRay(0.5, 0.5, 1, 0, 0, 0.9, a);
        c.generateRay(0.5, 0.5, 1, 0, 0, 0.25, b);
        assertEquals(b.ox, a.ox, 0);
        assertEquals(b.dz, a.dz, 0);
    }

    @Test
    void refusesScalingKeysAndAnimatingTwice() {
        Keyframes.Pose big = new Keyframes.Pose(Vec3.ZERO, Vec3.ZERO, new Vec3(2, 2, 2));
        Keyframes scaling = Keyframes.of(new double[] {0}, new Keyframes.Pose[] {big}, Keyframes.Interpolation.LINEAR);
        assertThrows(IllegalArgumentException.class, () -> new AnimatedCamera(VIEW, scaling));
        AnimatedCamera once = new AnimatedCamera(VIEW, Keyframes.turntable(Vec3.Y, Vec3.ZERO, 1, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new AnimatedCamera(once, once.keys()));
    }
}
