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
}
