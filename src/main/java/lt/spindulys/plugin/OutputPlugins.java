package lt.spindulys.plugin;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Optional;
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
     * The plugin with this {@link OutputPlugin#id() id}.
     *
     * @param id the identifier
     * @return the plugin, or empty if none has it
     */
    public static Optional<OutputPlugin> find(String id) {
        return available().stream().filter(p -> p.id().equals(id)).findFirst();
    }
}
