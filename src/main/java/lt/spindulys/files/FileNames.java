package lt.spindulys.files;

import java.io.IOException;
import java.nio.file.Files;
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
     * Tells whether a file's name is an extension alone, such as {@code .png}: as an output it
     * would be a hidden file with no name, which is never what was meant.
     *
     * @param file the file
     * @return true for {@code out/.png}, false for {@code out.png} or {@code .out.png}
     */
    public static boolean isOnlyExtension(Path file) {
        Path name = file.getFileName();
        String s = name == null ? "" : name.toString();
        return s.length() > 1 && s.lastIndexOf('.') == 0;
    }

    /**
     * The refusal of an output whose name is {@link #isOnlyExtension only an extension}.
     *
     * @param file the output
     * @return "output '.png' is only an extension; give the file a name, such as out.png"
     */
    public static String onlyExtensionMessage(Path file) {
        return "output '" + file + "' is only an extension; give the file a name, such as out" + file.getFileName();
    }

    /**
     * Tells whether writing {@code output} would replace the file {@code input}: when the output
     * exists, whether the two are one file ({@link Files#isSameFile}: through symbolic and hard
     * links alike); when it does not, whether the real path of its folder with its name is the
     * input's real path (a link to nothing named as output would create the file it points to).
     *
     * @param output a file to be written
     * @param input  a file read
     * @return true if they are one file
     */
    public static boolean isSameFile(Path output, Path input) {
        try {
            if (Files.exists(output) && Files.exists(input)) return Files.isSameFile(output, input);
        } catch (IOException | SecurityException e) {
            // Not comparable as files: compared by their paths below.
        }
        return realPath(output).equals(realPath(input));
    }

    /**
     * The path with every symbolic link in it resolved, as far as it exists: the real path of its
     * nearest existing folder with the remaining names after it, normalised. A file that does not
     * exist yet gets the path it would be created at.
     *
     * @param file the file
     * @return an absolute, normalised path
     */
    public static Path realPath(Path file) {
        Path abs = file.toAbsolutePath().normalize();
        Path existing = abs;
        java.util.ArrayDeque<Path> rest = new java.util.ArrayDeque<>();
        while (existing != null) {
            try {
                Path real = existing.toRealPath();
                for (Path name : rest) real = real.resolve(name);
                return real.normalize();
            } catch (IOException | SecurityException e) {
                if (existing.getFileName() == null) break;
                rest.addFirst(existing.getFileName());
                existing = existing.getParent();
            }
        }
        return abs;
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
