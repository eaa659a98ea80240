package lt.spindulys.limits;

/**
 * Input echoed into an error message, kept to one short line: a token is cut to a readable
 * length ({@link #cut}, {@link #quote}), and characters that a terminal would not show as
 * themselves (controls, line and paragraph separators, lone surrogates) are written as escapes
 * ({@link #escape}). A 10 MB number in a scene file then gives a line of a hundred characters,
 * and a NUL or a U+2028 in it cannot break the line or hide part of it.
 */
public final class MessageText {
    private MessageText() {}

    /** Characters of a token shown before it is cut. */
    public static final int SHOWN = 40;

    /** A token is shown whole if cutting it would save fewer characters than this. */
    public static final int SLACK = 20;

    /**
     * {@code s} itself if it is at most {@value #SHOWN} + {@value #SLACK} characters, else its
     * first {@value #SHOWN} followed by "..." (never splitting a surrogate pair).
     */
    public static String cut(String s) { return cut(s, SHOWN); }

    /** As {@link #cut(String)}, showing the first {@code shown} characters (for paths, which are longer than tokens). */
    public static String cut(String s, int shown) {
        if (s.length() <= shown + SLACK) return s;
        int n = Character.isHighSurrogate(s.charAt(shown - 1)) ? shown - 1 : shown;
        return s.substring(0, n) + "...";
    }

    /**
     * {@code s} between {@code mark}s ("'", "\"", or "" for none), cut as by {@link #cut}; a cut
     * token is followed by its length: {@code 'abc...' (10485760 characters)}.
     */
    public static String quote(String s, String mark) {
        String c = cut(s);
        String q = mark + c + mark;
        return c.length() == s.length() ? q : q + " (" + s.length() + " characters)";
    }

    /** {@link #quote(String, String)} in single quotes, as messages quote a token after "found". */
    public static String quote(String s) { return quote(s, "'"); }

    /**
     * As {@link #quote(String, String)} for a token known by its start and its length, so that a
     * reader need not decode a huge token whole to quote it: {@code head} is the token itself if
     * it is at most {@value #SHOWN} + {@value #SLACK} characters long, else at least its first
     * {@value #SHOWN}.
     */
    public static String quote(String head, long length, String mark) {
        if (length <= SHOWN + SLACK) return mark + head + mark;
        int n = Character.isHighSurrogate(head.charAt(SHOWN - 1)) ? SHOWN - 1 : SHOWN;
        return mark + head.substring(0, n) + "..." + mark + " (" + length + " characters)";
    }

    /**
     * {@code s} with every character that would not print as itself on one line escaped: \0
     * (\x00 before a digit), \t, \n, \r; \xHH for the other C0 controls, DEL and the C1
     * controls; \\uHHHH for line and paragraph separators and lone surrogates. Backslashes are left alone, so escaping is
     * idempotent. Returns {@code s} itself when nothing needs escaping.
     */
    public static String escape(String s) {
        if (s == null) return null;
        int i = 0, n = s.length();
        while (i < n && !needsEscape(s, i)) i++;
        if (i == n) return s;
        StringBuilder b = new StringBuilder(n + 16).append(s, 0, i);
        for (; i < n; i++) {
            char c = s.charAt(i);
            if (!needsEscape(s, i)) {
                b.append(c);
            } else if (c == 0 && !(i + 1 < n && s.charAt(i + 1) >= '0' && s.charAt(i + 1) <= '9')) {
                b.append("\\0"); // \x00 before a digit, which would read as octal
            } else if (c == '\t') {
                b.append("\\t");
            } else if (c == '\n') {
                b.append("\\n");
            } else if (c == '\r') {
                b.append("\\r");
            } else if (c < 0x100) {
                b.append(String.format("\\x%02X", (int) c));
            } else {
                b.append(String.format("\\u%04X", (int) c));
            }
        }
        return b.toString();
    }

    private static boolean needsEscape(String s, int i) {
        char c = s.charAt(i);
        if (c < 0x20 || (c >= 0x7F && c <= 0x9F)) return true;
        if (c < 0x2000) return false; // the common case, decided without a table lookup
        if (Character.isSurrogate(c)) return loneSurrogate(s, i);
        int type = Character.getType(c);
        return type == Character.LINE_SEPARATOR || type == Character.PARAGRAPH_SEPARATOR;
    }

    private static boolean loneSurrogate(String s, int i) {
        char c = s.charAt(i);
        if (Character.isHighSurrogate(c)) return i + 1 >= s.length() || !Character.isLowSurrogate(s.charAt(i + 1));
        return i == 0 || !Character.isHighSurrogate(s.charAt(i - 1));
    }
}
