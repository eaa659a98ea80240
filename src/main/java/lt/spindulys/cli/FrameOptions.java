package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.BasicFileAttributes;
import java.nio.file.attribute.FileTime;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

import lt.spindulys.files.AtomicFile;

import lt.spindulys.image.Aov;
import lt.spindulys.limits.MessageText;
import lt.spindulys.scene.Animation;

/**
 * The frame half of the farm contract on the command line: {@code --frame N},
 * {@code --frames A-B[:STEP]} and {@code --skip-existing}: which frames a run renders, each into
 * {@link OutputPattern its own file} (written atomically, as every output is), and which of
 * them (or of a still) are finished already. A scene with an animation and neither option
 * renders its whole range.
 */
final class FrameOptions {
    static final String USAGE = """
              --frame N          render frame N of the scene's animation (its global number: the clock is N / fps)
              --frames A-B[:STEP]  render frames A to B, every STEP-th; without --frame or --frames an
                                 animated scene renders all its frames. Several frames need a run of '#'
                                 in the output name, replaced by the zero-padded frame number
                                 (-o out_####.png: out_0007.png; default SCENE_####.png)
              --skip-existing    leave frames (or a still) whose image (and passes) exist already, for a retried task;
                                 remove temporary files a killed run left beside them (untouched 15 min)
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

    /** {@return true if --skip-existing was given} */
    boolean skipExisting() { return skipExisting; }

    /**
     * One render of a run: its output and its frame (null: a still).
     *
     * @param output the image written
     * @param frame the frame number, or null for a scene rendered as a still
     */
    record Item(Path output, Integer frame) {
        /** The frames of {@code range}, each to its output of {@code pattern}. */
        static List<Item> frames(FrameRange range, OutputPattern pattern) {
            List<Item> items = new ArrayList<>();
            for (int i = 0; i < range.count(); i++) items.add(new Item(pattern.forFrame(range.frame(i)), range.frame(i)));
            return items;
        }
    }

    /**
     * The items a run renders, in order: all of them, or with --skip-existing those whose image
     * or a pass beside it is missing (writes are atomic, so an existing file is a finished one;
     * each item left says so on {@code log}), once the temporary files killed runs left in the
     * items' folders are removed.
     *
     * @param passes the render passes written beside each image
     * @param log where "skipped" and "removed" lines go, or null
     */
    List<Item> unfinished(List<Item> items, Set<Aov> passes, PrintStream log) {
        if (!skipExisting) return items;
        removeStaleTemporaries(items, log);
        List<Item> todo = new ArrayList<>();
        for (Item item : items) {
            if (!finished(item.output(), passes)) {
                todo.add(item);
            } else if (log != null) {
                String which = item.frame() == null ? "" : " (frame " + item.frame() + ")";
                log.println(MessageText.escape("skipped " + item.output() + which + ": it exists (--skip-existing)"));
            }
        }
        return todo;
    }

    /**
     * How long a temporary file of ours must have been left untouched before --skip-existing takes
     * it for one a killed run left. A writer writes its temporary file from start to end without
     * pausing (the frame is rendered before the file is created) and renames it as soon as the
     * frame's files are all written, so a live run's file is touched every moment; this leaves
     * room for the passes of a huge frame written one after another, and for clocks a little apart
     * on shared storage.
     */
    static final Duration STALE_AFTER = Duration.ofMinutes(15);

    /**
     * Deletes, in the folders the outputs of these items go to (and only there), the temporary
     * files of our atomic writes ({@link AtomicFile#isTemporaryName}) untouched for
     * {@link #STALE_AFTER}: what a run killed without a chance to clean up (SIGKILL, a crash, a
     * lost node) left. A temporary file being written now, by another task of the same farm in
     * that folder, is fresh and stays. Each removal is one line on {@code log}; a file that cannot
     * be removed is left as it is.
     */
    static void removeStaleTemporaries(List<Item> items, PrintStream log) {
        Set<Path> folders = new LinkedHashSet<>();
        for (Item item : items) {
            Path parent = item.output().toAbsolutePath().getParent();
            if (parent != null) folders.add(parent);
        }
        FileTime before = FileTime.from(Instant.now().minus(STALE_AFTER));
        for (Path folder : folders) {
            try (DirectoryStream<Path> in = Files.newDirectoryStream(folder, p -> AtomicFile.isTemporaryName(p.getFileName().toString()))) {
                for (Path p : in) {
                    try {
                        BasicFileAttributes a = Files.readAttributes(p, BasicFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
                        if (!a.isRegularFile() || a.lastModifiedTime().compareTo(before) >= 0) continue;
                        Files.delete(p);
                        if (log != null) {
                            log.println(MessageText.escape("removed " + p + ": a temporary file untouched for " + STALE_AFTER.toMinutes()
                                    + " minutes, left by a run that was killed (--skip-existing)"));
                        }
                    } catch (IOException e) {
                        // Gone already (another task cleaned it), or not ours to delete: left as it is.
                    }
                }
            } catch (IOException | java.nio.file.DirectoryIteratorException e) {
                // A folder that cannot be listed: the frames' own writes will say what is wrong with it.
            }
        }
    }

    /** True if the image and each pass beside it are regular files. */
    static boolean finished(Path image, Set<Aov> passes) {
        if (!Files.isRegularFile(image)) return false;
        for (Path p : Aov.filesBeside(image, passes)) if (!Files.isRegularFile(p)) return false;
        return true;
    }
}
