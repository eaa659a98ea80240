package lt.spindulys.cli;

import lt.spindulys.scene.Animation;

/**
 * The frames a command line asks for: {@code --frame N}, or {@code --frames A-B[:STEP]} (A to B
 * inclusive, every STEP-th from A; a single number is one frame). Frame numbers are the scene's
 * global ones, so a farm task given a chunk renders exactly those frames of the whole animation.
 *
 * @param first the first frame
 * @param last the last frame, at least first
 * @param step the step, at least 1
 */
record FrameRange(int first, int last, int step) {
    FrameRange {
        if (first < 0 || last < first || step < 1) throw new IllegalArgumentException("bad frame range " + first + "-" + last + ":" + step);
    }

    /** The animation's whole range. */
    static FrameRange of(Animation a) { return new FrameRange(a.first(), a.last(), 1); }

    /**
     * Parses {@code A-B[:STEP]} or {@code N} given after {@code option}.
     *
     * @throws UsageException naming the option and what was expected
     */
    static FrameRange parse(String option, String text) throws UsageException {
        String usage = option + " expects " + (option.equals("--frame") ? "a frame number N" : "A-B or A-B:STEP (frames A to B, every STEP-th) or N") + ", found '" + text + "'";
        String range = text, step = null;
        int colon = text.indexOf(':');
        if (colon >= 0) {
            if (option.equals("--frame")) throw new UsageException(usage);
            range = text.substring(0, colon);
            step = text.substring(colon + 1);
        }
        int dash = range.indexOf('-');
        if (dash >= 0 && option.equals("--frame")) throw new UsageException(usage);
        int a = number(range.substring(0, dash < 0 ? range.length() : dash), usage);
        int b = dash < 0 ? a : number(range.substring(dash + 1), usage);
        int s = step == null ? 1 : number(step, usage);
        if (s < 1) throw new UsageException(option + " step must be at least 1, found '" + text + "'");
        if (b < a) throw new UsageException(option + " must not end before it starts, found '" + text + "'");
        return new FrameRange(a, b, s);
    }

    /** A frame number as written: digits only, at most {@link Animation#MAX_FRAME}. */
    private static int number(String s, String usage) throws UsageException {
        if (s.isEmpty() || s.length() > 7 || !s.chars().allMatch(c -> c >= '0' && c <= '9')) {
            if (!s.isEmpty() && s.length() > 7 && s.chars().allMatch(c -> c >= '0' && c <= '9')) {
                throw new UsageException(usage + " (frame numbers are 0 to " + Animation.MAX_FRAME + ")");
            }
            throw new UsageException(usage);
        }
        return Integer.parseInt(s);
    }

    /** {@return how many frames it names} */
    int count() { return (last - first) / step + 1; }

    /** {@return frame i of it, from 0} */
    int frame(int i) { return first + i * step; }

    /** {@return the last frame it names (B, or less when the step passes it)} */
    int lastFrame() { return frame(count() - 1); }

    /** "1-48", "1-48:4" or "7", as given. */
    @Override public String toString() {
        return first == last ? Integer.toString(first) : first + "-" + last + (step == 1 ? "" : ":" + step);
    }
}
