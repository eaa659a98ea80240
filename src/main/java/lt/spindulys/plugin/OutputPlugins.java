package lt.spindulys.plugin;

import java.io.IOException;
import java.net.MalformedURLException;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.CodeSource;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
import java.util.ServiceConfigurationError;
import java.util.ServiceLoader;
import java.util.function.Consumer;

import lt.spindulys.limits.MessageText;

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
     * Every output plugin {@code loader} finds, sorted by name (then id). A plugin whose
     * {@link OutputPlugin#id() id} or {@link OutputPlugin#name() name} is null or blank, or that
     * throws when asked for them or its description, or whose id or name another plugin found
     * before it has already, is left out, and {@code skipped} is told so in one line naming its
     * class and where it was loaded from (its jar or folder), so one broken jar does not take the
     * host down with it.
     *
     * @param loader  where to look, for example a class loader over a folder of plugin jars
     * @param skipped told of each plugin left out
     * @return the plugins, new instances
     */
    public static List<OutputPlugin> available(ClassLoader loader, Consumer<String> skipped) {
        record Found(OutputPlugin plugin, String id, String name) {}
        List<Found> all = new ArrayList<>();
        for (OutputPlugin p : ServiceLoader.load(OutputPlugin.class, loader)) {
            String id, name;
            try {
                id = p.id();
                name = p.name();
                p.description();
            } catch (RuntimeException | LinkageError e) {
                skipped.accept(skippedLine(p, "its id(), name() or description() threw " + e));
                continue;
            }
            String problem = id == null ? "its id() is null" : id.isBlank() ? "its id() is blank"
                    : name == null ? "its name() is null" : name.isBlank() ? "its name() is blank" : null;
            for (Found f : all) {
                if (problem != null) break;
                if (f.id.equals(id)) problem = "its id '" + id + "' is that of " + where(f.plugin) + ", found first";
                else if (f.name.equals(name)) problem = "its name '" + name + "' is that of " + where(f.plugin) + ", found first";
            }
            if (problem != null) skipped.accept(skippedLine(p, problem));
            else all.add(new Found(p, id, name));
        }
        all.sort(Comparator.comparing(Found::name).thenComparing(Found::id));
        return new ArrayList<>(all.stream().map(Found::plugin).toList());
    }

    /**
     * {@link #available(ClassLoader, Consumer)}, telling of the plugins left out on standard error.
     *
     * @param loader where to look, for example a class loader over a folder of plugin jars
     * @return the plugins, new instances
     */
    public static List<OutputPlugin> available(ClassLoader loader) {
        return available(loader, OutputPlugins::toStandardError);
    }

    private static void toStandardError(String line) {
        System.err.println(line);
    }

    /** "skipped output plugin CLASS (from JAR): PROBLEM", one line whatever the plugin's texts hold. */
    private static String skippedLine(OutputPlugin p, String problem) {
        return MessageText.escape("skipped output plugin " + where(p) + ": " + problem);
    }

    /** The plugin's class and where it was loaded from: "com.example.Tracer (from /opt/plugins/tracer.jar)". */
    static String where(OutputPlugin p) {
        Class<?> c = p.getClass();
        CodeSource source = c.getProtectionDomain() == null ? null : c.getProtectionDomain().getCodeSource();
        URL location = source == null ? null : source.getLocation();
        String from;
        if (location == null) {
            from = "an unknown location";
        } else {
            try {
                from = Path.of(location.toURI()).toString();
            } catch (URISyntaxException | IllegalArgumentException | java.nio.file.FileSystemNotFoundException e) {
                from = location.toString();
            }
        }
        return c.getName() + " (from " + from + ")";
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
        return available(folders, OutputPlugins::toStandardError);
    }

    /**
     * {@link #available(List)}, telling {@code skipped} of each plugin left out as
     * {@link #available(ClassLoader, Consumer)} does.
     *
     * @param folders the plugin folders
     * @param skipped told of each plugin left out, in one line
     * @return the plugins, new instances
     * @throws IllegalArgumentException as {@link #available(List)}
     * @throws IOException if a folder cannot be listed
     */
    public static List<OutputPlugin> available(List<Path> folders, Consumer<String> skipped) throws IOException {
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
        if (jars.isEmpty()) return available(OutputPlugins.class.getClassLoader(), skipped);
        ClassLoader loader = new URLClassLoader("spindulys-plugins", jars.toArray(URL[]::new), OutputPlugins.class.getClassLoader());
        try {
            return available(loader, skipped);
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
