package lt.spindulys.viewer;

import java.io.IOException;
import java.util.concurrent.CancellationException;

import lt.spindulys.io.SceneException;
import lt.spindulys.limits.MessageText;

/**
 * The one line the viewer shows for a failed plugin run or a file it cannot use: the line
 * {@code render} prints for the same exception on the command line ({@code cli.Main}), so a
 * user sees the same words in both places.
 */
public final class UserMessages {
    private UserMessages() {}

    /** What a run the user cancelled reports; the plugin contract says it wrote nothing. */
    public static final String CANCELLED = "cancelled; nothing written";

    /**
     * The message for a failure.
     *
     * @param failure what a run or a read threw
     * @return one line: bad input (SceneException, IllegalArgumentException) as its own message,
     *         which names the place; "render: " and the message for an I/O failure; "cancelled;
     *         nothing written" for a cancelled run; an internal error named as such otherwise
     */
    public static String of(Throwable failure) {
        String line;
        if (failure instanceof CancellationException) {
            line = CANCELLED;
        } else if (failure instanceof SceneException || failure instanceof IllegalArgumentException) {
            line = failure.getMessage();
        } else if (failure instanceof IOException) {
            line = "render: " + failure.getMessage();
        } else if (failure instanceof InterruptedException) {
            line = "render: interrupted; nothing written";
        } else if (failure instanceof OutOfMemoryError) {
            line = "render: out of memory (give the JVM more with -Xmx, or lower the resolution)";
        } else {
            line = "render: internal error: " + failure;
        }
        return MessageText.escape(line == null ? "render: internal error: " + failure : line);
    }
}
