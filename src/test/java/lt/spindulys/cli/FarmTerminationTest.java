package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A farm manager cancels a task with SIGTERM: the run leaves no temporary file and ends with a
 * non-zero status; and what a run killed without warning left, --skip-existing cleans up.
 */
class FarmTerminationTest {
    @TempDir Path dir;

    private List<String> tmps() throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".tmp")).toList();
        }
    }

    /**
     * A real render in a child JVM, a large empty frame (quick to render, seconds to encode),
     * terminated while its image is being written: seen by its temporary file having content.
     */
    @Test
    void aRunTerminatedWhileWritingLeavesNoTemporaryFile() throws Exception {
        assumeFalse(System.getProperty("os.name").startsWith("Windows"), "Process.destroy sends SIGTERM on Linux and macOS");
        Path scene = dir.resolve("big.dat");
        Files.writeString(scene, "settings { width 2500 height 2500 samples 1 }\n");
        Path out = dir.resolve("out.png");
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp", classes.toString(),
                Main.class.getName(), scene.toString(), "-o", out.toString(), "--threads", "2", "--quiet"))
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        try {
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
            Path writing = null;
            while (writing == null && p.isAlive() && System.nanoTime() < deadline) {
                try (Stream<Path> s = Files.list(dir)) {
                    writing = s.filter(f -> f.getFileName().toString().endsWith(".tmp") && size(f) > 0).findFirst().orElse(null);
                }
                if (writing == null) Thread.sleep(5);
            }
            assertNotNull(writing, "the image's temporary file was seen being written (the run " + (p.isAlive() ? "is still going" : "ended first") + ")");
            p.destroy(); // SIGTERM
            assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the run ended");
            assertNotEquals(0, p.exitValue(), "a terminated run does not report success");
            assertEquals(List.of(), tmps(), "no temporary file left");
            assertFalse(Files.exists(out), "no image: the run was cut off before its rename");
        } finally {
            p.destroyForcibly();
        }
    }

    private static long size(Path f) {
        try {
            return Files.size(f);
        } catch (IOException e) {
            return 0; // renamed or deleted meanwhile
        }
    }

    /**
     * --skip-existing removes the temporary files a killed run left beside the frames' outputs,
     * once untouched for {@link FrameOptions#STALE_AFTER}; a fresh one (a run writing now), other
     * files and other folders are left alone.
     */
    @Test
    void skipExistingRemovesStaleTemporaryFilesBesideTheOutputs() throws IOException {
        Path scene = dir.resolve("anim.dat");
        Files.writeString(scene, "settings { width 8 height 6 samples 1 }\nanimation { frames 1 2 }\nsphere { }\n");
        Path out = Files.createDirectory(dir.resolve("out"));
        String frames = out.resolve("f_####.png").toString();
        assertEquals(0, CliTest.run(scene.toString(), "--frame", "1", "-o", frames, "--quiet").status());
        FileTime old = FileTime.from(Instant.now().minus(FrameOptions.STALE_AFTER).minus(Duration.ofMinutes(1)));
        Path stale = Files.writeString(out.resolve(".spindulys-3fa9c02b1d7e4a65.tmp"), "half a png");
        Path staleOther = Files.writeString(out.resolve(".spindulys-00000000000000a1.tmp"), "half a png");
        Path fresh = Files.writeString(out.resolve(".spindulys-5e0c7d1b2a3f4e69.tmp"), "being written");
        Path notOurs = Files.writeString(out.resolve(".spindulys-notes.tmp"), "someone else's");
        Path elsewhere = Files.writeString(dir.resolve(".spindulys-3fa9c02b1d7e4a65.tmp"), "not beside the outputs");
        for (Path p : List.of(stale, staleOther, notOurs, elsewhere)) Files.setLastModifiedTime(p, old);

        CliTest.Run r = CliTest.run(scene.toString(), "--frames", "1-2", "-o", frames, "--skip-existing");
        assertEquals(0, r.status(), r.err());
        assertFalse(Files.exists(stale));
        assertFalse(Files.exists(staleOther));
        assertTrue(Files.exists(fresh), "a temporary file being written now stays");
        assertTrue(Files.exists(notOurs), "only our own temporary files' names");
        assertTrue(Files.exists(elsewhere), "only in the outputs' folders");
        assertTrue(Files.exists(out.resolve("f_0002.png")));
        assertTrue(r.err().contains("removed " + stale.toAbsolutePath() + ": a temporary file untouched for 15 minutes, left by a run that was killed (--skip-existing)"
                + System.lineSeparator()), r.err());
        assertTrue(r.err().contains("skipped " + out.resolve("f_0001.png") + " (frame 1): it exists (--skip-existing)"), r.err());
    }
}
