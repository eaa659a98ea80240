package lt.spindulys.cli;

import java.nio.file.Path;

/**
 * An output name with a place for the frame number: the one run of '#' in the file name (not its
 * folder) becomes the frame number padded with zeros to the run's length ({@code out_####.png}:
 * frame 7 is {@code out_0007.png}; a number longer than the run is written whole, never cut).
 * A name without '#' is used as it is, which the command line allows for one frame only.
 */
final class OutputPattern {
    private final Path path;
    private final String prefix, suffix;
    private final int width;

    private OutputPattern(Path path, String prefix, String suffix, int width) {
        this.path = path;
        this.prefix = prefix;
        this.suffix = suffix;
        this.width = width;
    }

    /**
     * The pattern of an output path.
     *
     * @throws UsageException if the file name has more than one run of '#'
     */
    static OutputPattern of(Path output) throws UsageException {
        Path name = output.getFileName();
        String n = name == null ? "" : name.toString();
        int start = n.indexOf('#');
        if (start < 0) return new OutputPattern(output, null, null, 0);
        int end = start;
        while (end < n.length() && n.charAt(end) == '#') end++;
        if (n.indexOf('#', end) >= 0) {
            throw new UsageException("-o " + output + ": the file name has more than one run of '#'; give one, such as out_####.png, for the frame number");
        }
        return new OutputPattern(output, n.substring(0, start), n.substring(end), end - start);
    }

    /** {@return true if the name has a place for the frame number} */
    boolean hasFrame() { return width > 0; }

    /** {@return the path as given} */
    Path path() { return path; }

    /**
     * The output of one frame.
     *
     * @param frame the frame number, at least 0
     * @return the path with the '#' run replaced by the padded number, or the path itself when it has none
     */
    Path forFrame(int frame) {
        if (!hasFrame()) return path;
        String digits = Integer.toString(frame);
        String padded = "0".repeat(Math.max(0, width - digits.length())) + digits;
        return path.resolveSibling(prefix + padded + suffix);
    }

    /**
     * The default output of several frames: {@code NAME.png} becomes {@code NAME_####.png}.
     *
     * @param still the default output of a still
     * @return the pattern with a four-digit frame number before the extension
     */
    static Path defaultForFrames(Path still) {
        String n = still.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return still.resolveSibling((dot > 0 ? n.substring(0, dot) : n) + "_####" + (dot > 0 ? n.substring(dot) : ""));
    }
}
