package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

/** {@code render view} without a display, and its help. The window itself is tested with a real display elsewhere. */
class ViewCommandTest {
    @Test
    void withoutADisplayItSaysSoInOneLineAndFails() throws Exception {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = new ViewCommand(new String[] {"scenes/models/cube.dat"}, () -> true)
                .run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertEquals("", out.toString(StandardCharsets.UTF_8));
        String e = err.toString(StandardCharsets.UTF_8);
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("render view: the viewer needs a display"), e);
    }

    @Test
    void aHeadlessJvmRunningTheCommandLineFailsTheSameWay() throws Exception {
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        Process p = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Djava.awt.headless=true",
                "-cp", classes.toString(), Main.class.getName(), "view", "scenes/models/cube.dat")).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "render view returned");
        String e = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(1, p.exitValue(), e);
        assertEquals(1, e.lines().count(), e);
        assertTrue(e.startsWith("render view: the viewer needs a display"), e);
    }

    /**
     * A DISPLAY no X server answers (a stale ssh forwarding, a container): one line, the status of
     * the no-display case, no AWTError stack trace. The display is one with no X socket, named or abstract.
     */
    @Test
    void aDisplayThatNoServerAnswersIsOneLine() throws Exception {
        int n = 99;
        while (n < 1000 && xSocketExists(n)) n++;
        Path classes = Path.of(Main.class.getProtectionDomain().getCodeSource().getLocation().toURI());
        ProcessBuilder b = new ProcessBuilder(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", classes.toString(), Main.class.getName(), "view", "scenes/models/cube.dat")).redirectOutput(ProcessBuilder.Redirect.DISCARD);
        b.environment().put("DISPLAY", ":" + n);
        b.environment().remove("XAUTHORITY");
        Process p = b.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "render view returned");
        String e = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(1, p.exitValue(), e);
        assertEquals("render view: cannot connect to the display ':" + n + "' (DISPLAY); run it on a desktop or under a virtual X server,"
                + " or set DISPLAY to a display that is running" + System.lineSeparator(), e);
    }

    /** True if an X server may listen on display {@code n}: its socket file, or its abstract socket (Linux). */
    private static boolean xSocketExists(int n) throws java.io.IOException {
        if (java.nio.file.Files.exists(Path.of("/tmp/.X11-unix/X" + n))) return true;
        Path unix = Path.of("/proc/net/unix");
        String name = "@/tmp/.X11-unix/X" + n;
        return java.nio.file.Files.isReadable(unix) && java.nio.file.Files.readAllLines(unix).stream().anyMatch(l -> l.endsWith(" " + name));
    }

    @Test
    void helpAndBadOptions() {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        assertEquals(0, Main.run(new String[] {"view", "--help"}, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err)));
        assertTrue(out.toString(StandardCharsets.UTF_8).startsWith("usage: render view"), out.toString(StandardCharsets.UTF_8));
        err.reset();
        assertEquals(2, Main.run(new String[] {"view", "--fast"}, new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8)));
        assertEquals("render: unknown view option '--fast' (see render view --help)", err.toString(StandardCharsets.UTF_8).strip());
        out.reset();
        assertEquals(0, Main.run(new String[] {"--help"}, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err)));
        assertTrue(out.toString(StandardCharsets.UTF_8).contains("render view [MESH"), "the main usage lists view");
    }

    @Test
    void aBadPluginFolderIsOneLineBeforeAnyWindow() throws Exception {
        assertThrows(UsageException.class, () -> new ViewCommand(new String[] {"--plugins"}, () -> false));
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        // Not headless: the folder is looked at before the window would open.
        int status = new ViewCommand(new String[] {"--plugins", "no/such/folder", "scenes/models/cube.dat"}, () -> false)
                .run(new PrintStream(out, true, "UTF-8"), new PrintStream(err, true, "UTF-8"));
        assertEquals(1, status);
        assertEquals("render view: plugin folder no/such/folder is missing\n", err.toString("UTF-8"));
    }

    @Test
    void aSceneFileIsPreviewedAloneAndItsOptionsAreChecked() throws Exception {
        UsageException mixed = assertThrows(UsageException.class, () -> new ViewCommand(new String[] {"scenes/models/cube.dat", "scenes/spheres.dat"}, () -> false));
        assertEquals("scenes/spheres.dat is a scene file: a scene is previewed on its own (render view scenes/spheres.dat), not with other files", mixed.getMessage());
        UsageException plugins = assertThrows(UsageException.class, () -> new ViewCommand(new String[] {"--plugins", "p", "scenes/spheres.dat"}, () -> false));
        assertTrue(plugins.getMessage().startsWith("--plugins is for the mesh viewer"), plugins.getMessage());
        UsageException frame = assertThrows(UsageException.class, () -> new ViewCommand(new String[] {"--frame", "3", "scenes/models/cube.dat"}, () -> false));
        assertEquals("--frame is for a scene file's animation, and no scene file was given", frame.getMessage());
        assertThrows(UsageException.class, () -> new ViewCommand(new String[] {"--frame", "x", "scenes/spheres.dat"}, () -> false));
        assertThrows(UsageException.class, () -> new ViewCommand(new String[] {"--scene"}, () -> false));

        // Not headless: a missing scene file is one line before any window opens.
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = new ViewCommand(new String[] {"--scene", "no/such/scene.dat"}, () -> false)
                .run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertEquals("render view: no/such/scene.dat: no such file\n", err.toString(StandardCharsets.UTF_8));

        // Without a display a scene says so as a mesh does.
        err.reset();
        status = new ViewCommand(new String[] {"scenes/spheres.dat"}, () -> true)
                .run(new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(1, status);
        assertTrue(err.toString(StandardCharsets.UTF_8).startsWith("render view: the viewer needs a display"));
    }

    @Test
    void theHelpTellsHowASceneFileIsKnown() {
        assertTrue(ViewCommand.USAGE.contains("render view [--scene] [--frame N] SCENE.dat"), ViewCommand.USAGE);
        assertTrue(ViewCommand.USAGE.contains("first token is a word"), ViewCommand.USAGE);
    }
}
