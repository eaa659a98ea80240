package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/**
 * Characters that text read from a String may hold but a UTF-8 file cannot (lone surrogates), so
 * {@link BadInputCases}, whose scenes are also written to files, cannot carry them.
 */
class EscapedInputTest {
    private static String error(String scene) {
        return assertThrows(SceneException.class, () -> SceneParser.parse(scene, "s.dat", null)).getMessage();
    }

    @Test
    void loneSurrogatesAreEscaped() {
        assertEquals("s.dat:1:17: malformed number '1\\uD800'", error("sphere { radius 1\uD800 }"));
        assertEquals("s.dat:1:17: unexpected character U+DC00", error("sphere { radius \uDC00 }"));
        assertEquals("s.dat:1:17: expected a number for 'radius', found string \"\\uDBFFx\"", error("sphere { radius \"\uDBFFx\" }"));
    }

    @Test
    void aMessageCutInsideTheTokenStaysOneLine() {
        // The cut falls among NULs: what is shown is escaped, and the length counts the characters.
        String token = "1" + "\0".repeat(100);
        assertEquals("s.dat:1:17: malformed number '1" + "\\0".repeat(39) + "...' (101 characters)", error("sphere { radius " + token + " }"));
    }
}
