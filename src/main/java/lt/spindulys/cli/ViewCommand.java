package lt.spindulys.cli;

import java.awt.AWTError;
import java.awt.GraphicsEnvironment;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;

import javax.swing.SwingUtilities;

import lt.spindulys.io.SceneParser;
import lt.spindulys.limits.MessageText;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.OutputPlugins;
import lt.spindulys.viewer.ScenePreviewFrame;
import lt.spindulys.viewer.ViewerFrame;

/**
 * {@code render view [MESH...]}: opens the viewer's window with the meshes given, with a Plugins
 * menu of every output plugin found, and returns when it is closed; {@code render view SCENE.dat}
 * opens the live preview of a scene file instead ({@link ScenePreviewFrame}). A scene file is told
 * from a Workframe mesh, both {@code .dat}, by its first token ({@link SceneParser#isSceneFile}), or
 * named as one with {@code --scene}. Without a display, or with a DISPLAY no X server answers, it
 * prints one line saying so and fails (status 1), instead of the JDK's HeadlessException or AWTError.
 */
final class ViewCommand {
    static final String USAGE = """
            usage: render view [--plugins FOLDER]... [MESH.obj|MESH.dat|UNWRAP.tex ...]
                   render view [--scene] [--frame N] SCENE.dat

              Opens the subdivision-surface viewer (a desktop window) with the meshes given; more can be
              opened with File > Open or dropped on the window. A .dat mesh takes the .tex unwrap of the
              same name beside it; a .tex given on its own is attached to the surface opened before it.
              Mouse: left drag orbits, right (or shift) drag pans, the wheel zooms.
              Keys: arrows orbit, + and - zoom, F fits, 1 2 3 polyhedron / lattice / smoothed,
              C cage over the surface, Page Up / Page Down subdivision level.
              --plugins FOLDER  also list the output plugins of the jars in FOLDER in the Plugins menu
                                (see docs/plugins.md, Writing a plugin); may be given several times.

              A scene file (the format of docs/scene-format.md) opens the live preview instead: the scene
              rendered as render SCENE.dat renders it, coarse first and refined pass by pass to its full
              size and samples, and rendered again whenever the scene file or a file it reads changes
              (meshes, material libraries, textures, environment maps). A file that stops reading shows
              its error (file:line:column) above the last good picture. Left drag turns the view around
              the camera's look-at point, the wheel moves the camera nearer or farther; the Camera menu
              resets the view (Home), copies it as a camera block (Ctrl+C) or, after asking, saves that
              block into the scene file in place of its camera statement (Ctrl+S).
              A .dat whose first token is a word (camera, settings, an object...) is a scene; one that
              starts with a number is a Workframe mesh.
              --scene    take the file as a scene file whatever it looks like
              --frame N  show frame N of the scene's animation (default: its first frame)
            See README.md (Viewer).""";

    /** How long a closing viewer waits for cancelled plugin runs to stop (they check often; this is a backstop). */
    static final long RUNS_GRACE_SECONDS = 30;

    private final List<Path> files = new ArrayList<>();
    /** The scene file to preview, or null for the mesh viewer. */
    private final Path scene;
    private Integer frame;
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
        boolean sceneGiven = false;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            if (a.equals("--scene")) {
                sceneGiven = true;
            } else if (a.equals("--frame")) {
                if (i + 1 == args.length) throw new UsageException("--frame needs a frame number (see render view --help)");
                try {
                    frame = Integer.valueOf(args[++i]);
                } catch (NumberFormatException e) {
                    throw new UsageException("--frame: expected a whole frame number, found '" + MessageText.escape(args[i]) + "'");
                }
            } else if (a.equals("--plugins")) {
                if (i + 1 == args.length) throw new UsageException("--plugins needs a folder (see render view --help)");
                pluginFolders.add(Path.of(args[++i]));
            } else if (a.startsWith("-")) {
                throw new UsageException("unknown view option '" + a + "' (see render view --help)");
            } else {
                files.add(Path.of(a));
            }
        }
        scene = sceneOf(sceneGiven);
    }

    /** The scene file among the files, or null when they are meshes; a scene comes alone. */
    private Path sceneOf(boolean given) throws UsageException {
        Path found = null;
        for (Path f : files) {
            if (given || isSceneFile(f)) {
                if (files.size() > 1) {
                    throw new UsageException(f + " is a scene file: a scene is previewed on its own (render view " + f + "), not with other files");
                }
                found = f;
            }
        }
        if (found == null && given) throw new UsageException("--scene needs a scene file (see render view --help)");
        if (found == null && frame != null) throw new UsageException("--frame is for a scene file's animation, and no scene file was given");
        if (found != null && !pluginFolders.isEmpty()) {
            throw new UsageException("--plugins is for the mesh viewer: the output plugins are not in the scene preview");
        }
        return found;
    }

    /** A .dat file that reads as a scene rather than a Workframe mesh; a file that cannot be read is left to the viewer's own message. */
    private static boolean isSceneFile(Path f) {
        String name = f.getFileName() == null ? "" : f.getFileName().toString().toLowerCase(java.util.Locale.ROOT);
        if (!name.endsWith(".dat") || !Files.isRegularFile(f)) return false;
        try {
            return SceneParser.isSceneFile(f);
        } catch (IOException e) {
            return false;
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

    /**
     * A DISPLAY that no X server answers (a stale ssh forwarding, a container) is not headless:
     * the JDK finds out only when it connects, with an AWTError. Asked here, it is one line too.
     */
    private static boolean displayReachable(PrintStream err) {
        String unreachable = unreachableDisplay();
        if (unreachable == null) return true;
        err.println(MessageText.escape("render view: cannot connect to the display " + unreachable
                + "; run it on a desktop or under a virtual X server, or set DISPLAY to a display that is running"));
        return false;
    }

    /** The live preview of the scene file, until its window is closed. */
    private int preview(PrintStream err) throws InterruptedException {
        if (!Files.isRegularFile(scene)) {
            err.println(MessageText.escape("render view: " + scene + ": " + (Files.exists(scene) ? "not a regular file" : "no such file")));
            return 1;
        }
        if (!displayReachable(err)) return 1;
        CountDownLatch closed = new CountDownLatch(1);
        AtomicReference<String> failure = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                ScenePreviewFrame f;
                try {
                    f = ScenePreviewFrame.open(scene, frame);
                } catch (IOException e) {
                    failure.set("render view: cannot watch the scene's files: " + e.getMessage());
                    return;
                }
                f.addWindowListener(new WindowAdapter() {
                    @Override public void windowClosed(WindowEvent e) { closed.countDown(); }
                });
                f.setLocationByPlatform(true);
                f.setVisible(true);
            });
        } catch (InvocationTargetException e) {
            Throwable c = e.getCause();
            if (c instanceof RuntimeException r) throw r;
            if (c instanceof Error x) throw x;
            throw new IllegalStateException(c);
        }
        if (failure.get() != null) {
            err.println(MessageText.escape(failure.get()));
            return 1;
        }
        closed.await();
        return 0;
    }

    int run(PrintStream out, PrintStream err) throws InterruptedException {
        if (headless.getAsBoolean()) {
            err.println("render view: the viewer needs a display, and there is none (no DISPLAY, or java.awt.headless is set); "
                    + "run it on a desktop or under a virtual X server");
            return 1;
        }
        if (scene != null) return preview(err);
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
        if (!displayReachable(err)) return 1;
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
