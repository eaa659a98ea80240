package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.scene.Animation;

/** The frame half of the farm contract: frame ranges, output names, --skip-existing and exit codes. */
class CliFramesTest {
    @TempDir Path dir;

    private static CliTest.Run run(String... args) { return CliTest.run(args); }

    /**
     * Everything that moves across and within frames: a lens on a turntable camera, smooth keys, a
     * keyed CSG node with a moving operand, and each frame's own seed behind the jittered samples.
     */
    private static final String ANIMATED = """
            settings { width 24 height 16 samples 4 }
            animation { frames 1 6  fps 6  shutter 180 }
            camera { eye 0 1 -4  lookat 0 0.5 0  aperture 0.05  turntable { turns 0.25 } }
            light { position 3 5 -4 }
            plane { normal 0 1 0 }
            sphere { radius 0.4  material { color 1 0 0 }
                     keys { interpolation smooth  key 1 { translate -1 0.5 0 }  key 3 { translate 0 1 0 }  key 6 { translate 1 0.5 0 } } }
            difference { box { min -0.3 0 -0.3  max 0.3 0.6 0.3 }
                         sphere { radius 0.35  translate 0 0.6 0  motion { translate 0.2 0 0 } }
                         keys { key 1 { }  key 6 { rotate 0 180 0 } }  translate 1.2 0 1 }
            """;

    private Path scene(String text) throws IOException {
        Path p = dir.resolve("anim.dat");
        Files.writeString(p, text);
        return p;
    }

    private String out(String name) { return dir.resolve(name).toString(); }

    private byte[] bytes(String name) throws IOException { return Files.readAllBytes(dir.resolve(name)); }

    @Test
    void framesRenderedInChunksEqualTheSameFramesFromOneRun() throws IOException {
        Path s = scene(ANIMATED);
        CliTest.Run whole = run(s.toString(), "-o", out("whole_####.pfm"), "--quiet");
        assertEquals(0, whole.status(), whole.err());
        for (int f = 1; f <= 6; f++) assertTrue(Files.exists(dir.resolve("whole_000" + f + ".pfm")), "frame " + f);
        assertEquals(0, run(s.toString(), "--frames", "1-2", "-o", out("chunk_####.pfm"), "--quiet").status());
        assertEquals(0, run(s.toString(), "--frames", "3-6:3", "-o", out("chunk_####.pfm"), "--quiet", "--threads", "1").status());
        assertEquals(0, run(s.toString(), "--frames", "5", "-o", out("chunk_####.pfm"), "--quiet", "--threads", "3").status());
        assertEquals(0, run(s.toString(), "--frame", "4", "-o", out("single.pfm"), "--quiet").status());
        for (int f : new int[] {1, 2, 3, 5, 6}) {
            assertArrayEquals(bytes("whole_000" + f + ".pfm"), bytes("chunk_000" + f + ".pfm"), "frame " + f);
        }
        assertFalse(Files.exists(dir.resolve("chunk_0004.pfm")), "a step of 3 from 3 skips 4");
        assertArrayEquals(bytes("whole_0004.pfm"), bytes("single.pfm"));
        // And the frames do differ: the animation moves.
        assertFalse(Arrays.equals(bytes("whole_0001.pfm"), bytes("whole_0002.pfm")));
        // A lens given on the command line rides along with the turning camera.
        assertEquals(0, run(s.toString(), "--frame", "4", "--aperture", "0.2", "-o", out("lens.pfm"), "--quiet").status());
        assertFalse(Arrays.equals(bytes("whole_0004.pfm"), bytes("lens.pfm")));
    }

    /** A turning camera blurs a still scene across its shutter: the samples draw times though no object moves. */
    @Test
    void aMovingCameraAloneBlursTheFrame() throws IOException {
        String body = """
                settings { width 64 height 48 samples 16 background 0 0 0 ambient 1 1 1 }
                camera { eye 0 1 -6 lookat 0 0 0 fov 40 turntable { axis 0 1 0 center 0 0 0 } }
                sphere { center 1.5 0 0 radius 0.5 material { color 1 1 1 ka 1 kd 0 } }
                """;
        Path blurred = scene("animation { frames 1 2 fps 1 shutter 180 }\n" + body);
        assertEquals(0, run(blurred.toString(), "--frame", "1", "-o", out("blurred.png"), "--quiet").status());
        Path sharp = Files.writeString(dir.resolve("sharp.dat"), "animation { frames 1 2 fps 1 shutter 0 }\n" + body);
        assertEquals(0, run(sharp.toString(), "--frame", "1", "-o", out("sharp.png"), "--quiet").status());
        int streak = partlyCovered(dir.resolve("blurred.png")), edge = partlyCovered(dir.resolve("sharp.png"));
        assertTrue(streak > 3 * edge, "partly covered pixels: " + streak + " blurred, " + edge + " sharp");
    }

    /** Pixels the white sphere covers only in part: its anti-aliased edge, or its motion streak. */
    private static int partlyCovered(Path image) throws IOException {
        lt.spindulys.image.FrameBuffer f = lt.spindulys.image.Images.read(image);
        int n = 0;
        for (int y = 0; y < f.height(); y++) for (int x = 0; x < f.width(); x++) if (f.get(x, y, 0) > 0.05 && f.get(x, y, 0) < 0.95) n++;
        return n;
    }

    /** At a key, with the shutter closed, a keyed object is exactly where a still puts it at that pose. */
    @Test
    void aKeyedObjectAtItsKeyIsWhereTheStillPutsIt() throws IOException {
        String body = """
                settings { width 24 height 16 samples 2 }
                camera { eye 0 1 -4  lookat 0 0.5 0 }
                light { position 3 5 -4 }
                plane { normal 0 1 0 }
                """;
        Path animated = scene(body + "animation { frames 1 3  fps 1  shutter 0 }\n"
                + "sphere { radius 0.4  keys { key 1 { translate -1 0.5 0 }  key 3 { translate 1 0.5 0  rotate 0 0 90 } } }");
        Path still = dir.resolve("still.dat");
        Files.writeString(still, body + "sphere { radius 0.4  rotate z 90  translate 1 0.5 0 }");
        assertEquals(0, run(animated.toString(), "--frame", "3", "-o", out("frame.pfm"), "--quiet").status());
        CliTest.Run r = run(still.toString(), "--seed", Long.toString(Animation.frameSeed(0, 3)), "-o", out("still.pfm"), "--quiet");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(bytes("still.pfm"), bytes("frame.pfm"));
    }

    @Test
    void severalFramesNeedAPlaceForTheFrameNumber() throws IOException {
        Path s = scene(ANIMATED);
        CliTest.Run r = run(s.toString(), "-o", out("out.png"), "--quiet");
        assertEquals(2, r.status());
        assertEquals("render: -o " + out("out.png") + ": 6 frames (1-6) need a run of '#' in the output name for the frame number, such as out_####.png, or one frame (--frame N)\n", r.err());
        r = run(s.toString(), "--frames", "2-4:2", "-o", out("out.png"), "--quiet");
        assertEquals(2, r.status());
        assertTrue(r.err().contains("2 frames (2-4:2) need a run of '#'"), r.err());
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "nothing written but the scene");
        }
        // One frame may go to any name.
        assertEquals(0, run(s.toString(), "--frame", "2", "-o", out("out.png"), "--quiet").status());
        assertTrue(Files.exists(dir.resolve("out.png")));
        // Padding: the run's length, and a longer number whole.
        assertEquals(0, run(s.toString(), "--frames", "1-2", "-o", out("f#.png"), "--quiet").status());
        assertTrue(Files.exists(dir.resolve("f1.png")) && Files.exists(dir.resolve("f2.png")));
    }

    @Test
    void outputPatterns() throws UsageException {
        assertEquals(Path.of("out_0007.png"), OutputPattern.of(Path.of("out_####.png")).forFrame(7));
        assertEquals(Path.of("out_12345.png"), OutputPattern.of(Path.of("out_####.png")).forFrame(12345));
        assertEquals(Path.of("dir/a07b.pfm"), OutputPattern.of(Path.of("dir/a##b.pfm")).forFrame(7));
        assertEquals(Path.of("0000000.tga"), OutputPattern.of(Path.of("#######.tga")).forFrame(0));
        // A '#' in a folder's name is not a place for the number.
        OutputPattern folder = OutputPattern.of(Path.of("take#2/out.png"));
        assertFalse(folder.hasFrame());
        assertEquals(Path.of("take#2/out.png"), folder.forFrame(3));
        UsageException e = assertThrows(UsageException.class, () -> OutputPattern.of(Path.of("a##_##.png")));
        assertTrue(e.getMessage().contains("more than one run of '#'"), e.getMessage());
        assertEquals(Path.of("dir/scene_####.png"), OutputPattern.defaultForFrames(Path.of("dir/scene.png")));
    }

    @Test
    void frameRanges() throws UsageException {
        assertEquals(new FrameRange(1, 48, 1), FrameRange.parse("--frames", "1-48"));
        assertEquals(new FrameRange(1, 48, 4), FrameRange.parse("--frames", "1-48:4"));
        assertEquals(new FrameRange(7, 7, 1), FrameRange.parse("--frames", "7"));
        assertEquals(new FrameRange(7, 7, 1), FrameRange.parse("--frame", "7"));
        FrameRange r = FrameRange.parse("--frames", "1-10:4");
        assertEquals(3, r.count());
        assertEquals(9, r.lastFrame());
        for (String bad : new String[] {"", "a", "1-", "-3", "5-3", "1-4:0", "1-4:", "1.5", "+1", "12345678", "1-2-3"}) {
            assertThrows(UsageException.class, () -> FrameRange.parse("--frames", bad), bad);
        }
        assertThrows(UsageException.class, () -> FrameRange.parse("--frame", "1-3"));
        assertThrows(UsageException.class, () -> FrameRange.parse("--frame", "1:2"));
    }

    @Test
    void skipExistingLeavesFinishedFramesAndRendersMissingOnes() throws IOException {
        Path s = scene(ANIMATED);
        assertEquals(0, run(s.toString(), "--frames", "1-3", "-o", out("s_####.pfm"), "--quiet").status());
        byte[] second = bytes("s_0002.pfm");
        byte[] marker = "finished by an earlier task".getBytes(StandardCharsets.UTF_8);
        Files.write(dir.resolve("s_0001.pfm"), marker);
        Files.delete(dir.resolve("s_0002.pfm"));
        CliTest.Run r = run(s.toString(), "--frames", "1-3", "-o", out("s_####.pfm"), "--skip-existing");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(marker, bytes("s_0001.pfm"), "a finished frame is not rendered again");
        assertArrayEquals(second, bytes("s_0002.pfm"), "a missing one is, the same as before");
        assertTrue(r.err().contains("skipped " + out("s_0001.pfm") + " (frame 1): it exists (--skip-existing)"), r.err());
        assertTrue(r.err().contains("wrote " + out("s_0002.pfm")), r.err());
        assertFalse(r.err().contains("wrote " + out("s_0003.pfm")), r.err());
        // Without the option every frame is rendered.
        assertEquals(0, run(s.toString(), "--frames", "1", "-o", out("s_####.pfm"), "--quiet").status());
        assertFalse(Arrays.equals(marker, bytes("s_0001.pfm")));
    }

    @Test
    void skipExistingWantsThePassesToo() throws IOException {
        Path s = scene(ANIMATED);
        assertEquals(0, run(s.toString(), "--frame", "2", "--aov", "depth", "-o", out("p_####.png"), "--quiet").status());
        Files.delete(dir.resolve("p_0002.depth.pfm"));
        CliTest.Run r = run(s.toString(), "--frame", "2", "--aov", "depth", "-o", out("p_####.png"), "--skip-existing");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("wrote " + out("p_0002.png")), r.err());
        assertTrue(Files.exists(dir.resolve("p_0002.depth.pfm")));
    }

    @Test
    void skipExistingLeavesAnExistingStillToo() throws IOException {
        Path still = dir.resolve("still.dat");
        Files.writeString(still, "settings { width 8 height 6 }\nsphere { }\n");
        byte[] marker = "finished by an earlier task".getBytes(StandardCharsets.UTF_8);
        Files.write(dir.resolve("still.png"), marker);
        CliTest.Run r = run(still.toString(), "-o", out("still.png"), "--skip-existing");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(marker, bytes("still.png"), "an existing still is not rendered again");
        assertEquals("skipped " + out("still.png") + ": it exists (--skip-existing)" + System.lineSeparator(), r.err());
        r = run(still.toString(), "-o", out("still.png"), "--skip-existing", "--progress", "openjd", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("openjd_status: " + out("still.png") + " exists (--skip-existing)"), r.out());
        // Without the option, or with the image missing, the still is rendered.
        assertEquals(0, run(still.toString(), "-o", out("still.png"), "--quiet").status());
        assertFalse(Arrays.equals(marker, bytes("still.png")));
        Files.delete(dir.resolve("still.png"));
        r = run(still.toString(), "-o", out("still.png"), "--skip-existing");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().contains("wrote " + out("still.png")), r.err());
    }

    @Test
    void badFrameRequestsAreOneLineUsageErrors() throws IOException {
        Path s = scene(ANIMATED);
        Path still = dir.resolve("still.dat");
        Files.writeString(still, "sphere { }");
        String[][] cases = {
                {s.toString(), "--frame", "9", "-o", out("x.png")},
                {s.toString(), "--frames", "0-3", "-o", out("x_#.png")},
                {still.toString(), "--frames", "1-3", "-o", out("x_#.png")},
                {s.toString(), "--frames", "3-1"},
                {s.toString(), "--frame", "1", "--frames", "2-3"},
                {s.toString(), "--shutter", "0,1", "-o", out("x_#.png")},
                {s.toString(), "--frames"},
                {s.toString(), "-o", out("missing/x_#.png")},
        };
        String[] messages = {
                "render: --frame 9: outside the frames of " + s + "'s animation, 1-6",
                "render: --frames 0-3: outside the frames of " + s + "'s animation, 1-6",
                "render: --frames 1-3: " + still + " has no animation statement (animation { frames FIRST LAST  fps F }), so it has no frames",
                "render: --frames must not end before it starts, found '3-1'",
                "render: --frames given after --frame 1: give one frame range",
                "render: --shutter does not combine with an animation's frames: each frame's shutter is set by its shutter angle",
                "render: option --frames needs a value",
                "render: ",
        };
        for (int i = 0; i < cases.length; i++) {
            CliTest.Run r = run(cases[i]);
            assertEquals(2, r.status(), String.join(" ", cases[i]) + ": " + r.err());
            assertTrue(r.err().startsWith(messages[i]), r.err());
            assertEquals(1, r.err().lines().count(), r.err());
        }
        try (var files = Files.list(dir)) {
            assertEquals(2, files.count(), "nothing written but the scenes");
        }
    }

    /** A run stops at the first frame that fails, non-zero with its one-line error; the frames before it stay. */
    @Test
    void aFailingFrameStopsTheRun() throws IOException {
        Path s = scene(ANIMATED);
        Files.createDirectory(dir.resolve("w_0002.png")); // frame 2's output cannot be written
        CliTest.Run r = run(s.toString(), "--frames", "1-3", "-o", out("w_####.png"), "--quiet");
        assertTrue(r.status() != 0);
        assertEquals(1, r.err().lines().count(), r.err());
        assertTrue(r.err().contains("w_0002.png"), r.err());
        assertTrue(Files.isRegularFile(dir.resolve("w_0001.png")));
        assertFalse(Files.exists(dir.resolve("w_0003.png")));
    }
}
