package lt.spindulys.files;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The temporary files AtomicFile is writing are known while they exist, and their names are recognised. */
class TemporaryFilesTest {
    @TempDir Path dir;

    @Test
    void aTemporaryFileIsRegisteredWhileItIsWrittenOnly() throws IOException {
        int before = TemporaryFiles.live();
        Path out = dir.resolve("a.txt");
        AtomicFile.write(out, o -> {
            assertEquals(before + 1, TemporaryFiles.live(), "registered while written");
            try (Stream<Path> s = Files.list(dir)) {
                assertTrue(s.allMatch(p -> AtomicFile.isTemporaryName(p.getFileName().toString())), "its name has our form");
            }
            o.write(1);
        });
        assertEquals(before, TemporaryFiles.live(), "renamed: no longer temporary");
        assertThrows(IOException.class, () -> AtomicFile.writeAll(List.of(dir.resolve("b.txt"), dir.resolve("c.txt")),
                List.of(o -> o.write(1), o -> { throw new IOException("body failed"); })));
        assertEquals(before, TemporaryFiles.live(), "deleted after a failure: no longer temporary");
        AtomicFile.checkWritable(dir.resolve("d.txt"));
        assertEquals(before, TemporaryFiles.live());
        try (Stream<Path> s = Files.list(dir)) {
            assertEquals(List.of("a.txt"), s.map(p -> p.getFileName().toString()).toList());
        }
    }
}
