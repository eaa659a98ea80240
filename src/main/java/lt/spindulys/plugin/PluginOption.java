package lt.spindulys.plugin;

import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Set;

import lt.spindulys.limits.MessageText;

/**
 * One thing a plugin asks the user, described so that any host can build a form field for it and
 * check the answer. Values travel as text, in the forms below.
 *
 * @param key          the key of the value in {@link PluginRequest#options()}; per-surface options
 *                     carry the surface's index: {@code surface.2.material}
 * @param label        the field's label, a few words
 * @param group        the heading it belongs under ("Image", "Lighting", or a surface's name)
 * @param kind         the value's form
 * @param defaultValue the value when the user gives none, in the kind's form
 * @param choices      for {@link Kind#CHOICE}: the allowed values (their text is what is shown); else empty
 * @param min          for {@link Kind#INTEGER} and {@link Kind#NUMBER}: the least value; else 0
 * @param max          for {@link Kind#INTEGER} and {@link Kind#NUMBER}: the greatest value; else 0
 * @param help         one sentence for a tooltip
 * @param when         the key of the option this one depends on, or null: it matters only while that
 *                     option's value is one of {@code whenValues} (a host may disable its field otherwise;
 *                     its value is still checked and handed over)
 * @param whenValues   the values of {@code when} under which this option matters; empty without {@code when}
 */
public record PluginOption(String key, String label, String group, Kind kind, String defaultValue,
                           List<String> choices, double min, double max, String help, String when, List<String> whenValues) {
    /** The form of a value. */
    public enum Kind {
        /** A whole number in [min, max], in decimal: {@code 16}. */
        INTEGER,
        /** A finite number in [min, max], as Java's {@link Double#parseDouble} reads it: {@code 1.5}. */
        NUMBER,
        /** {@code true} or {@code false}. */
        BOOLEAN,
        /** One of {@link PluginOption#choices()}. */
        CHOICE,
        /** A colour as three numbers in [0, 1] separated by spaces: {@code 0.8 0.4 0.2}. */
        COLOR,
        /** A path to an existing file to read (a texture image, for example), or empty for none. */
        FILE,
        /** Any text on one line. */
        TEXT
    }

    /**
     * An option that always matters.
     *
     * @param key the key
     * @param label the label
     * @param group the heading
     * @param kind the kind
     * @param defaultValue the default
     * @param choices the allowed values of a CHOICE
     * @param min the least value of a number
     * @param max the greatest value of a number
     * @param help a sentence
     */
    public PluginOption(String key, String label, String group, Kind kind, String defaultValue,
                        List<String> choices, double min, double max, String help) {
        this(key, label, group, kind, defaultValue, choices, min, max, help, null, List.of());
    }

    /**
     * Copies the lists and checks that the default is valid.
     *
     * @throws IllegalArgumentException if the default does not pass {@link #check(String)}, or
     *                                  {@code when} and {@code whenValues} do not go together
     */
    public PluginOption {
        Objects.requireNonNull(key, "key");
        Objects.requireNonNull(label, "label");
        Objects.requireNonNull(group, "group");
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(defaultValue, "defaultValue");
        choices = List.copyOf(choices);
        Objects.requireNonNull(help, "help");
        whenValues = List.copyOf(whenValues);
        if ((when == null) != whenValues.isEmpty()) {
            throw new IllegalArgumentException("option " + key + ": a condition needs both the option it depends on and its values");
        }
        if (kind == Kind.CHOICE && choices.isEmpty()) throw new IllegalArgumentException("option " + key + " has no choices");
        if (kind != Kind.FILE) {
            String problem = problem(kind, defaultValue, choices, min, max);
            if (problem != null) throw new IllegalArgumentException("option " + key + ": default " + problem);
        }
    }

    /**
     * A whole-number option.
     *
     * @param key the key
     * @param label the label
     * @param group the heading
     * @param defaultValue the default
     * @param min the least value
     * @param max the greatest value
     * @param help a sentence
     * @return the option
     */
    public static PluginOption integer(String key, String label, String group, long defaultValue, long min, long max, String help) {
        return new PluginOption(key, label, group, Kind.INTEGER, Long.toString(defaultValue), List.of(), min, max, help);
    }

    /**
     * A number option.
     *
     * @param key the key
     * @param label the label
     * @param group the heading
     * @param defaultValue the default
     * @param min the least value
     * @param max the greatest value
     * @param help a sentence
     * @return the option
     */
    public static PluginOption number(String key, String label, String group, double defaultValue, double min, double max, String help) {
        return new PluginOption(key, label, group, Kind.NUMBER, Double.toString(defaultValue), List.of(), min, max, help);
    }

    /**
     * A choice among fixed values.
     *
     * @param key the key
     * @param label the label
     * @param group the heading
     * @param defaultValue the default, one of the choices
     * @param choices the allowed values
     * @param help a sentence
     * @return the option
     */
    public static PluginOption choice(String key, String label, String group, String defaultValue, List<String> choices, String help) {
        return new PluginOption(key, label, group, Kind.CHOICE, defaultValue, choices, 0, 0, help);
    }

    /**
     * An option of a kind without range or choices (BOOLEAN, COLOR, FILE, TEXT).
     *
     * @param key the key
     * @param label the label
     * @param group the heading
     * @param kind the kind
     * @param defaultValue the default
     * @param help a sentence
     * @return the option
     */
    public static PluginOption of(String key, String label, String group, Kind kind, String defaultValue, String help) {
        return new PluginOption(key, label, group, kind, defaultValue, List.of(), 0, 0, help);
    }

    /**
     * The same option, mattering only while option {@code key} has one of {@code values} (for
     * example the index of refraction only for a transparent material).
     *
     * @param key    the option this one depends on
     * @param values its values under which this one matters
     * @return the conditional option
     */
    public PluginOption onlyWhen(String key, String... values) {
        Objects.requireNonNull(key, "key");
        if (values.length == 0) throw new IllegalArgumentException("option " + this.key + ": a condition needs at least one value");
        return new PluginOption(this.key, label, group, kind, defaultValue, choices, min, max, help, key, List.of(values));
    }

    /**
     * Whether this option matters with these answers: it has no condition, or the option it
     * depends on has (or defaults to) one of the values named.
     *
     * @param options the plugin's options (for the default of the option depended on)
     * @param values  the answers, key to text
     * @return true if the option matters
     */
    public boolean applies(List<PluginOption> options, Map<String, String> values) {
        if (when == null) return true;
        for (PluginOption o : options) if (o.key().equals(when)) return whenValues.contains(o.valueIn(values).strip());
        return whenValues.contains(values.get(when));
    }

    /**
     * Checks a value against this option's kind, range and choices (a FILE must name a readable
     * regular file, or be empty).
     *
     * @param value the text
     * @return null if it is valid, else what is wrong, as the end of a sentence naming the option
     *         ("must be between 1 and 4096, found 0")
     */
    public String check(String value) {
        Objects.requireNonNull(value, "value");
        if (kind == Kind.FILE) {
            if (value.isEmpty()) return null;
            java.nio.file.Path p;
            try {
                p = java.nio.file.Path.of(value);
            } catch (java.nio.file.InvalidPathException e) {
                return "is not a valid path: " + quote(value);
            }
            if (!java.nio.file.Files.isRegularFile(p)) return "names no file: " + quote(value);
            if (!java.nio.file.Files.isReadable(p)) return "names a file that cannot be read: " + quote(value);
            return null;
        }
        return problem(kind, value, choices, min, max);
    }

    /**
     * Checks every value of a request against its options: each key must be an option's, each
     * value valid.
     *
     * @param options the plugin's options
     * @param values  the values, key to text
     * @return null if all are valid, else one line naming the first option at fault
     *         ("Samples per pixel (samples) must be between 1 and 1024, found 0")
     */
    public static String check(List<PluginOption> options, Map<String, String> values) {
        Set<String> known = new HashSet<>();
        for (PluginOption o : options) known.add(o.key());
        for (String k : values.keySet().stream().sorted().toList()) {
            if (!known.contains(k)) {
                return "unknown option " + quote(k) + "; expected one of: " + String.join(", ", options.stream().map(PluginOption::key).toList());
            }
        }
        for (PluginOption o : options) {
            String v = values.get(o.key());
            if (v == null) continue;
            String problem = o.check(v);
            if (problem != null) return o.describe() + " " + problem;
        }
        return null;
    }

    /**
     * The value to use: the one given, or the default.
     *
     * @param values the values, key to text
     * @return the text
     */
    public String valueIn(Map<String, String> values) {
        String v = values.get(key);
        return v != null ? v : defaultValue;
    }

    /**
     * The option as messages name it: {@code Samples per pixel (samples)}, with the group for a
     * surface's option.
     *
     * @return the description
     */
    public String describe() {
        return label + " (" + key + ")";
    }

    private static String problem(Kind kind, String value, List<String> choices, double min, double max) {
        String t = value.strip();
        switch (kind) {
            case INTEGER -> {
                long n;
                try {
                    n = Long.parseLong(t);
                } catch (NumberFormatException e) {
                    return "must be a whole number, found " + quote(value);
                }
                if (n < min || n > max) return "must be between " + (long) min + " and " + (long) max + ", found " + n;
                return null;
            }
            case NUMBER -> {
                double d = parse(t);
                if (Double.isNaN(d)) return "must be a number, found " + quote(value);
                if (d < min || d > max) return "must be between " + min + " and " + max + ", found " + t;
                return null;
            }
            case BOOLEAN -> {
                return t.equals("true") || t.equals("false") ? null : "must be true or false, found " + quote(value);
            }
            case CHOICE -> {
                return choices.contains(t) ? null : "must be one of " + String.join(", ", choices) + ", found " + quote(value);
            }
            case COLOR -> {
                String[] parts = t.isEmpty() ? new String[0] : t.split("\\s+");
                if (parts.length != 3) return "must be three numbers r g b between 0 and 1, found " + quote(value);
                for (String p : parts) {
                    double d = parse(p);
                    if (!(d >= 0 && d <= 1)) return "must be three numbers r g b between 0 and 1, found " + quote(value);
                }
                return null;
            }
            case TEXT -> {
                return value.indexOf('\n') >= 0 || value.indexOf('\r') >= 0 ? "must be one line" : null;
            }
            default -> throw new AssertionError(kind);
        }
    }

    /** A finite number, or NaN when the text is not one (no hex, no infinities, no trailing letters such as 1d). */
    private static double parse(String t) {
        if (!t.matches("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?")) return Double.NaN;
        double d = Double.parseDouble(t);
        return Double.isFinite(d) ? d : Double.NaN;
    }

    /** A value as messages quote it: escaped to one line and cut when long, as every message does. */
    private static String quote(String s) {
        return MessageText.quote(MessageText.escape(s));
    }
}
