package lt.spindulys.files;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@link AtomicFile#writeAll}: several files replaced together, or none of them. */
class AtomicFileGroupTest {
    @TempDir Path dir;

    private static AtomicFile.Body text(String s) {
        return out -> out.write(s.getBytes(StandardCharsets.UTF_8));
    }

    private Set<String> names() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.map(p -> p.getFileName().toString()).collect(Collectors.toSet());
        }
    }

    @Test
    void writesAndReplacesEveryFile() throws IOException {
        Files.writeString(dir.resolve("a"), "old a");
        AtomicFile.writeAll(List.of(dir.resolve("a"), dir.resolve("b")), List.of(text("new a"), text("new b")));
        assertEquals("new a", Files.readString(dir.resolve("a")));
        assertEquals("new b", Files.readString(dir.resolve("b")));
        assertEquals(Set.of("a", "b"), names(), "no temporary or backup file left");
    }

    @Test
    void aFailingBodyLeavesNoNewFile() throws IOException {
        Files.writeString(dir.resolve("a"), "old a");
        AtomicFile.Body failing = out -> {
            out.write(1);
            throw new IOException("disk full");
        };
        IOException e = assertThrows(IOException.class, () -> AtomicFile.writeAll(
                List.of(dir.resolve("a"), dir.resolve("b"), dir.resolve("c")), List.of(text("new a"), text("new b"), failing)));
        assertEquals("disk full", e.getMessage());
        assertEquals("old a", Files.readString(dir.resolve("a")));
        assertEquals(Set.of("a"), names());
    }

    @Test
    void aFailingRenameRestoresTheFilesAlreadyReplaced() throws IOException {
        Files.writeString(dir.resolve("a"), "old a");
        // The last body makes its own target a non-empty directory (as a concurrent process
        // might), so that its rename fails after "a" and "b" were renamed into place.
        AtomicFile.Body blocking = out -> {
            Files.createDirectory(dir.resolve("c"));
            Files.writeString(dir.resolve("c").resolve("inside"), "x");
            out.write(1);
        };
        assertThrows(IOException.class, () -> AtomicFile.writeAll(
                List.of(dir.resolve("a"), dir.resolve("b"), dir.resolve("c")), List.of(text("new a"), text("new b"), blocking)));
        assertEquals("old a", Files.readString(dir.resolve("a")), "the replaced file has its old content back");
        assertFalse(Files.exists(dir.resolve("b")), "the new file is removed");
        assertTrue(Files.isDirectory(dir.resolve("c")));
        assertEquals(Set.of("a", "c"), names(), "no temporary or backup file left");
    }

    @Test
    void refusesTheSameTargetTwiceBeforeWriting() {
        assertThrows(IllegalArgumentException.class, () -> AtomicFile.writeAll(
                List.of(dir.resolve("a"), dir.resolve("./a")), List.of(text("1"), text("2"))));
        assertFalse(Files.exists(dir.resolve("a")));
    }
}
