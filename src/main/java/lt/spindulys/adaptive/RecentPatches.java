package lt.spindulys.adaptive;

/**
 * One thread's last two patches, each with its table and face: the whole cache under
 * {@link CachePolicy#LAST_TWO}, and a tiny front cache under {@link CachePolicy#LRU} that answers a ray hitting
 * the patch it hit last without touching shared memory. One per render thread (held in its trace context); never
 * shared, so its fields are plain.
 */
public final class RecentPatches {
    // The newest entry (a*) and the older one (b*); a null table marks an empty entry.
    PatchCache.Table aTable;
    int aFace;
    CachedPatch aPatch;
    PatchCache.Table bTable;
    int bFace;
    CachedPatch bPatch;

    /** Two empty entries. */
    public RecentPatches() {}

    /** Makes the older entry the newest: swaps the two. */
    void promoteB() {
        PatchCache.Table t = aTable;
        int f = aFace;
        CachedPatch p = aPatch;
        aTable = bTable;
        aFace = bFace;
        aPatch = bPatch;
        bTable = t;
        bFace = f;
        bPatch = p;
    }

    /** Puts a new newest entry; the older entry is dropped and the newest becomes the older. */
    void push(PatchCache.Table table, int face, CachedPatch patch) {
        PatchCache.Table droppedTable = bTable;
        CachedPatch dropped = bPatch;
        bTable = aTable;
        bFace = aFace;
        bPatch = aPatch;
        aTable = table;
        aFace = face;
        aPatch = patch;
        if (droppedTable != null) droppedTable.dropped(dropped);
    }

    /** Forgets both entries (under LAST_TWO, their patches leave the cache). */
    public void clear() {
        if (bTable != null) bTable.dropped(bPatch);
        if (aTable != null) aTable.dropped(aPatch);
        aTable = bTable = null;
        aPatch = bPatch = null;
    }
}
