package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.scene.SceneBuildException;

/** Every malformed scene of {@link BadInputCases} is refused with its exact file:line:column message. */
class BadInputTest {
    /** The scene's folder, where a case's mesh files are written. */
    @TempDir Path base;

    static Stream<BadInputCases.Case> cases() {
        return BadInputCases.scenes().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void refusedWithLocation(BadInputCases.Case c) throws IOException {
        c.writeFiles(base);
        // Parsed, then built: some errors show only when the scene is frozen (transforms composed).
        RuntimeException e = assertThrows(RuntimeException.class, () -> SceneParser.parse(c.scene(), "bad.dat", base).build());
        assertEquals(c.expectedMessage("bad.dat", base), e.getMessage());
        if (e instanceof SceneBuildException b) {
            // Found by the build, named by the object's statement.
            assertEquals(c.expectedFile("bad.dat", base) + ":" + c.expected().substring(0, c.expected().indexOf(": ")), b.source());
            return;
        }
        SceneException se = assertInstanceOf(SceneException.class, e);
        // The structured location agrees with the message.
        String[] at = c.expected().split(":", 3);
        assertEquals(c.expectedFile("bad.dat", base), se.file());
        assertEquals(Integer.parseInt(at[0]), se.line());
        assertEquals(Integer.parseInt(at[1]), se.column());
    }
}
