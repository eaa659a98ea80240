package lt.spindulys.limits;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
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

    /**
     * Opens an input file for reading, refusing one that is not a regular file (a pipe would
     * block and a device never end) with an IOException naming it and the {@link #problem}.
     *
     * @param path the file
     * @return a stream the caller closes
     * @throws IOException if it is not a regular file or cannot be opened
     */
    public static InputStream open(Path path) throws IOException {
        String problem = problem(path);
        if (problem != null) throw new IOException(path + " " + problem);
        return Files.newInputStream(path);
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
        checkedSize(path, what, bytesPerByte);
        return Files.readAllBytes(path);
    }

    /** Files at least this large are read in parts at once by {@link #readAllBytes(Path, String, int, int)}. */
    static final long PARTS_FROM = 8 << 20;

    /**
     * {@link #readAllBytes(Path, String, int)}, a large file read in {@code threads} parts at once
     * (the caller's thread reads one): copying from the system's cache into new heap pages is
     * most of a read, and it divides among cores. A file whose size changes while it is read is
     * read again whole, as the one-thread read would.
     */
    public static byte[] readAllBytes(Path path, String what, int bytesPerByte, int threads) throws IOException {
        long size = checkedSize(path, what, bytesPerByte);
        if (threads <= 1 || size < PARTS_FROM) return Files.readAllBytes(path);
        byte[] b = readParts(path, (int) size, threads);
        // The heap was checked for one copy: the parts, if they are not the whole file, are garbage by now.
        return b != null ? b : Files.readAllBytes(path);
    }

    /** The file read in parts at once, or null if its size is no longer {@code size}. */
    private static byte[] readParts(Path path, int size, int threads) throws IOException {
        byte[] b = new byte[size];
        boolean whole;
        try (FileChannel channel = FileChannel.open(path)) {
            boolean[] complete = new boolean[threads];
            PartThreads.run(threads, "spindulys-read", k -> complete[k] = readPart(channel, b, k, threads));
            whole = channel.size() == size;
            for (boolean c : complete) whole &= c;
        }
        return whole ? b : null;
    }

    /** Bytes per read call: the channel copies through a native buffer as large as the call, new for each new thread. */
    private static final int SLICE = 1 << 20;

    /** Reads part {@code k} of {@code parts} of the file into the same range of {@code b}; false if the file ended first. */
    private static boolean readPart(FileChannel channel, byte[] b, int k, int parts) throws IOException {
        int from = (int) ((long) b.length * k / parts), to = (int) ((long) b.length * (k + 1) / parts);
        for (int at = from; at < to;) {
            int n = channel.read(ByteBuffer.wrap(b, at, Math.min(SLICE, to - at)), at);
            if (n < 0) return false;
            at += n;
        }
        return true;
    }

    /** The file's size after the checks every whole-file read makes: a regular file, under 2 GiB, room on the heap. */
    private static long checkedSize(Path path, String what, int bytesPerByte) throws IOException {
        String p = problem(path);
        if (p != null) throw new IOException(what + " " + path + " " + p);
        long size = Files.size(path);
        if (size > Integer.MAX_VALUE - 16) throw new IOException(what + " " + path + " is " + HeapBudget.format(size) + ", more than the 2 GiB one file may have");
        HeapBudget.require(HeapBudget.product(size, Math.max(1, bytesPerByte)), "reading " + what + " " + path + " (" + HeapBudget.format(size) + ")");
        return size;
    }
}
