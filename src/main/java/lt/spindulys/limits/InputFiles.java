package lt.spindulys.limits;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;

/**
 * Input files are regular files. A named pipe would block a reader forever, a device such as
 * /dev/zero never ends, and a directory cannot be read: every reader asks {@link #problem} before
 * it opens a path (links are followed, so a link to a device is refused as the device), and reads
 * whole files through {@link #readAllBytes}, which checks the size against the heap first.
 */
public final class InputFiles {
    private InputFiles() {}

    /**
     * What is wrong with reading {@code path} as an input file, as a phrase to follow its name
     * ("is a named pipe, not a regular file", "not found"), or null when it is a regular file.
     */
    public static String problem(Path path) {
        BasicFileAttributes a;
        try {
            a = Files.readAttributes(path, BasicFileAttributes.class);
        } catch (IOException | SecurityException e) {
            return Files.exists(path, LinkOption.NOFOLLOW_LINKS) ? "is a link to nothing (not found)" : "not found";
        }
        if (a.isRegularFile()) return null;
        if (a.isDirectory()) return "is a directory, not a regular file";
        return "is " + otherKind(path) + ", not a regular file";
    }

    /** "a named pipe", "a character device", ...: the kind of a path that is neither file nor directory. */
    private static String otherKind(Path path) {
        try {
            int mode = (Integer) Files.getAttribute(path, "unix:mode");
            switch (mode & 0170000) {
                case 0010000: return "a named pipe";
                case 0020000: return "a character device";
                case 0060000: return "a block device";
                case 0140000: return "a socket";
                default: break;
            }
        } catch (IOException | UnsupportedOperationException | IllegalArgumentException | ClassCastException | SecurityException e) {
            // No unix view on this platform: the generic word below.
        }
        return "a device, pipe or socket";
    }

    /**
     * The whole content of a regular file, after checking that it is one and that the heap can
     * hold it ({@code bytesPerByte} times its size: 1 for the bytes alone, more when the caller
     * will also decode them into characters or numbers).
     *
     * @param what what the file is, for messages ("OBJ file")
     * @throws IOException with a one-line message "WHAT PATH is a named pipe, not a regular file"
     *         or the system's reason
     * @throws InsufficientMemoryException if the heap cannot hold it
     */
    public static byte[] readAllBytes(Path path, String what, int bytesPerByte) throws IOException {
        String p = problem(path);
        if (p != null) throw new IOException(what + " " + path + " " + p);
        long size = Files.size(path);
        if (size > Integer.MAX_VALUE - 16) throw new IOException(what + " " + path + " is " + HeapBudget.format(size) + ", more than the 2 GiB one file may have");
        HeapBudget.require(HeapBudget.product(size, Math.max(1, bytesPerByte)), "reading " + what + " " + path + " (" + HeapBudget.format(size) + ")");
        return Files.readAllBytes(path);
    }
}
