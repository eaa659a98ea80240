package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.math.Vec3;
import lt.spindulys.camera.LensPattern;
import lt.spindulys.scene.SceneBuilder;

/** The camera's lens keys: aperture, focus or focuspoint, and lens. */
class SceneParserLensTest {
    private static SceneBuilder parse(String text) {
        return SceneParser.parse(text, "test.dat", Path.of("."));
    }

    @Test
    void withoutLensKeysTheCameraIsAPinhole() {
        assertInstanceOf(PinholeCamera.class, parse("camera { eye 0 0 -5  lookat 0 0 0 }").camera());
    }

    @Test
    void apertureAndFocusMakeAThinLens() {
        ThinLensCamera c = assertInstanceOf(ThinLensCamera.class,
                parse("camera { eye 0 1 -5  lookat 0 1 0  fov 30  aperture 0.2  focus 7.5  lens ring }").camera());
        assertEquals(0.2, c.aperture());
        assertEquals(7.5, c.focusDistance());
        assertEquals(LensPattern.RING, c.lensPattern());
        assertEquals(new Vec3(0, 1, -5), c.view().eye());
        assertEquals(30, c.view().fovDegrees());
    }

    @Test
    void withoutFocusTheLookAtPointIsInFocus() {
        ThinLensCamera c = (ThinLensCamera) parse("camera { eye 0 3 -4  lookat 0 0 0  aperture 0.1 }").camera();
        assertEquals(5, c.focusDistance(), 1e-12);
        assertEquals(LensPattern.CONCENTRIC, c.lensPattern());
    }

    /** The focal plane through a focus point is perpendicular to the view direction: only the distance along it counts. */
    @Test
    void focusPointGivesTheDistanceAlongTheViewDirection() {
        ThinLensCamera c = (ThinLensCamera) parse("camera { eye 0 0 -5  lookat 0 0 0  aperture 0.1  focuspoint 2 -1 3 }").camera();
        assertEquals(8, c.focusDistance(), 1e-12);
    }

    @Test
    void focusAloneKeepsAClosedLens() {
        ThinLensCamera c = (ThinLensCamera) parse("camera { eye 0 0 -5  lookat 0 0 0  focus 3 }").camera();
        assertEquals(0, c.aperture());
        assertEquals(3, c.focusDistance());
    }
}
