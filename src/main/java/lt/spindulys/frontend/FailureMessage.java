package lt.spindulys.frontend;

import java.io.IOException;
import java.util.concurrent.CancellationException;

import lt.spindulys.image.NonFinitePixelException;
import lt.spindulys.io.SceneException;
import lt.spindulys.limits.MessageText;

/**
 * The one line a user is shown for a failure, in every front end: {@code render} prints it on
 * the command line ({@code cli.Main}) and the viewer shows it in a dialog (a file it cannot open,
 * a level it refuses, a plugin run that failed), so a user sees the same words in both places.
 */
public final class FailureMessage {
    private FailureMessage() {}

    /** What a run the user cancelled reports; the plugin contract says it wrote nothing. */
    public static final String CANCELLED = "cancelled; nothing written";

    /**
     * The message for a failure.
     *
     * @param failure what a run, a read or an action threw
     * @return one line, escaped ({@link MessageText#escape}): bad input (SceneException,
     *         IllegalArgumentException) as its own message, which names the place; "render: " and
     *         the message for an I/O failure; "cancelled; nothing written" for a cancelled run;
     *         an internal error named as such otherwise
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
        } else if (failure instanceof NonFinitePixelException) {
            // Its message says which pixel; unreachable from input the readers accept, so a bug.
            line = "render: internal error: " + failure.getMessage();
        } else {
            line = "render: internal error: " + failure;
        }
        return MessageText.escape(line == null ? "render: internal error: " + failure : line);
    }
}
