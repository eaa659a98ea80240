package lt.spindulys.adaptive;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.Arrays;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReferenceArray;
import lt.spindulys.limits.HeapBudget;

/**
 * One scene's tessellation cache for lazy subdivision, shared by all render threads and all adaptive surfaces of
 * the scene: a refined patch per coarse face, built by a {@link PatchSource} when a ray first reaches the face and
 * kept within a budget in bytes (in the spirit of Embree's lazy tessellation cache and Benthin et al., HPG 2015).
 *
 * <p>Each tessellation gets a {@link Table} of one slot per coarse face (an instanced surface shares its table, so
 * one entry serves every instance). Under {@link CachePolicy#LRU}:
 * <ul>
 * <li>A hit takes no lock and writes no shared counter: it is answered by the thread's last two built patches
 *     ({@link RecentPatches}) or by the slot (an {@link AtomicReferenceArray}), sets the slot's reference bit
 *     (written only when clear, so a hot slot's cache line stays shared between cores), and is counted in the
 *     thread's {@link RecentPatches}, which adds its hits to the stats in batches.
 * <li>A miss builds outside any lock. Two threads may build the same face at once; the first to install it wins,
 *     the other drops its copy, counts a race and returns the winner's (equal, since sources are pure).
 * <li>Before installing, a builder reserves the patch's bytes with a compare-and-set that succeeds only within
 *     the room the budget leaves, so the cached bytes never exceed it. When there is no room, one thread at a
 *     time (a try-lock: the others yield and retry) moves a CLOCK hand over the occupied slots of all tables,
 *     clearing reference bits and evicting slots whose bit was already clear, until the patch fits with a little
 *     to spare. Nothing stops the other threads: a reader still holding an evicted patch keeps it alive through
 *     the garbage collector, so the heap used is about the budget plus the pinned bytes plus, per thread, its
 *     two recent patches and the one it is building.
 * <li>A patch larger than the room the budget leaves on its own is returned but not kept (counted as "too large
 *     to keep"); so is one for which no room could be found because all the cached bytes are still being
 *     installed by other threads.
 * </ul>
 * Under {@link CachePolicy#LAST_TWO} nothing is shared: a patch comes from the thread's {@link RecentPatches} or
 * is built, and replaces the older of the thread's two. Pinned patches ({@link #pin}) are shared under both
 * policies and never evicted.
 *
 * <p>Which patch a ray sees never depends on the budget, the policy or the thread count, because every patch of a
 * face is equal; that is the caller's side of the contract ({@link PatchSource} must be pure).
 */
public final class PatchCache {
    // Reference bits, one byte per slot: read and written with opaque access (atomic, no ordering needed).
    private static final VarHandle REF = MethodHandles.arrayElementVarHandle(byte[].class);
    // Bitmaps of slots (occupied, pinned), 64 to a long, changed with atomic bitwise operations.
    private static final VarHandle BITS = MethodHandles.arrayElementVarHandle(long[].class);

    /** How many more tries at finding room after an eviction pass, before a patch is returned without keeping it. */
    private static final int EVICTION_TRIES = 4;

    private final long budget;
    private final CachePolicy policy;
    private final boolean lru;
    /** Cache-wide bytes: cached (reserved before installing), their peak, and pinned. Counts live in the tables. */
    private final Stats totals = new Stats();
    /** Every table, in creation order; the CLOCK hand sweeps them all. Replaced (never changed) when one is added. */
    private volatile Table[] tables = new Table[0];
    /** The eviction lock: held by the one thread moving the hand, or pinning. Not re-entrant. */
    private final AtomicBoolean evicting = new AtomicBoolean();
    // The CLOCK hand, guarded by `evicting`: a table index and a face in it.
    private int handTable;
    private long handFace;

    /**
     * An empty cache.
     *
     * @param budgetBytes the most bytes the cached (not pinned) patches may take; 0 keeps nothing but pins
     * @param policy      how patches are kept between rays
     */
    public PatchCache(long budgetBytes, CachePolicy policy) {
        if (budgetBytes < 0) throw new IllegalArgumentException("the tessellation cache's budget is negative: " + budgetBytes + " bytes");
        if (policy == null) throw new IllegalArgumentException("no tessellation cache policy given");
        this.budget = budgetBytes;
        this.policy = policy;
        this.lru = policy == CachePolicy.LRU;
    }

    /** The budget in bytes given at construction. */
    public long budget() { return budget; }

    /** The policy given at construction. */
    public CachePolicy policy() { return policy; }

    /**
     * A table of {@code faces} slots for one tessellation (shared by every instance of a surface), with its own
     * stats. Its few bytes per face are checked against the heap first.
     *
     * @param name what the table is for, in messages and stats ("object 3 'torus'")
     */
    public Table table(int faces, String name) {
        if (faces < 0) throw new IllegalArgumentException("a tessellation cache table of " + faces + " faces");
        long words = (faces + 63L) >>> 6;
        // Slots (a reference each, 8 bytes at worst), the pinned bits, and under LRU a reference byte and an
        // occupied bit per slot.
        long bytes = HeapBudget.sum(HeapBudget.product(faces, 8), HeapBudget.product(words, 8),
                lru ? HeapBudget.sum(faces, HeapBudget.product(words, 8)) : 0, 256);
        HeapBudget.require(bytes, "the tessellation cache's table of " + faces + " faces for " + name);
        Table t = new Table(faces, String.valueOf(name), (int) words);
        synchronized (this) {
            Table[] grown = Arrays.copyOf(tables, tables.length + 1);
            grown[grown.length - 1] = t;
            tables = grown;
        }
        return t;
    }

    /**
     * The patch of {@code face}: from the thread's recent patches, a shared slot or a pin, else built by
     * {@code source} (then inserted under LRU, evicting as needed, or made the thread's newest under LAST_TWO).
     *
     * @param table  a table of this cache
     * @param recent the calling thread's own scratch: the whole cache under LAST_TWO, a tiny front cache under LRU
     * @return a patch equal to {@code source.build(face)}; a patch larger than the budget is returned but not kept
     */
    public CachedPatch get(Table table, int face, PatchSource source, RecentPatches recent) {
        if (table.cache() != this) throw new IllegalArgumentException("the table " + table.name + " belongs to another tessellation cache");
        if (recent.aTable == table && recent.aFace == face) {
            table.hit(face, recent);
            return recent.aPatch;
        }
        if (recent.bTable == table && recent.bFace == face) {
            recent.promoteB();
            table.hit(face, recent);
            return recent.aPatch;
        }
        if (face < 0 || face >= table.faces) {
            throw new IllegalArgumentException("face " + face + " is outside the " + table.faces + " faces of " + table.name);
        }
        CachedPatch p = table.slots.get(face);
        if (p != null) {
            // Not made the thread's newest: the slot is as quick to ask again, and under LAST_TWO the recent
            // entries are the thread's own patches (their bytes counted as held), which a pinned one is not.
            table.hit(face, recent);
            return p;
        }
        return miss(table, face, source, recent);
    }

    private CachedPatch miss(Table t, int face, PatchSource source, RecentPatches recent) {
        recent.flush();
        if (!lru) return build(t, face, source, recent);
        java.util.concurrent.CompletableFuture<CachedPatch> mine = new java.util.concurrent.CompletableFuture<>();
        java.util.concurrent.CompletableFuture<CachedPatch> other = t.building.putIfAbsent(face, mine);
        if (other != null) {
            CachedPatch p;
            try {
                p = other.join();
            } catch (java.util.concurrent.CompletionException e) {
                // The builder's own failure (it reports it too); this thread builds for itself.
                return build(t, face, source, recent);
            }
            t.hit(face, recent);
            return p;
        }
        try {
            // The build that registered just before may have finished and installed it.
            CachedPatch there = t.slots.get(face);
            if (there != null) t.hit(face, recent);
            CachedPatch p = there != null ? there : build(t, face, source, recent);
            mine.complete(p);
            return p;
        } catch (RuntimeException | Error e) {
            mine.completeExceptionally(e);
            throw e;
        } finally {
            t.building.remove(face, mine);
        }
    }

    /** Builds the patch of {@code face} and keeps it as the policy says. */
    private CachedPatch build(Table t, int face, PatchSource source, RecentPatches recent) {
        CachedPatch p = source.build(face);
        if (p == null) throw new IllegalArgumentException("the patch source of " + t.name + " gave no patch for face " + face);
        long b = p.bytes();
        if (b < 0) throw new IllegalArgumentException("the patch of face " + face + " of " + t.name + " reports " + b + " bytes");
        t.stats.built.increment();
        t.stats.misses.increment();
        if (!lru) {
            // Held until the thread replaces it: counted so that peak bytes shows what LAST_TWO really keeps
            // (after the push, which lets go of the older one).
            recent.push(t, face, p);
            t.stats.addBytes(b);
            totals.addBytes(b);
            return p;
        }
        CachedPatch kept = insert(t, face, p, b);
        recent.push(t, face, kept);
        return kept;
    }

    /** Installs a built patch in its slot if there is room; returns the patch the slot holds, or {@code p}. */
    private CachedPatch insert(Table t, int face, CachedPatch p, long b) {
        CachedPatch there = t.slots.get(face);
        if (there != null) {
            // Another thread built and installed the same face while this one was building.
            t.stats.raced.increment();
            return there;
        }
        if (!reserve(b)) {
            t.stats.uncached.increment();
            return p;
        }
        if (t.slots.compareAndSet(face, null, p)) {
            // The slot is published first, then made visible to the hand; the hand never sees an empty occupied slot
            // it must account for, and a reservation not yet visible simply cannot be evicted for a moment.
            REF.setOpaque(t.referenced, face, (byte) 1);
            BITS.getAndBitwiseOr(t.occupied, face >>> 6, 1L << face);
            t.stats.addBytes(b);
            return p;
        }
        totals.bytes.addAndGet(-b);
        t.stats.raced.increment();
        there = t.slots.get(face);
        return there != null ? there : p;
    }

    /** Reserves {@code b} bytes within the budget's room, evicting if this thread gets the lock; false if no room. */
    private boolean reserve(long b) {
        for (;;) {
            long room = budget - totals.pinnedBytes.get();
            if (b > room) return false;
            if (addWithin(b, room)) return true;
            if (evicting.compareAndSet(false, true)) {
                try {
                    return reserveEvicting(b);
                } finally {
                    evicting.set(false);
                }
            }
            // Another thread is evicting and will make room: let it run (the machine may have fewer cores than threads).
            Thread.yield();
        }
    }

    /** {@link #reserve} with the eviction lock held. */
    private boolean reserveEvicting(long b) {
        long room = budget - totals.pinnedBytes.get();
        // Free a thirty-second of the room more than needed, so the next insertions find room without the lock.
        evictDownTo(Math.max(0, room - b - (room >>> 5)));
        for (int tries = 0; tries <= EVICTION_TRIES; tries++) {
            room = budget - totals.pinnedBytes.get();
            if (b > room) return false;
            if (addWithin(b, room)) return true;
            if (!evictDownTo(room - b)) return false;
        }
        return false;
    }

    /** Adds {@code b} to the cached bytes if they stay within {@code room} (retrying lost races); false if not. */
    private boolean addWithin(long b, long room) {
        for (;;) {
            long now = totals.bytes.get();
            if (now + b > room) return false;
            if (totals.bytes.compareAndSet(now, now + b)) {
                totals.peakBytes.accumulateAndGet(now + b, Math::max);
                return true;
            }
        }
    }

    /**
     * Moves the CLOCK hand until the cached bytes are at most {@code target}; false if it could not (everything
     * left is pinned or still being installed). Two turns of the hand give every entry a second chance; a third
     * evicts regardless of reference bits, so the sweep always ends. With the eviction lock held.
     */
    private boolean evictDownTo(long target) {
        if (!lru) return totals.bytes.get() <= target;
        Table[] ts = tables;
        long words = 0;
        for (Table t : ts) words += t.words + 1;
        long steps = 0;
        while (totals.bytes.get() > target) {
            if (ts.length == 0 || steps > 3 * words) return false;
            boolean force = steps > 2 * words;
            if (handTable >= ts.length) handTable = 0;
            Table t = ts[handTable];
            int w = (int) (handFace >>> 6);
            steps++;
            if (w >= t.words) {
                handTable = handTable + 1 == ts.length ? 0 : handTable + 1;
                handFace = 0;
                continue;
            }
            long bits = (long) BITS.getVolatile(t.occupied, w) & (-1L << (handFace & 63));
            while (bits != 0) {
                int face = (w << 6) | Long.numberOfTrailingZeros(bits);
                bits &= bits - 1;
                handFace = face + 1L;
                if (visit(t, face, force) && totals.bytes.get() <= target) return true;
            }
            handFace = (w + 1L) << 6;
        }
        return true;
    }

    /** The hand at one occupied slot: a second chance if referenced, else eviction; true if it evicted. */
    private boolean visit(Table t, int face, boolean force) {
        int w = face >>> 6;
        long m = 1L << face;
        if (((long) BITS.getVolatile(t.pinnedBits, w) & m) != 0) {
            // Pinned after it was installed: not the hand's.
            BITS.getAndBitwiseAnd(t.occupied, w, ~m);
            return false;
        }
        if (!force && (byte) REF.getOpaque(t.referenced, face) != 0) {
            REF.setOpaque(t.referenced, face, (byte) 0);
            return false;
        }
        // Cleared before the slot is emptied, so a new patch installed in the emptied slot keeps its bit.
        BITS.getAndBitwiseAnd(t.occupied, w, ~m);
        CachedPatch p = t.slots.getAndSet(face, null);
        if (p == null) return false;
        long b = p.bytes();
        totals.bytes.addAndGet(-b);
        t.stats.addBytes(-b);
        t.stats.evictions.increment();
        return true;
    }

    /**
     * Pins {@code patch} as the patch of {@code face}: never evicted, shared under both policies (the combined
     * method's eager part). Its bytes count against the budget, so cached patches are evicted to make room; pins
     * beyond the budget are kept all the same and leave no room for caching. Replaces what the slot held.
     */
    public void pin(Table table, int face, CachedPatch patch) {
        if (table.cache() != this) throw new IllegalArgumentException("the table " + table.name + " belongs to another tessellation cache");
        if (face < 0 || face >= table.faces) {
            throw new IllegalArgumentException("face " + face + " is outside the " + table.faces + " faces of " + table.name);
        }
        if (patch == null) throw new IllegalArgumentException("no patch to pin for face " + face + " of " + table.name);
        long b = patch.bytes();
        if (b < 0) throw new IllegalArgumentException("the patch of face " + face + " of " + table.name + " reports " + b + " bytes");
        while (!evicting.compareAndSet(false, true)) Thread.yield();
        try {
            int w = face >>> 6;
            long m = 1L << face;
            boolean wasPinned = ((long) BITS.getAndBitwiseOr(table.pinnedBits, w, m) & m) != 0;
            CachedPatch old = table.slots.getAndSet(face, patch);
            if (lru) BITS.getAndBitwiseAnd(table.occupied, w, ~m);
            if (old != null) {
                long ob = old.bytes();
                if (wasPinned) {
                    totals.pinnedBytes.addAndGet(-ob);
                    table.stats.pinnedBytes.addAndGet(-ob);
                    table.stats.pinned.decrementAndGet();
                } else {
                    totals.bytes.addAndGet(-ob);
                    table.stats.addBytes(-ob);
                }
            }
            totals.pinnedBytes.addAndGet(b);
            table.stats.pinnedBytes.addAndGet(b);
            table.stats.pinned.incrementAndGet();
            evictDownTo(Math.max(0, budget - totals.pinnedBytes.get()));
        } finally {
            evicting.set(false);
        }
    }

    /**
     * The whole cache's stats, a snapshot: the tables' counts summed, and the cache-wide current and peak bytes
     * (under LRU the cached patches; under LAST_TWO what the threads' recent entries hold) and pinned bytes.
     */
    public Stats stats() {
        Stats s = new Stats();
        for (Table t : tables) s.addCounts(t.stats);
        s.bytes.set(totals.bytes.get());
        s.peakBytes.set(totals.peakBytes.get());
        s.pinnedBytes.set(totals.pinnedBytes.get());
        return s;
    }

    /** The slots of one tessellation in a {@link PatchCache}, with their own {@link Stats}. */
    public final class Table {
        final int faces;
        final String name;
        final int words;
        final AtomicReferenceArray<CachedPatch> slots;
        /** Slots holding a pinned patch. */
        final long[] pinnedBits;
        /** LRU only: the reference bit of each slot (a byte each), and which slots the hand may evict. */
        final byte[] referenced;
        final long[] occupied;
        final Stats stats = new Stats();
        /**
         * LRU only: the builds under way, by face, so that a thread missing a face another thread is
         * building waits for that build instead of repeating it (a deep patch takes milliseconds,
         * and render threads working on neighbouring tiles often reach the same face together).
         */
        final java.util.concurrent.ConcurrentHashMap<Integer, java.util.concurrent.CompletableFuture<CachedPatch>> building =
                new java.util.concurrent.ConcurrentHashMap<>();

        Table(int faces, String name, int words) {
            this.faces = faces;
            this.name = name;
            this.words = words;
            this.slots = new AtomicReferenceArray<>(faces);
            this.pinnedBits = new long[words];
            this.referenced = lru ? new byte[faces] : null;
            this.occupied = lru ? new long[words] : null;
        }

        PatchCache cache() { return PatchCache.this; }

        /** This table's stats (bytes are this table's share of the cache's). */
        public Stats stats() { return stats; }

        /** The number of faces (slots). */
        public int faces() { return faces; }

        /** The name given at creation. */
        public String name() { return name; }

        void hit(int face, RecentPatches recent) {
            recent.hit(this);
            if (lru && (byte) REF.getOpaque(referenced, face) == 0) REF.setOpaque(referenced, face, (byte) 1);
        }

        /** A thread's recent entry of this table was dropped: under LAST_TWO that is an eviction from the cache. */
        void dropped(CachedPatch p) {
            if (lru) return;
            long b = p.bytes();
            stats.addBytes(-b);
            totals.addBytes(-b);
            stats.evictions.increment();
        }

        @Override
        public String toString() { return name + ": " + stats.summary(); }
    }
}
