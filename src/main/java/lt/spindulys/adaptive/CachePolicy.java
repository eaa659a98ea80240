package lt.spindulys.adaptive;

/** How a {@link PatchCache} keeps patches between rays. */
public enum CachePolicy {
    /**
     * One store shared by all threads and tables, bounded in bytes, evicting what has not been used recently
     * (a CLOCK approximation of least recently used: a reference bit per slot, set on a hit, cleared by the hand).
     */
    LRU,
    /**
     * The thesis's policy (section 6.2): each thread keeps the last two patches it used, nothing is shared, and a
     * miss replaces the older of the two. The budget is not used (only pinned patches are shared).
     */
    LAST_TWO
}
