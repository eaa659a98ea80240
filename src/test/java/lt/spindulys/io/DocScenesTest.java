package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.Images;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;

/**
 * The scenes in docs/scenes/ only make pictures for the documentation, so no golden image guards
 * them; this keeps them from rotting: each must still read, build and render, and its picture
 * docs/images/NAME.png must exist at the scene's own size and be shown in docs/scene-format.md.
 */
class DocScenesTest {
    private static final Path SCENES = Path.of("docs/scenes");
    private static final Path IMAGES = Path.of("docs/images");
    private static final Path DOC = Path.of("docs/scene-format.md");

    static List<Path> scenes() throws IOException {
        try (Stream<Path> files = Files.list(SCENES)) {
            return files.filter(p -> p.toString().endsWith(".dat")).sorted().toList();
        }
    }

    @Test
    void everyMappingAndPatternHasAScene() throws IOException {
        // Guards against the parameterised test passing vacuously on an empty or moved folder.
        List<String> names = scenes().stream().map(p -> p.getFileName().toString()).toList();
        for (String n : List.of("tex-mapping-planar", "tex-mapping-spherical", "tex-mapping-cylindrical", "tex-mapping-uv",
                "tex-checker", "tex-noise", "tex-marble", "tex-wood")) {
            assertTrue(names.contains(n + ".dat"), "docs/scenes has no " + n + ".dat: " + names);
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scenes")
    void rendersAndIsPictured(Path scene) throws Exception {
        SceneBuilder b = SceneParser.parse(scene);
        RenderSettings s = b.settings();
        String name = scene.getFileName().toString().replaceAll("\\.dat$", "");
        Path picture = IMAGES.resolve(name + ".png");
        assertTrue(Files.exists(picture), "no picture " + picture + " for " + scene + "; see docs/scenes/README.md");
        FrameBuffer image = Images.read(picture, s.srgb());
        assertEquals(s.width(), image.width(), picture + " width");
        assertEquals(s.height(), image.height(), picture + " height");
        assertTrue(Files.readString(DOC).contains("](images/" + name + ".png)"), DOC + " does not show " + picture);

        // A tiny render: exercises loading textures and shading without the cost of the picture.
        b.settings(s.toBuilder().size(16, 12).samplesPerPixel(1).build());
        FrameBuffer small = Renderer.render(b.build(), 1, ProgressListener.NONE).frame();
        double sum = 0;
        for (int y = 0; y < small.height(); y++) for (int x = 0; x < small.width(); x++) sum += small.get(x, y, 0);
        assertTrue(sum > 0, scene + " renders black");
    }
}
