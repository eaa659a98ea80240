package lt.spindulys.adaptive;

import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.LongAdder;
import lt.spindulys.limits.HeapBudget;

/**
 * Counters of a {@link PatchCache} or of one of its tables: patches built, hits, misses, evictions, current and
 * peak bytes, pinned patches, and a histogram of the subdivision levels of the patches built (recorded by the
 * caller with {@link #recordLevel}). Thread-safe: every render thread updates them at once, so the counts are
 * {@link LongAdder}s and the byte counts atomics; a reading taken while threads run is a close, not an exact,
 * snapshot.
 */
public final class Stats {
    /** Levels 0 to this (inclusive) can be recorded. */
    public static final int MAX_LEVEL = 31;

    final LongAdder built = new LongAdder();
    final LongAdder hits = new LongAdder();
    final LongAdder misses = new LongAdder();
    final LongAdder evictions = new LongAdder();
    final LongAdder raced = new LongAdder();
    final LongAdder uncached = new LongAdder();
    final AtomicLong bytes = new AtomicLong();
    final AtomicLong peakBytes = new AtomicLong();
    final AtomicLong pinnedBytes = new AtomicLong();
    final AtomicLong pinned = new AtomicLong();
    private final AtomicLongArray levels = new AtomicLongArray(MAX_LEVEL + 1);

    Stats() {}

    /** Patches made by a {@link PatchSource} (a race that builds one face twice counts two). */
    public long built() { return built.sum(); }

    /**
     * Requests answered without building: from a thread's recent patches, a shared slot or a pinned patch. Each
     * thread adds its hits in batches; they are all here once every thread has called {@link RecentPatches#flush}.
     */
    public long hits() { return hits.sum(); }

    /** Requests that had to build (equal to {@link #built()}). */
    public long misses() { return misses.sum(); }

    /** Patches dropped to make room (under LAST_TWO: older entries a thread replaced). */
    public long evictions() { return evictions.sum(); }

    /** Builds lost to another thread that built the same face at the same time and inserted it first. */
    public long raced() { return raced.sum(); }

    /** Patches returned but not kept because they alone were larger than the room the budget leaves. */
    public long uncached() { return uncached.sum(); }

    /**
     * Bytes of the cached (not pinned) patches now; under LAST_TWO, of the patches the threads' recent entries
     * hold.
     */
    public long currentBytes() { return bytes.get(); }

    /** The most {@link #currentBytes()} has been. */
    public long peakBytes() { return peakBytes.get(); }

    /** Bytes of the pinned patches, which are never evicted and are reported apart from the cached ones. */
    public long pinnedBytes() { return pinnedBytes.get(); }

    /** Number of pinned patches. */
    public long pinnedPatches() { return pinned.get(); }

    /** Number of built patches recorded at {@code level}. */
    public long level(int level) {
        checkLevel(level);
        return levels.get(level);
    }

    /** Records that a patch was built at subdivision {@code level} (0 to {@link #MAX_LEVEL}). */
    public void recordLevel(int level) {
        checkLevel(level);
        levels.incrementAndGet(level);
    }

    private static void checkLevel(int level) {
        if (level < 0 || level > MAX_LEVEL) {
            throw new IllegalArgumentException("subdivision level " + level + " is outside 0.." + MAX_LEVEL);
        }
    }

    /** Adds {@code bytes} (may be negative) to the current bytes and raises the peak to match. */
    void addBytes(long delta) {
        long now = bytes.addAndGet(delta);
        if (delta > 0) peakBytes.accumulateAndGet(now, Math::max);
    }

    /** Adds the other's counts and histogram to these (the byte figures are not summed: they are the caller's). */
    void addCounts(Stats other) {
        built.add(other.built.sum());
        hits.add(other.hits.sum());
        misses.add(other.misses.sum());
        evictions.add(other.evictions.sum());
        raced.add(other.raced.sum());
        uncached.add(other.uncached.sum());
        pinned.addAndGet(other.pinned.get());
        for (int i = 0; i <= MAX_LEVEL; i++) levels.addAndGet(i, other.levels.get(i));
    }

    /**
     * One line for {@code --stats}: "patches 1234 built, 5678 hits, 1234 misses, 12 evictions, peak 61.2 MiB;
     * levels 3:12 4:400 5:822", with races, patches too large to keep and pinned patches added only when there are
     * any.
     */
    public String summary() {
        StringBuilder s = new StringBuilder(120);
        s.append("patches ").append(built()).append(" built, ").append(hits()).append(" hits, ")
                .append(misses()).append(" misses, ").append(evictions()).append(" evictions");
        long r = raced();
        if (r != 0) s.append(", ").append(r).append(" raced");
        long u = uncached();
        if (u != 0) s.append(", ").append(u).append(" too large to keep");
        s.append(", peak ").append(HeapBudget.format(peakBytes()));
        long p = pinnedPatches();
        if (p != 0) s.append(", ").append(p).append(" pinned (").append(HeapBudget.format(pinnedBytes())).append(')');
        s.append("; levels");
        int shown = 0;
        for (int i = 0; i <= MAX_LEVEL; i++) {
            long n = levels.get(i);
            if (n != 0) {
                s.append(' ').append(i).append(':').append(n);
                shown++;
            }
        }
        if (shown == 0) s.append(" none");
        return s.toString();
    }

    @Override
    public String toString() { return summary(); }
}
