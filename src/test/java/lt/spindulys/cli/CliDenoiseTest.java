package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.Images;

/** {@code --denoise} and {@code --keep-noisy} through the command line. */
class CliDenoiseTest {
    @TempDir Path dir;

    private static final String SCENE = """
            settings { width 24 height 16 samples 4 }
            camera { eye 0 1 -4 lookat 0 0.5 0 }
            rectlight { center 1 3 -1 normal 0 -1 0 tangent 1 0 0 width 1 height 1 intensity 4 samples 1 }
            material grey { color 0.5 0.25 1 kd 0.8 }
            plane { normal 0 1 0 material grey }
            sphere { center 0 0.5 0 radius 0.5 }
            """;

    private Path scene() throws IOException {
        Path p = dir.resolve("scene.dat");
        Files.writeString(p, SCENE);
        return p;
    }

    @Test
    void denoiseWritesTheImageAloneAndNoTemporaryFile() throws IOException {
        Path scene = scene();
        CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--denoise", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertEquals(Set.of("scene.dat", "out.png"), CliAovTest.files(dir));
    }

    @Test
    void keepNoisyWritesTheNoisyImageBesideForEveryFormat() throws IOException {
        Path scene = scene();
        for (String ext : new String[] {"png", "pfm", "exr", "jpg"}) {
            CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("out." + ext).toString(), "--denoise", "--keep-noisy");
            assertEquals(0, r.status(), r.err());
            assertTrue(r.err().contains("wrote " + dir.resolve("out." + ext) + ", " + dir.resolve("out.noisy." + ext) + " ("), r.err());
        }
        assertEquals(Set.of("scene.dat", "out.png", "out.noisy.png", "out.pfm", "out.noisy.pfm", "out.exr", "out.noisy.exr",
                "out.jpg", "out.noisy.jpg"), CliAovTest.files(dir));
        // The noisy one is the render without denoising, exactly.
        assertEquals(0, CliTest.run(scene.toString(), "-o", dir.resolve("plain.pfm").toString(), "--quiet").status());
        FrameBuffer noisy = Images.read(dir.resolve("out.noisy.pfm")), plain = Images.read(dir.resolve("plain.pfm"));
        assertArrayEquals(plain.data(), noisy.data());
        FrameBuffer denoised = Images.read(dir.resolve("out.pfm"));
        assertFalse(java.util.Arrays.equals(plain.data(), denoised.data()), "the denoised image is the noisy one");
    }

    @Test
    void framesOfAnAnimationAreDenoisedEach() throws IOException {
        Path scene = dir.resolve("anim.dat");
        Files.writeString(scene, SCENE + "animation { frames 1 2 }\n");
        CliTest.Run r = CliTest.run(scene.toString(), "--frames", "1-2", "-o", dir.resolve("f_####.png").toString(), "--denoise", "--keep-noisy", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertEquals(Set.of("anim.dat", "f_0001.png", "f_0001.noisy.png", "f_0002.png", "f_0002.noisy.png"), CliAovTest.files(dir));
    }

    @Test
    void albedoPassBesideTheImage() throws IOException {
        Path scene = scene();
        CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--aov", "albedo", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertEquals(Set.of("scene.dat", "out.png", "out.albedo.pfm"), CliAovTest.files(dir));
        FrameBuffer albedo = Images.read(dir.resolve("out.albedo.pfm"));
        // The floor's kd times its colour (the sky at the top row: 0).
        assertEquals(0, albedo.get(0, 0, 0));
        assertEquals(0.4, albedo.get(12, 15, 0), 1e-6);
        assertEquals(0.2, albedo.get(12, 15, 1), 1e-6);
        assertEquals(0.8, albedo.get(12, 15, 2), 1e-6);
    }

    @Test
    void aFrameThatCannotBeDenoisedIsRefusedBeforeRendering() throws IOException {
        // 512x512: the frame alone needs 9 MiB (36 bytes a pixel), with the features (104) and the denoiser's buffers (160) 75 MiB.
        Path scene = dir.resolve("big.dat");
        Files.writeString(scene, SCENE.replace("settings { width 24 height 16 samples 4 }", "settings { width 512 height 512 }"));
        CliTest.Run r;
        try (lt.spindulys.limits.HeapBudget.Scope s = lt.spindulys.limits.HeapBudget.cap(CliHeapLimitsTest.CAP)) {
            r = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--denoise", "--quiet");
        }
        assertEquals(2, r.status(), r.err());
        assertTrue(r.err().contains("the 512x512 frame with its denoising features and the denoiser's buffers needs 75 MiB of heap, but only 64 MiB"),
                r.err());
        assertEquals(1, r.err().lines().count(), r.err());
        assertEquals(Set.of("big.dat"), CliAovTest.files(dir));
    }

    @Test
    void theScenesDenoiseSettingDenoisesAsTheOptionDoes() throws IOException {
        Path option = scene();
        assertEquals(0, CliTest.run(option.toString(), "-o", dir.resolve("option.pfm").toString(), "--denoise", "--quiet").status());
        Path setting = dir.resolve("setting.dat");
        Files.writeString(setting, SCENE.replace("samples 4 }", "samples 4 denoise true }"));
        CliTest.Run r = CliTest.run(setting.toString(), "-o", dir.resolve("setting.pfm").toString(), "--keep-noisy", "--quiet");
        assertEquals(0, r.status(), r.err());
        assertArrayEquals(Images.read(dir.resolve("option.pfm")).data(), Images.read(dir.resolve("setting.pfm")).data());
        assertTrue(Files.exists(dir.resolve("setting.noisy.pfm")));
        // A tile of such a scene is refused in one line, before anything is written.
        CliTest.Run tile = CliTest.run(setting.toString(), "-o", dir.resolve("tile.png").toString(), "--tile", "1/2");
        assertNotEquals(0, tile.status());
        assertEquals(1, tile.err().lines().count(), tile.err());
        assertTrue(tile.err().contains("needs the whole frame"), tile.err());
        assertFalse(Files.exists(dir.resolve("tile.png")));
    }

    @Test
    void oneLineErrors() throws IOException {
        Path scene = scene();
        CliTest.Run noisy = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--keep-noisy");
        assertEquals(2, noisy.status());
        assertEquals("render: --keep-noisy keeps the noisy image of a denoised one: give --denoise too, or settings { denoise true }" + System.lineSeparator(), noisy.err());
        CliTest.Run tile = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--denoise", "--tile", "1/2");
        assertEquals(2, tile.status());
        assertTrue(tile.err().startsWith("render: --tile 1/2: --denoise needs the whole frame"), tile.err());
        assertEquals(1, tile.err().lines().count(), tile.err());
        CliTest.Run region = CliTest.run(scene.toString(), "-o", dir.resolve("out.png").toString(), "--region", "0,8,0,8", "--denoise");
        assertEquals(2, region.status());
        assertEquals(1, region.err().lines().count(), region.err());
        assertEquals(Set.of("scene.dat"), CliAovTest.files(dir));
    }
}
