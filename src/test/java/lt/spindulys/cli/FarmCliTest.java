package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.Images;
import lt.spindulys.image.TileFile;

/**
 * The render farm contract on the command line (docs/farm.md): regions and tiles put back
 * together by {@code render assemble} equal the whole frame bit for bit, bad tiles are refused
 * with one line and nothing written, progress lines have their documented forms, and the exit
 * status is 0 only on success.
 */
class FarmCliTest {
    @TempDir Path dir;

    /** Soft shadows, a thin lens and a moving sphere: every kind of per-sample random number. */
    private static final String SCENE = """
            settings { width 37 height 23 samples 4 }
            camera { eye 0 1 -4 lookat 0 0.5 0 aperture 0.05 }
            rectlight { center 2 4 -3  normal 0 -1 0  tangent 1 0 0  width 1  height 1  intensity 4  samples 2 }
            plane { normal 0 1 0 }
            sphere { center 0 0.5 0 radius 0.5 material { color 1 0 0 kr 0.3 } motion { direction 1 0 0 speed 0.2 } }
            """;

    private Path scene() throws IOException {
        Path p = dir.resolve("scene.dat");
        Files.writeString(p, SCENE);
        return p;
    }

    private static CliTest.Run run(String... args) { return CliTest.run(args); }

    private Path whole(Path scene, String... extra) {
        Path out = dir.resolve("whole.png");
        List<String> a = new ArrayList<>(List.of(scene.toString(), "-o", out.toString(), "--quiet", "--threads", "2"));
        a.addAll(Arrays.asList(extra));
        CliTest.Run r = run(a.toArray(new String[0]));
        assertEquals(0, r.status(), r.err());
        return out;
    }

    private void assertSameImage(Path expected, Path actual) throws IOException {
        FrameBuffer a = Images.read(expected), b = Images.read(actual);
        assertEquals(a.width() + "x" + a.height(), b.width() + "x" + b.height());
        assertArrayEquals(a.toRgb8(false), b.toRgb8(false), actual + " differs from " + expected);
        // The same pixels through the same encoder: the very same file.
        assertArrayEquals(Files.readAllBytes(expected), Files.readAllBytes(actual));
    }

    @Test
    void tilesOfEveryCountAssembleToTheWholeFrameBitForBit() throws IOException {
        Path scene = scene();
        Path whole = whole(scene);
        // 23 rows: 5 bands of 4 and 5 rows, one band, and 23 bands of one row each.
        for (int n : new int[] {5, 1, 23}) {
            List<String> tiles = new ArrayList<>();
            for (int i = 1; i <= n; i++) {
                Path t = dir.resolve("t" + n + "_" + i + ".png");
                CliTest.Run r = run(scene.toString(), "--tile", i + "/" + n, "-o", t.toString(), "--threads", "1");
                assertEquals(0, r.status(), r.err());
                assertTrue(r.err().startsWith("wrote " + t + " (region 0,37,"), r.err());
                tiles.add(t.toString());
            }
            Path out = dir.resolve("assembled" + n + ".png");
            List<String> a = new ArrayList<>(List.of("assemble"));
            a.addAll(tiles);
            a.addAll(List.of("-o", out.toString()));
            CliTest.Run r = run(a.toArray(new String[0]));
            assertEquals(0, r.status(), r.err());
            assertEquals("assembled " + n + " tile" + (n == 1 ? "" : "s") + " into " + out + " (37x23)" + System.lineSeparator(), r.err());
            assertSameImage(whole, out);
        }
    }

    @Test
    void aGridOfOddRegionsFromAPatternAssemblesToTheWholeFrame() throws IOException {
        Path scene = scene();
        Path whole = whole(scene, "--timesteps", "2");
        int[] xs = {0, 11, 24, 37}, ys = {0, 1, 9, 23}; // odd widths, and a row of one-pixel-high tiles
        for (int i = 0; i + 1 < xs.length; i++) {
            for (int j = 0; j + 1 < ys.length; j++) {
                String region = xs[i] + "," + xs[i + 1] + "," + ys[j] + "," + ys[j + 1];
                Path t = dir.resolve("grid_" + i + "_" + j + ".png");
                CliTest.Run r = run(scene.toString(), "--region", region, "--timesteps", "2", "-o", t.toString(), "--quiet");
                assertEquals(0, r.status(), r.err());
                assertEquals(region + " of 37x23", TileFile.readPlacement(t).text());
                FrameBuffer img = Images.read(t);
                assertEquals((xs[i + 1] - xs[i]) + "x" + (ys[j + 1] - ys[j]), img.width() + "x" + img.height());
            }
        }
        for (String ext : new String[] {"png", "tga"}) {
            Path out = dir.resolve("grid." + ext);
            CliTest.Run r = run("assemble", dir.resolve("grid_*.png").toString(), "-o", out.toString(), "--quiet");
            assertEquals(0, r.status(), r.err());
            assertEquals("", r.err());
            assertArrayEquals(Images.read(whole).toRgb8(false), Images.read(out).toRgb8(false), ext);
        }
        assertSameImage(whole, dir.resolve("grid.png"));
    }

    @Test
    void assembleFillsTheFrameNumberIntoTheTileNamesAndTheOutput() throws IOException {
        Path scene = scene();
        Files.createDirectories(dir.resolve("tiles"));
        for (int i = 1; i <= 3; i++) {
            Path t = dir.resolve("tiles/shot_0042.tile_" + i + "_of_3.png");
            assertEquals(0, run(scene.toString(), "--tile", i + "/3", "-o", t.toString(), "--quiet").status());
        }
        Path decoy = dir.resolve("tiles/shot_0043.tile_1_of_3.png");
        Files.copy(dir.resolve("tiles/shot_0042.tile_1_of_3.png"), decoy);
        CliTest.Run r = run("assemble", "--frame", "42", dir.resolve("tiles/shot_####.tile_*_of_3.png").toString(), "-o", dir.resolve("shot_###.png").toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("assembled 3 tiles into " + dir.resolve("shot_042.png") + " (37x23)" + System.lineSeparator(), r.err());
        assertSameImage(whole(scene), dir.resolve("shot_042.png"));

        r = run("assemble", "--frame", "7", dir.resolve("tiles/shot_0042.tile_*_of_3.png").toString(), "-o", dir.resolve("x_#.png").toString());
        assertEquals(2, r.status());
        assertTrue(r.err().startsWith("render: --frame 7: " + dir.resolve("tiles/shot_0042.tile_*_of_3.png") + " has no run of '#'"), r.err());
        r = run("assemble", "--frame", "-1", "a.png", "-o", "b.png");
        assertEquals("render: --frame expects a frame number (0 or more), found '-1'" + System.lineSeparator(), r.err());
    }

    /** Runs assemble with these tiles; expects status 2, one line containing {@code message}, and no output. */
    private void assertRefused(String message, String... tiles) {
        Path out = dir.resolve("refused.png");
        List<String> a = new ArrayList<>(List.of("assemble"));
        a.addAll(Arrays.asList(tiles));
        a.addAll(List.of("-o", out.toString()));
        CliTest.Run r = run(a.toArray(new String[0]));
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains(message), r.err());
        assertEquals(1, r.err().lines().count(), r.err());
        assertFalse(Files.exists(out), "nothing is written");
    }

    @Test
    void tilesRecordTheirAnimationFrameAndTilesOfTwoFramesAreRefused() throws IOException {
        Path scene = dir.resolve("anim.dat");
        Files.writeString(scene, SCENE + "animation { frames 1 2  fps 2  shutter 90 }\n");
        for (int f = 1; f <= 2; f++) {
            for (int i = 1; i <= 2; i++) {
                CliTest.Run r = run(scene.toString(), "--frame", String.valueOf(f), "--tile", i + "/2",
                        "-o", dir.resolve("a_000" + f + ".tile_" + i + "_of_2.png").toString(), "--quiet");
                assertEquals(0, r.status(), r.err());
            }
        }
        assertEquals(Integer.valueOf(2), lt.spindulys.image.TileFile.readPlacement(dir.resolve("a_0002.tile_1_of_2.png")).frame());
        // A still's tile records no frame.
        assertEquals(null, lt.spindulys.image.TileFile.readPlacement(whole(scene(), "--tile", "1/2")).frame());
        assertRefused("a tile of frame 2, but", dir.resolve("a_0001.tile_1_of_2.png").toString(), dir.resolve("a_0002.tile_2_of_2.png").toString());
        // The frame asked for must be the one the tiles were rendered for, whatever their names say.
        for (int i = 1; i <= 2; i++) Files.copy(dir.resolve("a_0001.tile_" + i + "_of_2.png"), dir.resolve("c_0002.tile_" + i + "_of_2.png"));
        Path out = dir.resolve("b_2.png");
        CliTest.Run r = run("assemble", "--frame", "2", dir.resolve("c_####.tile_*_of_2.png").toString(), "-o", dir.resolve("b_#.png").toString());
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("a tile of frame 1, but --frame 2 was given"), r.err());
        assertFalse(Files.exists(out));
        r = run("assemble", "--frame", "2", dir.resolve("a_####.tile_*_of_2.png").toString(), "-o", dir.resolve("b_#.png").toString(), "--quiet");
        assertEquals(0, r.status(), r.err());
        assertTrue(Files.exists(out));

        // A retried task whose frames all exist still tells an OpenJD manager it is done.
        String frames = dir.resolve("d_####.png").toString();
        assertEquals(0, run(scene.toString(), "--frames", "1-2", "-o", frames, "--quiet").status());
        r = run(scene.toString(), "--frames", "1-2", "-o", frames, "--skip-existing", "--progress", "openjd");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("openjd_progress: 100.0"), r.out());
    }

    @Test
    void tilesThatDoNotCoverTheFrameExactlyOnceAreRefused() throws IOException {
        Path scene = scene();
        String[] t = new String[3];
        for (int i = 0; i < 3; i++) {
            t[i] = dir.resolve("b" + i + ".png").toString();
            assertEquals(0, run(scene.toString(), "--tile", (i + 1) + "/3", "-o", t[i], "--quiet").status());
        }
        String other = dir.resolve("other.png").toString();
        assertEquals(0, run(scene.toString(), "--tile", "2/3", "--width", "36", "-o", other, "--quiet").status());
        String overlapping = dir.resolve("overlap.png").toString();
        assertEquals(0, run(scene.toString(), "--region", "5,9,7,9", "-o", overlapping, "--quiet").status());
        Path notTile = whole(scene);

        assertRefused("render: the tiles cover 555 of the 851 pixels of the 37x23 frame, e.g. rows 7 to 14 (no tile has them): a tile is missing", t[0], t[2]);
        assertRefused("render: " + t[1] + " and " + t[1] + " overlap (regions 0,37,7,15 and 0,37,7,15)", t[0], t[1], t[1], t[2]);
        assertRefused(" overlap (regions ", t[0], t[1], t[2], overlapping);
        assertRefused(other + ": a tile of a 36x22 frame, but " + t[0] + " is of a 37x23 frame", t[0], other, t[2]);
        assertRefused(notTile + ": not a tile (no spindulys-region text chunk", t[0], notTile.toString());
        assertRefused(dir.resolve("missing.png") + ": tile not found", t[0], dir.resolve("missing.png").toString());
        assertRefused("no file matches the tile pattern", dir.resolve("nothing*.png").toString());
        Path damaged = dir.resolve("damaged.png");
        Files.write(damaged, Arrays.copyOf(Files.readAllBytes(Path.of(t[0])), 40));
        assertRefused(damaged + ": damaged PNG", damaged.toString());
    }

    @Test
    void badRegionsAndTilesAreUsageErrorsNamingTheOption() throws IOException {
        Path scene = scene();
        String out = dir.resolve("x.png").toString();
        String[][] cases = {
                {"--tile", "0/3", "render: --tile 0/3: tile 0/3 does not exist (tiles are numbered from 1 to their count)"},
                {"--tile", "4/3", "render: --tile 4/3: tile 4/3 does not exist (tiles are numbered from 1 to their count)"},
                {"--tile", "1-3", "render: --tile expects I/N, tile I of N counted from 1 (1/4 to 4/4), found '1-3'"},
                {"--tile", "1/24", "render: --tile 1/24: the 37x23 frame has 23 rows, too few for 24 tiles of whole rows"},
                {"--region", "0,38,0,1", "render: --region 0,38,0,1: the region 0,38,0,1 reaches past the 37x23 frame (x1 is at most 37)"},
                {"--region", "4,4,0,1", "render: --region: the region 4,4,0,1 is empty (x1 must be greater than x0)"},
                {"--region", "0,1,0", "render: --region: expected X0,X1,Y0,Y1 (four whole numbers separated by commas), found '0,1,0'"},
                {"--progress", "loud", "render: --progress expected openjd or plain, found 'loud'"},
        };
        for (String[] c : cases) {
            CliTest.Run r = run(scene.toString(), c[0], c[1], "-o", out);
            assertEquals(2, r.status(), r.err());
            assertEquals(c[2] + System.lineSeparator(), r.err());
        }
        CliTest.Run r = run(scene.toString(), "--tile", "1/2", "--region", "0,1,0,1", "-o", out);
        assertEquals("render: --region 0,1,0,1: the part of the frame was already given by --tile 1/2" + System.lineSeparator(), r.err());
        r = run(scene.toString(), "--tile", "1/2", "-o", dir.resolve("x.jpg").toString());
        assertEquals(2, r.status());
        assertTrue(r.err().startsWith("render: --tile 1/2: a region of a frame is written as a PNG tile"), r.err());
        r = run(scene.toString(), "--tile", "1/2", "--aov", "depth", "-o", out);
        assertEquals(2, r.status());
        assertTrue(r.err().startsWith("render: --tile 1/2: render passes (aov depth) are made for whole frames only"), r.err());
        assertFalse(Files.exists(Path.of(out)));
    }

    @Test
    void theHelpListsTheFarmOptionsInItsColumns() {
        CliTest.Run r = run("--help");
        assertEquals(0, r.status());
        assertTrue(r.out().startsWith("usage: render SCENE.dat "), r.out());
        for (String option : new String[] {"--region X0,X1,Y0,Y1  render", "--tile I/N         render", "--progress MODE    one line"}) {
            assertTrue(r.out().contains(System.lineSeparator() + "  " + option) || r.out().contains("\n  " + option), option);
        }
        r = run("assemble", "--help");
        assertTrue(r.out().startsWith("usage: render assemble TILE.png... -o OUT"), r.out());
    }

    @Test
    void openjdProgressIsLinesAManagerParsesAndTheStatusSaysHowItEnded() throws IOException {
        Path scene = scene();
        Path out = dir.resolve("p.png");
        CliTest.Run r = run(scene.toString(), "--progress", "openjd", "-o", out.toString(), "--tile", "2/2");
        assertEquals(0, r.status(), r.err());
        List<String> lines = r.out().lines().toList();
        for (String line : lines) assertTrue(line.matches("openjd_status: .+|openjd_progress: (\\d|[1-9]\\d|100)\\.\\d"), line);
        assertEquals("openjd_status: starting " + out, lines.get(0));
        assertEquals("openjd_progress: 100.0", lines.get(lines.size() - 2));
        assertTrue(lines.get(lines.size() - 1).startsWith("openjd_status: wrote " + out + " (region 0,37,11,23 of 37x23, 4 spp) in "), lines.toString());

        Path bad = dir.resolve("bad.dat");
        Files.writeString(bad, "sphere { radius }\n");
        r = run(bad.toString(), "--progress", "openjd", "-o", out.toString());
        assertEquals(2, r.status());
        List<String> failed = r.out().lines().toList();
        String error = r.err().strip();
        assertTrue(error.startsWith(bad + ":1:"), error);
        assertEquals("openjd_fail: " + error, failed.get(failed.size() - 1));
        assertTrue(failed.stream().noneMatch(l -> l.startsWith("openjd_progress: 100")), failed.toString());

        r = run(dir.resolve("none.dat").toString(), "--progress", "openjd");
        assertEquals(2, r.status());
        assertEquals("openjd_fail: " + r.err().strip(), r.out().lines().reduce((a, b) -> b).orElseThrow());
    }

    /**
     * An error in the arguments themselves, before anything is rendered, is an openjd_fail: line
     * too when --progress openjd is asked for, wherever it stands on the line.
     */
    @Test
    void argumentErrorsUnderOpenjdProgressEndWithOpenjdFail() throws IOException {
        String scene = scene().toString(), out = dir.resolve("x.png").toString();
        String[][] cases = {
                {scene, "--progress", "openjd", "--tile", "9/3", "-o", out},
                {scene, "--region", "0,1,0", "-o", out, "--progress", "openjd"},
                {scene, "--progress", "openjd", "--spp", "0"},
                {scene, "--progress", "openjd", "--fast"},
                {scene, "--progress", "openjd", "-o", dir.resolve("x.gif").toString()},
                {"--progress", "openjd"},
                {scene, "--progress", "openjd", "--tile", "1/2", "-o", dir.resolve("x.jpg").toString()},
        };
        for (String[] c : cases) {
            CliTest.Run r = run(c);
            assertEquals(2, r.status(), r.err());
            assertEquals(1, r.err().lines().count(), r.err());
            assertTrue(r.err().startsWith("render: "), r.err());
            assertEquals("openjd_fail: " + r.err().strip() + System.lineSeparator(), r.out(), String.join(" ", c));
        }
        // Without it, stdout stays empty.
        CliTest.Run r = run(scene, "--tile", "9/3", "-o", out);
        assertEquals(2, r.status());
        assertEquals("", r.out());
        assertFalse(Files.exists(Path.of(out)));
    }

    @Test
    void plainProgressPrintsLinesOnStderrAndNothingOnStdout() throws IOException {
        Path scene = scene();
        Path out = dir.resolve("plain.png");
        CliTest.Run r = run(scene.toString(), "--progress", "plain", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.out());
        List<String> lines = r.err().lines().toList();
        assertEquals("render: starting " + out + ", 0:00 elapsed", lines.get(0));
        for (String line : lines.subList(0, lines.size() - 1)) {
            assertTrue(line.matches("render: [a-z ]+ \\Q" + out + "\\E(, \\d+% done)?, \\d+:\\d\\d elapsed(, about \\d+:\\d\\d to go)?"), line);
        }
        assertTrue(lines.get(lines.size() - 1).startsWith("wrote " + out + " (37x23, 4 spp)"), lines.toString());
    }
}
