package lt.spindulys.cli;

import lt.spindulys.math.Ranges;

/**
 * The values of command-line options, read and checked with one wording for every command:
 * {@code option --x needs a value}, {@code --x must be between A and B, found V},
 * {@code --x expects a whole number, found 'V'}.
 */
final class OptionValues {
    private OptionValues() {}

    /** The value after option {@code args[i - 1]}. */
    static String value(String[] args, int i, String option) throws UsageException {
        if (i >= args.length) throw new UsageException("option " + option + " needs a value");
        return args[i];
    }

    /** A whole number in [min, max]. */
    static int intValue(String[] args, int i, String option, int min, int max) throws UsageException {
        String v = value(args, i, option);
        try {
            int n = Integer.parseInt(v);
            if (n < min || n > max) throw new UsageException(option + " must be between " + min + " and " + max + ", found " + v);
            return n;
        } catch (NumberFormatException e) {
            throw new UsageException(option + " expects a whole number, found '" + v + "'");
        }
    }

    /** OPEN,CLOSE: two finite numbers, close not before open. */
    static double[] shutterValue(String[] args, int i, String option) throws UsageException {
        String v = value(args, i, option);
        String[] parts = v.split(",", -1);
        if (parts.length != 2) throw new UsageException(option + " expects OPEN,CLOSE (two numbers separated by a comma), found '" + v + "'");
        double[] out = new double[2];
        for (int k = 0; k < 2; k++) {
            try {
                out[k] = Double.parseDouble(parts[k].trim());
            } catch (NumberFormatException e) {
                throw new UsageException(option + " expects OPEN,CLOSE (two numbers separated by a comma), found '" + v + "'");
            }
            if (!Double.isFinite(out[k])) throw new UsageException(option + " times must be finite, found '" + v + "'");
        }
        if (out[1] < out[0]) throw new UsageException(option + " must close after it opens, found '" + v + "'");
        return out;
    }

    /** Any whole number a long holds. */
    static long longValue(String[] args, int i, String option) throws UsageException {
        String v = value(args, i, option);
        try {
            return Long.parseLong(v);
        } catch (NumberFormatException e) {
            throw new UsageException(option + " expects a whole number, found '" + v + "'");
        }
    }

    /** A number in [min, max]. */
    static double doubleValue(String[] args, int i, String option, double min, double max) throws UsageException {
        String v = value(args, i, option);
        try {
            double d = Double.parseDouble(v);
            if (!(d >= min && d <= max)) throw new UsageException(option + " must be between " + bound(min) + " and " + bound(max) + ", found " + v);
            return d;
        } catch (NumberFormatException e) {
            throw new UsageException(option + " expects a number, found '" + v + "'");
        }
    }

    /** A range's end as a person writes it: 0, 1, 16777216, 0.01 (not 0.0 or 1.6777216E7). */
    static String bound(double b) {
        if (b == Math.rint(b) && Math.abs(b) < 1e15) return Long.toString((long) b);
        return java.math.BigDecimal.valueOf(b).stripTrailingZeros().toPlainString();
    }

    /** A finite lens dimension: at least 0, or with {@code positive} greater than 0. */
    static double lensValue(String[] args, int i, String option, boolean positive) throws UsageException {
        String v = value(args, i, option);
        double d;
        try {
            d = Double.parseDouble(v);
        } catch (NumberFormatException e) {
            throw new UsageException(option + " expects a number, found '" + v + "'");
        }
        if (!Double.isFinite(d) || (positive ? !(d > 0) : !(d >= 0))) {
            throw new UsageException(option + " must be a finite number " + (positive ? "greater than 0" : "at least 0") + ", found " + v);
        }
        // As any scene number (Ranges): larger ones could overflow the camera's ray arithmetic.
        if (!Ranges.isModest(d)) throw new UsageException(option + " must be at most " + Ranges.show(Ranges.MAX_NUMBER) + ", found " + v);
        return d;
    }
}
