package lt.spindulys.limits;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class InputFilesTest {
    @Test
    void aLargeFileReadInPartsIsTheWholeFile(@TempDir Path dir) throws IOException {
        byte[] content = new byte[(int) InputFiles.PARTS_FROM + 12_345];
        new Random(3).nextBytes(content);
        Path file = Files.write(dir.resolve("large.bin"), content);
        for (int threads : new int[] {1, 2, 3, 7}) {
            assertArrayEquals(content, InputFiles.readAllBytes(file, "file", 1, threads), threads + " threads");
        }
    }

    @Test
    void theChecksComeFirst(@TempDir Path dir) throws IOException {
        Path file = Files.write(dir.resolve("f.bin"), new byte[(int) InputFiles.PARTS_FROM]);
        IOException e = assertThrows(IOException.class, () -> InputFiles.readAllBytes(dir, "OBJ file", 1, 2));
        assertEquals("OBJ file " + dir + " is a directory, not a regular file", e.getMessage());
        try (HeapBudget.Scope cap = HeapBudget.cap(1 << 20)) {
            assertThrows(InsufficientMemoryException.class, () -> InputFiles.readAllBytes(file, "OBJ file", 1, 2));
        }
    }
}
