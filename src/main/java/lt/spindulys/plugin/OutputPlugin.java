package lt.spindulys.plugin;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.CancellationException;

/**
 * An output algorithm of a subdivision-surface viewer (the thesis's Workframe plugins): it takes
 * what the viewer displays and turns it into a file, such as a ray-traced picture or an exported
 * mesh. Plugins are found with {@link java.util.ServiceLoader} (see {@link OutputPlugins}); a
 * plugin jar lists its classes in {@code META-INF/services/lt.spindulys.plugin.OutputPlugin} (or
 * with {@code provides} in its module descriptor), and each needs a public no-argument constructor.
 *
 * <h2>What a host does</h2>
 * <ol>
 *   <li>Lists {@link OutputPlugins#available()} in a menu, by {@link #name()}.</li>
 *   <li>When one is chosen, describes what it shows: a {@link DisplayedSurface} per surface (its
 *       control mesh, with creases, corners, holes and texture coordinates where it has them, and
 *       the subdivision it applied) and a {@link PluginView} (the camera and the viewport size).</li>
 *   <li>Asks the user for the {@link #options(List, PluginView) options} (each says its kind,
 *       default, range or choices, so a host can build a form from them), checks the answers with
 *       {@link PluginOption#check(List, java.util.Map)}, and asks for an output file with one of
 *       the {@link #fileExtensions()}.</li>
 *   <li>Calls {@link #run(PluginRequest)} off its user-interface thread, passing a
 *       {@link PluginProgress} that reports progress and previews and answers whether the user
 *       cancelled.</li>
 *   <li>Shows the message of any exception {@code run} throws: every message is one line meant
 *       for the user.</li>
 * </ol>
 *
 * <p>Implementations are stateless between runs and safe to run from any thread; a run writes its
 * files atomically, so a failed or cancelled run leaves no file, and an existing file is replaced
 * only by a complete one.
 */
public interface OutputPlugin {
    /**
     * A short stable identifier, lower case, for command lines and settings: {@code raytrace}.
     *
     * @return the identifier
     */
    String id();

    /**
     * The name a host shows in its menu: {@code Ray tracer}.
     *
     * @return the display name
     */
    String name();

    /**
     * One sentence saying what the plugin makes.
     *
     * @return the description
     */
    String description();

    /**
     * The extensions of the files the plugin can write, without the dot, lower case, the default
     * first: {@code [jpg, png, tga]}.
     *
     * @return at least one extension
     */
    List<String> fileExtensions();

    /**
     * What to ask the user before a run, for these surfaces and this view; the defaults may depend
     * on them (the image size defaults to the viewport's, and options that concern one surface are
     * repeated for each, in a {@link PluginOption#group() group} named after the surface).
     *
     * @param surfaces what the host displays, at least one
     * @param view     the host's camera and viewport
     * @return the options, in the order to show them
     */
    List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view);

    /**
     * Makes the output. Called off the host's user-interface thread; reports through the
     * request's {@link PluginProgress}, and stops soon after it says the user cancelled.
     *
     * @param request the surfaces, view, option values and output file
     * @return what was written
     * @throws IllegalArgumentException if an option value or a surface cannot be used (the message
     *                                  names the option or the surface and face, in one line)
     * @throws IOException              if the output cannot be written (nothing is left behind)
     * @throws CancellationException    if the user cancelled (nothing is written)
     * @throws InterruptedException     if the calling thread was interrupted (nothing is written)
     */
    PluginResult run(PluginRequest request) throws IOException, InterruptedException;
}
