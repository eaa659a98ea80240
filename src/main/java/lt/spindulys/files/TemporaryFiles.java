package lt.spindulys.files;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The temporary files {@link AtomicFile} is writing right now, and a JVM shutdown hook that
 * deletes them: a run ended by SIGTERM or SIGINT (a farm manager cancelling a task, Ctrl+C) leaves
 * no {@code .tmp} file beside its outputs. A temporary file is registered as soon as it is
 * created and unregistered once it is renamed into place or deleted. (SIGKILL, a crash or a power
 * cut runs no hook: what they leave, {@code render --skip-existing} cleans up later.)
 *
 * <p>The hook is installed when the first temporary file is registered. Once it has started, a
 * temporary file registered afterwards is deleted at once and its write fails, so none created
 * while the JVM shuts down outlives it.
 */
public final class TemporaryFiles {
    private TemporaryFiles() {}

    private static final Set<Path> LIVE = ConcurrentHashMap.newKeySet();
    private static volatile boolean closing;

    /** Installs the hook on first use (the class is initialised by the first registration). */
    private static final class Hook {
        static {
            Runtime.getRuntime().addShutdownHook(new Thread(TemporaryFiles::deleteAll, "spindulys-temporary-files"));
        }

        static void installed() {}
    }

    /**
     * Records a temporary file just created, to be deleted if the JVM shuts down before it is
     * renamed or deleted.
     *
     * @param tmp the temporary file
     * @throws IOException if the JVM is shutting down: {@code tmp} is then deleted, and the write must stop
     */
    static void register(Path tmp) throws IOException {
        Hook.installed();
        LIVE.add(tmp);
        if (closing) {
            Files.deleteIfExists(tmp);
            LIVE.remove(tmp);
            throw new IOException("the program is shutting down: '" + tmp + "' was not written");
        }
    }

    /**
     * Forgets a temporary file renamed into place or deleted.
     *
     * @param tmp the temporary file; nothing happens if it was not registered
     */
    static void unregister(Path tmp) {
        if (tmp != null) LIVE.remove(tmp);
    }

    /** {@return how many temporary files are being written now} For tests. */
    static int live() { return LIVE.size(); }

    /** The hook: deletes every temporary file being written. A writer may go on writing into a deleted file until the JVM halts; that is harmless. */
    private static void deleteAll() {
        closing = true;
        for (Path p : LIVE) {
            try {
                Files.deleteIfExists(p);
            } catch (IOException | RuntimeException e) {
                // Nothing to report to: the JVM is going down. The file stays for --skip-existing.
            }
        }
    }
}
