package lt.spindulys.io;

import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.Objects;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Atomic file writes, for every file the renderer writes (images, meshes): readers of the target
 * see either the old file or the complete new one, never a partial file, and a failed write
 * leaves the old file in place.
 */
public final class AtomicFile {
    private AtomicFile() {}

    /** What writes the file's content; may throw {@link IOException}. */
    @FunctionalInterface
    public interface Body {
        void write(OutputStream out) throws IOException;
    }

    /**
     * Writes a file atomically: {@code body} writes into a new temporary file
     * {@code .NAME.RANDOM.tmp} in the target's directory, which is flushed to disk, closed and
     * then renamed over {@code out} (an atomic move where the file system supports it, else a
     * plain replacing move). If anything fails, including {@code body} throwing, the temporary
     * file is deleted and an existing {@code out} is left untouched.
     *
     * <p>{@code body} gets a buffered stream; closing it only flushes, so the body may use
     * try-with-resources on wrappers around it.
     *
     * @throws IOException if the parent directory is missing (the message names it), {@code out}
     *         is a directory, or writing or renaming fails
     */
    public static void write(Path out, Body body) throws IOException {
        Objects.requireNonNull(body, "body");
        Path dir = checkTarget(out);
        Path target = out.toAbsolutePath();
        String name = target.getFileName().toString();

        Path tmp = null;
        FileChannel channel = null;
        for (int attempt = 0; channel == null; attempt++) {
            Path candidate = dir.resolve("." + name + "." + Long.toHexString(ThreadLocalRandom.current().nextLong())
                    + ".tmp");
            try {
                // CREATE_NEW gives the usual default permissions (unlike createTempFile's 0600).
                channel = FileChannel.open(candidate, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE);
                tmp = candidate;
            } catch (FileAlreadyExistsException e) {
                if (attempt >= 20) throw e;
            } catch (IOException e) {
                throw new IOException("cannot write '" + out + "': cannot create a temporary file in '" + dir
                        + "': " + e, e);
            }
        }

        try {
            try (FileChannel ch = channel) {
                OutputStream buffered = new BufferedOutputStream(Channels.newOutputStream(ch), 1 << 16);
                body.write(new NonClosingStream(buffered));
                buffered.flush();
                // Data must be on disk before the rename makes it visible, or a crash could leave
                // an empty or partial file under the final name.
                ch.force(true);
            }
            keepPermissions(target, tmp);
            try {
                Files.move(tmp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(tmp, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (Throwable t) {
            try {
                Files.deleteIfExists(tmp);
            } catch (IOException e) {
                t.addSuppressed(e);
            }
            throw t;
        }
        syncDirectory(dir);
    }

    /**
     * The checks {@link #write} makes before writing, without writing: the parent directory of
     * {@code out} exists and {@code out} is not a directory. Returns the (absolute) parent.
     */
    public static Path checkTarget(Path out) throws IOException {
        Objects.requireNonNull(out, "out");
        Path target = out.toAbsolutePath();
        Path dir = target.getParent();
        if (dir == null || target.getFileName() == null) {
            throw new IOException("cannot write '" + out + "': not a file name");
        }
        // Name the directory as the user wrote it where possible, so the message is recognisable.
        Path shown = out.getParent() != null ? out.getParent() : dir;
        if (!Files.exists(dir)) {
            throw new IOException("cannot write '" + out + "': directory '" + shown + "' does not exist");
        }
        if (!Files.isDirectory(dir)) {
            throw new IOException("cannot write '" + out + "': '" + shown + "' is not a directory");
        }
        if (Files.isDirectory(target)) {
            throw new IOException("cannot write '" + out + "': it is a directory");
        }
        return dir;
    }

    /** A replaced file keeps its POSIX permissions, as it would if it were overwritten in place. */
    private static void keepPermissions(Path target, Path tmp) {
        try {
            if (Files.isRegularFile(target)) {
                Files.setPosixFilePermissions(tmp, Files.getPosixFilePermissions(target));
            }
        } catch (IOException | UnsupportedOperationException e) {
            // Cosmetic only: the new file then simply has default permissions.
        }
    }

    /** Makes the rename itself durable; not every platform can open a directory, so best effort. */
    private static void syncDirectory(Path dir) {
        try (FileChannel d = FileChannel.open(dir, StandardOpenOption.READ)) {
            d.force(true);
        } catch (IOException | RuntimeException e) {
            // The file is complete and in place; only durability across a power cut is weaker.
        }
    }

    private static final class NonClosingStream extends FilterOutputStream {
        NonClosingStream(OutputStream out) { super(out); }

        @Override public void write(byte[] b, int off, int len) throws IOException { out.write(b, off, len); }

        @Override public void close() throws IOException { out.flush(); }
    }
}
