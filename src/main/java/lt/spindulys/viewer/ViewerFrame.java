package lt.spindulys.viewer;

import java.awt.BorderLayout;
import java.awt.Toolkit;
import java.awt.datatransfer.DataFlavor;
import java.awt.event.KeyEvent;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;

import javax.swing.AbstractAction;
import javax.swing.ButtonGroup;
import javax.swing.DefaultListModel;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JRadioButtonMenuItem;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.ListSelectionModel;
import javax.swing.SwingUtilities;
import javax.swing.TransferHandler;
import javax.swing.filechooser.FileNameExtensionFilter;

import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * The viewer's window: the viewport, the list of open surfaces, a status line and the menus File,
 * View and Surface; files can be dropped on it. Everything here runs on the event thread and
 * only wires Swing to {@link ViewerModel}, where the actions live. An output-plugin host adds its
 * menu with {@link #addMenu(JMenu)} and reads what is displayed with {@link #displayed()}.
 */
public final class ViewerFrame extends JFrame {
    private final ViewerModel model;
    private final ExecutorService background;
    private final Rasterizer rasterizer = new Rasterizer();
    private final ViewportPanel viewport;
    private final DefaultListModel<String> listModel = new DefaultListModel<>();
    private final JList<String> list = new JList<>(listModel);
    private final JLabel status = new JLabel(" ");
    private final JRadioButtonMenuItem[] modeItems = new JRadioButtonMenuItem[DisplayMode.values().length];
    private final JRadioButtonMenuItem[] boundaryItems = new JRadioButtonMenuItem[SubdivOptions.Boundary.values().length];
    private final JRadioButtonMenuItem[] schemeItems = new JRadioButtonMenuItem[SubdivOptions.Scheme.values().length];
    private final JCheckBoxMenuItem cageItem = new JCheckBoxMenuItem("Cage over surface   C");
    private final JMenuBar menuBar = new JMenuBar();
    private boolean updating;
    /** Where File > Open last found its files; null until it has been used. */
    private File openFolder;
    /** The plugin menus added (their runs are waited for when the viewer closes). */
    private final List<PluginsMenu> pluginMenus = new java.util.concurrent.CopyOnWriteArrayList<>();

    /**
     * Makes the window (not yet visible). Call on the event thread.
     */
    public ViewerFrame() {
        super("Spindulys viewer");
        background = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "spindulys-viewer-io");
            t.setDaemon(true);
            return t;
        });
        // Work handed over on the event thread (the only caller) after the window closed, when
        // a result still arriving asks for more, is dropped rather than refused with an exception.
        java.util.concurrent.Executor work = task -> {
            if (!background.isShutdown()) background.execute(task);
        };
        model = new ViewerModel(work, SwingUtilities::invokeLater, new ViewerModel.Listener() {
            @Override public void changed() { update(); }
            // The list, the menus and the status line do not show the camera.
            @Override public void viewChanged() { viewport.repaint(); }
            @Override public void error(String message) { showError(message); }
        });
        viewport = new ViewportPanel(model, rasterizer);

        list.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        // Not focusable: the arrow keys belong to the viewport.
        list.setFocusable(false);
        list.addListSelectionListener(e -> {
            if (!updating && !e.getValueIsAdjusting()) model.select(list.getSelectedIndex());
        });
        JScrollPane side = new JScrollPane(list);
        side.setPreferredSize(new java.awt.Dimension(220, 100));

        setJMenuBar(menuBar);
        menuBar.add(fileMenu());
        menuBar.add(viewMenu());
        menuBar.add(surfaceMenu());

        getContentPane().add(viewport, BorderLayout.CENTER);
        getContentPane().add(side, BorderLayout.WEST);
        getContentPane().add(status, BorderLayout.SOUTH);
        TransferHandler drop = new FileDrop();
        setTransferHandler(drop);
        viewport.setTransferHandler(drop);
        list.setTransferHandler(drop);

        setDefaultCloseOperation(DISPOSE_ON_CLOSE);
        addWindowListener(new WindowAdapter() {
            @Override public void windowClosed(WindowEvent e) {
                background.shutdownNow();
                rasterizer.close();
            }
        });
        pack();
        update();
    }

    /**
     * The viewer as {@code render view} opens it: with a Plugins menu over {@code plugins}, which
     * hands a chosen plugin what the viewer displays ({@link PluginAdapter}). Call on the event thread.
     *
     * @param plugins the output plugins, usually {@code OutputPlugins.available()}
     * @param folder  where outputs go until the user picks another folder
     * @return the window, not yet visible
     */
    public static ViewerFrame withPlugins(List<lt.spindulys.plugin.OutputPlugin> plugins, Path folder) {
        ViewerFrame f = new ViewerFrame();
        f.addMenu(PluginAdapter.menu(f, plugins, folder));
        return f;
    }

    /**
     * Opens files as File > Open does: meshes (.obj, .dat) become surfaces, a .tex is attached to
     * the selected one. Errors are shown in a dialog.
     *
     * @param files the files
     */
    public void open(List<Path> files) {
        model.open(files);
        viewport.requestFocusInWindow();
    }

    /**
     * Adds a menu to the end of the menu bar (the output plugins' menu).
     *
     * @param menu the menu
     */
    public void addMenu(JMenu menu) {
        if (menu instanceof PluginsMenu p) pluginMenus.add(p);
        menuBar.add(menu);
        menuBar.revalidate();
        menuBar.repaint();
    }

    /**
     * What is displayed now: every open surface with its control mesh, level, boundary rule and
     * mode, and the camera with the viewport's size. Call on the event thread.
     *
     * @return the snapshot
     */
    public ViewerSnapshot displayed() {
        return model.snapshot();
    }

    /**
     * Waits for the plugin runs started from this viewer's plugin menus to end. Closing the viewer
     * cancels them (its render windows close with it); a host that exits when the viewer closes
     * calls this first, so that no run is cut off between its temporary file and the rename.
     * Any thread but the event thread.
     *
     * @param timeout how long at most, in all
     * @param unit    its unit
     * @return whether every run ended in time
     * @throws InterruptedException if interrupted while waiting
     */
    public boolean awaitPluginRuns(long timeout, java.util.concurrent.TimeUnit unit) throws InterruptedException {
        long deadline = System.nanoTime() + unit.toNanos(timeout);
        for (PluginsMenu p : pluginMenus) {
            if (!p.awaitRuns(Math.max(0, deadline - System.nanoTime()), java.util.concurrent.TimeUnit.NANOSECONDS)) return false;
        }
        return true;
    }

    /** {@return the viewer's logic, for hosts that act on it (on the event thread)} */
    public ViewerModel model() { return model; }

    private JMenu fileMenu() {
        JMenu m = new JMenu("File");
        m.setMnemonic(KeyEvent.VK_F);
        int ctrl = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        m.add(item("Open...", KeyStroke.getKeyStroke(KeyEvent.VK_O, ctrl), this::chooseFiles));
        m.add(item("Close surface", KeyStroke.getKeyStroke(KeyEvent.VK_W, ctrl), model::closeSelected));
        m.addSeparator();
        m.add(item("Quit", KeyStroke.getKeyStroke(KeyEvent.VK_Q, ctrl), this::dispose));
        return m;
    }

    private JMenu viewMenu() {
        JMenu m = new JMenu("View");
        m.setMnemonic(KeyEvent.VK_V);
        m.add(item("Fit   F", null, model::fit));
        m.addSeparator();
        ButtonGroup g = new ButtonGroup();
        for (DisplayMode d : DisplayMode.values()) {
            JRadioButtonMenuItem it = new JRadioButtonMenuItem(d.label() + "   " + (d.ordinal() + 1));
            it.addActionListener(e -> { if (!updating) model.mode(d); });
            g.add(it);
            modeItems[d.ordinal()] = it;
            m.add(it);
        }
        m.addSeparator();
        cageItem.addActionListener(e -> { if (!updating) model.toggleCage(); });
        m.add(cageItem);
        return m;
    }

    private JMenu surfaceMenu() {
        JMenu m = new JMenu("Surface");
        m.setMnemonic(KeyEvent.VK_S);
        m.add(item("Level up   Page Up", null, model::levelUp));
        m.add(item("Level down   Page Down", null, model::levelDown));
        m.addSeparator();
        JMenu b = new JMenu("Boundary rule");
        ButtonGroup g = new ButtonGroup();
        String[] names = {"None (boundary faces dropped)", "Edges sharp", "Edges and corners sharp"};
        for (SubdivOptions.Boundary r : SubdivOptions.Boundary.values()) {
            JRadioButtonMenuItem it = new JRadioButtonMenuItem(names[r.ordinal()]);
            it.addActionListener(e -> { if (!updating) model.boundary(r); });
            g.add(it);
            boundaryItems[r.ordinal()] = it;
            b.add(it);
        }
        m.add(b);
        JMenu sc = new JMenu("Scheme");
        ButtonGroup sg = new ButtonGroup();
        for (SubdivOptions.Scheme r : SubdivOptions.Scheme.values()) {
            JRadioButtonMenuItem it = new JRadioButtonMenuItem(SchemeChoice.label(r));
            it.addActionListener(e -> { if (!updating) model.scheme(r); });
            sg.add(it);
            schemeItems[r.ordinal()] = it;
            sc.add(it);
        }
        m.add(sc);
        return m;
    }

    private static JMenuItem item(String text, KeyStroke key, Runnable action) {
        JMenuItem it = new JMenuItem(new AbstractAction(text) {
            @Override public void actionPerformed(java.awt.event.ActionEvent e) { action.run(); }
        });
        if (key != null) it.setAccelerator(key);
        return it;
    }

    private void chooseFiles() {
        JFileChooser c = new JFileChooser(openFolder != null ? openFolder : new File(System.getProperty("user.dir")));
        c.setMultiSelectionEnabled(true);
        c.setFileFilter(new FileNameExtensionFilter("Meshes and unwraps (.obj, .dat, .tex)", "obj", "dat", "tex"));
        if (c.showOpenDialog(this) != JFileChooser.APPROVE_OPTION) return;
        // The next Open starts where this one ended, as a user opening a series of meshes expects.
        openFolder = c.getCurrentDirectory();
        List<Path> files = new ArrayList<>();
        for (File f : c.getSelectedFiles()) files.add(f.toPath());
        open(files);
    }

    private void showError(String message) {
        JOptionPane.showMessageDialog(this, message, "Spindulys viewer", JOptionPane.ERROR_MESSAGE);
    }

    /** Brings the list, the menus' marks and the status line in line with the model, and repaints. */
    private void update() {
        updating = true;
        try {
            List<ViewedSurface> ss = model.surfaces();
            while (listModel.size() > ss.size()) listModel.remove(listModel.size() - 1);
            for (int i = 0; i < ss.size(); i++) {
                ViewedSurface s = ss.get(i);
                String text = s.name() + "  " + s.mode().label().toLowerCase(java.util.Locale.ROOT) + ", level " + s.level();
                if (i < listModel.size()) {
                    if (!listModel.get(i).equals(text)) listModel.set(i, text);
                } else {
                    listModel.addElement(text);
                }
            }
            list.setSelectedIndex(model.selectedIndex());
            if (model.selectedIndex() < 0) list.clearSelection();
            ViewedSurface s = model.selected();
            for (JRadioButtonMenuItem it : modeItems) it.setEnabled(s != null);
            for (JRadioButtonMenuItem it : boundaryItems) it.setEnabled(s != null);
            for (SubdivOptions.Scheme r : SubdivOptions.Scheme.values()) {
                schemeItems[r.ordinal()].setEnabled(SchemeChoice.enabled(s, r));
                schemeItems[r.ordinal()].setToolTipText(SchemeChoice.tooltip(s, r));
            }
            cageItem.setEnabled(s != null);
            if (s != null) {
                modeItems[s.mode().ordinal()].setSelected(true);
                boundaryItems[s.boundary().ordinal()].setSelected(true);
                schemeItems[s.scheme().ordinal()].setSelected(true);
                cageItem.setSelected(s.cage());
            }
            status.setText(statusText(s));
        } finally {
            updating = false;
        }
        viewport.repaint();
    }

    private String statusText(ViewedSurface s) {
        StringBuilder b = new StringBuilder();
        if (s == null) {
            b.append("Open a mesh (.obj, .dat) with File > Open or drop it here");
        } else {
            b.append(s.source()).append(": ").append(s.mode().label()).append(", level ").append(s.level())
                    .append(", boundary ").append(s.boundary().name().toLowerCase(java.util.Locale.ROOT).replace('_', ' '));
            if (s.scheme() != SubdivOptions.Scheme.CATMARK) b.append(", scheme ").append(s.scheme().keyword());
            if (s.unwrap() != null) b.append(", UVs from ").append(s.unwrap().getFileName());
            if (s.cage()) b.append(", cage shown");
        }
        if (model.pending() > 0) b.append("   (working...)");
        return b.toString();
    }

    /** Files dropped on the window: opened as File > Open opens them. */
    private final class FileDrop extends TransferHandler {
        @Override
        public boolean canImport(TransferSupport support) {
            return support.isDataFlavorSupported(DataFlavor.javaFileListFlavor);
        }

        @Override
        public boolean importData(TransferSupport support) {
            if (!canImport(support)) return false;
            try {
                List<?> dropped = (List<?>) support.getTransferable().getTransferData(DataFlavor.javaFileListFlavor);
                List<Path> files = new ArrayList<>();
                for (Object o : dropped) if (o instanceof File f) files.add(f.toPath());
                open(files);
                return true;
            } catch (java.awt.datatransfer.UnsupportedFlavorException | java.io.IOException e) {
                showError(FailureMessage.of(e));
                return false;
            }
        }
    }
}
