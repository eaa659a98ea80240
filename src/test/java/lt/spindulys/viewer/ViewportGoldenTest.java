package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.ImageDiff;
import lt.spindulys.math.Vec3;

/**
 * The viewport's picture, headless: two meshes of scenes/models opened in the model (the gourd,
 * whose faces wind clockwise but whose outside shows in its colour, closed as it is, and the open sheet seen
 * from above and below), one smoothed with its cage, one as a polyhedron, rendered by the
 * rasterizer and compared with a golden PNG. Regenerate it after an intended change with
 * {@code mvn test -Dtest=ViewportGoldenTest -Dgolden.update=true} and look at it first.
 */
class ViewportGoldenTest {
    static final Path GOLDEN = Path.of("src/test/resources/golden/viewer/gourd-sheet.png"), OUT = Path.of("target/regression");
    static final int W = 240, H = 160;

    @Test
    void theViewportShowsWhatItShowed() throws IOException {
        List<String> errors = new ArrayList<>();
        ViewerModel m = new ViewerModel(Runnable::run, Runnable::run, new ViewerModel.Listener() {
            @Override public void changed() {}
            @Override public void error(String message) { errors.add(message); }
        });
        m.viewport(W, H);
        m.open(List.of(Path.of("scenes/models/gourd.obj"), Path.of("scenes/models/sheet.obj")));
        assertEquals(List.of(), errors);
        m.select(0);
        m.level(2);
        m.toggleCage();
        m.select(1);
        m.mode(DisplayMode.POLYHEDRON);
        m.level(1);
        m.camera().set(m.camera().target(), m.camera().distance() / 1.4, 0.5, -0.3);
        int[] frame = new int[W * H];
        try (Rasterizer r = new Rasterizer(2)) {
            r.render(m.drawList(), m.camera(), frame, W, H);
        }
        BufferedImage actual = new BufferedImage(W, H, BufferedImage.TYPE_INT_RGB);
        actual.setRGB(0, 0, W, H, frame, 0, W);
        if (Boolean.getBoolean("golden.update")) {
            Files.createDirectories(GOLDEN.getParent());
            ImageIO.write(actual, "png", GOLDEN.toFile());
        }
        assertTrue(Files.exists(GOLDEN), "no golden " + GOLDEN + "; create it with mvn test -Dtest=ViewportGoldenTest -Dgolden.update=true");
        BufferedImage golden = ImageIO.read(GOLDEN.toFile());
        int[] expected = golden.getRGB(0, 0, W, H, null, 0, W);
        int[] got = actual.getRGB(0, 0, W, H, null, 0, W);
        // Shading goes through Math.tan and Math.pow, which may differ in the last bit between JVMs.
        ImageDiff.Result d = ImageDiff.compare(W, H, expected, got, 3);
        if (d.fractionOver() > 0.002) {
            Files.createDirectories(OUT);
            ImageIO.write(actual, "png", OUT.resolve("viewer-gourd-sheet-actual.png").toFile());
            fail("the viewport differs from " + GOLDEN + ": " + d + "; the frame is in " + OUT.resolve("viewer-gourd-sheet-actual.png"));
        }
    }
}
