package lt.spindulys.frontend;

import java.lang.management.ManagementFactory;
import java.lang.management.MemoryPoolMXBean;
import java.lang.management.MemoryType;

/**
 * The most heap the process has used: the peak {@code render --stats} prints and the bench
 * records for each of its renders.
 */
public final class HeapPeak {
    private HeapPeak() {}

    /**
     * The most heap the process has used so far: the sum over the heap pools of each pool's peak
     * (the JVM tracks these between collections, so a short-lived spike still counts). The pools
     * peak at different moments, so the sum can exceed the true peak a little; it never misses it.
     */
    public static long bytes() {
        long sum = 0;
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP && pool.isValid()) sum += pool.getPeakUsage().getUsed();
        }
        return sum;
    }

    /** Starts a new peak: {@link #bytes()} then reports the peak since this call. */
    public static void reset() {
        for (MemoryPoolMXBean pool : ManagementFactory.getMemoryPoolMXBeans()) {
            if (pool.getType() == MemoryType.HEAP && pool.isValid()) pool.resetPeakUsage();
        }
    }
}
