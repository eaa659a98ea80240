package lt.spindulys.bench;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * A plain-text table: columns sized to their widest cell, numbers right-aligned; and the figures
 * the bench puts in its cells (medians, fixed decimals).
 */
final class BenchTable {
    private final String[] header;
    private final List<String[]> rows = new ArrayList<>();

    BenchTable(String... header) { this.header = header; }

    void add(String... cells) {
        if (cells.length != header.length) throw new IllegalArgumentException("row has " + cells.length + " cells, table has " + header.length + " columns");
        rows.add(cells);
    }

    void print(PrintStream out) {
        int[] w = new int[header.length];
        for (int i = 0; i < w.length; i++) w[i] = header[i].length();
        for (String[] r : rows) for (int i = 0; i < w.length; i++) w[i] = Math.max(w[i], r[i].length());
        line(out, header, w, false);
        StringBuilder rule = new StringBuilder();
        for (int i = 0; i < w.length; i++) rule.append(i == 0 ? "" : "  ").append("-".repeat(w[i]));
        out.println(rule);
        for (String[] r : rows) line(out, r, w, true);
    }

    private static void line(PrintStream out, String[] cells, int[] w, boolean alignNumbers) {
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < cells.length; i++) {
            if (i > 0) s.append("  ");
            boolean right = alignNumbers && !cells[i].isEmpty() && (Character.isDigit(cells[i].charAt(0)) || cells[i].charAt(0) == '-');
            String pad = " ".repeat(w[i] - cells[i].length());
            s.append(right ? pad + cells[i] : cells[i] + (i == cells.length - 1 ? "" : pad));
        }
        out.println(s.toString().stripTrailing());
    }

    /** The median of the known (not NaN) values; NaN if there are none. */
    static double median(double[] v) {
        double[] s = Arrays.stream(v).filter(x -> !Double.isNaN(x)).sorted().toArray();
        if (s.length == 0) return Double.NaN;
        return s.length % 2 == 1 ? s[s.length / 2] : (s[s.length / 2 - 1] + s[s.length / 2]) / 2;
    }

    /** {@code v} with {@code decimals} decimals, or "-" when it is not known (NaN). */
    static String fmt(double v, int decimals) {
        return Double.isNaN(v) ? "-" : String.format(Locale.ROOT, "%." + decimals + "f", v);
    }
}
