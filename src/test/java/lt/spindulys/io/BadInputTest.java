package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Every malformed scene of {@link BadInputCases} is refused with its exact file:line:column message. */
class BadInputTest {
    private static final Path BASE = Path.of("/tmp/spindulys-bad-input-scenes");

    static Stream<BadInputCases.Case> cases() {
        return BadInputCases.scenes().stream();
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void refusedWithLocation(BadInputCases.Case c) {
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(c.scene(), "bad.dat", BASE));
        assertEquals(c.expectedMessage("bad.dat", BASE), e.getMessage());
        // The structured location agrees with the message.
        String[] at = c.expected().split(":", 3);
        assertEquals("bad.dat", e.file());
        assertEquals(Integer.parseInt(at[0]), e.line());
        assertEquals(Integer.parseInt(at[1]), e.column());
    }
}
