package lt.spindulys.io;

import java.nio.ByteBuffer;
import java.nio.CharBuffer;
import java.nio.charset.CharsetDecoder;
import java.nio.charset.CoderResult;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.regex.Pattern;

import lt.spindulys.limits.MessageText;

/**
 * Splits scene text into tokens on demand, recording the line and column where each starts.
 * Tokens: numbers, bare words, double-quoted strings, '{' and '}'; '#' starts a comment that runs
 * to the end of the line. Lines end with \n, \r\n or \r; columns count characters from 1 (a tab
 * is one column), so positions agree with what an editor shows.
 */
final class SceneLexer {
    enum Kind { WORD, NUMBER, STRING, OPEN, CLOSE, EOF }

    /**
     * One token. {@code text} is the source text, except for strings, where it is the content with
     * escapes resolved; {@code number} is the value of a number token (always finite).
     */
    record Token(Kind kind, String text, double number, int line, int column) {
        /** The token as an error message quotes it after "found" (a long one cut, see {@link MessageText#quote}). */
        String describe() {
            return switch (kind) {
                case EOF -> "end of file";
                case STRING -> "string " + MessageText.quote(text, "\"");
                default -> MessageText.quote(text);
            };
        }

        boolean isWord(String w) { return kind == Kind.WORD && text.equals(w); }

        /** "line:column", as messages refer back to an earlier token. */
        String position() { return line + ":" + column; }
    }

    // Signed decimal with optional fraction and exponent; "5." and ".5" are accepted.
    private static final Pattern NUMBER = Pattern.compile("[+-]?(?:\\d+(?:\\.\\d*)?|\\.\\d+)(?:[eE][+-]?\\d+)?");
    private static final Pattern NOT_FINITE = Pattern.compile("[+-]?(?:nan|inf|infinity)", Pattern.CASE_INSENSITIVE);

    private final String src;
    private final String file;
    private int pos;
    private int line = 1, column = 1;
    private Token peeked;

    SceneLexer(String text, String file) {
        // A byte-order mark is invisible in editors, so it must not count as a column.
        this.src = text.startsWith("\uFEFF") ? text.substring(1) : text;
        this.file = file;
    }

    Token peek() {
        if (peeked == null) peeked = scan();
        return peeked;
    }

    Token next() {
        Token t = peek();
        peeked = null;
        return t;
    }

    SceneException error(int line, int column, String message) {
        return new SceneException(file, line, column, message);
    }

    /** True for the spellings of NaN and infinity that the language refuses, so messages can say why. */
    static boolean isNonFiniteSpelling(String s) {
        return NOT_FINITE.matcher(s).matches();
    }

    /** True if {@code s} is an integer literal: optional sign and digits only. */
    static boolean isIntegerLiteral(String s) {
        int i = s.startsWith("+") || s.startsWith("-") ? 1 : 0;
        if (i == s.length()) return false;
        for (; i < s.length(); i++) if (s.charAt(i) < '0' || s.charAt(i) > '9') return false;
        return true;
    }

    private Token scan() {
        skipBlanksAndComments();
        if (pos >= src.length()) return new Token(Kind.EOF, "", 0, line, column);
        int l = line, c = column;
        char ch = src.charAt(pos);
        if (ch == '{' || ch == '}') {
            advance();
            return new Token(ch == '{' ? Kind.OPEN : Kind.CLOSE, String.valueOf(ch), 0, l, c);
        }
        if (ch == '"') return string(l, c);
        if (isWordStart(ch)) return word(l, c);
        if ((ch >= '0' && ch <= '9') || ch == '+' || ch == '-' || ch == '.') return number(l, c);
        throw error(l, c, "unexpected character " + describeChar(src.codePointAt(pos)));
    }

    private void skipBlanksAndComments() {
        while (pos < src.length()) {
            char ch = src.charAt(pos);
            if (ch == '#') {
                while (pos < src.length() && src.charAt(pos) != '\n' && src.charAt(pos) != '\r') advance();
            } else if (ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f') {
                advance();
            } else {
                return;
            }
        }
    }

    private Token word(int l, int c) {
        int start = pos;
        while (pos < src.length() && isWordPart(src.charAt(pos))) advance();
        String w = src.substring(start, pos);
        if (pos < src.length() && !isDelimiter(src.charAt(pos))) {
            char ch = src.charAt(pos);
            String hint = ch == '=' || ch == ':' ? " (write a value after its key, separated by a space)" : "";
            throw error(line, column, "unexpected character " + describeChar(src.codePointAt(pos)) + " after " + MessageText.quote(w) + hint);
        }
        return new Token(Kind.WORD, w, 0, l, c);
    }

    private Token number(int l, int c) {
        int start = pos;
        // Take the whole run up to a delimiter so that "1.2.3" or "2x" is reported as one bad number
        // rather than silently split into two tokens.
        while (pos < src.length() && !isDelimiter(src.charAt(pos))) advance();
        String s = src.substring(start, pos);
        if (!NUMBER.matcher(s).matches()) {
            if (isNonFiniteSpelling(s)) throw error(l, c, "NaN and Infinity are not allowed, found " + MessageText.quote(s));
            throw error(l, c, "malformed number " + MessageText.quote(s));
        }
        double v = Double.parseDouble(s);
        if (!Double.isFinite(v)) throw error(l, c, "number " + MessageText.quote(s) + " is out of range");
        return new Token(Kind.NUMBER, s, v, l, c);
    }

    private Token string(int l, int c) {
        advance(); // opening quote
        StringBuilder sb = new StringBuilder();
        while (true) {
            if (pos >= src.length() || src.charAt(pos) == '\n' || src.charAt(pos) == '\r') {
                throw error(l, c, "unterminated string (a string must end with \" on the same line)");
            }
            char ch = src.charAt(pos);
            if (ch == '"') {
                advance();
                return new Token(Kind.STRING, sb.toString(), 0, l, c);
            }
            if (ch == '\\') {
                int el = line, ec = column;
                advance();
                char e = pos < src.length() ? src.charAt(pos) : ' ';
                if (e != '"' && e != '\\') {
                    throw error(el, ec, "unknown escape '\\" + (pos < src.length() && e >= ' ' ? String.valueOf(e) : "")
                            + "' in string (only \\\" and \\\\ are allowed)");
                }
                sb.append(e);
                advance();
            } else {
                sb.append(ch);
                advance();
            }
        }
    }

    /** Moves one character on, keeping line and column; \r\n counts as one line end. */
    private void advance() {
        char ch = src.charAt(pos++);
        if (ch == '\n' || (ch == '\r' && (pos >= src.length() || src.charAt(pos) != '\n'))) {
            line++;
            column = 1;
        } else if (ch != '\r') {
            column++;
        }
    }

    /**
     * {line, column} just after the end of {@code text}, counting line ends as {@link #advance} does;
     * used to place errors found before tokenising (undecodable bytes).
     */
    static int[] endPosition(String text) {
        int l = 1, c = 1;
        for (int i = 0; i < text.length(); i++) {
            char ch = text.charAt(i);
            if (ch == '\n' || (ch == '\r' && (i + 1 >= text.length() || text.charAt(i + 1) != '\n'))) {
                l++;
                c = 1;
            } else if (ch != '\r' && !(i == 0 && ch == '\uFEFF')) {
                c++;
            }
        }
        return new int[] {l, c};
    }

    /**
     * Decodes UTF-8 strictly, so that text in another encoding is reported rather than read as
     * garbage: "FILE:LINE:COLUMN: WHAT is not UTF-8 text: byte 0xE9 cannot be decoded", placed
     * where an editor shows the bad byte. Shared by every line-based text reader (scene files,
     * Workframe meshes and unwraps), whose positions count as {@link #endPosition} does.
     *
     * @param what the file as the message names it: "the file", "the mesh file"
     */
    static String decodeUtf8(byte[] bytes, String fileName, String what) {
        CharsetDecoder d = StandardCharsets.UTF_8.newDecoder()
                .onMalformedInput(CodingErrorAction.REPORT)
                .onUnmappableCharacter(CodingErrorAction.REPORT);
        ByteBuffer in = ByteBuffer.wrap(bytes);
        CharBuffer out = CharBuffer.allocate(bytes.length + 1);
        CoderResult r = d.decode(in, out, true);
        if (!r.isError()) r = d.flush(out);
        out.flip();
        if (r.isError()) {
            int[] at = endPosition(out.toString());
            throw new SceneException(fileName, at[0], at[1],
                    String.format("%s is not UTF-8 text: byte 0x%02X cannot be decoded", what, bytes[in.position()] & 0xff));
        }
        return out.toString();
    }

    static boolean isWordStart(char ch) {
        return (ch >= 'A' && ch <= 'Z') || (ch >= 'a' && ch <= 'z') || ch == '_';
    }

    static boolean isWordPart(char ch) {
        return isWordStart(ch) || (ch >= '0' && ch <= '9') || ch == '.' || ch == '-';
    }

    private static boolean isDelimiter(char ch) {
        return ch == ' ' || ch == '\t' || ch == '\n' || ch == '\r' || ch == '\f' || ch == '{' || ch == '}' || ch == '#' || ch == '"';
    }

    /** A character quoted, or as U+XXXX if it would not show as itself (blanks, controls, separators, a lone surrogate). */
    private static String describeChar(int codePoint) {
        String s = new String(Character.toChars(codePoint));
        return codePoint > ' ' && MessageText.escape(s).equals(s) ? "'" + s + "'" : String.format("U+%04X", codePoint);
    }
}
