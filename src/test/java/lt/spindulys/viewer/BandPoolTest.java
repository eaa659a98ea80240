package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.util.concurrent.atomic.AtomicIntegerArray;

import org.junit.jupiter.api.Test;

class BandPoolTest {
    @Test
    void everyJobRunsOnceOnEveryRun() {
        for (int threads : new int[] {1, 2, 3}) {
            try (BandPool pool = new BandPool(threads, "test")) {
                for (int run = 0; run < 200; run++) {
                    int n = run % 7 + 1;
                    AtomicIntegerArray seen = new AtomicIntegerArray(n);
                    pool.run(n, seen::incrementAndGet);
                    for (int i = 0; i < n; i++) assertEquals(1, seen.get(i), "job " + i + " of run " + run + " with " + threads + " threads");
                }
                pool.run(0, i -> fail("no jobs"));
            }
        }
    }

    @Test
    void aFailingJobIsRethrownAfterTheOthersAndThePoolGoesOn() {
        try (BandPool pool = new BandPool(2, "test")) {
            AtomicIntegerArray seen = new AtomicIntegerArray(10);
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> pool.run(10, i -> {
                seen.incrementAndGet(i);
                if (i == 3) throw new IllegalStateException("job 3");
            }));
            assertEquals("job 3", e.getMessage());
            for (int i = 0; i < 10; i++) assertEquals(1, seen.get(i));
            AtomicIntegerArray again = new AtomicIntegerArray(4);
            pool.run(4, again::incrementAndGet);
            for (int i = 0; i < 4; i++) assertEquals(1, again.get(i));
        }
    }

    @Test
    void closedIsClosed() {
        BandPool pool = new BandPool(2, "test");
        pool.close();
        pool.close();
        assertThrows(IllegalStateException.class, () -> pool.run(1, i -> {}));
    }
}
