package lt.spindulys.bench;

/** Bad usage of {@code render bench}; the command line prints its message as one line and exits with 2, as for its own options. */
public final class BenchUsageException extends Exception {
    BenchUsageException(String message) { super(message); }
}
