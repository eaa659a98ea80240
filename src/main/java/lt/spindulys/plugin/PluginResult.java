package lt.spindulys.plugin;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * What a plugin run wrote.
 *
 * @param files   the files written, the main output first
 * @param summary one line for the user ("1280 x 720, 16 samples, 2.4 s")
 */
public record PluginResult(List<Path> files, String summary) {
    /**
     * Copies the list.
     *
     * @throws NullPointerException if an argument is null
     */
    public PluginResult {
        files = List.copyOf(files);
        Objects.requireNonNull(summary, "summary");
    }
}
