package lt.spindulys.limits;

/**
 * An allocation sized by input that the heap cannot give, refused before it was made. It is an
 * {@link IllegalArgumentException} because the input asked for it: callers that locate bad input
 * (the scene parser, the readers) report it at the statement or header that asked, and the command
 * line exits with status 2 as for any other bad input.
 */
public final class InsufficientMemoryException extends IllegalArgumentException {
    private final long needed, free;

    InsufficientMemoryException(String what, long needed, long free) {
        super(what + " needs " + HeapBudget.format(needed) + " of heap, but only " + HeapBudget.format(free)
                + " is free (raise the JVM's limit with -Xmx, for example SPINDULYS_JAVA_OPTS=-Xmx8g ./render ...)");
        this.needed = needed;
        this.free = free;
    }

    /** Bytes the refused allocation needed. */
    public long needed() { return needed; }

    /** Bytes the heap could give when it was refused (after the headroom). */
    public long free() { return free; }
}
