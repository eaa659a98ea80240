package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Which changes the scene preview's watcher counts, and that it tells one. */
class InputWatcherTest {
    @TempDir Path dir;

    @Test
    void theScenesFilesCountOthersBesideThemDoNot() throws Exception {
        Path sub = Files.createDirectories(dir.resolve("textures"));
        try (InputWatcher w = new InputWatcher(() -> { }, 150)) {
            w.watch(List.of(dir.resolve("scene.dat"), sub.resolve("wood.png")), false);
            assertTrue(w.counts(dir.resolve("scene.dat")));
            assertTrue(w.counts(sub.resolve("wood.png")));
            assertTrue(w.counts(sub.resolve("../scene.dat")), "named another way, the same file");
            assertFalse(w.counts(dir.resolve("scene.png")), "an image rendered beside the scene");
            assertFalse(w.counts(dir.resolve(".spindulys-0123456789abcdef.tmp")), "an atomic write's temporary file");
            assertFalse(w.counts(dir.resolve("elsewhere").resolve("scene.dat")));
            // While the scene does not read, the file it misses may be any in its folders.
            w.watch(List.of(dir.resolve("scene.dat")), true);
            assertTrue(w.counts(dir.resolve("missing.obj")));
            assertFalse(w.counts(sub.resolve("wood.png")), "the folder is no longer watched");
        }
    }

    @Test
    void aChangeIsTold() throws Exception {
        Path scene = Files.writeString(dir.resolve("scene.dat"), "sphere { radius 1 }\n");
        CountDownLatch told = new CountDownLatch(1);
        try (InputWatcher w = new InputWatcher(told::countDown, 150)) {
            w.watch(List.of(scene), false);
            Files.writeString(scene, "sphere { radius 2 }\n");
            // A guard, not a measure: the change is told after 150 ms of quiet.
            assertTrue(told.await(20, TimeUnit.SECONDS), "the change was told");
        }
    }
}
