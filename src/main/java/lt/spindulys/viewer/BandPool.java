package lt.spindulys.viewer;

import java.util.concurrent.Phaser;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.IntConsumer;

/**
 * A fixed set of threads that run numbered jobs (a frame's bands) together with the caller and
 * return when all are done. Two barriers of one {@link Phaser} per run, the jobs claimed from a
 * counter: nothing is allocated per run, and the caller works too, so {@code threads} threads in
 * all take part. Which thread runs which job varies; callers make each job write its own part of
 * the output, so the result does not.
 */
final class BandPool implements AutoCloseable {
    private final int threads;
    private final Phaser phaser;
    private final AtomicInteger next = new AtomicInteger();
    private volatile IntConsumer job;
    private volatile int jobs;
    private volatile boolean closed;
    private volatile Throwable failure;

    /**
     * Starts {@code threads - 1} daemon workers.
     *
     * @param threads threads that run jobs, the caller included; at least 1
     * @param name the workers' name prefix
     */
    BandPool(int threads, String name) {
        if (threads < 1) throw new IllegalArgumentException("threads must be at least 1, found " + threads);
        this.threads = threads;
        this.phaser = new Phaser(threads);
        for (int i = 1; i < threads; i++) {
            Thread t = new Thread(this::workerLoop, name + "-" + i);
            t.setDaemon(true);
            t.start();
        }
    }

    /** {@return the threads that run jobs, the caller included} */
    int threads() { return threads; }

    private void workerLoop() {
        while (true) {
            phaser.arriveAndAwaitAdvance();
            if (closed) {
                phaser.arriveAndDeregister();
                return;
            }
            work();
            phaser.arriveAndAwaitAdvance();
        }
    }

    /**
     * Runs {@code job} for 0 .. count-1, spread over the threads; returns when all have run.
     *
     * @param count the number of jobs
     * @param job what to run for each number
     * @throws IllegalStateException after {@link #close()}
     * @throws RuntimeException (or Error) the first a job threw, after the others finished
     */
    synchronized void run(int count, IntConsumer job) {
        if (closed) throw new IllegalStateException("the band pool is closed");
        if (threads == 1) {
            for (int i = 0; i < count; i++) job.accept(i);
            return;
        }
        this.job = job;
        this.jobs = count;
        this.failure = null;
        next.set(0);
        phaser.arriveAndAwaitAdvance();
        work();
        phaser.arriveAndAwaitAdvance();
        this.job = null;
        Throwable t = failure;
        if (t instanceof RuntimeException r) throw r;
        if (t instanceof Error e) throw e;
        if (t != null) throw new IllegalStateException(t);
    }

    private void work() {
        IntConsumer j = job;
        int n = jobs;
        for (int i; (i = next.getAndIncrement()) < n; ) {
            try {
                j.accept(i);
            } catch (Throwable t) {
                if (failure == null) failure = t;
            }
        }
    }

    /** Stops the workers; idempotent. */
    @Override
    public synchronized void close() {
        if (closed) return;
        closed = true;
        if (threads > 1) phaser.arriveAndDeregister();
    }
}
