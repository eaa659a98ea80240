package lt.spindulys.plugin;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;

/** Finds the output plugins on the class path or module path with {@link ServiceLoader}. */
public final class OutputPlugins {
    private OutputPlugins() {}

    /**
     * Every output plugin found by the loader that loaded this class (the library's own two among
     * them), sorted by name.
     *
     * @return the plugins, new instances
     * @throws java.util.ServiceConfigurationError if a listed plugin cannot be loaded
     */
    public static List<OutputPlugin> available() {
        return available(OutputPlugins.class.getClassLoader());
    }

    /**
     * Every output plugin {@code loader} finds, sorted by name (then id).
     *
     * @param loader where to look, for example a class loader over a folder of plugin jars
     * @return the plugins, new instances
     */
    public static List<OutputPlugin> available(ClassLoader loader) {
        List<OutputPlugin> all = new ArrayList<>();
        ServiceLoader.load(OutputPlugin.class, loader).forEach(all::add);
        all.sort(Comparator.comparing(OutputPlugin::name).thenComparing(OutputPlugin::id));
        return all;
    }

    /**
     * The library's plugins and those in the jars of these folders (each {@code *.jar} directly in
     * a folder, listing its plugins in {@code META-INF/services/lt.spindulys.plugin.OutputPlugin}),
     * sorted by name: how a host lets its users add plugins without rebuilding it. The jars are
     * loaded by a class loader of their own, whose parent loaded this class, and stay open while
     * the plugins are in use.
     *
     * @param folders the plugin folders
     * @return the plugins, new instances
     * @throws IllegalArgumentException one line naming the folder or jar: a folder that is not one,
     *                                  or a plugin listed in a jar that cannot be loaded
     * @throws IOException if a folder cannot be listed
     */
    public static List<OutputPlugin> available(List<Path> folders) throws IOException {
        List<URL> jars = new ArrayList<>();
        for (Path folder : folders) {
            if (!Files.isDirectory(folder)) {
                throw new IllegalArgumentException("plugin folder " + folder + " is " + (Files.exists(folder) ? "not a folder" : "missing"));
            }
            List<Path> found = new ArrayList<>();
            try (DirectoryStream<Path> in = Files.newDirectoryStream(folder, "*.jar")) {
                for (Path jar : in) if (Files.isRegularFile(jar)) found.add(jar);
            }
            found.sort(Comparator.naturalOrder()); // the same order on every file system
            for (Path jar : found) jars.add(url(jar));
        }
        if (jars.isEmpty()) return available();
        ClassLoader loader = new URLClassLoader("spindulys-plugins", jars.toArray(URL[]::new), OutputPlugins.class.getClassLoader());
        try {
            return available(loader);
        } catch (ServiceConfigurationError e) {
            throw new IllegalArgumentException("an output plugin in " + String.join(", ", folders.stream().map(Path::toString).toList())
                    + " cannot be loaded: " + e.getMessage(), e);
        }
    }

    private static URL url(Path jar) {
        try {
            return jar.toAbsolutePath().toUri().toURL();
        } catch (MalformedURLException e) {
            throw new IllegalArgumentException("plugin jar " + jar + " has no URL: " + e.getMessage(), e);
        }
    }

    /**
     * The plugin with this {@link OutputPlugin#id() id}.
     *
     * @param id the identifier
     * @return the plugin, or empty if none has it
     */
    public static Optional<OutputPlugin> find(String id) {
        return available().stream().filter(p -> p.id().equals(id)).findFirst();
    }
}
