package lt.spindulys.viewer;

import java.awt.Window;
import java.nio.file.Path;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;

import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;

import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginView;

/**
 * The viewer's Plugins menu: an item per output plugin; choosing one takes what the viewer
 * displays, asks for the plugin's options ({@link PluginDialog}) and runs it in a
 * {@link RenderWindow} beside the viewer. With nothing displayed, or when the plugin cannot take
 * the surfaces, it says so in one line and nothing runs.
 */
public final class PluginsMenu extends JMenu {
    private final Window owner;
    private final Supplier<List<DisplayedSurface>> surfaces;
    private final Supplier<PluginView> view;
    /** Where the next output goes by default: the folder of the last one, so a series of pictures lands together. */
    private Path folder;
    /** The runs started and not yet seen to end; read by the thread that waits for them when the viewer closes. */
    private final List<PluginRun> runs = new CopyOnWriteArrayList<>();

    /**
     * A menu over {@code plugins}, usually {@code OutputPlugins.available()}.
     *
     * @param owner    the viewer's window: dialogs centre on it, the render window goes beside it
     * @param plugins  the plugins to list, in order
     * @param surfaces what the viewer displays now (asked when a plugin is chosen; may be empty)
     * @param view     the viewer's camera and viewport now (asked only when a surface is displayed)
     * @param folder   where outputs go until the user picks another folder
     */
    public PluginsMenu(Window owner, List<OutputPlugin> plugins, Supplier<List<DisplayedSurface>> surfaces,
                       Supplier<PluginView> view, Path folder) {
        super("Plugins");
        setName("pluginsMenu");
        this.owner = owner;
        this.surfaces = Objects.requireNonNull(surfaces, "surfaces");
        this.view = Objects.requireNonNull(view, "view");
        this.folder = Objects.requireNonNull(folder, "folder").toAbsolutePath();
        if (plugins.isEmpty()) {
            JMenuItem none = new JMenuItem("No output plugins found");
            none.setEnabled(false);
            add(none);
        }
        for (OutputPlugin p : plugins) {
            JMenuItem item = new JMenuItem(p.name() + "...");
            item.setName("plugin:" + p.id());
            item.setToolTipText(p.description());
            item.addActionListener(e -> choose(p));
            add(item);
        }
    }

    /**
     * What choosing {@code plugin} does: the form for what is displayed, then the dialog, then the
     * run. Public so a host can offer the same from elsewhere (a toolbar, a key). Call on the event thread.
     *
     * @param plugin the plugin
     * @return the render window of the run started, or null if nothing was started
     */
    public RenderWindow choose(OutputPlugin plugin) {
        PluginForm form;
        try {
            List<DisplayedSurface> shown = surfaces.get();
            if (shown == null || shown.isEmpty()) {
                JOptionPane.showMessageDialog(owner, PluginForm.NO_SURFACE, plugin.name(), JOptionPane.INFORMATION_MESSAGE);
                return null;
            }
            form = new PluginForm(plugin, shown, view.get(), folder);
        } catch (RuntimeException e) {
            // A plugin that rejects the surfaces (IllegalArgumentException) or fails: one line, and the viewer goes on.
            JOptionPane.showMessageDialog(owner, FailureMessage.of(e), plugin.name(), JOptionPane.ERROR_MESSAGE);
            return null;
        }
        PluginForm.Accepted accepted = new PluginDialog(owner, form).ask();
        if (accepted == null) return null;
        Path parent = accepted.output().toAbsolutePath().getParent();
        if (parent != null) folder = parent;
        RenderWindow window = RenderWindow.start(owner, form, accepted);
        runs.removeIf(PluginRun::isDone);
        runs.add(window.run());
        return window;
    }

    /**
     * Waits for the runs this menu started to end (closing their windows, or the viewer that owns
     * them, cancels them), so that a host about to exit does not cut a plugin off mid-file.
     *
     * @param timeout how long at most, in all
     * @param unit    its unit
     * @return whether every run ended in time
     * @throws InterruptedException if interrupted while waiting
     */
    public boolean awaitRuns(long timeout, TimeUnit unit) throws InterruptedException {
        long deadline = System.nanoTime() + unit.toNanos(timeout);
        for (PluginRun r : runs) {
            if (!r.await(Math.max(0, deadline - System.nanoTime()), TimeUnit.NANOSECONDS)) return false;
        }
        return true;
    }
}
