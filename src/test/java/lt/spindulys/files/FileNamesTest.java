package lt.spindulys.files;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

class FileNamesTest {
    @Test
    void theExtensionIsTheLowerCaseTextAfterTheNamesLastDot() {
        assertEquals("obj", FileNames.extension(Path.of("a.b/mesh.OBJ")));
        assertEquals("gz", FileNames.extension(Path.of("mesh.tar.gz")));
        assertEquals("", FileNames.extension(Path.of("a.b/mesh")), "a dot in a folder's name is not the file's");
        assertEquals("", FileNames.extension(Path.of("mesh.")));
        assertEquals("", FileNames.extension(Path.of("/")));
    }

    @Test
    void aUsersNameBecomesASafeStem() {
        assertEquals("cube", FileNames.stem("cube.OBJ", "s"));
        assertEquals("small_cube", FileNames.stem(" small cube ", "s"));
        assertEquals("a_b_c", FileNames.stem("a/b\\c", "s"));
        assertEquals("hidden", FileNames.stem("..hidden", "s"), "no hidden file, no parent folder");
        assertEquals("s", FileNames.stem("...", "s"));
        assertEquals(80, FileNames.stem("x".repeat(200), "s").length());
    }
}
