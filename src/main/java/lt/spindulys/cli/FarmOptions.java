package lt.spindulys.cli;

import java.io.PrintStream;
import java.nio.file.Path;

import java.util.stream.Collectors;

import lt.spindulys.image.Aov;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.render.RenderJob;
import lt.spindulys.render.RenderResult;
import lt.spindulys.scene.RenderSettings;

/**
 * The options of {@code render} that a render farm's manager uses to split a frame and follow a
 * task (docs/farm.md): {@code --region X0,X1,Y0,Y1} (half-open pixel bounds, as pbrt's
 * {@code --pixelbounds}), {@code --tile I/N} (band I of N bands of whole rows, from 1) and
 * {@code --progress openjd|plain}.
 */
final class FarmOptions {
    static final String USAGE = """
              --region X0,X1,Y0,Y1  render only the pixels X0 <= x < X1, Y0 <= y < Y1 (row 0 at the top) of the
                                 frame, exactly as a whole render gives them, into a PNG tile that records its
                                 place; render assemble puts tiles back together
              --tile I/N         render tile I of N (1 <= I <= N) as --region does: band I of N bands of whole
                                 rows from the top, which cover the frame exactly once (N at most its height)
              --progress MODE    one line at least every 2 s, for a farm's manager: openjd (openjd_status: and
                                 openjd_progress: lines on stdout, openjd_fail: on failure) or plain (on stderr)
            """;

    private PixelRegion region;
    private int tileNumber = -1, tileCount;
    private String regionOption;
    private FarmProgress.Mode progress;

    /**
     * Takes the option at {@code args[i]} with its value, if it is one of these.
     *
     * @return the index of the last argument used, or -1 if {@code args[i]} is not a farm option
     */
    int parse(String[] args, int i) throws UsageException {
        String a = args[i];
        switch (a) {
            case "--region" -> {
                String v = OptionValues.value(args, i + 1, a);
                noSecondRegion(a + " " + v);
                try {
                    region = PixelRegion.parse(v);
                } catch (IllegalArgumentException e) {
                    throw new UsageException(a + ": " + e.getMessage());
                }
                return i + 1;
            }
            case "--tile" -> {
                String v = OptionValues.value(args, i + 1, a);
                noSecondRegion(a + " " + v);
                int slash = v.indexOf('/');
                try {
                    if (slash < 0) throw new NumberFormatException();
                    tileNumber = Integer.parseInt(v.substring(0, slash));
                    tileCount = Integer.parseInt(v.substring(slash + 1));
                    PixelRegion.checkTile(tileNumber, tileCount);
                } catch (NumberFormatException e) {
                    throw new UsageException(a + " expects I/N, tile I of N counted from 1 (1/4 to 4/4), found '" + v + "'");
                } catch (IllegalArgumentException e) {
                    throw new UsageException(a + " " + v + ": " + e.getMessage());
                }
                return i + 1;
            }
            case "--progress" -> {
                String v = OptionValues.value(args, i + 1, a);
                try {
                    progress = FarmProgress.Mode.of(v);
                } catch (IllegalArgumentException e) {
                    throw new UsageException(a + " " + e.getMessage());
                }
                return i + 1;
            }
            default -> {
                return -1;
            }
        }
    }

    private void noSecondRegion(String given) throws UsageException {
        if (regionOption != null) throw new UsageException(given + ": the part of the frame was already given by " + regionOption);
        regionOption = given;
    }

    /**
     * True if {@code --progress openjd} is among the arguments, wherever it stands and whatever
     * else is wrong with them: an argument refused before it is read is still reported as
     * {@code openjd_fail:}.
     */
    static boolean asksForOpenjd(String[] args) {
        for (int i = 0; i + 1 < args.length; i++) {
            if (args[i].equals("--progress") && args[i + 1].equals("openjd")) return true;
        }
        return false;
    }

    /** Refuses denoising a part of the frame (the option that asked for it named), once all options are read. */
    void checkDenoise(boolean denoise) throws UsageException {
        if (denoise && regionOption != null) throw new UsageException(regionOption + ": " + lt.spindulys.render.Renderer.DENOISE_OF_REGION);
    }

    /** Refuses an output a tile cannot be written to, once the output is known. */
    void checkOutput(Path output) throws UsageException {
        if (regionOption == null) return;
        try {
            RenderResult.checkTileOutput(output);
        } catch (IllegalArgumentException e) {
            throw new UsageException(regionOption + ": " + e.getMessage());
        }
    }

    /**
     * Refuses, naming the option, a region or tile the frame these settings describe has no room
     * for, and render passes with a region (the job would refuse both, without the option's name).
     */
    void checkFrame(RenderSettings s) throws UsageException {
        if (regionOption == null) return;
        try {
            if (region != null) region.checkInside(s.width(), s.height());
            else PixelRegion.band(tileNumber, tileCount, s.width(), s.height());
        } catch (IllegalArgumentException e) {
            throw new UsageException(regionOption + ": " + e.getMessage());
        }
        if (!s.aovs().isEmpty()) {
            throw new UsageException(regionOption + ": render passes (aov " + s.aovs().stream().map(Aov::keyword).collect(Collectors.joining(","))
                    + ") are made for whole frames only: render the region without them (the scene's aov key or --aov), or the whole frame with them");
        }
    }

    /** Gives the job the region or tile asked for. */
    void apply(RenderJob job) {
        if (region != null) job.region(region);
        else if (tileCount > 0) job.tile(tileNumber, tileCount);
    }

    /** The option that chose a part of the frame ("--tile 2/4"), for messages; null when the whole frame is rendered. */
    String regionOption() { return regionOption; }

    /**
     * The progress sink asked for, reporting on the steps {@code stage} tells; null when none was asked for.
     *
     * @param out the command's standard output (OpenJD lines)
     * @param err its standard error (plain lines)
     */
    FarmProgress progress(java.util.function.Supplier<RenderJob.Stage> stage, PrintStream out, PrintStream err, String what, long startNanos) {
        if (progress == null) return null;
        return new FarmProgress(progress, progress == FarmProgress.Mode.OPENJD ? out : err, stage, what, startNanos);
    }
}
