package lt.spindulys.viewer;

import java.awt.BorderLayout;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.Window;
import java.awt.event.ActionEvent;
import java.awt.event.KeyEvent;
import java.io.File;
import java.io.IOException;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;

import javax.swing.AbstractAction;
import javax.swing.BorderFactory;
import javax.swing.BoxLayout;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JColorChooser;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JFormattedTextField;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSpinner;
import javax.swing.JTabbedPane;
import javax.swing.JTextField;
import javax.swing.KeyStroke;
import javax.swing.SpinnerNumberModel;
import javax.swing.SwingUtilities;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;
import javax.swing.filechooser.FileNameExtensionFilter;
import javax.swing.text.DefaultFormatter;
import javax.swing.text.JTextComponent;

import lt.spindulys.frontend.FailureMessage;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.PluginOption;

/**
 * A plugin's options dialog (the thesis's figure 60), built from the plugin's
 * {@link PluginOption}s alone: a field per option under its group's heading, the help as tooltip,
 * the output file with Browse, and a line saying what is wrong while OK is disabled. The fields
 * only mirror a {@link PluginForm}, which holds the values and does every check.
 */
public final class PluginDialog extends JDialog {
    private final PluginForm form;
    private final JLabel problem = new JLabel(" ");
    private final JButton ok = new JButton("OK");
    private final JTextField output;
    private PluginForm.Accepted accepted;
    private boolean refreshPending;
    /** The label and field of each option that matters only for some values of another. */
    private final Map<String, JComponent[]> conditional = new LinkedHashMap<>();

    /**
     * Builds the dialog over a form; {@link #ask()} shows it.
     *
     * @param owner the viewer's window, or null
     * @param form  the form, its fields at their values
     */
    public PluginDialog(Window owner, PluginForm form) {
        super(owner, form.plugin().name(), ModalityType.APPLICATION_MODAL);
        this.form = form;
        setName("pluginDialog");
        setDefaultCloseOperation(DISPOSE_ON_CLOSE);

        // Options that concern the whole picture in a column; each surface's (grouped under its
        // name, as the plugin interface asks) on a tab of its own, so many surfaces stay compact.
        JPanel general = new JPanel();
        general.setLayout(new BoxLayout(general, BoxLayout.Y_AXIS));
        JTabbedPane tabs = new JTabbedPane();
        tabs.setName("surfaces");
        Map<String, String> surfaceLabels = new LinkedHashMap<>();
        for (DisplayedSurface surface : form.surfaces()) surfaceLabels.putIfAbsent(surface.name(), surface.subdivisionLabel());
        for (Map.Entry<String, List<PluginOption>> group : form.groups().entrySet()) {
            JPanel box = new JPanel(new GridBagLayout());
            int row = 0;
            for (PluginOption o : group.getValue()) {
                JComponent f = field(o);
                JLabel l = addRow(box, row++, o.label(), f, o.help());
                if (o.when() != null) conditional.put(o.key(), new JComponent[] {l, f});
            }
            if (surfaceLabels.containsKey(group.getKey())) {
                box.setBorder(BorderFactory.createEmptyBorder(4, 4, 4, 4));
                JPanel top = new JPanel(new BorderLayout());
                top.add(box, BorderLayout.NORTH);
                tabs.addTab(group.getKey(), null, top, group.getKey() + ": " + surfaceLabels.get(group.getKey()));
            } else {
                box.setBorder(BorderFactory.createTitledBorder(group.getKey()));
                box.setAlignmentX(LEFT_ALIGNMENT);
                general.add(box);
            }
        }
        output = new JTextField(form.output(), 28);
        output.setName("output");
        onEdit(output, form::setOutput);
        JButton browse = new JButton("Browse...");
        browse.setName("outputBrowse");
        browse.addActionListener(e -> browseOutput());
        JPanel out = new JPanel(new GridBagLayout());
        out.setBorder(BorderFactory.createTitledBorder("Output file"));
        out.setAlignmentX(LEFT_ALIGNMENT);
        addRow(out, 0, "File", withButton(output, browse),
                "The file to write: " + String.join(", ", form.extensions().stream().map(x -> "." + x).toList()) + ".");
        general.add(out);

        JPanel fields = new JPanel(new GridBagLayout());
        GridBagConstraints c = new GridBagConstraints();
        c.anchor = GridBagConstraints.FIRST_LINE_START;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = 1;
        c.weighty = 1;
        c.insets = new Insets(0, 0, 0, 8);
        fields.add(general, c);
        if (tabs.getTabCount() > 0) {
            c.gridx = 1;
            c.insets = new Insets(6, 0, 0, 0);
            fields.add(tabs, c);
        }
        JLabel description = new JLabel(form.plugin().description());
        description.setBorder(BorderFactory.createEmptyBorder(0, 0, 6, 0));
        JPanel content = new JPanel(new BorderLayout());
        content.add(description, BorderLayout.NORTH);
        content.add(fields, BorderLayout.CENTER);

        JScrollPane scroll = new JScrollPane(content);
        scroll.setBorder(BorderFactory.createEmptyBorder(8, 8, 0, 8));
        scroll.getVerticalScrollBar().setUnitIncrement(16);

        problem.setName("problem");
        problem.setForeground(new Color(0xB0, 0x00, 0x20));
        ok.setName("ok");
        ok.addActionListener(e -> accept());
        JButton cancel = new JButton("Cancel");
        cancel.setName("cancel");
        cancel.addActionListener(e -> dispose());
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(ok);
        buttons.add(cancel);
        JPanel south = new JPanel(new BorderLayout());
        south.setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        south.add(problem, BorderLayout.CENTER);
        south.add(buttons, BorderLayout.SOUTH);
        getContentPane().add(scroll, BorderLayout.CENTER);
        getContentPane().add(south, BorderLayout.SOUTH);
        getRootPane().setDefaultButton(ok);
        getRootPane().getInputMap(JComponent.WHEN_IN_FOCUSED_WINDOW).put(KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), "close");
        getRootPane().getActionMap().put("close", new AbstractAction() {
            @Override public void actionPerformed(ActionEvent e) { dispose(); }
        });
        refresh();
        // A plugin with many surfaces asks many questions: keep the dialog on the screen and scroll.
        // (Sized without pack(), which would map the window before it is placed; see RenderWindow.)
        Dimension wanted = getPreferredSize();
        Dimension screen = getGraphicsConfiguration().getBounds().getSize();
        setSize(Math.min(wanted.width + 24, screen.width * 9 / 10), Math.min(wanted.height + 8, screen.height * 9 / 10));
        setLocationRelativeTo(owner);
    }

    /**
     * Shows the dialog and waits (modally, the event thread keeps running) until the user accepts
     * or cancels it.
     *
     * @return the accepted values and output, or null if cancelled
     */
    public PluginForm.Accepted ask() {
        setVisible(true);
        return accepted;
    }

    /** @return the line saying what is wrong, blank when nothing is */
    public String problem() { return problem.getText(); }

    private void accept() {
        try {
            accepted = form.accept();
            dispose();
        } catch (IOException | IllegalArgumentException e) {
            // An output folder that will not take a file: say so and let the user pick another.
            show(FailureMessage.of(e));
            ok.setEnabled(false);
        }
    }

    /**
     * Refreshes once the current event is over: a field that replaces its text (a spinner
     * committing on focus loss) passes through an empty text, and disabling OK for that instant
     * would swallow the click that moved the focus to OK.
     */
    private void refreshLater() {
        if (refreshPending) return;
        refreshPending = true;
        SwingUtilities.invokeLater(() -> {
            refreshPending = false;
            refresh();
        });
    }

    private void refresh() {
        for (Map.Entry<String, JComponent[]> e : conditional.entrySet()) {
            boolean on = form.applies(e.getKey());
            for (JComponent c : e.getValue()) enable(c, on);
        }
        String p = form.problem();
        show(p);
        ok.setEnabled(p == null);
    }

    private void show(String p) {
        problem.setText(p == null ? " " : p);
        problem.setToolTipText(p);
    }

    private JComponent field(PluginOption o) {
        String key = o.key();
        JComponent c = switch (o.kind()) {
            case INTEGER -> spinner(o);
            case NUMBER, TEXT -> text(o, 10);
            case BOOLEAN -> {
                JCheckBox box = new JCheckBox("", Boolean.parseBoolean(form.value(key)));
                box.addItemListener(e -> {
                    form.set(key, Boolean.toString(box.isSelected()));
                    refresh();
                });
                yield box;
            }
            case CHOICE -> {
                JComboBox<String> combo = new JComboBox<>(o.choices().toArray(new String[0]));
                combo.setSelectedItem(form.value(key));
                combo.addActionListener(e -> {
                    form.set(key, (String) combo.getSelectedItem());
                    refresh();
                });
                yield combo;
            }
            case COLOR -> colour(o);
            case FILE -> {
                JTextField t = text(o, 24);
                JButton browse = new JButton("Browse...");
                browse.setName("browse:" + key);
                browse.addActionListener(e -> {
                    JFileChooser chooser = new JFileChooser(t.getText().isBlank() ? null : new File(t.getText()));
                    if (chooser.showOpenDialog(this) == JFileChooser.APPROVE_OPTION) t.setText(chooser.getSelectedFile().getPath());
                });
                yield withButton(t, browse);
            }
        };
        c.setToolTipText(o.help());
        return c;
    }

    private JTextField text(PluginOption o, int columns) {
        JTextField t = new JTextField(form.value(o.key()), columns);
        t.setName("option:" + o.key());
        t.setToolTipText(o.help());
        onEdit(t, v -> form.set(o.key(), v));
        return t;
    }

    /** A spinner whose text is read as typed, so an out-of-range number is reported, not silently reverted. */
    private JSpinner spinner(PluginOption o) {
        long min = (long) Math.max(o.min(), Long.MIN_VALUE + 1.0), max = (long) Math.min(o.max(), Long.MAX_VALUE - 1.0);
        long value = Long.parseLong(form.value(o.key()).strip());
        JSpinner s = new JSpinner(new SpinnerNumberModel(Long.valueOf(value), Long.valueOf(min), Long.valueOf(max), Long.valueOf(1)));
        s.setEditor(new JSpinner.NumberEditor(s, "#"));
        JFormattedTextField t = ((JSpinner.DefaultEditor) s.getEditor()).getTextField();
        t.setColumns(8);
        t.setName("option:" + o.key());
        t.setToolTipText(o.help());
        if (t.getFormatter() instanceof DefaultFormatter f) {
            f.setAllowsInvalid(true);
            f.setCommitsOnValidEdit(true);
        }
        onEdit(t, v -> form.set(o.key(), v));
        return s;
    }

    /** The colour's text, a swatch showing it (empty while the text names no colour) and a chooser. */
    private JComponent colour(PluginOption o) {
        JTextField t = text(o, 12);
        JLabel swatch = new JLabel();
        swatch.setName("swatch:" + o.key());
        swatch.setOpaque(true);
        swatch.setPreferredSize(new Dimension(28, 18));
        swatch.setBorder(BorderFactory.createLineBorder(Color.GRAY));
        Runnable paint = () -> {
            Color c = parseColour(t.getText());
            swatch.setOpaque(c != null);
            swatch.setBackground(c);
            swatch.repaint();
        };
        paint.run();
        onEdit(t, v -> paint.run());
        JButton choose = new JButton("Choose...");
        choose.setName("colour:" + o.key());
        choose.addActionListener(e -> {
            Color start = parseColour(t.getText());
            Color chosen = JColorChooser.showDialog(this, o.label(), start != null ? start : Color.WHITE);
            if (chosen != null) t.setText(formatColour(chosen));
        });
        JPanel buttons = new JPanel(new BorderLayout(4, 0));
        buttons.add(swatch, BorderLayout.WEST);
        buttons.add(choose, BorderLayout.CENTER);
        JPanel p = new JPanel(new BorderLayout(4, 0));
        p.add(t, BorderLayout.CENTER);
        p.add(buttons, BorderLayout.EAST);
        return p;
    }

    private void browseOutput() {
        JFileChooser chooser = new JFileChooser();
        List<String> exts = form.extensions();
        chooser.setFileFilter(new FileNameExtensionFilter(form.plugin().name() + " output ("
                + String.join(", ", exts.stream().map(x -> "*." + x).toList()) + ")", exts.toArray(new String[0])));
        String current = output.getText().strip();
        if (!current.isEmpty()) {
            try {
                chooser.setSelectedFile(Path.of(current).toAbsolutePath().toFile());
            } catch (java.nio.file.InvalidPathException e) {
                // the field says what is wrong with it; start the chooser where it likes
            }
        }
        if (chooser.showSaveDialog(this) != JFileChooser.APPROVE_OPTION) return;
        String chosen = chooser.getSelectedFile().getPath();
        // A name typed without an extension gets the default one, as save dialogs usually do.
        if (!exts.contains(PluginForm.extension(chooser.getSelectedFile().getName()))) chosen += "." + exts.get(0);
        output.setText(chosen);
    }

    private void onEdit(JTextComponent t, Consumer<String> set) {
        t.getDocument().addDocumentListener(new DocumentListener() {
            @Override public void insertUpdate(DocumentEvent e) { changed(); }
            @Override public void removeUpdate(DocumentEvent e) { changed(); }
            @Override public void changedUpdate(DocumentEvent e) { changed(); }
            private void changed() {
                set.accept(t.getText());
                refreshLater();
            }
        });
    }

    private static JPanel withButton(JComponent field, JButton button) {
        JPanel p = new JPanel(new BorderLayout(4, 0));
        p.add(field, BorderLayout.CENTER);
        p.add(button, BorderLayout.EAST);
        return p;
    }

    /** Enables or disables a field with everything inside it (a text field and its button). */
    private static void enable(java.awt.Component c, boolean on) {
        c.setEnabled(on);
        if (c instanceof java.awt.Container k) for (java.awt.Component child : k.getComponents()) enable(child, on);
    }

    private static JLabel addRow(JPanel panel, int row, String label, JComponent field, String help) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = row;
        c.insets = new Insets(2, 4, 2, 4);
        c.anchor = GridBagConstraints.LINE_START;
        JLabel l = new JLabel(label);
        l.setToolTipText(help);
        l.setLabelFor(field);
        panel.add(l, c);
        c.gridx = 1;
        c.weightx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        panel.add(field, c);
        return l;
    }

    /** The colour a COLOR value names, or null if it names none. */
    static Color parseColour(String text) {
        if (new PluginOption("c", "c", "c", PluginOption.Kind.COLOR, "0 0 0", List.of(), 0, 0, "").check(text) != null) return null;
        String[] p = text.strip().split("\\s+");
        return new Color((float) Double.parseDouble(p[0]), (float) Double.parseDouble(p[1]), (float) Double.parseDouble(p[2]));
    }

    /** A chosen colour as a COLOR value: three numbers in [0, 1], three decimals at most. */
    static String formatColour(Color c) {
        return channel(c.getRed()) + " " + channel(c.getGreen()) + " " + channel(c.getBlue());
    }

    private static String channel(int v) {
        String s = String.format(Locale.ROOT, "%.3f", v / 255.0);
        s = s.replaceAll("0+$", "");
        return s.endsWith(".") ? s.substring(0, s.length() - 1) : s;
    }
}
