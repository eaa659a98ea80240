package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.io.CameraBlock;
import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.SceneBuilder;

/** What the scene preview renders next, what it keeps and what it drops, step by step without threads. */
class PreviewStateTest {
    private static final String SCENE = "settings { width 16 height 8 samples 4 }\ncamera { eye 0 1 -5  lookat 0 0 0 }\nsphere { radius 1 }\n";
    private static final BufferedImage A = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB), B = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);

    private final PreviewState state = new PreviewState();

    /** Reads {@code text} as the worker would, for the current Read. */
    private void read(String text) {
        PreviewState.Read r = assertInstanceOf(PreviewState.Read.class, state.next());
        SceneBuilder b = SceneParser.parse(text, "s.dat", null);
        CameraBlock.Located camera = CameraBlock.locate(text, "s.dat");
        String rest = camera == null ? text : text.substring(0, camera.start()) + text.substring(camera.end());
        assertTrue(state.read(r.generation(), b, camera, rest));
    }

    private PreviewState.Render render() { return assertInstanceOf(PreviewState.Render.class, state.next()); }

    /** Renders every pass the state hands out, each with picture {@code p}; returns how many. */
    private int renderAll(BufferedImage p) {
        int n = 0;
        for (PreviewState.Work w; (w = state.next()) != null; n++) {
            PreviewState.Render r = assertInstanceOf(PreviewState.Render.class, w);
            assertTrue(state.rendered(r.generation(), r.index(), p));
        }
        return n;
    }

    @Test
    void itReadsThenRendersThePassesInOrderThenRests() {
        assertInstanceOf(PreviewState.Read.class, state.next());
        read(SCENE);
        PreviewState.Render first = render();
        assertEquals(0, first.index());
        assertEquals(new PreviewPlan.Pass(2, 1, 1, true, false), first.pass());
        assertNull(first.camera(), "the scene's own camera");
        assertTrue(state.rendered(first.generation(), 0, A));
        assertEquals(1, render().index());
        assertEquals(4, renderAll(A));
        assertNull(state.next());
        assertTrue(state.finished());
        assertEquals(16, state.pictureOf().width());
        assertEquals(4, state.pictureOf().samples());
    }

    @Test
    void aChangeDropsTheWorkUnderWayAndReadsAgain() {
        read(SCENE);
        PreviewState.Render old = render();
        state.filesChanged();
        assertFalse(state.rendered(old.generation(), old.index(), B), "a render of an older generation is dropped");
        assertNull(state.picture());
        PreviewState.Read r = assertInstanceOf(PreviewState.Read.class, state.next());
        state.filesChanged();
        assertFalse(state.read(r.generation(), SceneParser.parse(SCENE, "s.dat", null), null, null), "so is a read of one");
        read(SCENE);
        assertEquals(0, render().index());
    }

    @Test
    void aBrokenFileKeepsTheLastGoodPictureAndItsSceneUntilFixed() {
        read(SCENE);
        renderAll(A);
        state.filesChanged();
        PreviewState.Read r = assertInstanceOf(PreviewState.Read.class, state.next());
        assertTrue(state.readFailed(r.generation(), "s.dat:3:8: expected a number"));
        assertEquals("s.dat:3:8: expected a number", state.error());
        assertSame(A, state.picture());
        assertNull(state.next(), "nothing new to render from a file that does not read");
        // The view can still be turned: the last good scene renders, the error stays shown.
        state.dragged(10, 0);
        PreviewState.Render turned = render();
        assertNotNull(turned.camera());
        assertTrue(state.rendered(turned.generation(), turned.index(), B));
        assertEquals("s.dat:3:8: expected a number", state.error());
        state.filesChanged();
        read(SCENE);
        assertNull(state.error());
    }

    @Test
    void aPassThatFailsStopsThePassesAndTheNextGoodOneClearsIt() {
        read(SCENE);
        PreviewState.Render r = render();
        assertTrue(state.renderFailed(r.generation(), "the frame needs 3 GiB"));
        assertNull(state.next());
        assertEquals("the frame needs 3 GiB", state.error());
        state.dollied(1);
        PreviewState.Render again = render();
        assertTrue(state.rendered(again.generation(), again.index(), A));
        assertNull(state.error());
    }

    @Test
    void whileDraggingOnlyCoarsePassesRunThenTheRestFollow() {
        read(SCENE);
        state.dragged(5, 0);
        assertEquals(2, renderAll(A), "only the coarse passes of a 16x8 image: 2x1 and 4x2");
        state.dragged(5, 0);
        PreviewState.Render r = render();
        assertEquals(0, r.index(), "each move starts again from the coarsest pass");
        assertTrue(state.rendered(r.generation(), 0, A));
        PreviewState.Render second = render();
        assertEquals(1, second.index());
        assertTrue(state.rendered(second.generation(), 1, A));
        assertNull(state.next());
        state.released();
        assertEquals(2, render().index(), "released, the passes go on from where they stopped");
    }

    @Test
    void theOrbitOutlivesEditsElsewhereButFollowsAnEditedCamera() {
        read(SCENE);
        state.dragged(30, 10);
        state.released();
        PinholeCamera turned = (PinholeCamera) state.camera();
        state.filesChanged();
        read(SCENE.replace("sphere { radius 1 }", "sphere { radius 2 }").replace("lookat 0 0 0 }", "lookat 0 0 0 }  # spacing and comments\n"));
        assertEquals(turned.eye(), ((PinholeCamera) state.camera()).eye(), "the camera statement reads the same: the view stays");
        assertNotNull(render().camera());
        state.filesChanged();
        read(SCENE.replace("eye 0 1 -5", "eye 0 1 -6"));
        assertTrue(state.atFileCamera(), "an edited camera: the view follows the file");
        assertNull(render().camera());
    }

    @Test
    void afterTheViewIsSavedTheFilesCameraIsTheView() {
        read(SCENE);
        state.dragged(-25, 12);
        state.dollied(-1);
        state.released();
        PinholeCamera view = (PinholeCamera) state.camera();
        String saved = CameraBlock.replace(SCENE, "s.dat", state.cameraBlock());
        state.filesChanged();
        read(saved);
        assertTrue(state.atFileCamera());
        PinholeCamera file = (PinholeCamera) state.camera();
        assertEquals(view.eye(), file.eye());
        assertEquals(view.lookAt(), file.lookAt());
        assertEquals(view.up(), file.up());
        assertEquals(view.fovDegrees(), file.fovDegrees());
    }

    @Test
    void resetGoesBackToTheFilesCamera() {
        read(SCENE);
        long g = state.generation();
        state.reset();
        assertEquals(g, state.generation(), "nothing to reset: the work goes on");
        state.dragged(3, 3);
        state.reset();
        assertTrue(state.atFileCamera());
        assertEquals("camera { eye 0 1 -5  lookat 0 0 0  up 0 1 0  fov 45 }", state.cameraBlock());
    }

    @Test
    void aMoveTheCameraWouldRefuseLeavesTheViewAsItIs() {
        read("camera { eye 0 0 -1e10  lookat 0 0 0 }\nsphere { radius 1 }\n");
        state.dollied(100);
        long g = state.generation();
        PinholeCamera far = (PinholeCamera) state.camera();
        assertTrue(Math.abs(far.eye().z()) <= 1e15, far.eye().toString());
        assertTrue(far.eye().z() < -1e14, far.eye().toString());
        state.dollied(100);
        assertEquals(g, state.generation(), "an eye beyond 10^15 is refused: nothing to render again");
        assertEquals(far.eye(), ((PinholeCamera) state.camera()).eye());
    }

    @Test
    void savingTheViewKeepsThePassesDoneAndThePicture() {
        read(SCENE);
        state.dragged(-25, 12);
        state.released();
        assertEquals(5, renderAll(A));
        String saved = CameraBlock.replace(SCENE, "s.dat", state.cameraBlock());
        state.filesChanged();
        read(saved);
        assertNull(state.next(), "the file's camera is the view and nothing else changed: nothing to render again");
        assertSame(A, state.picture());
        // Anything else changed with it, and the passes run again.
        state.filesChanged();
        read(saved.replace("radius 1", "radius 2"));
        assertEquals(0, render().index());
    }
}
