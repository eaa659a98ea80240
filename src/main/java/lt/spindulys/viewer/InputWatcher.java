package lt.spindulys.viewer;

import java.io.IOException;
import java.nio.file.ClosedWatchServiceException;
import java.nio.file.FileSystems;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardWatchEventKinds;
import java.nio.file.WatchEvent;
import java.nio.file.WatchKey;
import java.nio.file.WatchService;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import lt.spindulys.files.AtomicFile;

/**
 * Watches the files a scene reads (the scene file, meshes, material libraries, textures, maps)
 * and says once when some of them changed: a burst of events (an editor writing a temporary file
 * and renaming it, a program writing a texture in pieces) is told as one change, after the
 * folders have been quiet for a while. Folders are watched rather than files, so a file replaced
 * by a rename, deleted or created is seen too; a link is watched where it is and where it leads.
 * The temporary files of atomic writes ({@link AtomicFile#isTemporaryName}) are not changes.
 *
 * <p>With {@link #watch}'s {@code anyFile}, any change in the watched folders counts: while a
 * scene does not read, the file it is missing may be the one that appears. Runs a thread of its
 * own until {@link #close}.
 */
final class InputWatcher implements AutoCloseable {
    private final WatchService service;
    private final Runnable changed;
    private final long quietMillis;
    private final Thread thread;
    /** The watched file names of each folder, and the folders' keys; guarded by this. */
    private final Map<Path, Set<Path>> names = new HashMap<>();
    private final Map<Path, WatchKey> keys = new HashMap<>();
    private boolean anyFile;

    /**
     * Starts watching nothing yet.
     *
     * @param changed     called (on the watcher's thread) once per burst of changes
     * @param quietMillis how long the folders must be quiet before a burst is told
     * @throws IOException if the file system cannot watch
     */
    InputWatcher(Runnable changed, long quietMillis) throws IOException {
        this.changed = changed;
        this.quietMillis = quietMillis;
        service = FileSystems.getDefault().newWatchService();
        thread = new Thread(this::loop, "spindulys-preview-watcher");
        thread.setDaemon(true);
        thread.start();
    }

    /**
     * Watches these files (instead of those watched before).
     *
     * @param files   the files; missing folders are skipped
     * @param anyFile true to count a change of any file in their folders
     */
    synchronized void watch(Collection<Path> files, boolean anyFile) {
        this.anyFile = anyFile;
        Map<Path, Set<Path>> wanted = new HashMap<>();
        for (Path f : files) {
            add(wanted, f.toAbsolutePath().normalize());
            try {
                if (Files.isSymbolicLink(f)) add(wanted, f.toRealPath());
            } catch (IOException e) {
                // A broken link: its own folder is watched, where a fix would show.
            }
        }
        for (Map.Entry<Path, WatchKey> e : Map.copyOf(keys).entrySet()) {
            if (!wanted.containsKey(e.getKey())) {
                e.getValue().cancel();
                keys.remove(e.getKey());
            }
        }
        for (Path dir : wanted.keySet()) {
            if (keys.containsKey(dir) || !Files.isDirectory(dir)) continue;
            try {
                keys.put(dir, dir.register(service, StandardWatchEventKinds.ENTRY_CREATE, StandardWatchEventKinds.ENTRY_MODIFY,
                        StandardWatchEventKinds.ENTRY_DELETE));
            } catch (IOException | ClosedWatchServiceException e) {
                // An unwatchable folder (gone meanwhile, no permission): its files are simply not watched.
            }
        }
        names.clear();
        names.putAll(wanted);
    }

    private static void add(Map<Path, Set<Path>> to, Path file) {
        Path dir = file.getParent();
        if (dir != null && file.getFileName() != null) to.computeIfAbsent(dir, d -> new HashSet<>()).add(file.getFileName());
    }

    private void loop() {
        try {
            while (true) {
                if (!matters(service.take())) continue;
                // A burst: told once the folders have been quiet for a while.
                for (WatchKey k; (k = service.poll(quietMillis, TimeUnit.MILLISECONDS)) != null; ) matters(k);
                changed.run();
            }
        } catch (InterruptedException | ClosedWatchServiceException e) {
            // Closed.
        }
    }

    /** Takes a key's events and resets it; true if one of them is a watched file's (or lost events). */
    private synchronized boolean matters(WatchKey key) {
        boolean any = false;
        Path dir = (Path) key.watchable();
        for (WatchEvent<?> e : key.pollEvents()) {
            if (e.kind() == StandardWatchEventKinds.OVERFLOW) any = true;
            else if (e.context() instanceof Path name) any |= counts(dir, name);
        }
        key.reset();
        return any;
    }

    /**
     * Tells whether a change of {@code file} counts as a change of the scene's files, as things are watched now.
     *
     * @param file a file in a watched folder, or anywhere
     * @return true for a watched file, or any file of a watched folder while {@code anyFile}; never
     *         for a temporary file of an atomic write
     */
    synchronized boolean counts(Path file) {
        Path f = file.toAbsolutePath().normalize();
        return f.getParent() != null && f.getFileName() != null && counts(f.getParent(), f.getFileName());
    }

    private boolean counts(Path dir, Path name) {
        Set<Path> watched = names.get(dir);
        if (watched == null || AtomicFile.isTemporaryName(name.toString())) return false;
        return anyFile || watched.contains(name);
    }

    @Override
    public void close() {
        try {
            service.close();
        } catch (IOException e) {
            // Nothing is left to watch either way.
        }
        thread.interrupt();
    }
}
