package lt.spindulys.limits;

import static org.junit.jupiter.api.Assertions.*;

import java.util.concurrent.CyclicBarrier;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;

/** Reservations: a check and the allocation it allows are one step for every thread. */
class HeapBudgetTest {
    private static final long MIB = 1L << 20;

    @Test
    void threadsThatCheckAtOnceCannotAllPass() throws Exception {
        // Each thread sees 100 MiB free and wants 60: one may have it, the others must be refused,
        // however their checks interleave. Plain require() would let all of them pass.
        int n = 8;
        CyclicBarrier start = new CyclicBarrier(n);
        AtomicInteger granted = new AtomicInteger(), refused = new AtomicInteger();
        HeapBudget.Reservation[] held = new HeapBudget.Reservation[n];
        Thread[] threads = new Thread[n];
        long before = HeapBudget.reserved();
        for (int k = 0; k < n; k++) {
            int index = k;
            threads[k] = new Thread(() -> {
                try (HeapBudget.Scope s = HeapBudget.cap(100 * MIB)) {
                    start.await();
                    held[index] = HeapBudget.reserve(60 * MIB, "a thread's scratch");
                    granted.incrementAndGet();
                } catch (InsufficientMemoryException e) {
                    refused.incrementAndGet();
                } catch (Exception e) {
                    throw new AssertionError(e);
                }
            });
            threads[k].start();
        }
        for (Thread t : threads) t.join();
        assertEquals(1, granted.get());
        assertEquals(n - 1, refused.get());
        for (HeapBudget.Reservation r : held) if (r != null) r.close();
        assertEquals(before, HeapBudget.reserved());
    }

    @Test
    void reservedBytesCountAsUsedUntilReleased() {
        try (HeapBudget.Scope s = HeapBudget.cap(100 * MIB)) {
            HeapBudget.Reservation r = HeapBudget.reserve(70 * MIB, "two parts");
            assertFalse(HeapBudget.fits(40 * MIB));
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> HeapBudget.require(40 * MIB, "more"));
            assertEquals(30 * MIB, e.free());
            r.release(35 * MIB); // one part allocated (here: nothing is, so the cap alone counts)
            assertEquals(35 * MIB, r.left());
            assertTrue(HeapBudget.fits(40 * MIB));
            r.close();
            r.close(); // a second release releases nothing more
            assertEquals(0, r.left());
            assertTrue(HeapBudget.fits(100 * MIB));
        }
    }
}
