package lt.spindulys;

/**
 * Measures what a piece of work allocates once it has reached its steady state, for the tests
 * that hold a query path to allocating nothing: the least of a few runs on this thread, so that
 * a compilation the JIT finishes late (its queue is long while other test classes run beside)
 * does not count, while work that allocates on every run still shows.
 */
public final class SteadyAllocation {
    private SteadyAllocation() {}

    /**
     * Runs {@code work} twice to warm up, then up to {@code attempts} more times, stopping once a
     * run allocates less than {@code bound} bytes.
     *
     * @return the least number of bytes one measured run allocated
     */
    public static long least(Runnable work, int attempts, long bound) {
        work.run(); // warm up: scratch arrays grow once, the JIT compiles
        work.run();
        var bean = (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        long least = Long.MAX_VALUE;
        for (int attempt = 0; attempt < attempts && least >= bound; attempt++) {
            long before = bean.getCurrentThreadAllocatedBytes();
            work.run();
            least = Math.min(least, bean.getCurrentThreadAllocatedBytes() - before);
        }
        return least;
    }
}
