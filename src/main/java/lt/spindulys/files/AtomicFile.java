package lt.spindulys.files;

import java.io.BufferedOutputStream;
import java.io.FilterOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.ThreadLocalRandom;

/**
 * Atomic file writes, for every file the renderer writes (images, meshes): readers of the target
 * see either the old file or the complete new one, never a partial file, and a failed write
 * leaves the old file in place.
 *
 * <p>Temporary files are named {@code .spindulys-RANDOM.tmp} ({@link #TEMPORARY_PREFIX}, 16
 * lower-case hexadecimal digits, {@link #TEMPORARY_SUFFIX}) in the target's folder, whatever the
 * target is called: short, so that a target name of the longest length a file system allows
 * (255 bytes on most) still has a temporary beside it, and recognisable, so that a clean-up (after a
 * killed run, or of a folder a retried task writes into) can tell ours by {@link #isTemporaryName}
 * and leave everything else. The copies of old files kept while a group is renamed into place
 * ({@link #writeAll}) are {@code .spindulys-RANDOM.bak}.
 */
public final class AtomicFile {
    private AtomicFile() {}

    /** How the name of every temporary file this class makes starts: {@value}. */
    public static final String TEMPORARY_PREFIX = ".spindulys-";

    /** How the name of every temporary file this class makes ends: {@value}. */
    public static final String TEMPORARY_SUFFIX = ".tmp";

    /**
     * Tells whether a file name is one of this class's temporary files:
     * {@code .spindulys-} followed by 16 hexadecimal digits and {@code .tmp}, nothing else.
     *
     * @param name a file name (not a path)
     * @return true for a temporary file of an atomic write or of a writability probe
     */
    public static boolean isTemporaryName(String name) {
        return hasRandomName(name, TEMPORARY_SUFFIX);
    }

    private static boolean hasRandomName(String name, String suffix) {
        int p = TEMPORARY_PREFIX.length();
        if (name == null || name.length() != p + 16 + suffix.length() || !name.startsWith(TEMPORARY_PREFIX) || !name.endsWith(suffix)) return false;
        for (int i = p; i < p + 16; i++) {
            char c = name.charAt(i);
            if (!(c >= '0' && c <= '9' || c >= 'a' && c <= 'f')) return false;
        }
        return true;
    }

    /** What writes the file's content; may throw {@link IOException}. */
    @FunctionalInterface
    public interface Body {
        void write(OutputStream out) throws IOException;
    }

    /**
     * Writes a file atomically: {@code body} writes into a new temporary file
     * {@code .spindulys-RANDOM.tmp} in the target's directory, which is flushed to disk, closed and
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
        writeAll(List.of(out), List.of(body));
    }

    /**
     * Writes several files as one: every body first writes its own temporary file as in
     * {@link #write}; only when all of them are complete are they renamed into place. If a body or
     * a rename fails, the temporary files are deleted and the targets already replaced get their
     * old content back (or are removed if they did not exist), so the failed call leaves none of
     * the new files and every old one. Each single file still changes atomically for readers. (A
     * process killed between two renames can leave some files new and some old, with hidden
     * {@code .bak} copies of the old ones; that cannot be avoided without a transactional file system.)
     *
     * @param outs   distinct target files
     * @param bodies what to write into each, in the same order
     * @throws IOException as {@link #write}, for the first target that fails
     */
    public static void writeAll(List<Path> outs, List<Body> bodies) throws IOException {
        if (outs.size() != bodies.size()) {
            throw new IllegalArgumentException(outs.size() + " files but " + bodies.size() + " bodies");
        }
        int n = outs.size();
        Path[] dirs = new Path[n], targets = new Path[n], tmps = new Path[n];
        for (int i = 0; i < n; i++) {
            Objects.requireNonNull(bodies.get(i), "body");
            dirs[i] = checkTarget(outs.get(i));
            targets[i] = outs.get(i).toAbsolutePath();
            for (int j = 0; j < i; j++) {
                if (targets[j].normalize().equals(targets[i].normalize())) throw new IllegalArgumentException("'" + outs.get(i) + "' is named twice");
            }
        }
        try {
            for (int i = 0; i < n; i++) tmps[i] = writeTemporary(outs.get(i), dirs[i], targets[i], bodies.get(i));
            commit(targets, tmps);
        } catch (Throwable t) {
            for (Path tmp : tmps) deleteQuietly(tmp, t);
            throw t;
        }
        for (int i = 0; i < n; i++) if (i == 0 || !dirs[i].equals(dirs[i - 1])) syncDirectory(dirs[i]);
    }

    /** Writes {@code body} into a new temporary file beside {@code target}, on disk and closed; deletes it on failure. */
    private static Path writeTemporary(Path out, Path dir, Path target, Body body) throws IOException {
        Path tmp = null;
        FileChannel channel = null;
        for (int attempt = 0; channel == null; attempt++) {
            Path candidate = hiddenSibling(dir, TEMPORARY_SUFFIX);
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
                TemporaryFiles.register(tmp);
                OutputStream buffered = new BufferedOutputStream(Channels.newOutputStream(ch), 1 << 16);
                body.write(new NonClosingStream(buffered));
                buffered.flush();
                // Data must be on disk before the rename makes it visible, or a crash could leave
                // an empty or partial file under the final name.
                ch.force(true);
            }
            keepPermissions(target, tmp);
            return tmp;
        } catch (Throwable t) {
            deleteQuietly(tmp, t);
            throw t;
        }
    }

    /**
     * Renames every temporary file over its target. Before replacing a target that may need to be
     * restored (every one but the last), its old content is kept under a hidden name, as a hard
     * link where the file system has them (the target stays in place meanwhile), else as a copy.
     */
    private static void commit(Path[] targets, Path[] tmps) throws IOException {
        int n = targets.length;
        Path[] backups = new Path[n];
        boolean[] moved = new boolean[n];
        try {
            for (int i = 0; i < n; i++) {
                if (i < n - 1 && Files.isRegularFile(targets[i])) backups[i] = backup(targets[i]);
                move(tmps[i], targets[i]);
                TemporaryFiles.unregister(tmps[i]);
                moved[i] = true;
            }
        } catch (Throwable t) {
            for (int i = n - 1; i >= 0; i--) {
                if (!moved[i]) continue;
                try {
                    if (backups[i] != null) move(backups[i], targets[i]);
                    else Files.deleteIfExists(targets[i]);
                } catch (IOException | RuntimeException e) {
                    t.addSuppressed(e);
                }
            }
            for (Path b : backups) deleteQuietly(b, t);
            throw t;
        }
        for (Path b : backups) {
            try {
                if (b != null) Files.deleteIfExists(b);
            } catch (IOException e) {
                // Every new file is in place; a leftover hidden copy of an old one is harmless.
            }
        }
    }

    private static Path backup(Path target) throws IOException {
        for (int attempt = 0; ; attempt++) {
            Path b = hiddenSibling(target.getParent(), ".bak");
            try {
                try {
                    return Files.createLink(b, target);
                } catch (UnsupportedOperationException | FileSystemException e) {
                    if (e instanceof FileAlreadyExistsException) throw (FileAlreadyExistsException) e;
                    return Files.copy(target, b, StandardCopyOption.COPY_ATTRIBUTES);
                }
            } catch (FileAlreadyExistsException e) {
                if (attempt >= 20) throw e;
            }
        }
    }

    private static void move(Path from, Path to) throws IOException {
        try {
            Files.move(from, to, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
        } catch (AtomicMoveNotSupportedException e) {
            Files.move(from, to, StandardCopyOption.REPLACE_EXISTING);
        }
    }

    /** A new name in {@code dir}: {@link #TEMPORARY_PREFIX}, 16 random hexadecimal digits, {@code ext}; short whatever the target's name. */
    private static Path hiddenSibling(Path dir, String ext) {
        return dir.resolve(TEMPORARY_PREFIX + String.format("%016x", ThreadLocalRandom.current().nextLong()) + ext);
    }

    private static void deleteQuietly(Path p, Throwable into) {
        if (p == null) return;
        try {
            Files.deleteIfExists(p);
            TemporaryFiles.unregister(p);
        } catch (IOException e) {
            into.addSuppressed(e);
        }
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
        checkNameLength(out, target);
        return dir;
    }

    /**
     * Refuses a name the file system will not take (longer than its limit, 255 bytes on most),
     * asking the system itself with a look-up of the name, which creates nothing: the temporary
     * file's name is short, so otherwise only the final rename would find out, after the work.
     */
    private static void checkNameLength(Path out, Path target) throws IOException {
        try {
            Files.readAttributes(target, java.nio.file.attribute.BasicFileAttributes.class, java.nio.file.LinkOption.NOFOLLOW_LINKS);
        } catch (java.nio.file.NoSuchFileException e) {
            // The usual case: a new file, and a name the system could look up.
        } catch (FileSystemException e) {
            throw new IOException("cannot write '" + out + "': " + reason(e), e);
        }
    }

    /**
     * {@link #checkTarget} and a trial: a temporary file is created beside {@code out} and deleted
     * again, so an output the system will not let us create (a read-only or pseudo file system,
     * a folder without write permission) is found before the work that would fill it, not after.
     * Leaves no file behind.
     *
     * @throws IOException "cannot write 'OUT': cannot create a file in 'DIR': permission denied"
     */
    public static void checkWritable(Path out) throws IOException {
        Path dir = checkTarget(out);
        Path shown = out.getParent() != null ? out.getParent() : dir;
        for (int attempt = 0; ; attempt++) {
            // A short name, as the atomic write's temporary has: the probe tries the folder, not the name.
            Path probe = hiddenSibling(dir, TEMPORARY_SUFFIX);
            try {
                FileChannel.open(probe, StandardOpenOption.CREATE_NEW, StandardOpenOption.WRITE).close();
                TemporaryFiles.register(probe);
            } catch (FileAlreadyExistsException e) {
                if (attempt < 20) continue;
                throw new IOException("cannot write '" + out + "': cannot create a file in '" + shown + "': " + reason(e), e);
            } catch (IOException | SecurityException e) {
                throw new IOException("cannot write '" + out + "': cannot create a file in '" + shown + "': " + reason(e), e);
            }
            Files.deleteIfExists(probe);
            TemporaryFiles.unregister(probe);
            return;
        }
    }

    /** The system's reason for a failed file operation, as words rather than an exception's name. */
    private static String reason(Exception e) {
        if (e instanceof java.nio.file.AccessDeniedException) return "permission denied";
        if (e instanceof java.nio.file.NoSuchFileException) return "the file system does not accept new files there";
        if (e instanceof FileSystemException f && f.getReason() != null) return f.getReason();
        String m = e.getMessage();
        return m == null || m.isBlank() ? e.getClass().getSimpleName() : m;
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
