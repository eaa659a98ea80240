package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.camera.Camera;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Vec3;

/** The preview's orbit of a scene's camera: around the look-at point, about the camera's own up vector. */
class CameraOrbitTest {
    private static final PinholeCamera CAMERA = new PinholeCamera(new Vec3(0, 2, -6), new Vec3(0, 1, 0), Vec3.Y, 40);

    private static void assertClose(double expected, double actual) { assertEquals(expected, actual, 1e-9); }

    @Test
    void noOrbitIsTheScenesCameraItself() {
        assertSame(CAMERA, CameraOrbit.NONE.apply(CAMERA));
        assertTrue(CameraOrbit.NONE.isNone());
    }

    @Test
    void draggingRightTakesTheEyeLeftAroundTheLookAtPointAtTheSameDistance() {
        PinholeCamera moved = (PinholeCamera) CameraOrbit.NONE.dragged(40, 0, CAMERA).apply(CAMERA);
        Vec3 lookAt = CAMERA.lookAt();
        assertClose(CAMERA.eye().minus(lookAt).length(), moved.eye().minus(lookAt).length());
        assertClose(CAMERA.eye().y(), moved.eye().y());
        // Looking along +z with up +y, the image's right is -x (forward x up): the eye goes to +x.
        assertTrue(moved.eye().x() > 0.5, moved.eye().toString());
        assertEquals(lookAt, moved.lookAt());
        assertEquals(CAMERA.up(), moved.up());
        assertEquals(CAMERA.fovDegrees(), moved.fovDegrees());
    }

    @Test
    void draggingDownRaisesTheEyeUpToALimit() {
        PinholeCamera up = (PinholeCamera) CameraOrbit.NONE.dragged(0, 50, CAMERA).apply(CAMERA);
        assertTrue(up.eye().y() > CAMERA.eye().y());
        PinholeCamera top = (PinholeCamera) CameraOrbit.NONE.dragged(0, 1e6, CAMERA).apply(CAMERA);
        Vec3 back = top.eye().minus(top.lookAt()).normalized();
        assertClose(Math.sin(CameraOrbit.MAX_ELEVATION), back.y());
    }

    @Test
    void theOrbitTurnsAboutTheCamerasOwnUp() {
        PinholeCamera zUp = new PinholeCamera(new Vec3(-6, 0, 2), new Vec3(0, 0, 1), Vec3.Z, 45);
        PinholeCamera moved = (PinholeCamera) CameraOrbit.NONE.dragged(100, 0, zUp).apply(zUp);
        assertClose(2, moved.eye().z());
        assertNotEquals(0, moved.eye().y(), 1e-3);
    }

    @Test
    void theWheelMovesTheEyeAlongTheViewAndAnOrthographicViewChangesWidth() {
        CameraOrbit nearer = CameraOrbit.NONE.dollied(-2);
        PinholeCamera p = (PinholeCamera) nearer.apply(CAMERA);
        double d0 = CAMERA.eye().minus(CAMERA.lookAt()).length();
        assertClose(d0 / 1.21, p.eye().minus(p.lookAt()).length());
        OrthographicCamera o = new OrthographicCamera(new Vec3(4, 3, -4), Vec3.ZERO, Vec3.Y, 5);
        OrthographicCamera oo = (OrthographicCamera) nearer.apply(o);
        assertClose(5 / 1.21, oo.viewWidth());
        assertClose(o.eye().length(), oo.eye().length());
    }

    @Test
    void aLensFocusedOnTheLookAtPointStaysSoAnotherKeepsItsDistance() {
        ThinLensCamera onLookAt = new ThinLensCamera(CAMERA, 0.1);
        CameraOrbit o = CameraOrbit.NONE.dollied(3).dragged(10, 5, onLookAt);
        ThinLensCamera moved = (ThinLensCamera) o.apply(onLookAt);
        assertEquals(ThinLensCamera.lookAtDistance(moved.view()), moved.focusDistance());
        assertEquals(0.1, moved.aperture());
        ThinLensCamera elsewhere = new ThinLensCamera(CAMERA, 0.1, 2.5, lt.spindulys.camera.LensPattern.RING);
        ThinLensCamera kept = (ThinLensCamera) o.apply(elsewhere);
        assertEquals(2.5, kept.focusDistance());
        assertEquals(lt.spindulys.camera.LensPattern.RING, kept.lensPattern());
    }

    @Test
    void anAnimatedCameraKeepsItsKeysAndHasItsRestingCameraMoved() {
        AnimatedCamera a = new AnimatedCamera(CAMERA, Keyframes.turntable(Vec3.Y, Vec3.ZERO, 1, 0, 2));
        Camera moved = CameraOrbit.NONE.dragged(30, 0, a).apply(a);
        AnimatedCamera m = assertInstanceOf(AnimatedCamera.class, moved);
        assertSame(a.keys(), m.keys());
        assertNotEquals(CAMERA.eye(), ((PinholeCamera) m.base()).eye());
    }
}
