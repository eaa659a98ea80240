package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.CRC32;
import java.util.zip.Deflater;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * Allocations sized by input that the heap cannot give are refused before they are made: small
 * files that ask for a huge texture, subdivision level or frame. Each runs through the command
 * line with the budget capped at {@link #CAP} on this thread ({@link HeapBudget#cap}), so the
 * outcome does not depend on the machine's free memory: exit status 2, one line naming the place
 * and what is needed and free, and no output file.
 */
class CliHeapLimitsTest {
    @TempDir Path dir;

    /** The budget the checks see: far below what every case needs, far below any test heap. */
    static final long CAP = 64L << 20;

    private static final String CAM = "camera { eye 0 0 -5  lookat 0 0 0 }\n";

    /**
     * A scene (with files beside it, as bytes) that must be refused.
     *
     * @param expected the start of the message after the scene's name, "line:column: ..."
     */
    record Case(String name, String scene, Map<String, byte[]> files, String expected) {
        @Override public String toString() { return name; }
    }

    /**
     * The texture figures: 8192 x 8192 pixels decoded (TGA: an int each, 256 MiB; a 1-bit PNG: 8
     * MiB), 3 bytes a texel (192 MiB) and the mip chain (256 MiB).
     */
    static Stream<Case> cases() {
        return Stream.of(
                new Case("frame of 32768x16384 (valid sides)", CAM + "settings {\n  width 32768\n  height 16384\n}\n", Map.of(),
                        "4:3: the 32768x16384 frame needs 18 GiB of heap, but only 64 MiB is free (raise the JVM's limit with -Xmx"),
                new Case("frame made too big by its passes", CAM + "settings { height 1024  width 1024  aov depth normal object }\n", Map.of(),
                        "2:37: the 1024x1024 frame with its depth, normal, object passes needs 108 MiB of heap, but only 64 MiB is free"),
                new Case("8192x8192 run-length TGA of 18 bytes", CAM + "texture t {\n  image \"big.tga\"\n}\n", Map.of("big.tga", tgaHeader(8192, 8192, 10)),
                        "3:9: cannot read texture image 'big.tga': the 8192x8192 image needs 704 MiB of heap"),
                new Case("8 KB PNG of 8192x8192 1-bit pixels", CAM + "texture t {\n  image \"big.png\"\n}\n", Map.of("big.png", blackPng(8192, 8192)),
                        "3:9: cannot read texture image 'big.png': the 8192x8192 image needs 456 MiB of heap"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("cases")
    void refusedBeforeAllocating(Case c) throws IOException {
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, c.scene());
        for (Map.Entry<String, byte[]> f : c.files().entrySet()) Files.write(dir.resolve(f.getKey()), f.getValue());
        Path out = dir.resolve("out.png");
        CliTest.Run r;
        try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
            r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet");
        }
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().startsWith(scene + ":" + c.expected()), r.err());
        assertTrue(r.err().contains("of heap, but only 64 MiB is free (raise the JVM's limit with -Xmx"), r.err());
        assertEquals(1, r.err().lines().count(), r.err());
        assertFalse(Files.exists(out), "no image written");
    }

    @Test
    void frameOptionsAreNamed() throws IOException {
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, CAM + "settings { width 64 height 48 }\nsphere { }\n");
        Path out = dir.resolve("out.png");
        try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
            CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet", "--width", "32768", "--height", "16384");
            assertEquals(2, r.status(), r.err());
            assertTrue(r.err().startsWith("render: --width 32768 --height 16384: the 32768x16384 frame needs 18 GiB of heap, but only 64 MiB is free"), r.err());
            assertEquals(1, r.err().lines().count(), r.err());
            r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet", "--width", "4096", "--height", "4096", "--aov", "normal");
            assertEquals(2, r.status(), r.err());
            assertTrue(r.err().startsWith("render: --width 4096 --height 4096 --aov normal: the 4096x4096 frame with its normal pass needs 1.3 GiB"), r.err());
        }
        assertFalse(Files.exists(out), "no image written");
    }

    @Test
    void aUniformLevelTooLargeForTheHeapRendersByTheCombinedMethod() throws IOException {
        // 4 quads at level 8 (262144 faces) would need more than the 64 MiB left for uniform
        // refinement; the combined method renders the same level within the scene's budget.
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, CAM + "settings { width 16 height 12 }\nsubdiv {\n  file \"grid.obj\"\n  level 8\n}\n");
        Files.write(dir.resolve("grid.obj"), grid(2, 2));
        Path out = dir.resolve("out.png");
        CliTest.Run r;
        try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
            r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet", "--stats");
        }
        assertEquals(0, r.status(), r.err());
        assertTrue(r.out().contains("subdiv grid.obj: combined"), r.out());
        assertTrue(Files.exists(out));
    }

    @Test
    void optionsThatShrinkAHugeFrameRenderIt() throws IOException {
        // The scene's own size is checked only once the options are known, so they can make it fit.
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, CAM + "settings { width 32768 height 16384 }\nsphere { }\n");
        Path out = dir.resolve("out.png");
        try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
            CliTest.Run r = CliTest.run(scene.toString(), "-o", out.toString(), "--quiet", "--width", "32", "--height", "16");
            assertEquals(0, r.status(), r.err());
        }
        assertTrue(Files.exists(out));
    }

    @Test
    void subdivideRefusesALevelAtTheOption() throws IOException {
        Path mesh = dir.resolve("grid.obj"), out = dir.resolve("out.obj");
        Files.write(mesh, grid(16, 8));
        CliTest.Run r;
        try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
            r = CliTest.run("subdivide", mesh.toString(), "--level", "8", "-o", out.toString());
        }
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().startsWith("render: --level 8: " + mesh + ": subdivision level 8 of this mesh (8388608 faces; uniform refinement"), r.err());
        assertTrue(r.err().contains("needs 1.4 GiB of heap, but only 64 MiB is free"), r.err());
        assertEquals(1, r.err().lines().count(), r.err());
        assertFalse(Files.exists(out), "no mesh written");
    }

    @Test
    void theRendererChecksTheFrameForLibraryUsers() {
        SceneBuilder b = new SceneBuilder();
        b.settings(RenderSettings.builder().size(32768, 16384).build());
        b.add(new Sphere(lt.spindulys.math.Vec3.ZERO, 1));
        var scene = b.build();
        try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
            InsufficientMemoryException e = assertThrows(InsufficientMemoryException.class, () -> Renderer.render(scene, 1, ProgressListener.NONE));
            assertTrue(e.getMessage().startsWith("the 32768x16384 frame needs 18 GiB of heap"), e.getMessage());
        }
    }

    @Test
    void theThreadsSampleBuffersAreRefusedAtTheSamplesInASmallHeap() throws Exception {
        // Within every documented range, 256 MiB of light strata a thread: two threads' do not fit
        // in 512 MiB. Checked one thread at a time, both could pass and then run out of memory,
        // and the run that lost a thread ended as a success. A real small heap, in a child JVM.
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, CAM + "settings { width 64  height 32  samples 65536 }\n"
                + "environment { file \"sky.hdr\"  light true  samples 1024 }\nsphere { }\n");
        Files.copy(Path.of("textures/sky.hdr"), dir.resolve("sky.hdr"));
        Path out = dir.resolve("a.pfm");
        Child r = child("-Xmx512m", scene.toString(), "-o", out.toString(), "--threads", "2", "--quiet");
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().startsWith(scene + ":2:33: buffering the samples of 2 render threads (samples 65536 of the settings x samples 1024 of the environment)"
                + " needs 518 MiB of heap, but only "), r.err());
        assertEquals(1, r.err().lines().count(), "one line, no stack trace: " + r.err());
        assertFalse(Files.exists(out), "no image written");
    }

    /** A lazy surface: its patches go to the cache, whose size the budget sets. */
    private static final String LAZY = CAM + "subdiv { file \"cube.dat\"  method lazy }\n";

    @Test
    void subdivisionBudgetsAboveTheHeapAreCappedByIt() throws IOException {
        // The README's example budgets, by the options and by the settings' keys, in a heap of 64 MiB:
        // capped to what the heap can give, said by --stats, and rendered.
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Path options = dir.resolve("options.dat"), keys = dir.resolve("keys.dat");
        Files.writeString(options, LAZY);
        Files.writeString(keys, "settings { subdivmemory 16777216  subdivcache 16777216 }\n" + LAZY);
        for (String[] run : new String[][] {{options.toString(), "--subdiv-memory", "3072", "--subdiv-cache", "1024"}, {keys.toString()}}) {
            Path out = dir.resolve("out.png");
            Files.deleteIfExists(out);
            java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of(run));
            args.addAll(java.util.List.of("-o", out.toString(), "--quiet", "--stats", "--width", "32"));
            CliTest.Run r;
            try (HeapBudget.Scope s = HeapBudget.cap(CAP)) {
                r = CliTest.run(args.toArray(String[]::new));
            }
            assertEquals(0, r.status(), r.err());
            String asked = run.length > 1 ? "3072" : "16777216", cache = run.length > 1 ? "1024" : "16777216";
            assertTrue(r.out().contains("subdivision memory " + asked + " MiB asked, capped to 32.0 MiB by the heap"), r.out());
            assertTrue(r.out().contains("subdivision cache " + cache + " MiB asked, shrunk to 32.0 MiB, the whole subdivision memory the heap allows"), r.out());
            assertTrue(Files.exists(out));
        }
    }

    @Test
    void subdivisionBudgetsAboveASmallHeapRenderInAChildJvm() throws Exception {
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Path scene = dir.resolve("scene.dat"), out = dir.resolve("out.png");
        Files.writeString(scene, LAZY);
        Child r = child("-Xmx96m", scene.toString(), "-o", out.toString(), "--quiet", "--width", "32", "--subdiv-memory", "3072", "--subdiv-cache", "1024");
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        assertTrue(Files.exists(out));
    }

    @Test
    void aCacheLargerThanTheMemoryIsShrunkToIt() throws IOException {
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Path keys = dir.resolve("keys.dat"), options = dir.resolve("options.dat"), out = dir.resolve("out.png");
        Files.writeString(keys, "settings { subdivmemory 16  subdivcache 64 }\n" + LAZY);
        Files.writeString(options, LAZY);
        for (String[] run : new String[][] {{keys.toString()}, {options.toString(), "--subdiv-cache", "64", "--subdiv-memory", "16"}}) {
            CliTest.Run r = CliTest.run(java.util.stream.Stream.concat(java.util.Arrays.stream(run),
                    java.util.stream.Stream.of("-o", out.toString(), "--quiet", "--stats", "--width", "32")).toArray(String[]::new));
            assertEquals(0, r.status(), r.err());
            assertTrue(r.out().contains("subdivision cache 64 MiB asked, shrunk to 16 MiB, the whole subdivision memory\n"), r.out());
            assertFalse(r.out().contains("capped"), r.out());
        }
    }

    /** What a run of the command line in a child JVM printed on stderr, and its exit status. */
    record Child(int status, String err) {}

    /** Runs the command line in a child JVM with {@code heap} (-Xmx...), as ./render runs it; at most 60 s. */
    static Child child(String heap, String... args) throws IOException, InterruptedException {
        java.util.List<String> cmd = new java.util.ArrayList<>(java.util.List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), heap));
        if (ModuleLayer.boot().findModule("jdk.incubator.vector").isPresent()) cmd.addAll(java.util.List.of("--add-modules", "jdk.incubator.vector"));
        cmd.addAll(java.util.List.of("-cp", System.getProperty("java.class.path"), Main.class.getName()));
        cmd.addAll(java.util.List.of(args));
        Path log = Files.createTempFile("spindulys-child", ".err");
        try {
            Process p = new ProcessBuilder(cmd).redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(log.toFile()).start();
            if (!p.waitFor(60, java.util.concurrent.TimeUnit.SECONDS)) {
                p.destroyForcibly();
                fail("the child JVM did not finish in 60 s: " + Files.readString(log));
            }
            return new Child(p.exitValue(), withoutNotice(Files.readString(log)));
        } finally {
            Files.deleteIfExists(log);
        }
    }

    /** Stderr without the JVM's own notice of the incubating vector module, which is not the command's output. */
    private static String withoutNotice(String err) {
        return err.lines().filter(l -> !l.equals("WARNING: Using incubator modules: jdk.incubator.vector"))
                .collect(java.util.stream.Collectors.joining("\n"));
    }

    /** A TGA header (true colour, 24 bits, top-left origin) of the given type, without pixels. */
    static byte[] tgaHeader(int w, int h, int type) {
        byte[] b = new byte[18];
        b[2] = (byte) type;
        b[12] = (byte) w;
        b[13] = (byte) (w >> 8);
        b[14] = (byte) h;
        b[15] = (byte) (h >> 8);
        b[16] = 24;
        b[17] = 0x20;
        return b;
    }

    /**
     * A whole black PNG of {@code w x h} 1-bit greyscale pixels: signature, IHDR, one IDAT of
     * deflated zero rows (8 KB for 8192 x 8192) and IEND.
     */
    static byte[] blackPng(int w, int h) {
        byte[] raw = new byte[(1 + (w + 7) / 8) * h]; // a filter byte (0) and the row's bits, all zero
        Deflater d = new Deflater(9);
        d.setInput(raw);
        d.finish();
        ByteArrayOutputStream z = new ByteArrayOutputStream();
        byte[] buf = new byte[1 << 16];
        while (!d.finished()) z.write(buf, 0, d.deflate(buf));
        d.end();
        ByteArrayOutputStream png = new ByteArrayOutputStream();
        png.writeBytes(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'});
        chunk(png, "IHDR", ByteBuffer.allocate(13).putInt(w).putInt(h).put((byte) 1).put((byte) 0).put((byte) 0).put((byte) 0).put((byte) 0).array());
        chunk(png, "IDAT", z.toByteArray());
        chunk(png, "IEND", new byte[0]);
        return png.toByteArray();
    }

    private static void chunk(ByteArrayOutputStream png, String type, byte[] data) {
        byte[] t = type.getBytes(StandardCharsets.US_ASCII);
        CRC32 crc = new CRC32();
        crc.update(t);
        crc.update(data);
        png.writeBytes(ByteBuffer.allocate(4).putInt(data.length).array());
        png.writeBytes(t);
        png.writeBytes(data);
        png.writeBytes(ByteBuffer.allocate(4).putInt((int) crc.getValue()).array());
    }

    /** An OBJ grid of {@code nx x ny} quads. */
    static byte[] grid(int nx, int ny) {
        StringBuilder s = new StringBuilder();
        for (int j = 0; j <= ny; j++) for (int i = 0; i <= nx; i++) s.append("v ").append(i).append(' ').append(j).append(" 0\n");
        for (int j = 0; j < ny; j++) {
            for (int i = 0; i < nx; i++) {
                int a = j * (nx + 1) + i + 1;
                s.append("f ").append(a).append(' ').append(a + 1).append(' ').append(a + nx + 2).append(' ').append(a + nx + 1).append('\n');
            }
        }
        return s.toString().getBytes(StandardCharsets.US_ASCII);
    }
}
