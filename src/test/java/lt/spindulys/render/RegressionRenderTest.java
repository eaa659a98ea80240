package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageDiff;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.image.Images;
import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;

/**
 * Renders every scene in scenes/ (and its subfolders) small and compares it with its golden image
 * in src/test/resources/golden/ (the path below scenes/, '/' as '_', .png). A pixel fails when a
 * channel differs by more than {@value #THRESHOLD}/255; the test fails when more than
 * {@value #ALLOWED_FRACTION} of the pixels fail. An animated scene is rendered at its first frame. On failure it writes the actual image and an
 * amplified diff under target/regression/.
 *
 * <p>Regenerate the goldens after an intended change with
 * {@code mvn test -Dtest=RegressionRenderTest -Dgolden.update=true}, then look at them.
 */
class RegressionRenderTest {
    static final int THRESHOLD = 6;
    static final double ALLOWED_FRACTION = 0.002;
    static final int WIDTH = 192;
    static final int MAX_SPP = 4;
    private static final Path SCENES = Path.of("scenes");
    private static final Path GOLDEN = Path.of("src/test/resources/golden");
    private static final Path OUT = Path.of("target/regression");

    static Stream<Path> scenes() throws IOException {
        try (Stream<Path> files = Files.walk(SCENES)) {
            return files.filter(p -> p.toString().endsWith(".dat")).filter(RegressionRenderTest::renderable).sorted().toList().stream();
        }
    }

    /**
     * Scenes that only exist to be measured (scenes/bench) are too large for a unit test, and
     * scenes/models holds meshes, Workframe .dat meshes among them, not scenes.
     */
    private static boolean renderable(Path p) {
        Path rel = SCENES.relativize(p);
        return !rel.startsWith("bench") && !rel.startsWith("models");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void matchesGolden(Path scene) throws Exception {
        SceneBuilder b = SceneParser.parse(scene);
        RenderSettings s = b.settings();
        int h = Math.max(1, (int) Math.round(WIDTH / s.aspect()));
        b.settings(s.toBuilder().size(WIDTH, h).samplesPerPixel(Math.min(s.samplesPerPixel(), MAX_SPP)).build());
        // An animation is compared at its first frame (its shutter and seed).
        if (b.animation() != null) b = b.forFrame(b.animation().first());
        boolean srgb = s.srgb();
        // Through a job, as the command line renders it: a scene that asks to be denoised is.
        FrameBuffer actual = RenderJob.of(b).threads(2).run().frame();

        String name = SCENES.relativize(scene).toString().replace('\\', '/').replace('/', '_').replaceAll("\\.dat$", "");
        Path golden = GOLDEN.resolve(name + ".png");
        if (Boolean.getBoolean("golden.update")) {
            Files.createDirectories(GOLDEN);
            ImageWriter.write(actual, golden, ImageOptions.DEFAULT.withSrgb(srgb));
            System.out.println("golden image written: " + golden);
            return;
        }
        assertTrue(Files.exists(golden), "no golden image " + golden + " for " + scene
                + "; create it with mvn test -Dtest=RegressionRenderTest -Dgolden.update=true");
        FrameBuffer expected = Images.read(golden, srgb);
        assertEquals(expected.width(), actual.width(), "golden width");
        assertEquals(expected.height(), actual.height(), "golden height");
        ImageDiff.Result diff = ImageDiff.compare(expected, actual, THRESHOLD, srgb);
        if (diff.fractionOver() > ALLOWED_FRACTION) {
            Files.createDirectories(OUT);
            ImageWriter.write(actual, OUT.resolve(name + "-actual.png"), ImageOptions.DEFAULT.withSrgb(srgb));
            ImageWriter.write(diff.diffImage(), OUT.resolve(name + "-diff.png"), ImageOptions.DEFAULT.withSrgb(false));
            fail(scene + " differs from " + golden + ": " + diff + "; actual and diff images are in " + OUT);
        }
    }
}
