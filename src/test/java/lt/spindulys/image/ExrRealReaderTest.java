package lt.spindulys.image;

import static org.junit.jupiter.api.Assertions.*;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.EnumSet;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Files of the OpenEXR writer read by the OpenEXR library's own tools (Debian package openexr:
 * exrheader, exrinfo, exrmaketiled) and by Blender's loader (Debian package blender). Each test is skipped, saying why, where its tool is not on
 * the PATH.
 */
class ExrRealReaderTest {
    private static final int W = 13, H = 37;

    @TempDir Path dir;

    private record Result(int status, String output) {}

    private static boolean onPath(String tool) {
        String path = System.getenv("PATH");
        if (path == null) return false;
        for (String folder : path.split(File.pathSeparator)) {
            if (!folder.isEmpty() && Files.isExecutable(Path.of(folder, tool))) return true;
        }
        return false;
    }

    private static void assumeTool(String tool) {
        assumeTrue(onPath(tool), tool + " is not on the PATH (it comes with the OpenEXR tools, Debian package openexr)");
    }

    private static Result run(String... command) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        byte[] out = p.getInputStream().readAllBytes();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), String.join(" ", command) + " did not finish");
        return new Result(p.exitValue(), new String(out, StandardCharsets.UTF_8));
    }

    /** A frame and all its passes, with smooth and rough values and the depth's infinite background. */
    private Path write(String name, ExrPrecision precision, ExrCompression compression) throws IOException {
        FrameBuffer fb = new FrameBuffer(W, H);
        AovFrame aovs = new AovFrame(W, H, EnumSet.allOf(Aov.class));
        java.util.Random random = new java.util.Random(3);
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                fb.set(x, y, x / (double) W, random.nextDouble() * 100, y == 5 ? 1e6 : 0.5);
                if (x == y) aovs.setBackground(x, y);
                else aovs.setHit(x, y, x * 0.37 + y, 0.6, 0, -0.8, x + y * W);
            }
        }
        Path out = dir.resolve(name);
        ImageWriter.write(fb, out, ImageOptions.DEFAULT.withExr(precision, compression), aovs);
        return out;
    }

    @Test
    void exrheaderReadsTheHeader() throws Exception {
        assumeTool("exrheader");
        for (ExrCompression compression : ExrCompression.values()) {
            for (ExrPrecision precision : ExrPrecision.values()) {
                Path file = write(compression.keyword() + "-" + precision.keyword() + ".exr", precision, compression);
                Result r = run("exrheader", file.toString());
                assertEquals(0, r.status(), r.output());
                String colour = precision == ExrPrecision.HALF ? "16-bit floating-point" : "32-bit floating-point";
                String out = r.output();
                assertTrue(out.contains("file format version: 2, flags 0x0"), out);
                assertTrue(out.contains("    A, " + colour), out);
                assertTrue(out.contains("    Normal.Z, " + colour), out);
                assertTrue(out.contains("    R, " + colour), out);
                assertTrue(out.contains("    Z, 32-bit floating-point"), out);
                assertTrue(out.contains("    IndexOB.X, 32-bit floating-point"), out);
                assertTrue(out.contains("dataWindow (type box2i): (0 0) - (12 36)"), out);
                String named = switch (compression) {
                    case NONE -> "none";
                    case ZIPS -> "zip, individual scanlines";
                    case ZIP -> "zip, multi-scanline blocks";
                };
                assertTrue(out.contains("compression (type compression): " + named), out);
            }
        }
    }

    @Test
    void exrinfoAcceptsEveryKind() throws Exception {
        assumeTool("exrinfo");
        for (ExrCompression compression : ExrCompression.values()) {
            for (ExrPrecision precision : ExrPrecision.values()) {
                Path file = write(compression.keyword() + "-" + precision.keyword() + ".exr", precision, compression);
                Result r = run("exrinfo", "-v", "-s", file.toString());
                assertEquals(0, r.status(), r.output());
                assertTrue(r.output().contains("IndexOB.X"), r.output());
            }
        }
    }

    /**
     * The library decodes every pixel of the file and stores them again, uncompressed, as one
     * tile the size of the image: that tile must hold exactly the bytes the writer's own
     * uncompressed file holds, whatever compression the library read.
     */
    @Test
    void theLibraryDecodesThePixelsTheWriterStored() throws Exception {
        assumeTool("exrmaketiled");
        for (ExrPrecision precision : ExrPrecision.values()) {
            byte[] expected = pixelBytes(write("raw-" + precision.keyword() + ".exr", precision, ExrCompression.NONE), precision);
            for (ExrCompression compression : ExrCompression.values()) {
                Path file = write(compression.keyword() + "-" + precision.keyword() + ".exr", precision, compression);
                Path tiled = dir.resolve("tiled-" + compression.keyword() + "-" + precision.keyword() + ".exr");
                Result r = run("exrmaketiled", "-o", "-z", "none", "-t", String.valueOf(W), String.valueOf(H), file.toString(), tiled.toString());
                assertEquals(0, r.status(), r.output());
                byte[] all = Files.readAllBytes(tiled);
                // A one-tile, one-level file ends with that tile's pixel data.
                byte[] tile = Arrays.copyOfRange(all, all.length - expected.length, all.length);
                assertArrayEquals(expected, tile, compression + " " + precision);
            }
        }
    }

    /**
     * Blender's own OpenEXR loader (the peer kit's Blender 3.x, run headless) reads a file with
     * every pass as a layered image whose passes carry Blender's names (the compositor's Image
     * node lists the passes it recognised), and a file of colour alone as a plain image holding
     * our colours.
     */
    /** The passes Blender's compositor shows for a file with every pass (its names for ours), sorted. */
    private static final List<String> EXPECTED_BLENDER_PASSES = List.of("Albedo", "Alpha", "Combined", "Depth", "IndexOB", "Noise", "Normal", "Samples");

    @Test
    void blenderNamesEveryPassAndReadsTheColours() throws Exception {
        assumeTrue(onPath("blender"), "blender is not on the PATH (Debian package blender, as the peer kit installs it)");
        Path passes = write("passes.exr", ExrPrecision.FLOAT, ExrCompression.ZIP);
        FrameBuffer fb = new FrameBuffer(W, H);
        for (int y = 0; y < H; y++) for (int x = 0; x < W; x++) fb.set(x, y, x / (double) W, y / (double) H, x == 7 ? 1e6 : 0.5);
        Path colour = dir.resolve("colour.exr");
        ImageWriter.write(fb, colour, ImageOptions.DEFAULT.withExr(ExrPrecision.FLOAT, ExrCompression.ZIPS));
        Path script = dir.resolve("read.py");
        Files.writeString(script, """
                import bpy, sys
                passes, colour = sys.argv[sys.argv.index('--') + 1:]
                bpy.context.scene.use_nodes = True
                node = bpy.context.scene.node_tree.nodes.new('CompositorNodeImage')
                node.image = bpy.data.images.load(passes)
                print('PASSES', ','.join(o.name for o in node.outputs))
                img = bpy.data.images.load(colour)
                w, h = img.size
                px = img.pixels[:]
                # Blender's rows run bottom-up: the file's pixel (x, y) is row h - 1 - y.
                for x, y in ((0, 0), (7, 3), (12, 36)):
                    o = 4 * ((h - 1 - y) * w + x)
                    print('PIXEL', x, y, *(repr(v) for v in px[o:o + 4]))
                """);
        Result r = run("blender", "-b", "--factory-startup", "--python", script.toString(), "--", passes.toString(), colour.toString());
        assertEquals(0, r.status(), r.output());
        String names = r.output().lines().filter(l -> l.startsWith("PASSES ")).findFirst().orElseThrow(() -> new AssertionError(r.output()));
        assertEquals(EXPECTED_BLENDER_PASSES, java.util.Arrays.stream(names.substring(7).split(",")).sorted().toList(), r.output());
        List<String> pixels = r.output().lines().filter(l -> l.startsWith("PIXEL ")).toList();
        assertEquals(3, pixels.size(), r.output());
        for (String l : pixels) {
            String[] f = l.split(" ");
            int x = Integer.parseInt(f[1]), y = Integer.parseInt(f[2]);
            double[] expected = {x / (double) W, y / (double) H, x == 7 ? 1e6 : 0.5, 1};
            for (int c = 0; c < 4; c++) assertEquals(expected[c], Double.parseDouble(f[3 + c]), 1e-6 * Math.max(1, expected[c]), l);
        }
    }

    /** The pixel bytes of an uncompressed scanline file of this test's channels: its blocks without their line and size. */
    private static byte[] pixelBytes(Path none, ExrPrecision precision) throws IOException {
        int colour = precision == ExrPrecision.HALF ? 2 : 4;
        int line = W * (10 * colour + 4 * 4); // A Albedo.B Albedo.G Albedo.R B G Normal.X Normal.Y Normal.Z R, and IndexOB.X Noise.X Samples.X Z as floats
        byte[] all = Files.readAllBytes(none);
        int start = all.length - H * (8 + line);
        byte[] out = new byte[H * line];
        for (int y = 0; y < H; y++) {
            int block = start + y * (8 + line);
            assertEquals(y, all[block] & 0xFF, "line number of block " + y);
            System.arraycopy(all, block + 8, out, y * line, line);
        }
        return out;
    }
}
