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
}
