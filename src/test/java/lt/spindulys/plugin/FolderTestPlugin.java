package lt.spindulys.plugin;

import java.io.IOException;
import java.nio.file.Files;
import java.util.List;

/**
 * A plugin that is listed only in a jar a test makes ({@link OutputPluginsFolderTest}), never in
 * the test class path's services: found only through a plugin folder. It writes the surfaces' names.
 */
public final class FolderTestPlugin implements OutputPlugin {
    /** For ServiceLoader. */
    public FolderTestPlugin() {}

    @Override public String id() { return "folder-test"; }
    @Override public String name() { return "Folder test"; }
    @Override public String description() { return "Writes the names of the surfaces."; }
    @Override public List<String> fileExtensions() { return List.of("txt"); }
    @Override public List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view) { return List.of(); }

    @Override
    public PluginResult run(PluginRequest request) throws IOException {
        Files.writeString(request.output(), String.join("\n", request.surfaces().stream().map(DisplayedSurface::name).toList()));
        return new PluginResult(List.of(request.output()), "names written");
    }
}
