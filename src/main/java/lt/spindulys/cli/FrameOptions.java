package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;

import lt.spindulys.image.Aov;
import lt.spindulys.limits.MessageText;
import lt.spindulys.scene.Animation;

/**
 * The frame half of the farm contract on the command line: {@code --frame N},
 * {@code --frames A-B[:STEP]} and {@code --skip-existing}, and the loop that renders the frames
 * one after another into {@link OutputPattern their own files} (each written atomically, as
 * every output is). A scene with an animation and neither option renders its whole range.
 */
final class FrameOptions {
    static final String USAGE = """
              --frame N          render frame N of the scene's animation (its global number: the clock is N / fps)
              --frames A-B[:STEP]  render frames A to B, every STEP-th; without --frame or --frames an
                                 animated scene renders all its frames. Several frames need a run of '#'
                                 in the output name, replaced by the zero-padded frame number
                                 (-o out_####.png: out_0007.png; default SCENE_####.png)
              --skip-existing    leave frames whose image (and passes) exist already, for a retried task
            """;

    private FrameRange range;
    private String rangeOption;
    private boolean skipExisting;

    /**
     * Reads the option at {@code args[i]} (one of {@code --frame}, {@code --frames},
     * {@code --skip-existing}) and its value; returns the index of the last argument used.
     */
    int option(String[] args, int i) throws UsageException {
        String a = args[i];
        if (a.equals("--skip-existing")) {
            skipExisting = true;
            return i;
        }
        if (range != null) throw new UsageException(a + " given after " + rangeOption + ": give one frame range");
        if (i + 1 >= args.length) throw new UsageException("option " + a + " needs a value");
        range = FrameRange.parse(a, args[i + 1]);
        rangeOption = a + " " + args[i + 1];
        return i + 1;
    }

    /** {@return true if --frame or --frames was given} */
    boolean given() { return range != null; }

    /** {@return the option as given, such as "--frames 1-48:2", or null} */
    String rangeOption() { return rangeOption; }

    /**
     * The frames to render of a scene with this animation (null: a still): those asked for,
     * else the whole range.
     *
     * @throws UsageException if frames are asked of a still, or outside the animation's range
     */
    FrameRange frames(Animation animation, Path scene) throws UsageException {
        if (animation == null) {
            throw new UsageException(rangeOption + ": " + scene + " has no animation statement (animation { frames FIRST LAST  fps F }), so it has no frames");
        }
        if (range == null) return FrameRange.of(animation);
        if (range.first() < animation.first() || range.lastFrame() > animation.last()) {
            throw new UsageException(rangeOption + ": outside the frames of " + scene + "'s animation, " + animation.first() + "-" + animation.last());
        }
        return range;
    }

    /**
     * The output pattern of these frames.
     *
     * @param output the -o path, or the default one of a still
     * @param defaulted true if no -o was given: several frames then go to NAME_####.png
     * @throws UsageException if several frames would go to one name without '#'
     */
    OutputPattern pattern(Path output, boolean defaulted, FrameRange frames) throws UsageException {
        OutputPattern p = OutputPattern.of(output);
        if (p.hasFrame() || frames.count() == 1) return p;
        if (defaulted) return OutputPattern.of(OutputPattern.defaultForFrames(output));
        throw new UsageException("-o " + output + ": " + frames.count() + " frames (" + frames + ") need a run of '#' in the output name for the frame number, such as "
                + OutputPattern.defaultForFrames(output).getFileName() + ", or one frame (--frame N)");
    }

    /** Renders one frame to its output: item {@code index} of the {@code count} this run renders. */
    interface FrameRenderer {
        void render(Path output, int frame, int index, int count) throws IOException, InterruptedException, UsageException;
    }

    /** Checks one frame's output before any frame is rendered. */
    interface OutputCheck {
        void check(Path output) throws UsageException;
    }

    /**
     * Renders the frames in order; with --skip-existing a frame whose image and passes all exist
     * is left as it is (writes are atomic, so an existing file is a finished one), and the others
     * are the run's items. Stops at the first failure, which propagates; the frames written before
     * it stay.
     *
     * @param passes the render passes written beside each image
     * @param log where "skipped" lines go, or null
     * @param check called with the output of every frame to be rendered, before the first is
     * @return how many frames were rendered (0 when --skip-existing found them all)
     */
    int render(FrameRange frames, OutputPattern pattern, Set<Aov> passes, PrintStream log, OutputCheck check, FrameRenderer renderer)
            throws IOException, InterruptedException, UsageException {
        List<Integer> todo = new ArrayList<>();
        for (int i = 0; i < frames.count(); i++) {
            int n = frames.frame(i);
            Path out = pattern.forFrame(n);
            if (skipExisting && finished(out, passes)) {
                if (log != null) log.println(MessageText.escape("skipped " + out + " (frame " + n + "): it exists (--skip-existing)"));
            } else {
                todo.add(n);
            }
        }
        for (int n : todo) check.check(pattern.forFrame(n));
        for (int i = 0; i < todo.size(); i++) renderer.render(pattern.forFrame(todo.get(i)), todo.get(i), i, todo.size());
        return todo.size();
    }

    /** True if the image and each pass beside it are regular files. */
    static boolean finished(Path image, Set<Aov> passes) {
        if (!Files.isRegularFile(image)) return false;
        for (Aov a : passes) if (!Files.isRegularFile(a.fileBeside(image))) return false;
        return true;
    }
}
