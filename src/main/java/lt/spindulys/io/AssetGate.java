package lt.spindulys.io;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import lt.spindulys.scene.InputFile;

/**
 * What one parse may read and what it has read: every file a scene names passes here before it
 * is opened, to be refused if it is outside the {@link AssetRoots}, and is recorded once read
 * (once per file) for {@link lt.spindulys.scene.SceneBuilder#inputFiles()}.
 */
final class AssetGate {
    private final AssetRoots roots;
    private final List<InputFile> read = new ArrayList<>();
    private final Set<Path> seen = new HashSet<>();

    AssetGate(AssetRoots roots) {
        this.roots = roots;
    }

    /** Why {@code path} may not be read, as a phrase to follow its name; null when it may. */
    String refusal(Path path) {
        return roots.refusal(path);
    }

    /** Records a file about to be read: {@code what} it is and where it was named ("scene.dat:3:12", or null). */
    void record(Path path, String what, String at) {
        if (seen.add(path.toAbsolutePath().normalize())) read.add(new InputFile(path, what, at));
    }

    /** The files recorded, in order. */
    List<InputFile> read() {
        return read;
    }
}
