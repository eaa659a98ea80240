package lt.spindulys.io;

import lt.spindulys.limits.MessageText;

/**
 * Bad input with its location: {@code file:line:column: message}. The message says what was
 * found and what was expected; the command line prints it as one line. Control characters and
 * line separators that reach the message from the input are shown escaped
 * ({@link MessageText#escape}), so the message is one line whatever the input held.
 */
public final class SceneException extends RuntimeException {
    /** The input's name, or null. */
    private final String file;
    /** The place in it, from 1; 0 when not known. */
    private final int line, column;

    /**
     * An error at a place in the input.
     *
     * @param file the input's name, or null
     * @param line the line, from 1; 0 if not known
     * @param column the column, from 1; 0 if not known
     * @param message what was found and what was expected
     */
    public SceneException(String file, int line, int column, String message) {
        super(format(file, line, column, message));
        this.file = file;
        this.line = line;
        this.column = column;
    }

    /**
     * An error at a place in the input, caused by another.
     *
     * @param file the input's name, or null
     * @param line the line, from 1; 0 if not known
     * @param column the column, from 1; 0 if not known
     * @param message what was found and what was expected
     * @param cause the error underneath
     */
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
     *
     * @param file the input's name, or null
     * @param line the line, from 1; 0 if not known
     * @param column the column, from 1; 0 if not known
     * @return the location text
     */
    public static String location(String file, int line, int column) {
        StringBuilder s = new StringBuilder(file == null ? "<input>" : file);
        if (line > 0) {
            s.append(':').append(line);
            if (column > 0) s.append(':').append(column);
        }
        return s.toString();
    }

    /** {@return the input's name, or null} */
    public String file() { return file; }
    /** {@return the line, from 1; 0 if not known} */
    public int line() { return line; }
    /** {@return the column, from 1; 0 if not known} */
    public int column() { return column; }
}
