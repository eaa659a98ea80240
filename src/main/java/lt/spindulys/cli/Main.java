package lt.spindulys.cli;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

import lt.spindulys.bench.BenchCommand;
import lt.spindulys.bench.BenchUsageException;
import lt.spindulys.image.NonFinitePixelException;
import lt.spindulys.io.SceneException;
import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.frontend.Version;
import lt.spindulys.limits.MessageText;

/**
 * The {@code render} command line: {@code render SCENE.dat ...} renders ({@link RenderCommand}),
 * {@code render subdivide ...} refines a mesh ({@link SubdivideCommand}), {@code render view ...} opens the viewer
 * ({@link ViewCommand}), {@code render assemble ...} puts tiles back into a frame ({@link AssembleCommand}),
 * {@code render bench ...} runs the benchmark suite ({@link BenchCommand}, a front end of its own). {@link #run} does the work and returns the exit status, so
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
        // A farm's manager told to read OpenJD lines reads openjd_fail: for an error in the
        // arguments too: asked for anywhere on the line, it is known before any other argument is read.
        PrintStream openjd = null;
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
                return new BenchCommand(rest.toArray(new String[0]), Main.class).run(out);
            }
            if (rest.isEmpty() || rest.contains("--help") || rest.contains("-h")) {
                (rest.isEmpty() ? err : out).println(RenderCommand.USAGE);
                return rest.isEmpty() ? 2 : 0;
            }
            if (rest.contains("--version")) {
                out.println("spindulys " + version());
                return 0;
            }
            String[] renderArgs = rest.toArray(new String[0]);
            if (FarmOptions.asksForOpenjd(renderArgs)) openjd = out;
            RenderCommand command = new RenderCommand(renderArgs, env);
            openjd = null; // from here on the command reports its own failures to the manager
            return command.run(out, err);
        } catch (UsageException | BenchUsageException e) {
            line(err, openjd, "render: " + e.getMessage());
            return 2;
        } catch (SceneException | RenderCommand.NoSuchFileException | IllegalArgumentException e) {
            // Bad input: the message already names the place (file:line:column or the object).
            line(err, openjd, e instanceof RenderCommand.NoSuchFileException ? e.getMessage() : FailureMessage.of(e));
            if (debug) e.printStackTrace(err);
            return 2;
        } catch (InterruptedException | java.io.IOException | NonFinitePixelException | OutOfMemoryError e) {
            // The same line the viewer shows for the same failure (FailureMessage); a non-finite
            // pixel is unreachable from any input the readers accept (their ranges keep pixels finite): a bug.
            line(err, openjd, FailureMessage.of(e));
            if (debug && !(e instanceof InterruptedException) && !(e instanceof OutOfMemoryError)) e.printStackTrace(err);
            return 1;
        } catch (RuntimeException e) {
            line(err, openjd, FailureMessage.of(e) + (debug ? "" : " (run with --debug for details)"));
            if (debug) e.printStackTrace(err);
            return 1;
        }
    }

    /** The message on stderr, and as {@code openjd_fail:} on {@code openjd} unless that is null. */
    private static void line(PrintStream err, PrintStream openjd, String message) {
        line(err, message);
        if (openjd != null) FarmProgress.failedBeforeStart(openjd, message);
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
        return Version.text();
    }
}
