package lt.spindulys.viewer;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.limits.MessageText;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginView;

/**
 * The model behind a plugin's dialog, without Swing: the plugin's options for what is displayed,
 * the text of every field, the output file, and what is wrong with them, so the dialog only
 * mirrors it (and tests need no display).
 *
 * <p>Values are kept as the text the user typed, in {@link PluginOption}'s forms; {@link #problem()}
 * is the one line the dialog shows while the form cannot be accepted, and {@link #accept()} makes the
 * last check (that a file can be created in the output's folder) before the run.
 */
public final class PluginForm {
    /**
     * What the user accepted.
     *
     * @param values every option's text, key to text
     * @param output the file to write
     */
    public record Accepted(Map<String, String> values, Path output) {
        /** Copies the values. */
        public Accepted {
            values = Map.copyOf(values);
            Objects.requireNonNull(output, "output");
        }
    }

    private final OutputPlugin plugin;
    private final List<DisplayedSurface> surfaces;
    private final PluginView view;
    private final List<PluginOption> options;
    private final Map<String, PluginOption> byKey = new LinkedHashMap<>();
    private final Map<String, String> values = new LinkedHashMap<>();
    private final List<String> extensions;
    private String output;

    /**
     * The form for one run of {@code plugin} on what the host displays, every field at its
     * default, the output named after the first surface in {@code folder}.
     *
     * @param plugin   the plugin chosen
     * @param surfaces the displayed surfaces
     * @param view     the host's view
     * @param folder   where the output goes by default
     * @throws IllegalArgumentException if no surface is displayed, or the plugin rejects the
     *                                  surfaces or gives unusable options (one line)
     */
    public PluginForm(OutputPlugin plugin, List<DisplayedSurface> surfaces, PluginView view, Path folder) {
        this.plugin = Objects.requireNonNull(plugin, "plugin");
        Objects.requireNonNull(view, "view");
        Objects.requireNonNull(folder, "folder");
        if (surfaces == null || surfaces.isEmpty()) throw new IllegalArgumentException(NO_SURFACE);
        this.surfaces = List.copyOf(surfaces);
        this.view = view;
        this.extensions = List.copyOf(plugin.fileExtensions());
        if (extensions.isEmpty()) throw new IllegalArgumentException("plugin " + plugin.name() + " names no file extension");
        this.options = List.copyOf(plugin.options(this.surfaces, view));
        for (PluginOption o : options) {
            if (byKey.putIfAbsent(o.key(), o) != null) {
                throw new IllegalArgumentException("plugin " + plugin.name() + " gives option " + MessageText.quote(o.key()) + " twice");
            }
            values.put(o.key(), o.defaultValue());
        }
        this.output = folder.resolve(defaultFileName(this.surfaces.get(0).name(), extensions.get(0))).toString();
    }

    /** The line shown when a plugin is chosen with nothing on screen. */
    public static final String NO_SURFACE = "no surface is displayed: open a mesh first, then choose the plugin";

    /** @return the plugin */
    public OutputPlugin plugin() { return plugin; }

    /** @return the surfaces the run will get */
    public List<DisplayedSurface> surfaces() { return surfaces; }

    /** @return the view the run will get */
    public PluginView view() { return view; }

    /** @return the plugin's options, in its order */
    public List<PluginOption> options() { return options; }

    /**
     * The options under their headings, headings in the order they first appear.
     *
     * @return heading to options
     */
    public Map<String, List<PluginOption>> groups() {
        Map<String, List<PluginOption>> groups = new LinkedHashMap<>();
        for (PluginOption o : options) groups.computeIfAbsent(o.group(), g -> new ArrayList<>()).add(o);
        groups.replaceAll((g, list) -> List.copyOf(list));
        return Collections.unmodifiableMap(groups);
    }

    /** @return the extensions the output may have, the default first */
    public List<String> extensions() { return extensions; }

    /**
     * The text of an option's field.
     *
     * @param key the option's key
     * @return the text
     * @throws IllegalArgumentException if no option has the key
     */
    public String value(String key) {
        option(key);
        return values.get(key);
    }

    /**
     * Whether an option matters with the values as they stand ({@link PluginOption#applies}): the
     * dialog disables the field of one that does not, such as the index of refraction of an
     * opaque surface.
     *
     * @param key the option's key
     * @return true if it matters
     * @throws IllegalArgumentException if no option has the key
     */
    public boolean applies(String key) {
        return option(key).applies(options, values);
    }

    /**
     * Sets an option's text as the user typed it; it is checked by {@link #problem()}.
     *
     * @param key  the option's key
     * @param text the text
     * @throws IllegalArgumentException if no option has the key
     */
    public void set(String key, String text) {
        option(key);
        values.put(key, Objects.requireNonNull(text, "text"));
    }

    /** @return every option's text, key to text, in the options' order */
    public Map<String, String> values() { return Collections.unmodifiableMap(values); }

    /** @return the output field's text */
    public String output() { return output; }

    /** @param text the output field's text, as typed */
    public void setOutput(String text) { output = Objects.requireNonNull(text, "text"); }

    /**
     * What stops the form from being accepted, as one line: the first option whose text is
     * invalid, else what is wrong with the output file (no name, an extension the plugin cannot
     * write, a folder that does not exist, a folder's name). Looks at the file system only to
     * see whether the folder exists.
     *
     * @return null if the form can be accepted
     */
    public String problem() {
        String p = PluginOption.check(options, values);
        if (p != null) return MessageText.escape(p);
        return outputProblem();
    }

    /** @return whether {@link #problem()} is null */
    public boolean valid() { return problem() == null; }

    /**
     * Checks the form and tries to create a file in the output's folder (deleting it again), so an
     * output that cannot be written is refused now rather than after the run.
     *
     * @return the values and the output file
     * @throws IllegalArgumentException with {@link #problem()} if the form is invalid
     * @throws IOException              "cannot write 'OUT': ..." if no file can be created there
     */
    public Accepted accept() throws IOException {
        String p = problem();
        if (p != null) throw new IllegalArgumentException(p);
        Path out = Path.of(output.strip());
        AtomicFile.checkWritable(out);
        return new Accepted(values, out);
    }

    private String outputProblem() {
        String text = output.strip();
        if (text.isEmpty()) return "Output file: give the file to write (" + String.join(", ", dotted()) + ")";
        Path out;
        try {
            out = Path.of(text);
        } catch (InvalidPathException e) {
            return MessageText.escape("Output file: " + MessageText.quote(text) + " is not a valid path: " + e.getReason());
        }
        if (out.getFileName() == null) return MessageText.escape("Output file: " + MessageText.quote(text) + " names no file");
        String ext = extension(out.getFileName().toString());
        if (!extensions.contains(ext)) {
            return MessageText.escape("Output file: " + plugin.name() + " writes " + String.join(", ", dotted())
                    + " files, found " + MessageText.quote(out.getFileName().toString()));
        }
        try {
            AtomicFile.checkTarget(out);
        } catch (IOException e) {
            return MessageText.escape(e.getMessage());
        }
        return null;
    }

    private List<String> dotted() {
        return extensions.stream().map(e -> "." + e).toList();
    }

    private PluginOption option(String key) {
        PluginOption o = byKey.get(key);
        if (o == null) throw new IllegalArgumentException("plugin " + plugin.name() + " has no option " + MessageText.quote(key));
        return o;
    }

    /** The lower-case extension of a file name, without the dot; empty if it has none. */
    static String extension(String fileName) {
        int dot = fileName.lastIndexOf('.');
        return dot <= 0 ? "" : fileName.substring(dot + 1).toLowerCase(Locale.ROOT);
    }

    /**
     * The output's default name: the surface's name without its extension or folders, with
     * characters that file systems refuse replaced, then the plugin's default extension
     * ({@code cube.obj} gives {@code cube.jpg}).
     */
    static String defaultFileName(String surfaceName, String extension) {
        String name = surfaceName.strip();
        int slash = Math.max(name.lastIndexOf('/'), name.lastIndexOf('\\'));
        name = name.substring(slash + 1);
        int dot = name.lastIndexOf('.');
        if (dot > 0) name = name.substring(0, dot);
        StringBuilder b = new StringBuilder(name.length());
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            b.append(c < 0x20 || c == 0x7f || "<>:\"/\\|?*".indexOf(c) >= 0 ? '_' : c);
        }
        String base = b.toString().strip();
        if (base.isEmpty() || base.chars().allMatch(c -> c == '.')) base = "surface";
        return base + "." + extension;
    }
}
