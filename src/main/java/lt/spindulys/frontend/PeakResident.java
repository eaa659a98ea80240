package lt.spindulys.frontend;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.OptionalLong;

/**
 * The most physical memory the whole process has held: what {@code render --stats} prints beside
 * the heap's peak. The heap's peak leaves out the JVM's own code, metadata and thread stacks and
 * any off-heap buffers, which is what a user (or a peer renderer's figure) compares; the kernel's
 * high-water mark counts all of it. Read from Linux's {@code /proc/self/status}; elsewhere
 * unknown.
 */
public final class PeakResident {
    private PeakResident() {}

    private static final Path STATUS = Path.of("/proc/self/status");

    /** The process's peak resident set so far, bytes; empty where /proc is missing or unreadable. */
    public static OptionalLong bytes() {
        try {
            if (!Files.isReadable(STATUS)) return OptionalLong.empty();
            return parse(Files.readString(STATUS, StandardCharsets.US_ASCII));
        } catch (IOException | RuntimeException e) {
            // A figure for information only: its absence must never fail a render.
            return OptionalLong.empty();
        }
    }

    /** The {@code VmHWM} line of a {@code /proc/PID/status} text, bytes (the kernel writes kB, meaning KiB). */
    static OptionalLong parse(String status) {
        for (String line : status.split("\n")) {
            if (!line.startsWith("VmHWM:")) continue;
            String[] words = line.substring(6).trim().split("\\s+");
            if (words.length < 1 || words[0].isEmpty()) return OptionalLong.empty();
            try {
                long kib = Long.parseLong(words[0]);
                return kib > 0 ? OptionalLong.of(kib * 1024) : OptionalLong.empty();
            } catch (NumberFormatException e) {
                return OptionalLong.empty();
            }
        }
        return OptionalLong.empty();
    }
}
