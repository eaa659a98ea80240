package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.PathMatcher;
import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageFormat;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.image.TileFile;
import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.MessageText;
import lt.spindulys.scene.InputFile;

/**
 * {@code render assemble TILE.png... -o OUT}: puts the tiles of one frame, rendered apart with
 * {@code --region} or {@code --tile}, back into the frame. Every tile records its place
 * ({@link TileFile}); the tiles must be of one frame size and cover it exactly once, else nothing
 * is written and one line names the tiles at fault. The pixels are copied as they are, so the
 * frame is bit for bit the one a whole render writes.
 */
final class AssembleCommand {
    static final String USAGE = """
            usage: render assemble TILE.png... -o OUT [--frame N] [--quiet]

              TILE.png           tiles written by render --region or --tile; a name with * or ? that names no
                                 file is a pattern, matched in its directory (for managers that run no shell):
                                 'out_0001.tile*.png'
              -o, --output OUT   the frame to write: .png, .tga or .jpg (written atomically)
              --frame N          the frame number for the run of '#' in the tile names and in OUT, padded
                                 with zeros to the run's length, as render writes them:
                                 --frame 7 'tiles/shot_####.tile_*_of_4.png' -o 'shot_####.png'
              --quality Q        JPEG quality from 0 to 1 (default 0.92)
              --quiet            no closing 'assembled N tiles into OUT (WxH)' line
            The tiles must be of one frame size and cover it exactly once, and OUT may not be one of them.
            Exit status: 0 success, 2 bad usage or bad tiles (nothing is written), 1 failure while writing.""";

    /** The most tiles one frame is assembled from: far more than any farm splits a frame into. */
    static final int MAX_TILES = 1 << 20;

    private final List<String> tiles = new ArrayList<>();
    private Path output;
    private double quality = ImageOptions.DEFAULT.jpegQuality();
    private boolean quiet;
    private Integer frame;

    AssembleCommand(String[] args) throws UsageException {
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "-o", "--output" -> {
                    if (++i >= args.length) throw new UsageException("option " + a + " needs a value");
                    output = Path.of(args[i]);
                }
                case "--quality" -> {
                    if (++i >= args.length) throw new UsageException("option " + a + " needs a value");
                    try {
                        quality = Double.parseDouble(args[i]);
                    } catch (NumberFormatException e) {
                        throw new UsageException(a + " expects a number, found '" + args[i] + "'");
                    }
                    if (!(quality >= 0 && quality <= 1)) throw new UsageException(a + " must be between 0 and 1, found " + args[i]);
                }
                case "--frame" -> {
                    if (++i >= args.length) throw new UsageException("option " + a + " needs a value");
                    try {
                        frame = Integer.parseInt(args[i]);
                    } catch (NumberFormatException e) {
                        frame = -1;
                    }
                    if (frame < 0 || !args[i].chars().allMatch(c -> c >= '0' && c <= '9')) {
                        throw new UsageException(a + " expects a frame number (0 or more), found '" + args[i] + "'");
                    }
                }
                case "--quiet", "-q" -> quiet = true;
                default -> {
                    if (a.startsWith("-") && a.length() > 1) throw new UsageException("unknown option '" + a + "' (see render assemble --help)");
                    tiles.add(a);
                }
            }
        }
        if (tiles.isEmpty()) throw new UsageException("no tiles given (see render assemble --help)");
        if (output == null) throw new UsageException("no output given: render assemble TILE.png... -o OUT");
        if (frame != null) {
            output = forFrame(output, frame);
            for (int k = 0; k < tiles.size(); k++) tiles.set(k, forFrame(Path.of(tiles.get(k)), frame).toString());
        }
        ImageFormat format;
        try {
            format = ImageWriter.checkFormat(output);
        } catch (IllegalArgumentException e) {
            throw new UsageException(e.getMessage());
        }
        if (format == ImageFormat.PFM || format == ImageFormat.EXR) {
            throw new UsageException("tiles hold 8-bit pixels: the assembled frame is written as .png, .tga or .jpg, not " + output);
        }
    }

    int run(PrintStream err) throws IOException, UsageException {
        try {
            ImageWriter.checkOutput(output);
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        }
        List<Path> files = expand(tiles);
        List<InputFile> inputs = new ArrayList<>(files.size());
        for (Path f : files) inputs.add(new InputFile(f, "tile", null));
        try {
            InputFile.checkOutput(output, inputs);
        } catch (InputFile.OutputIsInputException e) {
            throw new UsageException(e.getMessage());
        }
        List<TileFile.Placement> placements = new ArrayList<>(files.size());
        for (Path f : files) placements.add(TileFile.readPlacement(f));
        TileFile.Placement first = placements.get(0);
        if (frame != null && first.frame() != null && !first.frame().equals(frame)) {
            throw new IllegalArgumentException(files.get(0) + ": a tile of frame " + first.frame() + ", but --frame " + frame + " was given");
        }
        int w = first.frameWidth(), h = first.frameHeight();
        // Refusals that name no one file as their place are the run's: they start "render:" as usage errors do.
        try {
            checkCover(files, placements, w, h);
            // The frame's pixels, then the buffer, 8-bit copy and encoder image the writer makes.
            HeapBudget.require(HeapBudget.sum(HeapBudget.product(w, h, 4), FrameBuffer.bytesToRender(w, h, java.util.Set.of())),
                    "the assembled " + w + "x" + h + " frame");
        } catch (TilesRefused | lt.spindulys.limits.InsufficientMemoryException e) {
            throw new UsageException(e.getMessage());
        }
        int[] frame = new int[w * h];
        for (int k = 0; k < files.size(); k++) {
            PixelRegion r = placements.get(k).region();
            int[] px = TileFile.readPixels(files.get(k), placements.get(k));
            for (int y = 0; y < r.height(); y++) System.arraycopy(px, y * r.width(), frame, (r.y0() + y) * w + r.x0(), r.width());
        }
        if (ImageWriter.checkFormat(output) == ImageFormat.PNG) {
            ImageWriter.writeAtomically(output, ImageWriter.pngEncoder(w, h, frame));
        } else {
            // Linear values of the 8-bit codes, written back without a curve: the same codes.
            ImageWriter.write(FrameBuffer.fromRgb8(w, h, frame, false), output, new ImageOptions(false, quality));
        }
        if (!quiet) err.println(MessageText.escape("assembled " + files.size() + " tile" + (files.size() == 1 ? "" : "s") + " into " + output + " (" + w + "x" + h + ")"));
        return 0;
    }

    /** {@code path} with the run of '#' in its file name replaced by the frame number, as render names frames ({@link OutputPattern}). */
    static Path forFrame(Path path, int frame) throws UsageException {
        OutputPattern p = OutputPattern.of(path);
        if (!p.hasFrame()) throw new UsageException("--frame " + frame + ": " + path + " has no run of '#' for the frame number, such as shot_####.png");
        return p.forFrame(frame);
    }

    /**
     * The tile files: each argument that names a file as it is, and each one with {@code *} or
     * {@code ?} in its last part that names none as a pattern over its directory, its matches in
     * name order.
     */
    static List<Path> expand(List<String> args) throws IOException, UsageException {
        List<Path> out = new ArrayList<>();
        for (String a : args) {
            Path p = Path.of(a);
            Path name = p.getFileName();
            boolean pattern = name != null && (name.toString().contains("*") || name.toString().contains("?"));
            if (!pattern || Files.exists(p)) {
                out.add(p);
                continue;
            }
            Path dir = p.getParent() != null ? p.getParent() : Path.of(".");
            if (!Files.isDirectory(dir)) throw new UsageException("the tile pattern '" + a + "' names no directory: " + dir + " is not one");
            PathMatcher matcher = dir.getFileSystem().getPathMatcher("glob:" + name.toString().replace("\\", "\\\\").replace("[", "\\[").replace("{", "\\{"));
            TreeSet<String> names = new TreeSet<>();
            try (DirectoryStream<Path> entries = Files.newDirectoryStream(dir)) {
                for (Path e : entries) {
                    if (matcher.matches(e.getFileName()) && Files.isRegularFile(e)) {
                        names.add(e.getFileName().toString());
                        if (out.size() + names.size() > MAX_TILES) throw new UsageException("more than " + MAX_TILES + " tiles given");
                    }
                }
            }
            if (names.isEmpty()) throw new UsageException("no file matches the tile pattern '" + a + "'");
            for (String n : names) out.add(p.getParent() != null ? p.getParent().resolve(n) : Path.of(n));
        }
        if (out.size() > MAX_TILES) throw new UsageException("more than " + MAX_TILES + " tiles given");
        return out;
    }

    /** The tiles together are refused (they overlap, or leave pixels out): no one tile is the place. */
    static final class TilesRefused extends IllegalArgumentException {
        TilesRefused(String message) { super(message); }
    }

    /**
     * Refuses tiles of different frames, tiles that overlap, and tiles that leave pixels out:
     * inside one frame, tiles that do not overlap cover it exactly when their areas add up to it.
     */
    static void checkCover(List<Path> files, List<TileFile.Placement> placements, int w, int h) {
        long area = 0;
        for (int k = 0; k < files.size(); k++) {
            TileFile.Placement p = placements.get(k);
            if (p.frameWidth() != w || p.frameHeight() != h) {
                throw new IllegalArgumentException(files.get(k) + ": a tile of a " + p.frameWidth() + "x" + p.frameHeight() + " frame, but "
                        + files.get(0) + " is of a " + w + "x" + h + " frame");
            }
            if (!java.util.Objects.equals(p.frame(), placements.get(0).frame())) {
                throw new IllegalArgumentException(files.get(k) + ": a tile of " + frameName(p.frame()) + ", but " + files.get(0) + " is of "
                        + frameName(placements.get(0).frame()) + ": tiles of one frame only");
            }
            area += p.region().pixels();
        }
        checkOverlaps(files, placements);
        long all = (long) w * h;
        if (area != all) {
            throw new TilesRefused("the tiles cover " + area + " of the " + all + " pixels of the " + w + "x" + h + " frame"
                    + missing(placements, w, h) + ": a tile is missing");
        }
    }

    /**
     * Refuses two tiles that share a pixel, naming them, in O(n log n) for n tiles: a sweep down the
     * rows. The tiles are taken in order of their top row; those whose rows the sweep is in are kept
     * by their left column, and since no two of them overlap (else the sweep has stopped) their
     * column spans are disjoint, so a new tile can only overlap its two neighbours there. Tiles
     * whose bottom row is passed leave before those that start on the next row enter (regions are
     * half-open). Any overlapping pair is found: the later of the two (by top row, then by order
     * given) enters while the other is kept.
     */
    static void checkOverlaps(List<Path> files, List<TileFile.Placement> placements) {
        int n = placements.size();
        Integer[] byTop = new Integer[n], byBottom = new Integer[n];
        for (int k = 0; k < n; k++) byTop[k] = byBottom[k] = k;
        java.util.Arrays.sort(byTop, java.util.Comparator.comparingInt(k -> placements.get(k).region().y0()));
        java.util.Arrays.sort(byBottom, java.util.Comparator.comparingInt(k -> placements.get(k).region().y1()));
        // The tiles the sweep is in, by left column: their spans x0 <= x < x1 are disjoint.
        java.util.TreeMap<Integer, Integer> active = new java.util.TreeMap<>();
        int leaving = 0;
        for (int k : byTop) {
            PixelRegion r = placements.get(k).region();
            for (; leaving < n && placements.get(byBottom[leaving]).region().y1() <= r.y0(); leaving++) {
                int gone = byBottom[leaving];
                active.remove(placements.get(gone).region().x0(), gone);
            }
            java.util.Map.Entry<Integer, Integer> left = active.floorEntry(r.x0()), right = active.higherEntry(r.x0());
            Integer other = left != null && placements.get(left.getValue()).region().x1() > r.x0() ? left.getValue()
                    : right != null && right.getKey() < r.x1() ? right.getValue() : null;
            if (other != null) {
                PixelRegion o = placements.get(other).region();
                throw new TilesRefused(files.get(other) + " and " + files.get(k) + " overlap (regions " + o + " and " + r
                        + "): each pixel must come from one tile");
            }
            active.put(r.x0(), k);
        }
    }

    private static String frameName(Integer frame) { return frame == null ? "a still" : "frame " + frame; }

    /** ", e.g. rows 40 to 59 (no tile has them)" for tiles that cover whole rows and leave some out, else "". */
    private static String missing(List<TileFile.Placement> placements, int w, int h) {
        boolean bands = placements.stream().allMatch(p -> p.region().x0() == 0 && p.region().x1() == w);
        if (!bands) return "";
        List<PixelRegion> rs = placements.stream().map(TileFile.Placement::region).sorted(java.util.Comparator.comparingInt(PixelRegion::y0)).toList();
        int y = 0;
        for (PixelRegion r : rs) {
            if (r.y0() > y) return ", e.g. rows " + y + " to " + (r.y0() - 1) + " (no tile has them)";
            y = r.y1();
        }
        return y < h ? ", e.g. rows " + y + " to " + (h - 1) + " (no tile has them)" : "";
    }
}
