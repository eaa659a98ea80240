package lt.spindulys.adaptive;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.SplittableRandom;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;
import org.junit.jupiter.api.Test;

class PatchCacheTest {

    /** Bytes of the patches in the table's slots that are not pinned: what the cache's count must equal when idle. */
    private static long slotBytes(PatchCache.Table t) {
        long sum = 0;
        for (int f = 0; f < t.faces; f++) {
            CachedPatch p = t.slots.get(f);
            boolean pinned = (t.pinnedBits[f >>> 6] & (1L << f)) != 0;
            if (p != null && !pinned) sum += p.bytes();
        }
        return sum;
    }

    @Test
    void bytesStayWithinTheBudgetUnderRandomAccess() {
        FakePatches source = new FakePatches(2000, 100, 400);
        long budget = 20_000;
        PatchCache cache = new PatchCache(budget, CachePolicy.LRU);
        PatchCache.Table t = cache.table(source.faces, "random");
        RecentPatches recent = new RecentPatches();
        Random random = new Random(16);
        for (int i = 0; i < 200_000; i++) {
            int face = random.nextInt(source.faces);
            assertEquals(source.expected(face), cache.get(t, face, source, recent));
            assertTrue(cache.stats().currentBytes() <= budget, "bytes within the budget after request " + i);
        }
        recent.flush();
        assertEquals(slotBytes(t), cache.stats().currentBytes(), "the count matches the slots");
        assertEquals(t.stats().currentBytes(), cache.stats().currentBytes());
        assertTrue(cache.stats().peakBytes() <= budget);
        assertTrue(cache.stats().peakBytes() > budget * 9 / 10, "the cache fills up: " + cache.stats().peakBytes());
        assertEquals(source.totalBuilds(), t.stats().built());
        assertEquals(t.stats().built(), t.stats().misses());
        assertEquals(200_000, t.stats().hits() + t.stats().misses());
    }

    @Test
    void evictionsAreCounted() {
        FakePatches source = new FakePatches(100, 100, 1);
        PatchCache cache = new PatchCache(1000, CachePolicy.LRU); // ten patches
        PatchCache.Table t = cache.table(source.faces, "sequence");
        RecentPatches recent = new RecentPatches();
        for (int f = 0; f < 30; f++) cache.get(t, f, source, recent);
        Stats s = cache.stats();
        assertEquals(30, s.built());
        assertEquals(30, s.misses());
        assertEquals(0, s.hits());
        long resident = s.currentBytes() / 100;
        assertTrue(resident >= 9 && resident <= 10, "resident " + resident);
        assertEquals(30 - resident, s.evictions());
        assertEquals(s.evictions(), t.stats().evictions());
        assertEquals(1000, s.peakBytes());
    }

    @Test
    void theHandSweepsEveryTable() {
        FakePatches source = new FakePatches(1000, 100, 1);
        PatchCache cache = new PatchCache(2000, CachePolicy.LRU); // twenty patches, shared by both tables
        PatchCache.Table first = cache.table(source.faces, "first");
        PatchCache.Table second = cache.table(source.faces, "second");
        RecentPatches r = new RecentPatches();
        for (int f = 0; f < 20; f++) cache.get(first, f, source, r);
        assertEquals(2000, first.stats().currentBytes());
        for (int f = 0; f < 20; f++) cache.get(second, f, source, r);
        assertEquals(0, first.stats().currentBytes(), "the new table's patches took the old one's room");
        assertEquals(20, first.stats().evictions());
        assertTrue(second.stats().currentBytes() >= 1900, second.stats().summary());
        assertEquals(second.stats().currentBytes(), cache.stats().currentBytes());
        assertEquals(slotBytes(first) + slotBytes(second), cache.stats().currentBytes());
        assertEquals(40, cache.stats().built());
    }

    @Test
    void lruKeepsAHotSetThatLastTwoLoses() {
        for (CachePolicy policy : CachePolicy.values()) {
            FakePatches source = new FakePatches(100_000, 100, 1);
            PatchCache cache = new PatchCache(40 * 100, policy); // room for 40 patches
            PatchCache.Table t = cache.table(source.faces, "hot and cold");
            RecentPatches recent = new RecentPatches();
            int hot = 10;
            int cold = hot;
            long hotRequests = 0;
            long hotBuildsBefore = 0;
            for (int i = 0; i < 50_000; i++) {
                if (i == 1000) {
                    for (int h = 0; h < hot; h++) hotBuildsBefore += source.builds.get(h);
                }
                int h = i % hot;
                cache.get(t, h, source, recent);
                if (i >= 1000) hotRequests++;
                cache.get(t, cold++, source, recent); // every other request a face never seen again
            }
            long hotBuilds = -hotBuildsBefore;
            for (int h = 0; h < hot; h++) hotBuilds += source.builds.get(h);
            if (policy == CachePolicy.LRU) {
                assertEquals(0, hotBuilds, "LRU keeps the hot faces among the cold stream");
                assertTrue(t.stats().evictions() > 40_000, "the cold ones were evicted: " + t.stats().summary());
            } else {
                assertEquals(hotRequests, hotBuilds, "the last two patches never hold a face seen ten faces ago");
            }
        }
    }

    @Test
    void aPatchLargerThanTheBudgetIsReturnedButNotKept() {
        FakePatches source = new FakePatches(10, 5000, 1);
        PatchCache cache = new PatchCache(4000, CachePolicy.LRU);
        PatchCache.Table t = cache.table(source.faces, "big");
        RecentPatches recent = new RecentPatches();
        assertEquals(source.expected(3), cache.get(t, 3, source, recent));
        assertEquals(source.expected(4), cache.get(t, 4, source, recent));
        assertEquals(source.expected(5), cache.get(t, 5, source, recent));
        assertEquals(source.expected(3), cache.get(t, 3, source, recent));
        assertEquals(2, source.builds.get(3), "built again: not kept, and gone from the thread's last two");
        assertEquals(4, cache.stats().uncached());
        assertEquals(0, cache.stats().currentBytes());
        assertTrue(cache.stats().summary().contains("4 too large to keep"), cache.stats().summary());
        // A budget of zero keeps nothing.
        PatchCache none = new PatchCache(0, CachePolicy.LRU);
        PatchCache.Table n = none.table(source.faces, "none");
        none.get(n, 1, source, new RecentPatches());
        assertEquals(0, none.stats().peakBytes());
    }

    @Test
    void lastTwoKeepsEachThreadsLastTwoPatchesAndSharesNothing() {
        FakePatches source = new FakePatches(10, 100, 1);
        PatchCache cache = new PatchCache(1L << 30, CachePolicy.LAST_TWO);
        PatchCache.Table t = cache.table(source.faces, "two");
        RecentPatches r = new RecentPatches();
        int a = 0, b = 1, c = 2;
        cache.get(t, a, source, r); // miss
        cache.get(t, b, source, r); // miss
        cache.get(t, a, source, r); // hit: a is now the newer
        cache.get(t, c, source, r); // miss: replaces b, the older
        cache.get(t, a, source, r); // hit
        cache.get(t, b, source, r); // miss: replaces c
        r.flush();
        assertEquals(1, source.builds.get(a));
        assertEquals(2, source.builds.get(b));
        assertEquals(1, source.builds.get(c));
        Stats s = t.stats();
        assertEquals(2, s.hits());
        assertEquals(4, s.misses());
        assertEquals(2, s.evictions());
        assertEquals(200, s.currentBytes(), "what the thread holds");
        assertEquals(200, s.peakBytes());
        // Another thread's scratch sees none of it.
        RecentPatches other = new RecentPatches();
        cache.get(t, a, source, other);
        assertEquals(2, source.builds.get(a));
        assertEquals(300, cache.stats().currentBytes());
        other.clear();
        r.clear();
        assertEquals(0, cache.stats().currentBytes());
        assertEquals(300, cache.stats().peakBytes());
    }

    @Test
    void theFrontCacheAnswersTheLastTwoUnderLruToo() {
        FakePatches source = new FakePatches(10, 100, 1);
        PatchCache cache = new PatchCache(0, CachePolicy.LRU); // keeps nothing shared
        PatchCache.Table t = cache.table(source.faces, "front");
        RecentPatches r = new RecentPatches();
        CachedPatch first = cache.get(t, 7, source, r);
        assertSame(first, cache.get(t, 7, source, r));
        cache.get(t, 8, source, r);
        assertSame(first, cache.get(t, 7, source, r));
        assertEquals(1, source.builds.get(7));
        r.flush();
        assertEquals(2, t.stats().hits());
    }

    @Test
    void pinnedPatchesAreNeverEvictedAndCountAgainstTheBudget() {
        for (CachePolicy policy : CachePolicy.values()) {
            FakePatches source = new FakePatches(1000, 100, 1);
            PatchCache cache = new PatchCache(1000, policy);
            PatchCache.Table t = cache.table(source.faces, "pinned");
            RecentPatches r = new RecentPatches();
            FakePatches.Patch eager = new FakePatches.Patch(5, FakePatches.payload(5), 600);
            if (policy == CachePolicy.LRU) {
                cache.get(t, 5, source, r); // cached first; the pin takes its place
                r.clear();
            }
            cache.pin(t, 5, eager);
            assertEquals(600, cache.stats().pinnedBytes());
            assertEquals(1, cache.stats().pinnedPatches());
            assertEquals(0, cache.stats().currentBytes(), policy + ": the cached copy left when the pin replaced it");
            int builtBefore = source.builds.get(5);
            for (int i = 0; i < 500; i++) {
                assertSame(eager, cache.get(t, 5, source, r));
                cache.get(t, 100 + i, source, r);
                if (policy == CachePolicy.LRU) assertTrue(cache.stats().currentBytes() <= 400, "room left by the pin");
            }
            assertEquals(builtBefore, source.builds.get(5), "never rebuilt");
            assertSame(eager, t.slots.get(5));
            assertEquals(600, t.stats().pinnedBytes());
            assertTrue(t.stats().summary().contains("1 pinned (600 bytes)"), t.stats().summary());
            // Pinning more than the budget leaves no room for caching, but keeps the pins.
            cache.pin(t, 6, new FakePatches.Patch(6, FakePatches.payload(6), 600));
            assertEquals(1200, cache.stats().pinnedBytes());
            if (policy == CachePolicy.LRU) assertEquals(0, cache.stats().currentBytes());
            cache.get(t, 7, source, r);
            cache.get(t, 8, source, r);
            cache.get(t, 7, source, new RecentPatches());
            if (policy == CachePolicy.LRU) assertEquals(0, cache.stats().currentBytes());
        }
    }

    @Test
    void statsSummaryIsOneLine() {
        FakePatches source = new FakePatches(10, 100, 1);
        PatchCache cache = new PatchCache(1000, CachePolicy.LRU);
        PatchCache.Table t = cache.table(source.faces, "summary");
        RecentPatches r = new RecentPatches();
        cache.get(t, 0, source, r);
        cache.get(t, 1, source, r);
        cache.get(t, 2, source, r);
        cache.get(t, 0, source, r);
        r.flush();
        t.stats().recordLevel(3);
        t.stats().recordLevel(3);
        t.stats().recordLevel(5);
        assertEquals("patches 3 built, 1 hits, 3 misses, 0 evictions, peak 300 bytes; levels 3:2 5:1", cache.stats().summary());
        assertEquals(2, cache.stats().level(3));
        assertEquals("patches 0 built, 0 hits, 0 misses, 0 evictions, peak 0 bytes; levels none",
                new PatchCache(10, CachePolicy.LRU).stats().summary());
        assertThrows(IllegalArgumentException.class, () -> t.stats().recordLevel(-1));
        assertThrows(IllegalArgumentException.class, () -> t.stats().recordLevel(Stats.MAX_LEVEL + 1));
    }

    @Test
    void badArgumentsAreRefusedClearly() {
        FakePatches source = new FakePatches(10, 100, 1);
        assertThrows(IllegalArgumentException.class, () -> new PatchCache(-1, CachePolicy.LRU));
        assertThrows(IllegalArgumentException.class, () -> new PatchCache(1, null));
        PatchCache cache = new PatchCache(1000, CachePolicy.LRU);
        PatchCache.Table t = cache.table(source.faces, "mesh 'a'");
        PatchCache.Table foreign = new PatchCache(1000, CachePolicy.LRU).table(10, "b");
        RecentPatches r = new RecentPatches();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> cache.get(t, 10, source, r));
        assertEquals("face 10 is outside the 10 faces of mesh 'a'", e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> cache.get(t, -1, source, r));
        assertThrows(IllegalArgumentException.class, () -> cache.get(foreign, 0, source, r));
        assertThrows(IllegalArgumentException.class, () -> cache.get(t, 0, f -> null, r));
        assertThrows(IllegalArgumentException.class, () -> cache.get(t, 0, f -> () -> -5, r));
        assertThrows(IllegalArgumentException.class, () -> cache.pin(t, 0, null));
        assertThrows(IllegalArgumentException.class, () -> cache.pin(t, 11, source.expected(1)));
        assertThrows(IllegalArgumentException.class, () -> cache.table(-1, "negative"));
        try (HeapBudget.Scope ignored = HeapBudget.cap(1 << 20)) {
            InsufficientMemoryException m = assertThrows(InsufficientMemoryException.class, () -> cache.table(1 << 30, "huge"));
            assertTrue(m.getMessage().startsWith("the tessellation cache's table of 1073741824 faces for huge needs"), m.getMessage());
        }
    }

    /** A source that builds slowly enough for threads to race on the same face. */
    private static PatchSource slow(FakePatches source) {
        return face -> {
            long spin = 0;
            for (int i = 0; i < 200; i++) spin += i * (long) face;
            if (spin == 42) throw new AssertionError();
            return source.build(face);
        };
    }

    @Test
    void eightThreadsStressTheCache() throws Exception {
        for (CachePolicy policy : CachePolicy.values()) {
            FakePatches source = new FakePatches(5000, 64, 512);
            long budget = 256 * 1024; // about 800 patches: most of the hot faces fit, the cold tail evicts
            PatchCache cache = new PatchCache(budget, policy);
            PatchCache.Table t1 = cache.table(source.faces, "first");
            PatchCache.Table t2 = cache.table(source.faces / 2, "second");
            cache.pin(t2, 3, source.expected(3));
            PatchSource build = slow(source);
            int threads = 8;
            AtomicBoolean running = new AtomicBoolean(true);
            AtomicLong worst = new AtomicLong();
            Thread watcher = new Thread(() -> {
                while (running.get()) {
                    worst.accumulateAndGet(cache.stats().currentBytes(), Math::max);
                    Thread.yield();
                }
            });
            watcher.start();
            ExecutorService pool = Executors.newFixedThreadPool(threads);
            CountDownLatch start = new CountDownLatch(1);
            List<Future<Long>> done = new ArrayList<>();
            for (int k = 0; k < threads; k++) {
                long seed = k;
                done.add(pool.submit(() -> {
                    RecentPatches recent = new RecentPatches();
                    SplittableRandom random = new SplittableRandom(seed);
                    start.await();
                    long n = 0;
                    for (int i = 0; i < 100_000; i++) {
                        // Mostly a few hundred hot faces, so threads hit and race, with a cold tail that evicts.
                        boolean second = random.nextInt(4) == 0;
                        PatchCache.Table t = second ? t2 : t1;
                        int face = random.nextInt(8) == 0 ? random.nextInt(t.faces) : random.nextInt(300);
                        CachedPatch p = cache.get(t, face, build, recent);
                        if (!source.expected(face).equals(p)) throw new AssertionError("face " + face + " got " + p);
                        n++;
                    }
                    recent.clear();
                    return n;
                }));
            }
            start.countDown();
            long requests = 0;
            for (Future<Long> f : done) requests += f.get();
            pool.shutdown();
            running.set(false);
            watcher.join();
            Stats s = cache.stats();
            assertEquals(threads * 100_000L, requests);
            assertEquals(requests, s.hits() + s.misses(), s.summary());
            assertEquals(source.totalBuilds(), s.built());
            assertEquals(s.built(), t1.stats().built() + t2.stats().built());
            assertTrue(s.peakBytes() <= budget, policy + " peak " + s.peakBytes());
            if (policy == CachePolicy.LRU) {
                assertTrue(worst.get() <= budget, "bytes stayed within the budget: " + worst.get());
                assertEquals(slotBytes(t1) + slotBytes(t2), s.currentBytes(), "the count matches the slots");
                assertTrue(s.evictions() > 0 && s.hits() > s.misses(), s.summary());
            } else {
                assertEquals(0, s.currentBytes(), "every thread let go of its two");
            }
            assertEquals(source.bytesOf(3), s.pinnedBytes());
            System.out.println("stress " + policy + ": " + s.summary());
        }
    }

    /** The patches returned for a fixed list of requests, served by {@code threads} threads taking every n-th. */
    private static long[] serve(int[] requests, long budget, CachePolicy policy, int threads) throws Exception {
        FakePatches source = new FakePatches(3000, 100, 300);
        PatchCache cache = new PatchCache(budget, policy);
        PatchCache.Table t = cache.table(source.faces, "determinism");
        long[] payloads = new long[requests.length];
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        List<Future<?>> done = new ArrayList<>();
        for (int k = 0; k < threads; k++) {
            int first = k;
            done.add(pool.submit(() -> {
                RecentPatches recent = new RecentPatches();
                for (int i = first; i < requests.length; i += threads) {
                    FakePatches.Patch p = (FakePatches.Patch) cache.get(t, requests[i], source, recent);
                    payloads[i] = p.payload() ^ p.face() * 31L ^ p.bytes();
                }
                return null;
            }));
        }
        for (Future<?> f : done) f.get();
        pool.shutdown();
        return payloads;
    }

    @Test
    void resultsAreTheSameForAnyBudgetPolicyAndThreadCount() throws Exception {
        SplittableRandom random = new SplittableRandom(1616);
        int[] requests = new int[60_000];
        for (int i = 0; i < requests.length; i++) requests[i] = random.nextInt(8) == 0 ? random.nextInt(3000) : random.nextInt(200);
        long[] expected = new long[requests.length];
        for (int i = 0; i < requests.length; i++) {
            int f = requests[i];
            expected[i] = FakePatches.payload(f) ^ f * 31L ^ new FakePatches(3000, 100, 300).bytesOf(f);
        }
        for (CachePolicy policy : CachePolicy.values()) {
            for (long budget : new long[] {0, 400, 10_000, 1L << 40}) {
                for (int threads : new int[] {1, 2, 8}) {
                    assertArrayEquals(expected, serve(requests, budget, policy, threads), policy + " " + budget + " bytes, " + threads + " threads");
                }
            }
        }
    }

    /** This thread's CPU time in ns: unlike the wall clock, not inflated when other processes share the cores. */
    private static long cpuNanos() {
        java.lang.management.ThreadMXBean mx = java.lang.management.ManagementFactory.getThreadMXBean();
        return mx.isCurrentThreadCpuTimeSupported() ? mx.getCurrentThreadCpuTime() : System.nanoTime();
    }

    /** Printed, not asserted: what a hit costs on this machine, in thread CPU time. */
    @Test
    void measureHitCost() {
        FakePatches source = new FakePatches(1024, 100, 1);
        PatchCache cache = new PatchCache(1L << 30, CachePolicy.LRU);
        PatchCache.Table t = cache.table(source.faces, "measure");
        RecentPatches recent = new RecentPatches();
        for (int f = 0; f < source.faces; f++) cache.get(t, f, source, recent);
        long sink = 0;
        int n = 20_000_000;
        double slotNs = 0;
        double frontNs = 0;
        for (int round = 0; round < 3; round++) {
            long t0 = cpuNanos();
            for (int i = 0; i < n; i++) sink += cache.get(t, (i * 7) & 1023, source, recent).bytes();
            long t1 = cpuNanos();
            for (int i = 0; i < n; i++) sink += cache.get(t, (i >> 4) & 1023, source, recent).bytes();
            long t2 = cpuNanos();
            slotNs = (t1 - t0) / (double) n;
            frontNs = (t2 - t1) / (double) n;
        }
        assertNotNull(Long.valueOf(sink));
        System.out.printf("PatchCache hit cost: %.1f ns from a shared slot, %.1f ns from the thread's last two (1 thread)%n", slotNs, frontNs);
        // Two threads hitting the same slots at once: the shared counters and reference bits under contention.
        double[] each = new double[2];
        Thread[] threads = new Thread[2];
        for (int k = 0; k < threads.length; k++) {
            int id = k;
            threads[k] = new Thread(() -> {
                RecentPatches mine = new RecentPatches();
                long local = 0;
                for (int round = 0; round < 3; round++) {
                    long t0 = cpuNanos();
                    for (int i = 0; i < n; i++) local += cache.get(t, (i * 7 + id) & 1023, source, mine).bytes();
                    each[id] = (cpuNanos() - t0) / (double) n;
                }
                if (local == 42) throw new AssertionError();
            });
            threads[k].start();
        }
        for (Thread th : threads) {
            try {
                th.join();
            } catch (InterruptedException e) {
                throw new AssertionError(e);
            }
        }
        System.out.printf("PatchCache hit cost: %.1f and %.1f ns from a shared slot (2 threads at once)%n", each[0], each[1]);
    }
}
