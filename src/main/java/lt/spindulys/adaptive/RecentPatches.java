package lt.spindulys.adaptive;

/**
 * One thread's last two patches, each with its table and face: the whole cache under
 * {@link CachePolicy#LAST_TWO}, and a tiny front cache under {@link CachePolicy#LRU} holding the last two patches
 * this thread built, so a run of rays over a patch the shared cache could not keep (or has evicted) does not
 * rebuild it. One per render thread (held in its trace context); never shared, so its fields are plain.
 *
 * <p>It also counts this thread's hits and adds them to the table's {@link Stats} in batches (on a miss, on a
 * change of table, every {@value #HIT_BATCH} hits, and on {@link #flush}/{@link #clear}): a shared counter on every
 * hit cost more than the rest of the hit. A thread that is done calls {@link #flush} so the counts are exact.
 */
public final class RecentPatches {
    /** Hits counted here before they are added to the shared stats. */
    static final int HIT_BATCH = 1024;

    // The newest entry (a*) and the older one (b*); a null table marks an empty entry.
    PatchCache.Table aTable;
    int aFace;
    CachedPatch aPatch;
    PatchCache.Table bTable;
    int bFace;
    CachedPatch bPatch;

    // Hits of hitTable not yet added to its stats.
    private PatchCache.Table hitTable;
    private int hits;

    /** Two empty entries. */
    public RecentPatches() {}

    /** Counts a hit of {@code table}. */
    void hit(PatchCache.Table table) {
        if (table == hitTable) {
            if (++hits >= HIT_BATCH) flush();
        } else {
            flush();
            hitTable = table;
            hits = 1;
        }
    }

    /** Adds the hits counted here to the shared stats; call when the thread is done with the cache. */
    public void flush() {
        if (hits != 0) {
            hitTable.stats.hits.add(hits);
            hits = 0;
        }
    }

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

    /** Forgets both entries (under LAST_TWO, their patches leave the cache) after a {@link #flush}. */
    public void clear() {
        flush();
        hitTable = null;
        if (bTable != null) bTable.dropped(bPatch);
        if (aTable != null) aTable.dropped(aPatch);
        aTable = bTable = null;
        aPatch = bPatch = null;
    }
}
