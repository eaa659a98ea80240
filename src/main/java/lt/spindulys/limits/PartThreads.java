package lt.spindulys.limits;

/**
 * A short job cut into a few parts run at once: part 0 on the caller's thread, the others on new
 * daemon threads, all waited for. For reading and parsing one large input file on every core,
 * where each part is bounded by the file, so the wait for them is not interruptible (an
 * interrupt that arrives meanwhile is kept for the caller).
 */
public final class PartThreads {
    private PartThreads() {}

    /**
     * One part of the job.
     *
     * @param <E> the checked exception a part may throw
     */
    @FunctionalInterface
    public interface Part<E extends Exception> {
        /**
         * Does part {@code k}.
         *
         * @param k the part, 0 to the part count - 1
         * @throws E if the part fails
         */
        void run(int k) throws E;
    }

    /**
     * Runs {@code part} for 0 to {@code parts} - 1 at once and waits for all of them; then throws
     * the failure of the lowest part that failed, if any.
     *
     * @param <E> the checked exception a part may throw
     * @param parts how many parts, at least 1
     * @param name the helper threads' name
     * @param part the work of one part
     * @throws E the lowest failed part's exception (unchecked ones and errors as they were)
     */
    @SuppressWarnings("unchecked")
    public static <E extends Exception> void run(int parts, String name, Part<E> part) throws E {
        Thread[] helpers = new Thread[Math.max(0, parts - 1)];
        Throwable[] failed = new Throwable[helpers.length + 1];
        for (int k = 1; k <= helpers.length; k++) {
            int p = k;
            helpers[k - 1] = new Thread(() -> {
                try {
                    part.run(p);
                } catch (Throwable t) {
                    failed[p] = t;
                }
            }, name);
            helpers[k - 1].setDaemon(true);
            helpers[k - 1].start();
        }
        try {
            part.run(0);
        } catch (Throwable t) {
            failed[0] = t;
        }
        boolean interrupted = false;
        for (Thread t : helpers) {
            while (true) {
                try {
                    t.join();
                    break;
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        }
        if (interrupted) Thread.currentThread().interrupt();
        for (Throwable t : failed) {
            if (t == null) continue;
            if (t instanceof RuntimeException e) throw e;
            if (t instanceof Error e) throw e;
            throw (E) t; // a part throws only E or unchecked exceptions
        }
    }
}
