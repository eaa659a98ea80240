package lt.spindulys.io;

/**
 * Bad input with its location: {@code file:line:column: message}. The message says what was
 * found and what was expected; the command line prints it as one line.
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
        StringBuilder s = new StringBuilder(file == null ? "<input>" : file);
        if (line > 0) {
            s.append(':').append(line);
            if (column > 0) s.append(':').append(column);
        }
        return s.append(": ").append(message).toString();
    }

    public String file() { return file; }
    public int line() { return line; }
    public int column() { return column; }
}
