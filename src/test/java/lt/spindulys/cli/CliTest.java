package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.Images;

class CliTest {
    @TempDir Path dir;

    /** Exit status, stdout and stderr of one in-process run. */
    record Run(int status, String out, String err) {}

    static Run run(String... args) {
        ByteArrayOutputStream out = new ByteArrayOutputStream(), err = new ByteArrayOutputStream();
        int status = Main.run(args, new PrintStream(out, true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        return new Run(status, out.toString(StandardCharsets.UTF_8), err.toString(StandardCharsets.UTF_8));
    }

    private Path scene(String text) throws IOException {
        Path p = dir.resolve("scene.dat");
        Files.writeString(p, text);
        return p;
    }

    private static final String SMALL = """
            settings { width 24 height 16 }
            camera { eye 0 1 -4 lookat 0 0.5 0 }
            light { position 3 5 -4 }
            plane { normal 0 1 0 }
            sphere { center 0 0.5 0 radius 0.5 material { color 1 0 0 } }
            """;

    @Test
    void rendersEveryFormatWithOverrides() throws IOException {
        Path scene = scene(SMALL);
        for (String ext : new String[] {"png", "tga", "jpg", "pfm"}) {
            Path out = dir.resolve("out." + ext);
            Run r = run(scene.toString(), "-o", out.toString(), "--width", "20", "--height", "10", "--spp", "2", "--quiet");
            assertEquals(0, r.status(), r.err());
            FrameBuffer img = Images.read(out);
            assertEquals(20, img.width());
            assertEquals(10, img.height());
        }
    }

    @Test
    void oneSideAloneKeepsTheScenesAspectRatio() throws IOException {
        Path scene = scene(SMALL.replace("width 24 height 16", "width 800 height 450"));
        Path out = dir.resolve("one.png");
        // {option, value, expected width, expected height}
        int[][] cases = {{0, 40, 40, 23}, {1, 9, 16, 9}, {0, 1, 1, 1}, {1, 1, 2, 1}};
        for (int[] c : cases) {
            String option = c[0] == 0 ? "--width" : "--height";
            Run r = run(scene.toString(), "-o", out.toString(), option, Integer.toString(c[1]), "--spp", "1", "--quiet");
            assertEquals(0, r.status(), r.err());
            FrameBuffer img = Images.read(out);
            assertEquals(c[2] + "x" + c[3], img.width() + "x" + img.height(), option + " " + c[1]);
        }
    }

    @Test
    void aFinishedRenderEndsWithOneLineOnStderrUnlessQuiet() throws IOException {
        Path scene = scene(SMALL);
        Path out = dir.resolve("out.png");
        Run r = run(scene.toString(), "-o", out.toString(), "--spp", "2");
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.out());
        assertTrue(r.err().matches("wrote \\Q" + out + "\\E \\(24x16, 2 spp\\) in \\d+\\.\\d s" + System.lineSeparator()), r.err());

        // The passes are named after the image; --stats keeps stdout for its figures.
        r = run(scene.toString(), "-o", out.toString(), "--aov", "depth,object", "--width", "12", "--stats");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().startsWith("load:"), r.out());
        String passes = ", " + dir.resolve("out.depth.pfm") + ", " + dir.resolve("out.object.png");
        assertTrue(r.err().matches("wrote \\Q" + out + passes + "\\E \\(12x8, 1 spp\\) in \\d+\\.\\d s" + System.lineSeparator()), r.err());

        r = run(scene.toString(), "-o", out.toString(), "--quiet");
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
    }

    @Test
    void scaledSideRoundsAndStaysInRange() {
        assertEquals(225, RenderCommand.scaledSide(400, 800, 450));   // 800x450 --width 400
        assertEquals(400, RenderCommand.scaledSide(225, 450, 800));   // 800x450 --height 225
        assertEquals(23, RenderCommand.scaledSide(40, 800, 450));     // 22.5 rounds up
        assertEquals(1, RenderCommand.scaledSide(1, 1000, 1));        // never below one pixel
        assertEquals(32768, RenderCommand.scaledSide(32768, 1, 32768)); // never above MAX_SIDE
        assertEquals(32768, RenderCommand.scaledSide(100, 1, 32768));
    }

    @Test
    void everyAcceleratorRendersTheSameImage() throws IOException {
        // Enough objects for a scene-level structure, and meshes with structures of their own.
        StringBuilder text = new StringBuilder(SMALL.replace("settings { width 24 height 16 }", "settings { width 24 height 16 accelerator octree }"));
        for (int i = 0; i < 6; i++) {
            text.append("mesh { file \"tri.obj\" translate ").append(i * 0.3 - 0.9).append(" 0.2 ").append(i % 2).append(" }\n");
        }
        Files.writeString(dir.resolve("tri.obj"), "v 0 0 0\nv 0.3 0 0\nv 0 0.4 0.1\nv 0.3 0.4 0.2\nf 1 2 3\nf 2 4 3\n");
        Path scene = scene(text.toString());
        FrameBuffer first = null;
        for (String kind : new String[] {"bvh", "bvh2", "octree", "bruteforce", null}) {
            Path out = dir.resolve("acc-" + kind + ".pfm");
            Run r = kind == null ? run(scene.toString(), "-o", out.toString(), "--quiet")
                    : run(scene.toString(), "-o", out.toString(), "--accel", kind, "--quiet");
            assertEquals(0, r.status(), r.err());
            FrameBuffer img = Images.read(out);
            if (first == null) {
                first = img;
                continue;
            }
            org.junit.jupiter.api.Assertions.assertArrayEquals(first.data(), img.data(), String.valueOf(kind));
        }
    }

    /** The options override the scene: a path traced image differs from the Whitted one, its depth and clamp matter, and --integrator whitted restores the scene's image. */
    @Test
    void integratorOptionsOverrideTheScene() throws IOException {
        Path scene = scene(SMALL.replace("settings { width 24 height 16 }", "settings { width 24 height 16 integrator path maxdepth 3 }"));
        byte[][] images = new byte[5][];
        String[][] options = {{}, {"--integrator", "whitted"}, {"--maxdepth", "0"}, {"--clamp", "0.01"}, {"--integrator", "whitted", "--maxdepth", "3"}};
        for (int k = 0; k < options.length; k++) {
            Path out = dir.resolve("int-" + k + ".pfm");
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of(scene.toString(), "-o", out.toString(), "--quiet"));
            args.addAll(java.util.List.of(options[k]));
            Run r = run(args.toArray(new String[0]));
            assertEquals(0, r.status(), r.err());
            images[k] = Files.readAllBytes(out);
        }
        assertFalse(java.util.Arrays.equals(images[0], images[1]), "path tracing differs from Whitted");
        assertFalse(java.util.Arrays.equals(images[0], images[2]), "maxdepth 0 is direct light only");
        assertFalse(java.util.Arrays.equals(images[0], images[3]), "the clamp takes energy");
        assertArrayEquals(images[1], images[4], "Whitted at the scene's depth");
    }

    /**
     * --filter overrides the scene's filter, taking the filter's own default width unless it is
     * given after a comma or by --filter-width; the same filter and width as the scene's give
     * the scene's image.
     */
    @Test
    void filterOptionsOverrideTheScene() throws IOException {
        Path scene = scene(SMALL.replace("settings { width 24 height 16 }", "settings { width 24 height 16 samples 4 filter mitchell filterwidth 3 }"));
        String[][] options = {{}, {"--filter", "box"}, {"--filter", "mitchell"}, {"--filter", "mitchell,3"}, {"--filter-width", "3"},
                {"--filter", "mitchell", "--filter-width", "3"}, {"--filter-width", "3", "--filter", "mitchell"}, {"--filter", "blackman-harris,1.5"}};
        byte[][] images = new byte[options.length][];
        for (int k = 0; k < options.length; k++) {
            Path out = dir.resolve("filter-" + k + ".pfm");
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of(scene.toString(), "-o", out.toString(), "--quiet"));
            args.addAll(java.util.List.of(options[k]));
            Run r = run(args.toArray(new String[0]));
            assertEquals(0, r.status(), r.err());
            images[k] = Files.readAllBytes(out);
        }
        assertFalse(java.util.Arrays.equals(images[0], images[1]), "the box differs from the scene's Mitchell");
        assertFalse(java.util.Arrays.equals(images[0], images[2]), "Mitchell named alone is at its default width 4");
        for (int k = 3; k <= 6; k++) assertArrayEquals(images[0], images[k], "the scene's filter and width: " + String.join(" ", options[k]));
        assertFalse(java.util.Arrays.equals(images[0], images[7]));
    }

    @Test
    void statsPrintRaysAndThroughput() throws IOException {
        Run r = run(scene(SMALL).toString(), "-o", dir.resolve("a.png").toString(), "--stats", "--threads", "1");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("rays:    384 camera"), r.out());
        assertTrue(r.out().matches("(?s).*speed: +\\d+\\.\\d+ Mrays/s.*"), r.out());
        // The whole process's peak, where the kernel tells it (Linux); no line elsewhere.
        boolean proc = Files.isReadable(Path.of("/proc/self/status"));
        java.util.regex.Matcher m = java.util.regex.Pattern.compile("(?m)^memory:  (\\d+\\.\\d) MiB peak resident$").matcher(r.out());
        assertEquals(proc, m.find(), r.out());
        if (proc) assertTrue(Double.parseDouble(m.group(1)) > 0, r.out());
    }

    @Test
    void statsPrintEachMeshsTreeCost() throws IOException {
        // A mesh of more than one leaf's triangles has a tree; --stats names it with its SAH cost.
        StringBuilder obj = new StringBuilder();
        for (int i = 0; i < 8; i++) obj.append("v ").append(i * 0.2).append(" 0 0\nv ").append(i * 0.2).append(" 0.3 0\nv ").append(i * 0.2 + 0.1).append(" 0 0.2\n");
        for (int i = 0; i < 8; i++) obj.append("f ").append(3 * i + 1).append(' ').append(3 * i + 2).append(' ').append(3 * i + 3).append('\n');
        Files.writeString(dir.resolve("strip.obj"), obj.toString());
        Path scene = scene(SMALL + "mesh { file \"strip.obj\" name \"strip\" }\n");
        Run r = run(scene.toString(), "-o", dir.resolve("m.png").toString(), "--stats", "--threads", "1");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().matches("(?s).*\nmesh strip: 8 triangles, SAH cost \\d+\\.\\d{4}(, [a-z ]+)?, \\d+\\.\\d bytes/triangle\n.*"), r.out());
    }

    @Test
    void helpAndVersion() {
        Run help = run("--help");
        assertEquals(0, help.status());
        assertTrue(help.out().contains("usage: render SCENE.dat"));
        Run version = run("--version");
        assertEquals(0, version.status());
        assertTrue(version.out().startsWith("spindulys "));
        Run none = run();
        assertEquals(2, none.status());
    }

    /** --shutter and --timesteps reach the renderer: a closed shutter freezes the motion, time steps change the image but not with the thread count. */
    @Test
    void shutterAndTimeStepsOverrideTheScene() throws IOException {
        Path still = dir.resolve("still.dat"), moving = dir.resolve("moving.dat");
        Files.writeString(still, SMALL);
        Files.writeString(moving, SMALL.replace("radius 0.5 material", "radius 0.5 motion { translate 1 0 0 } material"));
        Path a = dir.resolve("a.pfm"), b = dir.resolve("b.pfm"), c = dir.resolve("c.pfm"), d = dir.resolve("d.pfm"), e = dir.resolve("e.pfm");
        assertEquals(0, run(still.toString(), "-o", a.toString(), "--spp", "4", "--quiet").status());
        Run r = run(moving.toString(), "-o", b.toString(), "--spp", "4", "--shutter", "0,0", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(Files.readAllBytes(a), Files.readAllBytes(b), "a shutter closed at 0 sees the sphere where it starts");
        assertEquals(0, run(moving.toString(), "-o", c.toString(), "--spp", "4", "--quiet").status());
        assertEquals(0, run(moving.toString(), "-o", d.toString(), "--spp", "4", "--timesteps", "2", "--threads", "1", "--quiet").status());
        assertEquals(0, run(moving.toString(), "-o", e.toString(), "--spp", "4", "--timesteps", "2", "--threads", "3", "--quiet").status());
        assertFalse(java.util.Arrays.equals(Files.readAllBytes(a), Files.readAllBytes(c)), "the sphere moved");
        assertFalse(java.util.Arrays.equals(Files.readAllBytes(c), Files.readAllBytes(d)), "time steps render differently");
        assertArrayEquals(Files.readAllBytes(d), Files.readAllBytes(e), "time steps do not depend on the thread count");
    }

    @Test
    void adaptiveSamplingSaysTheMeanSamplesAndWritesTheNoisePass() throws IOException {
        Path out = dir.resolve("adaptive.png");
        Run r = run(scene(SMALL).toString(), "-o", out.toString(), "--spp", "32", "--noise-threshold", "0.05", "--min-samples", "8", "--aov", "noise", "--threads", "2");
        assertEquals(0, r.status(), r.err());
        assertTrue(r.err().matches("wrote \\Q" + out + ", " + dir.resolve("adaptive.noise.pfm")
                + "\\E \\(24x16, \\d+\\.\\d of 32 spp adaptive\\) in \\d+\\.\\d s" + System.lineSeparator()), r.err());
        lt.spindulys.image.FrameBuffer noise = lt.spindulys.image.Images.read(dir.resolve("adaptive.noise.pfm"));
        double min = Double.POSITIVE_INFINITY, max = 0;
        for (int y = 0; y < 16; y++) for (int x = 0; x < 24; x++) { min = Math.min(min, noise.get(x, y, 0)); max = Math.max(max, noise.get(x, y, 0)); }
        assertTrue(min >= 8 && max <= 32 && min < max, "samples from " + min + " to " + max);
    }

    @Test
    void badUsageIsOneLineAndExitsTwo() throws IOException {
        Path scene = scene(SMALL);
        String[][] cases = {
                {"render: unknown option '--widht' (see render --help)", scene.toString(), "--widht", "3"},
                {"render: --width expects a whole number, found 'ten'", scene.toString(), "--width", "ten"},
                {"render: --spp must be between 1 and 65536, found 0", scene.toString(), "--spp", "0"},
                {"render: --accel expects one of bvh, bvh-compact, bvh2, octree, bruteforce, found 'kdtree'", scene.toString(), "--accel", "kdtree"},
                {"render: option -o needs a value", scene.toString(), "-o"},
                {"render: unsupported output format '.bmp' (expected .tga, .png, .jpg, .jpeg, .pfm or .exr)", scene.toString(), "-o", dir.resolve("x.bmp").toString()},
                {"render: no scene file given (see render --help)", "--quiet"},
                {"render: --shutter expects OPEN,CLOSE (two numbers separated by a comma), found '1'", scene.toString(), "--shutter", "1"},
                {"render: --shutter must close after it opens, found '1,0'", scene.toString(), "--shutter", "1,0"},
                {"render: --timesteps must be between 1 and 65536, found 0", scene.toString(), "--timesteps", "0"},
                {"render: --integrator expects one of whitted, path, found 'photon'", scene.toString(), "--integrator", "photon"},
                {"render: --maxdepth must be between 0 and 64, found 65", scene.toString(), "--maxdepth", "65"},
                {"render: --clamp must be between 0 and 100, found -1", scene.toString(), "--clamp", "-1"},
                {"render: --filter expects one of box, gaussian, blackman-harris, mitchell, found 'lanczos'", scene.toString(), "--filter", "lanczos"},
                {"render: --filter width must be between 0.1 and 16 pixels, found 0", scene.toString(), "--filter", "gaussian,0"},
                {"render: --filter-width expects a width in pixels, found 'wide'", scene.toString(), "--filter-width", "wide"},
                {"render: --spp 3 is not a multiple of --timesteps 2 (each time step renders spp / timesteps per pixel)", scene.toString(),
                        "--spp", "3", "--timesteps", "2", "-o", dir.resolve("x.png").toString()},
                {"render: --noise-threshold must be between 0 and 1, found 2", scene.toString(), "--noise-threshold", "2"},
                {"render: --min-samples must be between 0 and 65536, found -1", scene.toString(), "--min-samples", "-1"},
                {"render: --spp 16 --noise-threshold 0.01 --min-samples 32: minsamples 32 is more than samples 16 (expected at most the samples per pixel)",
                        scene.toString(), "--spp", "16", "--noise-threshold", "0.01", "--min-samples", "32", "-o", dir.resolve("x.png").toString()},
                {"render: --spp 4 --noise-threshold 0.01 --timesteps 2: noisethreshold 0.01 needs timesteps 1, found 2 (adaptive sampling stops a pixel on all its samples at once)",
                        scene.toString(), "--spp", "4", "--noise-threshold", "0.01", "--timesteps", "2", "-o", dir.resolve("x.png").toString()},
        };
        for (String[] c : cases) {
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            Run r = run(args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(c[0] + System.lineSeparator(), r.err(), String.join(" ", args));
        }
        Run missing = run(dir.resolve("nope.dat").toString(), "-o", dir.resolve("n.png").toString());
        assertEquals(2, missing.status());
        assertEquals(dir.resolve("nope.dat") + ": scene file not found" + System.lineSeparator(), missing.err());
        Run noDir = run(scene.toString(), "-o", dir.resolve("no/such/dir/x.png").toString());
        assertEquals(2, noDir.status());
        assertTrue(noDir.err().contains("does not exist"), noDir.err());
        try (var files = Files.list(dir)) {
            assertEquals(1, files.count(), "nothing but the scene was created");
        }
    }

    @Test
    void badSceneKeepsAnExistingImageAndPrintsNoStackTrace() throws IOException {
        Path out = dir.resolve("keep.png");
        Files.write(out, new byte[] {1, 2, 3});
        Run r = run(scene("sphere { radius -1 }").toString(), "-o", out.toString());
        assertEquals(2, r.status());
        assertEquals(1, r.err().lines().count(), r.err());
        assertTrue(r.err().startsWith(dir.resolve("scene.dat") + ":1:"), r.err());
        assertArrayEquals(new byte[] {1, 2, 3}, Files.readAllBytes(out), "existing output untouched");
        Run debug = run(scene("sphere { radius -1 }").toString(), "-o", out.toString(), "--debug");
        assertTrue(debug.err().lines().count() > 1, "--debug adds the stack trace");
    }

    @Test
    void benchListsItsRowsAndRefusesUnknownOnes() {
        Run list = run("bench", "--list");
        assertEquals(0, list.status(), list.err());
        assertTrue(list.out().startsWith("refine-bishop "), list.out());
        assertTrue(list.out().contains(System.lineSeparator() + "refine-loop-bishop "), list.out());
        assertTrue(list.out().contains(System.lineSeparator() + "torus-1m "), list.out());
        assertTrue(list.out().contains(System.lineSeparator() + "soft-shadow            scenes/bench/soft-shadow.dat: "), list.out());
        assertTrue(list.out().contains(System.lineSeparator() + "adaptive-close         [adaptive] "), list.out());
        assertTrue(list.out().contains(System.lineSeparator() + "viewer                 [viewer] "), list.out());
        assertEquals(2, run("bench", "--cell-timeout", "0").status());
        Run unknown = run("bench", "--only", "nope");
        assertEquals(2, unknown.status());
        assertEquals("render: unknown bench row 'nope' (rows: refine-bishop, refine-loop-bishop, torus-1k, torus-16k, torus-250k, torus-1m, knot-1m, torus-1m-close, soft-shadow, soft-shadow-light16, soft-shadow-16k, path-torus, csg-subdiv, motion-blur, "
                + "adaptive-close, adaptive-huge, adaptive-lazy, adaptive-cache, torus-1k-lazy, torus-1k-combined, torus-1k-projected, "
                + "torus-1k-close, adaptive-warm, torus-1k-level2, torus-1k-level2-lazy, viewer; "
                + "groups: adaptive, viewer)" + System.lineSeparator(), unknown.err());
        // A list names rows and groups; each must exist.
        Run unknownInList = run("bench", "--only", "torus-1k,viewer,nope");
        assertEquals(2, unknownInList.status());
        assertTrue(unknownInList.err().startsWith("render: unknown bench row 'nope' (rows: "), unknownInList.err());
        assertEquals(0, run("bench", "--only", "soft-shadow", "--list").status(), "--only takes the soft-shadow row");
        Run badPeer = run("bench", "--peers", "embree,sunflow");
        assertEquals(2, badPeer.status());
        assertEquals("render: unknown peer 'sunflow' in --peers (expected embree, povray, cycles or none)" + System.lineSeparator(), badPeer.err());
        Run badRuns = run("bench", "--runs", "0");
        assertEquals(2, badRuns.status());
        Run badAccel = run("bench", "--accel", "kdtree");
        assertEquals(2, badAccel.status());
        assertEquals("render: unknown accelerator 'kdtree' (expected one of bvh, bvh-compact, bvh2, octree, bruteforce)" + System.lineSeparator(), badAccel.err());
        assertEquals(0, run("bench", "--help").status());
    }
}
