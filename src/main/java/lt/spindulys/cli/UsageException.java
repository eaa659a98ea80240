package lt.spindulys.cli;

/** Bad command-line usage; its message is printed as one line and the process exits with 2. */
final class UsageException extends Exception {
    UsageException(String message) { super(message); }
}
