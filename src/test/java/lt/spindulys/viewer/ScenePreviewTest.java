package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.function.Predicate;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.Camera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.render.RenderJob;

/**
 * The scene preview with its threads and a real file watcher, without a window: its last pass is
 * the picture {@code render} makes, an edit of the scene or of a file it reads renders again, a
 * broken file shows its located error over the kept picture, and the saved view renders as the
 * orbited one. Tiny images; waits are for what the preview reports, with a timeout only as a guard.
 */
class ScenePreviewTest {
    static final long TIMEOUT_MS = 30_000;

    @TempDir Path dir;
    private ScenePreview preview;
    private final Seen seen = new Seen();

    /** What the preview told, in order. */
    static final class Seen implements ScenePreview.Listener {
        final List<BufferedImage> pictures = new ArrayList<>();
        final List<String> statuses = new ArrayList<>();
        final List<BufferedImage> partials = new ArrayList<>();
        String error;

        @Override public synchronized void picture(BufferedImage picture, String status) {
            pictures.add(picture);
            notifyAll();
        }

        @Override public synchronized void partial(BufferedImage partial, String status) {
            partials.add(partial);
        }

        @Override public synchronized void status(String status, String error) {
            statuses.add(status);
            this.error = error;
            notifyAll();
        }

        /** Waits until {@code done} holds of this (checked under its lock), failing with {@code what} after the guard timeout. */
        synchronized void await(String what, Predicate<Seen> done) throws InterruptedException {
            long end = System.currentTimeMillis() + TIMEOUT_MS;
            while (!done.test(this)) {
                long left = end - System.currentTimeMillis();
                if (left <= 0) fail("timed out waiting for " + what + "; statuses: " + statuses + ", error: " + error);
                wait(left);
            }
        }

        synchronized String last() { return statuses.isEmpty() ? "" : statuses.get(statuses.size() - 1); }
        synchronized int doneCount() { return (int) statuses.stream().filter(s -> s.startsWith("done: ")).count(); }
        synchronized BufferedImage picture() { return pictures.get(pictures.size() - 1); }
    }

    @AfterEach
    void close() {
        if (preview != null) preview.close();
    }

    static final String SCENE = """
            # A tiny scene for the preview's tests.
            settings { width 12  height 8  samples 2 }
            camera { eye 0 1 -5  lookat 0 0 0  fov 40 }
            light { position 3 5 -4 }
            material red { color 0.9 0.2 0.1 }
            sphere { radius 1  material red }
            plane { normal 0 1 0  offset -1 }
            """;

    private Path write(String name, String text) throws Exception {
        Path f = dir.resolve(name);
        // Through a rename, as editors save: the watcher sees the folder's entry change.
        Path tmp = dir.resolve(name + ".editing");
        Files.writeString(tmp, text);
        Files.move(tmp, f, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
        return f;
    }

    private void start(Path scene) throws Exception {
        preview = new ScenePreview(scene, null, Runnable::run, seen, 2);
        preview.start();
    }

    private void awaitDone(int count) throws InterruptedException {
        seen.await("the preview to finish " + count + " time(s)", s -> s.doneCount() >= count);
    }

    private static int[] pixels(BufferedImage img) { return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth()); }

    @Test
    void theLastPassIsThePictureRenderMakes() throws Exception {
        Path scene = write("scene.dat", SCENE);
        start(scene);
        awaitDone(1);
        BufferedImage last = seen.picture();
        assertEquals(12, last.getWidth());
        BufferedImage rendered = RenderJob.of(scene).threads(1).run().image();
        assertArrayEquals(pixels(rendered), pixels(last));
        synchronized (seen) {
            assertEquals(5, seen.pictures.size(), "a picture per pass: 2x1, 3x2, 6x4, 12x8 at 1 sample, 12x8 at 2");
            assertEquals(2, seen.pictures.get(0).getWidth());
        }
    }

    @Test
    void aBrokenFileShowsItsErrorOverTheKeptPictureAndAFixRendersAgain() throws Exception {
        Path scene = write("scene.dat", SCENE);
        start(scene);
        awaitDone(1);
        BufferedImage good = seen.picture();
        int pictures;
        synchronized (seen) { pictures = seen.pictures.size(); }
        write("scene.dat", SCENE.replace("radius 1", "radius oops"));
        seen.await("the error", s -> s.error != null);
        assertTrue(seen.error.startsWith(scene + ":6:17: "), seen.error);
        synchronized (seen) { assertEquals(pictures, seen.pictures.size(), "no picture replaces the last good one"); }
        write("scene.dat", SCENE.replace("0.9 0.2 0.1", "0.1 0.3 0.9"));
        awaitDone(2);
        assertNull(seen.error);
        assertFalse(Arrays.equals(pixels(good), pixels(seen.picture())), "the fixed scene's picture, blue");
    }

    @Test
    void aSceneThatNeverReadOrAMissingMeshIsRenderedOnceItIsThere() throws Exception {
        Path scene = write("scene.dat", SCENE.replace("sphere { radius 1  material red }", "mesh { file \"tri.obj\"  material red }"));
        start(scene);
        seen.await("the error", s -> s.error != null);
        assertTrue(seen.error.startsWith(scene + ":6:"), seen.error);
        assertEquals("the scene does not read", seen.last(), "no picture to keep yet");
        synchronized (seen) { assertTrue(seen.pictures.isEmpty()); }
        // The missing mesh appears beside the scene: a file the scene did not read yet, seen all the same.
        write("tri.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
        awaitDone(1);
        assertNull(seen.error);
    }

    @Test
    void anEditOfAFileTheSceneReadsRendersAgain() throws Exception {
        write("tri.obj", "v -1 -1 0\nv 1 -1 0\nv 0 1 0\nf 1 2 3\n");
        Path scene = write("scene.dat", SCENE.replace("sphere { radius 1  material red }", "mesh { file \"tri.obj\"  material red }"));
        start(scene);
        awaitDone(1);
        BufferedImage before = seen.picture();
        write("tri.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1 2 3\n");
        awaitDone(2);
        assertFalse(Arrays.equals(pixels(before), pixels(seen.picture())), "the edited mesh's picture");
    }

    @Test
    void theSavedViewRendersAsTheOrbitedOneAndTheViewStays() throws Exception {
        Path scene = write("scene.dat", SCENE);
        Path original = dir.resolve("original.dat");
        Files.copy(scene, original);
        start(scene);
        awaitDone(1);
        preview.dragged(35, -12);
        preview.dollied(-1.5);
        preview.released();
        awaitDone(2);
        Camera view = preview.camera();
        BufferedImage orbited = seen.picture();
        String block = preview.saveCamera();
        String text = Files.readString(scene, StandardCharsets.UTF_8);
        assertEquals(SCENE.replace("camera { eye 0 1 -5  lookat 0 0 0  fov 40 }", block), text, "only the camera statement changed");
        // The rewritten file renders the orbited view, pixel for pixel.
        BufferedImage fromFile = RenderJob.of(scene).threads(1).run().image();
        BufferedImage overridden = RenderJob.of(original).camera(c -> view).threads(1).run().image();
        assertArrayEquals(pixels(overridden), pixels(fromFile));
        assertArrayEquals(pixels(orbited), pixels(fromFile));
        // The preview reads the saved file; its view is where it was, and nothing is rendered again.
        awaitDone(3);
        assertTrue(seen.last().endsWith("(the file's camera is the view, and nothing else changed)"), seen.last());
        assertEquals(((PinholeCamera) view).eye(), ((PinholeCamera) preview.camera()).eye());
        assertSame(orbited, seen.picture());
    }
}
