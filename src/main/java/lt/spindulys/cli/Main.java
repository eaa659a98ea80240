package lt.spindulys.cli;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import lt.spindulys.image.NonFinitePixelException;
import lt.spindulys.io.SceneException;
import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.limits.MessageText;

/**
 * The {@code render} command line: {@code render SCENE.dat ...} renders ({@link RenderCommand}),
 * {@code render subdivide ...} refines a mesh ({@link SubdivideCommand}), {@code render view ...} opens the viewer
 * ({@link ViewCommand}), {@code render assemble ...} puts tiles back into a frame ({@link AssembleCommand}). {@link #run} does the work and returns the exit status, so
 * tests call it in-process; {@link #main} only exits with that status. Bad usage and bad input
 * print one line to stderr and exit 2; a failure while rendering or writing exits 1. Stack traces
 * appear only with {@code --debug}.
 */
public final class Main {
    private Main() {}

    public static void main(String[] args) {
        int status = run(args, System.out, System.err);
        System.out.flush();
        System.exit(status);
    }

    /** Runs the command line with the given streams; returns the process exit status. */
    public static int run(String[] args, PrintStream out, PrintStream err) {
        return run(args, out, err, System.getenv());
    }

    /** {@link #run(String[], PrintStream, PrintStream)} with the environment variables given (SPINDULYS_ASSETS_ROOT). */
    static int run(String[] args, PrintStream out, PrintStream err, Map<String, String> env) {
        List<String> rest = new ArrayList<>(Arrays.asList(args));
        boolean debug = rest.remove("--debug");
        try {
            if (!rest.isEmpty() && rest.get(0).equals("subdivide")) {
                rest.remove(0);
                if (rest.contains("--help") || rest.contains("-h")) {
                    out.println(SubdivideCommand.USAGE);
                    return 0;
                }
                return new SubdivideCommand(rest.toArray(new String[0]), env).run(out, err);
            }
            if (!rest.isEmpty() && rest.get(0).equals("view")) {
                rest.remove(0);
                if (rest.contains("--help") || rest.contains("-h")) {
                    out.println(ViewCommand.USAGE);
                    return 0;
                }
                return new ViewCommand(rest.toArray(new String[0])).run(out, err);
            }
            if (!rest.isEmpty() && rest.get(0).equals("assemble")) {
                rest.remove(0);
                if (rest.contains("--help") || rest.contains("-h")) {
                    out.println(AssembleCommand.USAGE);
                    return 0;
                }
                return new AssembleCommand(rest.toArray(new String[0])).run(err);
            }
            if (!rest.isEmpty() && rest.get(0).equals("bench")) {
                rest.remove(0);
                if (rest.contains("--help") || rest.contains("-h")) {
                    out.println(BenchCommand.USAGE);
                    return 0;
                }
                return new BenchCommand(rest.toArray(new String[0])).run(out);
            }
            if (rest.isEmpty() || rest.contains("--help") || rest.contains("-h")) {
                (rest.isEmpty() ? err : out).println(RenderCommand.USAGE);
                return rest.isEmpty() ? 2 : 0;
            }
            if (rest.contains("--version")) {
                out.println("spindulys " + version());
                return 0;
            }
            return new RenderCommand(rest.toArray(new String[0]), env).run(out, err);
        } catch (UsageException e) {
            line(err, "render: " + e.getMessage());
            return 2;
        } catch (SceneException | RenderCommand.NoSuchFileException | IllegalArgumentException e) {
            // Bad input: the message already names the place (file:line:column or the object).
            line(err, e instanceof RenderCommand.NoSuchFileException ? e.getMessage() : FailureMessage.of(e));
            if (debug) e.printStackTrace(err);
            return 2;
        } catch (InterruptedException | java.io.IOException | NonFinitePixelException | OutOfMemoryError e) {
            // The same line the viewer shows for the same failure (FailureMessage); a non-finite
            // pixel is unreachable from any input the readers accept (their ranges keep pixels finite): a bug.
            line(err, FailureMessage.of(e));
            if (debug && !(e instanceof InterruptedException) && !(e instanceof OutOfMemoryError)) e.printStackTrace(err);
            return 1;
        } catch (RuntimeException e) {
            line(err, FailureMessage.of(e) + (debug ? "" : " (run with --debug for details)"));
            if (debug) e.printStackTrace(err);
            return 1;
        }
    }

    /**
     * Prints one message line: whatever the input put into it (a newline, a NUL, a U+2028 in a
     * file name or a token), it stays one line on stderr. SceneException has escaped its own
     * already; this is the safety net for every other message.
     */
    private static void line(PrintStream err, String message) {
        err.println(MessageText.escape(message));
    }

    static String version() {
        String v = Main.class.getPackage().getImplementationVersion();
        // A jar's manifest gives the version on the class path; on the module path the
        // descriptor carries it (the compiler records the project's version there).
        if (v == null && Main.class.getModule().getDescriptor() != null) {
            v = Main.class.getModule().getDescriptor().rawVersion().orElse(null);
        }
        return v != null ? v : "development build";
    }
}
