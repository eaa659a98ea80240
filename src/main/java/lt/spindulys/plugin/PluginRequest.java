package lt.spindulys.plugin;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.Objects;

/**
 * Everything a plugin run gets from its host.
 *
 * @param surfaces the displayed surfaces, at least one, in the host's order
 * @param view     the host's camera and viewport
 * @param options  the user's answers, option key to text (see {@link PluginOption}); an option
 *                 left out takes its default, an unknown key is an error
 * @param output   the file to write; its extension is one of the plugin's {@link OutputPlugin#fileExtensions()}
 * @param progress where progress goes and whether the user cancelled
 */
public record PluginRequest(List<DisplayedSurface> surfaces, PluginView view, Map<String, String> options,
                            Path output, PluginProgress progress) {
    /**
     * Copies the collections.
     *
     * @throws IllegalArgumentException if there is no surface
     */
    public PluginRequest {
        surfaces = List.copyOf(surfaces);
        Objects.requireNonNull(view, "view");
        options = Map.copyOf(options);
        Objects.requireNonNull(output, "output");
        Objects.requireNonNull(progress, "progress");
        if (surfaces.isEmpty()) throw new IllegalArgumentException("there is no surface to output");
    }
}
