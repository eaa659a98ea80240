package lt.spindulys.cli;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import javax.swing.SwingUtilities;

import lt.spindulys.limits.MessageText;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.OutputPlugins;
import lt.spindulys.viewer.ViewerFrame;

/**
 * {@code render view [MESH...]}: opens the viewer's window with the meshes given, with a Plugins
 * menu of every output plugin found, and returns when it is closed. Without a display, or with a
 * DISPLAY no X server answers, it prints one line saying so and fails (status 1), instead of the
 * JDK's HeadlessException or AWTError.
 */
final class ViewCommand {
    static final String USAGE = """
            usage: render view [--plugins FOLDER]... [MESH.obj|MESH.dat|UNWRAP.tex ...]

              Opens the subdivision-surface viewer (a desktop window) with the meshes given; more can be
              opened with File > Open or dropped on the window. A .dat mesh takes the .tex unwrap of the
              same name beside it; a .tex given on its own is attached to the surface opened before it.
              Mouse: left drag orbits, right (or shift) drag pans, the wheel zooms.
              Keys: arrows orbit, + and - zoom, F fits, 1 2 3 polyhedron / lattice / smoothed,
              C cage over the surface, Page Up / Page Down subdivision level.
              --plugins FOLDER  also list the output plugins of the jars in FOLDER in the Plugins menu
                                (see docs/plugins.md, Writing a plugin); may be given several times.
            See README.md (Viewer).""";

    /** How long a closing viewer waits for cancelled plugin runs to stop (they check often; this is a backstop). */
    static final long RUNS_GRACE_SECONDS = 30;

    private final List<Path> files = new ArrayList<>();
    private final List<Path> pluginFolders = new ArrayList<>();
    private final BooleanSupplier headless;

    /**
     * Parses the arguments.
     *
     * @param args the mesh files
     * @param headless true when there is no display (GraphicsEnvironment::isHeadless, or a test's answer)
     */
    ViewCommand(String[] args, BooleanSupplier headless) throws UsageException {
        this.headless = headless;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--plugins")) {
                if (i + 1 == args.length) throw new UsageException("--plugins needs a folder (see render view --help)");
                pluginFolders.add(Path.of(args[++i]));
            } else if (a.startsWith("-")) {
                throw new UsageException("unknown view option '" + a + "' (see render view --help)");
            } else {
                files.add(Path.of(a));
            }
        }
    }

    ViewCommand(String[] args) throws UsageException {
        this(args, GraphicsEnvironment::isHeadless);
    }

    /**
     * The display the JDK cannot connect to, as "':99' (DISPLAY)"; null when it can (or when
     * there is no X server to ask: another platform, or headless).
     */
    static String unreachableDisplay() {
        try {
            GraphicsEnvironment.getLocalGraphicsEnvironment();
            return null;
        } catch (AWTError | LinkageError e) {
            // The first attempt throws AWTError; a later one finds the class's failed initialisation.
            String display = System.getenv("DISPLAY");
            return display == null ? "(" + e.getMessage() + ")" : "'" + display + "' (DISPLAY)";
        }
    }

    int run(PrintStream out, PrintStream err) throws InterruptedException {
        if (headless.getAsBoolean()) {
            err.println("render view: the viewer needs a display, and there is none (no DISPLAY, or java.awt.headless is set); "
                    + "run it on a desktop or under a virtual X server");
            return 1;
        }
        // Found before the window opens, so a bad plugin folder is one line on the terminal.
        List<OutputPlugin> plugins;
        try {
            // A plugin without a usable id or name is left out with one line naming its jar; the viewer goes on.
            plugins = OutputPlugins.available(pluginFolders, line -> err.println("render view: " + line));
        } catch (IOException e) {
            err.println("render view: cannot list a plugin folder: " + e.getMessage());
            return 1;
        } catch (IllegalArgumentException e) {
            err.println("render view: " + e.getMessage());
            return 1;
        }
        // A DISPLAY that no X server answers (a stale ssh forwarding, a container) is not headless:
        // the JDK finds out only when it connects, with an AWTError. Asked here, it is one line too.
        String unreachable = unreachableDisplay();
        if (unreachable != null) {
            err.println(MessageText.escape("render view: cannot connect to the display " + unreachable
                    + "; run it on a desktop or under a virtual X server, or set DISPLAY to a display that is running"));
            return 1;
        }
        CountDownLatch closed = new CountDownLatch(1);
        AtomicReference<ViewerFrame> frame = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                // Outputs go to the working folder until the user picks another, as the command line's do.
                ViewerFrame f = ViewerFrame.withPlugins(plugins, Path.of(""));
                frame.set(f);
                f.addWindowListener(new WindowAdapter() {
                    @Override public void windowClosed(WindowEvent e) { closed.countDown(); }
                });
                f.setLocationByPlatform(true);
                f.setVisible(true);
                if (!files.isEmpty()) f.open(files);
            });
        } catch (InvocationTargetException e) {
            Throwable c = e.getCause();
            if (c instanceof RuntimeException r) throw r;
            if (c instanceof Error x) throw x;
            throw new IllegalStateException(c);
        }
        closed.await();
        // Main exits the JVM next: plugin runs (cancelled as their windows closed with the viewer)
        // end first, so none is killed between its temporary file and the rename.
        if (!frame.get().awaitPluginRuns(RUNS_GRACE_SECONDS, TimeUnit.SECONDS)) {
            err.println("render view: a plugin run did not stop within " + RUNS_GRACE_SECONDS + " s of the viewer closing; it was ended with the viewer");
        }
        return 0;
    }
}
