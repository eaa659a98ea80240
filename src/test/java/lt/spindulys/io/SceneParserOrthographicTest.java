package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.camera.OrthographicCamera;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.SceneBuilder;

/** camera { projection orthographic  width W }: its keys, and what it refuses, located. */
class SceneParserOrthographicTest {
    @TempDir Path dir;

    private SceneBuilder parse(String text) {
        return SceneParser.parse(text, "t.dat", dir);
    }

    private String error(String text) {
        return assertThrows(SceneException.class, () -> parse(text)).getMessage();
    }

    @Test
    void projectionOrthographicMakesAnOrthographicCamera() {
        OrthographicCamera c = assertInstanceOf(OrthographicCamera.class,
                parse("camera { eye 0 1 -5  lookat 0 1 0  projection orthographic  width 6 }").camera());
        assertEquals(6, c.viewWidth());
        assertEquals(new Vec3(0, 1, -5), c.eye());
    }

    @Test
    void keysCarryAnOrthographicCamera() {
        AnimatedCamera c = assertInstanceOf(AnimatedCamera.class, parse("""
                animation { frames 1 10 }
                camera { eye 0 0 -5  lookat 0 0 0  projection orthographic  width 2
                  turntable { axis 0 1 0  center 0 0 0  turns 1 } }
                """).camera());
        assertInstanceOf(OrthographicCamera.class, c.base());
    }

    @Test
    void widthIsRequired() {
        assertEquals("t.dat:1:36: an orthographic camera needs 'width': the width of the view in scene units",
                error("camera { eye 0 0 -5  lookat 0 0 0  projection orthographic }"));
    }

    @Test
    void lensAndFieldOfViewKeysAreRefused() {
        assertEquals("t.dat:1:70: 'aperture' needs a perspective camera: an orthographic one has no lens, so everything is sharp",
                error("camera { eye 0 0 -5  lookat 0 0 0  projection orthographic  width 2  aperture 0.1 }"));
        assertEquals("t.dat:1:70: 'fov' needs a perspective camera: an orthographic one has 'width' instead",
                error("camera { eye 0 0 -5  lookat 0 0 0  projection orthographic  width 2  fov 30 }"));
    }

    @Test
    void widthWithoutOrthographicIsRefused() {
        assertEquals("t.dat:1:36: 'width' sizes an orthographic view: it needs 'projection orthographic' (a perspective camera is sized by 'fov')",
                error("camera { eye 0 0 -5  lookat 0 0 0  width 2 }"));
    }

    @Test
    void aNonPositiveWidthIsReportedAtWidth() {
        assertTrue(error("camera { eye 0 0 -5  lookat 0 0 0  projection orthographic  width 0 }")
                .startsWith("t.dat:1:61: orthographic width must be positive"));
    }

    @Test
    void adaptiveSubdivisionIsRefusedAtTheLaterOfTheTwo() throws IOException {
        Files.writeString(dir.resolve("tet.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
        String camera = "camera { eye 0 0 -5  lookat 0 0 0  projection orthographic  width 2 }\n";
        String subdiv = "subdiv { file \"tet.obj\"  method lazy }\n";
        assertEquals("t.dat:2:26: method lazy does not combine with the orthographic camera at 1:36: adaptive levels are sized by angles"
                + " at the eye, which parallel rays do not have; use method uniform with a level", error(camera + subdiv));
        assertEquals("t.dat:2:36: an orthographic camera does not combine with adaptive subdivision (method lazy at 1:26): adaptive levels are"
                + " sized by angles at the eye, which parallel rays do not have; use method uniform with a level", error(subdiv + camera));
        parse(camera + "subdiv { file \"tet.obj\"  level 1 }\n");
    }
}
