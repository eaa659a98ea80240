package lt.spindulys.files;

import java.nio.file.Path;
import java.util.Locale;

/**
 * File-name rules shared by the front ends (the command line, the viewer, the plugins), so that
 * a file is of the same kind wherever it is given.
 */
public final class FileNames {
    private FileNames() {}

    /**
     * The extension of a file's name: lower case, without the dot; empty if the name has no dot
     * (or the path has no name, like "/").
     *
     * @param file the file
     * @return {@code "obj"} for {@code a/b.OBJ}, {@code ""} for {@code a/b}
     */
    public static String extension(Path file) {
        Path name = file.getFileName();
        String s = name == null ? "" : name.toString();
        int dot = s.lastIndexOf('.');
        return dot < 0 ? "" : s.substring(dot + 1).toLowerCase(Locale.ROOT);
    }

    /**
     * A name a user gave (a surface's, say) as part of a file name: without a mesh file's
     * extension (.obj, .dat), letters, digits, '-', '_' and '.' kept and everything else '_', at most
     * 80 characters, no leading dots (no hidden files, no "..").
     *
     * @param name     the name
     * @param fallback the stem when nothing of the name is left
     * @return the stem, never empty
     */
    public static String stem(String name, String fallback) {
        String n = name.strip();
        String lower = n.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".obj") || lower.endsWith(".dat")) n = n.substring(0, n.length() - 4);
        StringBuilder b = new StringBuilder();
        n.codePoints().limit(80).forEach(c -> b.appendCodePoint(Character.isLetterOrDigit(c) || c == '-' || c == '_' || c == '.' ? c : '_'));
        String s = b.toString().replaceAll("^[.]+", "");
        return s.isEmpty() ? fallback : s;
    }
}
