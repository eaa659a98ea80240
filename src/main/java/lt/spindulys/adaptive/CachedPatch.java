package lt.spindulys.adaptive;

/**
 * A value kept in a {@link PatchCache}: one coarse face's refined patch. It knows the heap it retains, which the
 * cache counts against its budget; the answer must not change while the patch is cached.
 */
public interface CachedPatch {
    /** The heap this patch retains, in bytes (non-negative), including its arrays. */
    long bytes();
}
