package lt.spindulys.limits;

import java.util.Locale;
import java.util.concurrent.atomic.AtomicLong;

/**
 * The heap as a budget: every allocation whose size comes from input (counts in file headers,
 * image dimensions, subdivision levels, the frame size) is checked here before it is made, and
 * refused with a one-line {@link InsufficientMemoryException} saying how much it needs and how
 * much there is. The caller adds the location (file:line:column or the object) it knows.
 *
 * <p>What the heap can still give is {@code Runtime.maxMemory()} less what is in use. Garbage not
 * yet collected counts as in use, so a check that would fail first asks for a collection and looks
 * again; a check that passes costs nothing. A headroom is kept back for everything the caller did
 * not count (structures built later, the other threads' scratch), so an estimate that is a little
 * low does not end in OutOfMemoryError.
 *
 * <p>A check and the allocation after it are two steps: threads that check at once would all see
 * the same free heap and then all allocate. Where several threads allocate what input sizes, the
 * allocation is {@link #reserve reserved} instead: the check and the reservation are one atomic
 * step, and reserved bytes count as used for every check, on every thread, until the allocation
 * is made and the reservation released.
 */
public final class HeapBudget {
    private HeapBudget() {}

    /** Heap kept back from every check: an eighth of the maximum heap, at most this many bytes. */
    static final long MAX_HEADROOM = 64L << 20;

    /** Bytes the heap can still give without a collection (a lower bound: garbage counts as used). */
    public static long available() {
        Runtime r = Runtime.getRuntime();
        return r.maxMemory() - (r.totalMemory() - r.freeMemory());
    }

    /** The heap kept back from every check. */
    static long headroom() {
        return Math.min(MAX_HEADROOM, Runtime.getRuntime().maxMemory() / 8);
    }

    /**
     * Checks that {@code bytes} more can be allocated, keeping the headroom.
     *
     * @param what the thing that needs it, as a noun phrase that starts the message
     *             ("the 8192x8192 texture", "subdivision level 8 of this mesh")
     * @throws InsufficientMemoryException "WHAT needs 1.2 GiB of heap, but only 300 MiB is free
     *         (raise the limit with -Xmx, ...)"
     */
    public static void require(long bytes, String what) {
        if (fits(bytes)) return;
        // Garbage counts as used until it is collected: look again after a collection before refusing.
        System.gc();
        if (fits(bytes)) return;
        throw new InsufficientMemoryException(what, bytes, Math.max(0, free()));
    }

    /**
     * {@link #require} and keep: checks that {@code bytes} more can be allocated and, in the same
     * atomic step, reserves them, so that every check on any thread sees them as used until the
     * returned reservation is released. Allocate under it, then release it (close it, or
     * {@link Reservation#release(long) release} each part once that part is allocated).
     *
     * @param what as for {@link #require}
     * @return the reservation of {@code bytes}
     * @throws InsufficientMemoryException as {@link #require} does
     */
    public static Reservation reserve(long bytes, String what) {
        if (bytes < 0) throw new IllegalArgumentException("negative size " + bytes);
        synchronized (RESERVED) {
            if (fits(bytes)) return new Reservation(bytes);
        }
        System.gc(); // outside the lock: a collection takes a while, and other threads' checks need not wait for it
        synchronized (RESERVED) {
            if (fits(bytes)) return new Reservation(bytes);
            throw new InsufficientMemoryException(what, bytes, Math.max(0, free()));
        }
    }

    /** Bytes reserved by {@link #reserve} and not yet released: what every check counts as used. */
    public static long reserved() { return RESERVED.get(); }

    /** The sum of the reservations held; changed under its own lock when a reservation is made. */
    private static final AtomicLong RESERVED = new AtomicLong();

    /**
     * Heap held back by {@link #reserve} for an allocation not made yet. Releasing more than is
     * left releases what is left; releasing twice releases nothing more.
     */
    public static final class Reservation implements AutoCloseable {
        private final AtomicLong left;

        private Reservation(long bytes) {
            left = new AtomicLong(bytes);
            RESERVED.addAndGet(bytes);
        }

        /** Releases {@code bytes} of the reservation (an allocated part of it), or what is left if less. */
        public void release(long bytes) {
            if (bytes < 0) throw new IllegalArgumentException("negative size " + bytes);
            long before, after;
            do {
                before = left.get();
                after = Math.max(0, before - bytes);
            } while (!left.compareAndSet(before, after));
            RESERVED.addAndGet(after - before);
        }

        /** Bytes still reserved. */
        public long left() { return left.get(); }

        /** Releases the rest of the reservation. */
        @Override
        public void close() { release(Long.MAX_VALUE); }
    }

    /** True if {@code bytes} more fit now, with the headroom kept back; never collects. */
    public static boolean fits(long bytes) {
        return bytes >= 0 && bytes <= free();
    }

    /**
     * What a check may hand out: the available heap less the headroom, within this thread's cap,
     * less what is reserved (reserved bytes come out of a capped heap too).
     */
    private static long free() {
        long f = available() - headroom();
        Long cap = CAP.get();
        return (cap == null ? f : Math.min(f, cap)) - RESERVED.get();
    }

    /**
     * What a check on this thread may hand out now, never negative: the available heap less the
     * headroom and the reservations, within this thread's cap. For budgets that are fractions of
     * the heap (adaptive subdivision); never collects.
     */
    public static long spare() {
        return Math.max(0, free());
    }

    /** This thread's cap on {@link #free()}, set by {@link #cap}; null when none. */
    private static final ThreadLocal<Long> CAP = new ThreadLocal<>();

    /**
     * Until the returned scope is closed, checks on THIS thread see at most {@code bytes} free, as
     * if the heap were that small. For tests: a refusal that must not depend on the machine's
     * momentary free memory caps the budget below what the refused thing needs. Scopes nest.
     */
    public static Scope cap(long bytes) {
        if (bytes < 0) throw new IllegalArgumentException("negative cap " + bytes);
        Long previous = CAP.get();
        CAP.set(previous == null ? bytes : Math.min(previous, bytes));
        return () -> {
            if (previous == null) CAP.remove();
            else CAP.set(previous);
        };
    }

    /** The scope of a {@link #cap}: closing it restores the previous cap. */
    public interface Scope extends AutoCloseable {
        @Override
        void close();
    }

    /** Product of non-negative factors, saturating at Long.MAX_VALUE instead of overflowing. */
    public static long product(long... factors) {
        long p = 1;
        for (long f : factors) {
            if (f < 0) throw new IllegalArgumentException("negative size factor " + f);
            if (f != 0 && p > Long.MAX_VALUE / f) return Long.MAX_VALUE;
            p *= f;
        }
        return p;
    }

    /** Sum of non-negative sizes, saturating at Long.MAX_VALUE instead of overflowing (as {@link #product}). */
    public static long sum(long... terms) {
        long s = 0;
        for (long t : terms) {
            if (t < 0) throw new IllegalArgumentException("negative size " + t);
            s = t > Long.MAX_VALUE - s ? Long.MAX_VALUE : s + t;
        }
        return s;
    }

    /** "512 bytes", "3.2 MiB", "1.5 GiB": a size for a message. */
    public static String format(long bytes) {
        if (bytes == Long.MAX_VALUE) return "more than 8 EiB";
        if (bytes < 1024) return bytes + " bytes";
        String[] units = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
        double v = bytes;
        int u = -1;
        while (v >= 1024 && u < units.length - 1) {
            v /= 1024;
            u++;
        }
        return String.format(Locale.ROOT, v < 10 ? "%.1f %s" : "%.0f %s", v, units[u]);
    }
}
