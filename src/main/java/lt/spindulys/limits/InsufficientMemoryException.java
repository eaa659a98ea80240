package lt.spindulys.limits;

/**
 * An allocation sized by input that the heap cannot give, refused before it was made. It is an
 * {@link IllegalArgumentException} because the input asked for it: callers that locate bad input
 * (the scene parser, the readers) report it at the statement or header that asked, and the command
 * line exits with status 2 as for any other bad input.
 */
public final class InsufficientMemoryException extends IllegalArgumentException {
    private final long needed, free;
    private final String key;

    InsufficientMemoryException(String what, long needed, long free) {
        this(what + " needs " + HeapBudget.format(needed) + " of heap, but only " + HeapBudget.format(free)
                + " is free (raise the JVM's limit with -Xmx, for example SPINDULYS_JAVA_OPTS=-Xmx8g ./render ...)", needed, free, null);
    }

    private InsufficientMemoryException(String message, long needed, long free, String key) {
        super(message);
        this.needed = needed;
        this.free = free;
        this.key = key;
    }

    /**
     * The same refusal, saying which input key sized what was refused, so that a caller who knows
     * where that key was given can report it there.
     *
     * @param key the key, such as "samples"
     * @return a new exception with this one's message, sizes and stack
     */
    public InsufficientMemoryException sizedBy(String key) {
        InsufficientMemoryException e = new InsufficientMemoryException(getMessage(), needed, free, key);
        e.setStackTrace(getStackTrace());
        return e;
    }

    /** The input key that sized what was refused (see {@link #sizedBy}), or null when the caller did not say. */
    public String key() { return key; }

    /** Bytes the refused allocation needed. */
    public long needed() { return needed; }

    /** Bytes the heap could give when it was refused (after the headroom). */
    public long free() { return free; }
}
