package lt.spindulys.io;

import lt.spindulys.limits.MessageText;

/**
 * Bad input with its location: {@code file:line:column: message}. The message says what was
 * found and what was expected; the command line prints it as one line. Control characters and
 * line separators that reach the message from the input are shown escaped
 * ({@link MessageText#escape}), so the message is one line whatever the input held.
 */
public final class SceneException extends RuntimeException {
    private final String file;
    private final int line, column;

    public SceneException(String file, int line, int column, String message) {
        super(format(file, line, column, message));
        this.file = file;
        this.line = line;
        this.column = column;
    }

    public SceneException(String file, int line, int column, String message, Throwable cause) {
        super(format(file, line, column, message), cause);
        this.file = file;
        this.line = line;
        this.column = column;
    }

    private static String format(String file, int line, int column, String message) {
        return MessageText.escape(location(file, line, column) + ": " + message);
    }

    /**
     * "file:line:column" as messages name a place ("file" alone when the line is 0, "&lt;input&gt;"
     * for a null file); also what the scene parser gives objects as their source.
     */
    public static String location(String file, int line, int column) {
        StringBuilder s = new StringBuilder(file == null ? "<input>" : file);
        if (line > 0) {
            s.append(':').append(line);
            if (column > 0) s.append(':').append(column);
        }
        return s.toString();
    }

    public String file() { return file; }
    public int line() { return line; }
    public int column() { return column; }
}
