package lt.spindulys.limits;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;

class MessageTextTest {
    @Test
    void shortTokensAreShownWhole() {
        String s = "x".repeat(60);
        assertSame(s, MessageText.cut(s));
        assertEquals("'" + s + "'", MessageText.quote(s));
        assertEquals("\"ab\"", MessageText.quote("ab", "\""));
        assertEquals("12", MessageText.quote("12", ""));
    }

    @Test
    void longTokensAreCutWithTheirLength() {
        String s = "abcdefghij".repeat(1_000_000);
        assertEquals("abcdefghij".repeat(4) + "...", MessageText.cut(s));
        assertEquals("'" + "abcdefghij".repeat(4) + "...' (10000000 characters)", MessageText.quote(s));
        assertEquals("x".repeat(100) + "...", MessageText.cut("x".repeat(200), 100));
    }

    @Test
    void aTokenKnownByItsStartIsQuotedAlike() {
        assertEquals("'abc'", MessageText.quote("abc", 3, "'"));
        String head = "0123456789".repeat(7);
        assertEquals("'" + head.substring(0, 40) + "...' (123456789 characters)", MessageText.quote(head, 123456789, "'"));
        assertEquals(MessageText.quote("x".repeat(500)), MessageText.quote("x".repeat(61), 500, "'"));
    }

    @Test
    void cuttingKeepsSurrogatePairsWhole() {
        String s = "x".repeat(39) + "\uD83D\uDE00" + "y".repeat(40);
        assertEquals("x".repeat(39) + "...", MessageText.cut(s));
    }

    @Test
    void controlsAndSeparatorsAreEscaped() {
        assertEquals("a\\0b\\x7Fc\\x85d\\x9Fe\\x01f\\x1B", MessageText.escape("a\0b\u007Fc\u0085d\u009Fe\u0001f\u001B"));
        assertEquals("\\t\\n\\r", MessageText.escape("\t\n\r"));
        assertEquals("\\x007\\0x", MessageText.escape("\u00007\u0000x")); // \07 would read as octal
        assertEquals("l\\u2028p\\u2029", MessageText.escape("l\u2028p\u2029"));
        // Lone surrogates are escaped; a pair is a character and stays.
        assertEquals("\\uD800x\\uDC00", MessageText.escape("\uD800x\uDC00"));
        assertEquals("\\uD83D", MessageText.escape("\uD83D"));
        assertEquals("\uD83D\uDE00", MessageText.escape("\uD83D\uDE00"));
    }

    @Test
    void printableTextIsReturnedAsItIs() {
        String s = "scene.dat:1:2: unknown escape '\\t' in string (café, 日本, ü)";
        assertSame(s, MessageText.escape(s));
        // Escaping twice changes nothing more.
        String once = MessageText.escape("a\0\u2028");
        assertSame(once, MessageText.escape(once));
    }
}
