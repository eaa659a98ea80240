package lt.spindulys.adaptive;

/**
 * Makes the patch of one face of a tessellation. Pure: the same face always gives an equal patch, which is what
 * lets the cache drop and rebuild patches, and two threads race to build the same one, without changing an image.
 * Called outside any lock, possibly by several threads at once.
 */
@FunctionalInterface
public interface PatchSource {
    /** The patch of {@code face}; never null. */
    CachedPatch build(int face);
}
