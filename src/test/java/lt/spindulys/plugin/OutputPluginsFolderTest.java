package lt.spindulys.plugin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.jar.JarEntry;
import java.util.jar.JarOutputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Plugins added by a user: the jars of a plugin folder, beside the library's own. */
class OutputPluginsFolderTest {
    @TempDir
    Path dir;

    /** A jar holding only a services file that lists {@code providers}. */
    private Path jar(String name, String providers) throws IOException {
        Path jar = dir.resolve(name);
        try (OutputStream os = Files.newOutputStream(jar); JarOutputStream j = new JarOutputStream(os)) {
            j.putNextEntry(new JarEntry("META-INF/services/" + OutputPlugin.class.getName()));
            j.write(providers.getBytes(StandardCharsets.UTF_8));
            j.closeEntry();
        }
        return jar;
    }

    private static List<String> ids(List<OutputPlugin> plugins) {
        return plugins.stream().map(OutputPlugin::id).toList();
    }

    @Test
    void aFoldersJarsAddTheirPluginsToTheLibrarys() throws IOException {
        assertFalse(ids(OutputPlugins.available()).contains("folder-test"), "not on the class path's services");
        jar("names.jar", FolderTestPlugin.class.getName() + "\n");
        Files.writeString(dir.resolve("readme.txt"), "not a jar");
        List<String> ids = ids(OutputPlugins.available(List.of(dir)));
        assertEquals(List.of("folder-test", "obj", "raytrace"), ids, "by name: Folder test, OBJ export, Ray tracer");
    }

    @Test
    void anEmptyFolderGivesTheLibrarysPlugins() throws IOException {
        assertEquals(ids(OutputPlugins.available()), ids(OutputPlugins.available(List.of(dir))));
        assertEquals(ids(OutputPlugins.available()), ids(OutputPlugins.available(List.of())));
    }

    /**
     * A plugin whose name is null, throws or is blank, or whose id is taken, is left out with one
     * line naming its class and where it came from; the others are listed as ever.
     */
    @Test
    void aPluginWithoutAUsableNameIsSkippedWithOneLineNamingItsJar() throws Exception {
        String b = BrokenNamePlugins.class.getName();
        jar("broken-names.jar", b + "$NullName\n" + b + "$ThrowingName\n" + b + "$BlankName\n" + b + "$DuplicateId\n"
                + FolderTestPlugin.class.getName() + "\n");
        List<String> skipped = new java.util.ArrayList<>();
        List<String> ids = ids(OutputPlugins.available(List.of(dir), skipped::add));
        assertEquals(List.of("folder-test", "obj", "raytrace"), ids);
        // The classes are on the test class path, which the jar's loader asks first: that is where they come from.
        String from = " (from " + Path.of(BrokenNamePlugins.class.getProtectionDomain().getCodeSource().getLocation().toURI()) + "): ";
        String tracer = lt.spindulys.plugin.raytrace.RayTracePlugin.class.getName() + " (from "
                + Path.of(lt.spindulys.plugin.raytrace.RayTracePlugin.class.getProtectionDomain().getCodeSource().getLocation().toURI()) + ")";
        assertEquals(List.of(
                "skipped output plugin " + b + "$NullName" + from + "its name() is null",
                "skipped output plugin " + b + "$ThrowingName" + from + "its id(), name() or description() threw java.lang.IllegalStateException: no name\\nat all",
                "skipped output plugin " + b + "$BlankName" + from + "its name() is blank",
                "skipped output plugin " + b + "$DuplicateId" + from + "its id 'raytrace' is that of " + tracer + ", found first"), skipped);
    }

    @Test
    void badFoldersAndJarsAreOneLine() throws IOException {
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> OutputPlugins.available(List.of(dir.resolve("nope"))));
        assertEquals("plugin folder " + dir.resolve("nope") + " is missing", missing.getMessage());
        Path file = Files.writeString(dir.resolve("file"), "x");
        assertEquals("plugin folder " + file + " is not a folder",
                assertThrows(IllegalArgumentException.class, () -> OutputPlugins.available(List.of(file))).getMessage());
        jar("broken.jar", "no.such.Plugin\n");
        String m = assertThrows(IllegalArgumentException.class, () -> OutputPlugins.available(List.of(dir))).getMessage();
        assertTrue(m.startsWith("an output plugin in " + dir + " cannot be loaded: "), m);
        assertTrue(m.contains("no.such.Plugin"), m);
        assertFalse(m.contains("\n"), m);
    }
}
