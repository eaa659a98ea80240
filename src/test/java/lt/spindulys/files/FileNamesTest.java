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
}
