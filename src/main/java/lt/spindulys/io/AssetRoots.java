package lt.spindulys.io;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.List;
import java.util.stream.Collectors;

import lt.spindulys.files.FileNames;
import lt.spindulys.limits.MessageText;

/**
 * The folders a scene may read from, for a render farm that renders scenes it did not write: when
 * set, every file a scene reads (the scene file itself, meshes, subdivision meshes, unwraps,
 * material libraries and their texture maps, texture and environment images) must lie inside one
 * of them once symbolic links are resolved (a link inside a folder that points outside it is
 * outside). A file outside is refused before it is opened, with the place in the scene that named
 * it; its content is never read.
 *
 * <p>{@link #ANY} confines nothing (the default). Confinements combine with {@link #and}: a file
 * must then be inside both, so a farm's {@link #ENVIRONMENT_VARIABLE} cannot be widened by an
 * option given after it.
 */
public final class AssetRoots {
    /**
     * The environment variable the command line reads the folders from ({@value}), separated by
     * the platform's path separator (':' on Unix, ';' on Windows); it applies together with any
     * {@code --assets-root} given.
     */
    public static final String ENVIRONMENT_VARIABLE = "SPINDULYS_ASSETS_ROOT";

    /** No confinement: every file a scene names may be read. */
    public static final AssetRoots ANY = new AssetRoots(List.of());

    /** Each confinement's folders (real paths); a file must be inside one folder of every one. */
    private final List<List<Path>> layers;

    private AssetRoots(List<List<Path>> layers) {
        this.layers = layers;
    }

    /**
     * A confinement to these folders.
     *
     * @param folders existing folders; each is taken by its real path (links resolved)
     * @return the confinement ({@link #ANY} for no folders)
     * @throws IllegalArgumentException naming a folder that does not exist or is not a folder
     */
    public static AssetRoots of(Collection<Path> folders) {
        if (folders.isEmpty()) return ANY;
        List<Path> real = new ArrayList<>();
        for (Path f : folders) {
            if (!Files.isDirectory(f)) {
                throw new IllegalArgumentException("asset folder '" + MessageText.cut(f.toString(), 200) + "' "
                        + (Files.exists(f) ? "is not a folder" : "does not exist"));
            }
            try {
                real.add(f.toRealPath());
            } catch (IOException | SecurityException e) {
                throw new IllegalArgumentException("asset folder '" + MessageText.cut(f.toString(), 200) + "' cannot be resolved: " + e.getMessage(), e);
            }
        }
        return new AssetRoots(List.of(List.copyOf(real)));
    }

    /**
     * The confinement a list of folders separated by the platform's path separator gives, as
     * {@link #ENVIRONMENT_VARIABLE} holds it; empty entries are skipped.
     *
     * @param list such as "/farm/job1:/farm/shared"; null or blank: {@link #ANY}
     * @return the confinement
     * @throws IllegalArgumentException naming a folder that does not exist or is not a folder
     */
    public static AssetRoots parse(String list) {
        if (list == null || list.isBlank()) return ANY;
        List<Path> folders = new ArrayList<>();
        for (String s : list.split(java.util.regex.Pattern.quote(File.pathSeparator))) {
            if (s.isEmpty()) continue;
            try {
                folders.add(Path.of(s));
            } catch (InvalidPathException e) {
                throw new IllegalArgumentException("asset folder '" + MessageText.cut(s, 200) + "' is not a valid path: " + e.getReason(), e);
            }
        }
        return of(folders);
    }

    /**
     * This confinement and {@code other} together: a file must be allowed by both.
     *
     * @param other another confinement
     * @return the combination
     */
    public AssetRoots and(AssetRoots other) {
        if (other.layers.isEmpty()) return this;
        if (layers.isEmpty()) return other;
        List<List<Path>> all = new ArrayList<>(layers);
        all.addAll(other.layers);
        return new AssetRoots(List.copyOf(all));
    }

    /**
     * Tells whether any folder confines reads.
     *
     * @return false for {@link #ANY}
     */
    public boolean confines() { return !layers.isEmpty(); }

    /**
     * Tells whether a file may be read: its real path (links resolved as far as it exists) is
     * inside one folder of every confinement.
     *
     * @param file the file
     * @return true if it may be read
     */
    public boolean allows(Path file) {
        return refusal(file) == null;
    }

    /**
     * Why a file may not be read, as a phrase to follow its name, or null when it may:
     * "is outside the allowed asset folders (/farm/job1)", followed by
     * ": it resolves to /etc/passwd" when links or ".." lead elsewhere than the name says.
     *
     * @param file the file, as it would be opened
     * @return the phrase, or null
     */
    public String refusal(Path file) {
        if (layers.isEmpty()) return null;
        Path real = FileNames.realPath(file);
        for (List<Path> folders : layers) {
            boolean inside = false;
            for (Path f : folders) inside |= real.startsWith(f);
            if (!inside) {
                String shown = folders.stream().map(Path::toString).collect(Collectors.joining(", "));
                String phrase = "is outside the allowed asset folders (" + MessageText.cut(shown, 200) + ")";
                return real.equals(file.toAbsolutePath().normalize()) ? phrase : phrase + ": it resolves to " + MessageText.cut(real.toString(), 200);
            }
        }
        return null;
    }

    /**
     * The folders, each confinement's separated by " and ".
     *
     * @return such as "/farm/job1, /farm/shared"; "any folder" for {@link #ANY}
     */
    @Override
    public String toString() {
        if (layers.isEmpty()) return "any folder";
        return layers.stream().map(l -> l.stream().map(Path::toString).collect(Collectors.joining(", "))).collect(Collectors.joining(" and "));
    }
}
