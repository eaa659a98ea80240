package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.scene.Environment;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.TextureCache;

/** The environment statement: its keys, its image (shared with textures), and its errors, located. */
class SceneParserEnvironmentTest {
    private static final Path FOLDER = Path.of("textures");

    @TempDir
    Path dir;

    private static SceneBuilder parse(String text) {
        return SceneParser.parse(text, "t.dat", FOLDER);
    }

    private static String error(String text) {
        return assertThrows(SceneException.class, () -> parse(text)).getMessage();
    }

    @Test
    void keysReachTheEnvironmentAndTheImageIsSharedWithTextures() throws IOException {
        SceneBuilder b = parse("""
                texture sky { image "sky.hdr" }
                environment { file "sky.hdr"  rotate 30  intensity 1.5 }
                material m { map { texture sky } }
                """);
        Environment e = b.environment();
        assertEquals(30.0, e.rotateDegrees());
        assertEquals(1.5, e.intensity());
        assertSame(((ImageTexture) b.material("m").texture(lt.spindulys.texture.Channel.DIFFUSE)).image(), e.map());
        // Linear values, as read from the file.
        assertEquals(new TextureCache().load(FOLDER.resolve("sky.hdr")).texel(0, 3, 5, 1), e.map().texel(0, 3, 5, 1));

        Environment d = parse("environment { file \"sky.hdr\" }").environment();
        assertEquals(0.0, d.rotateDegrees());
        assertEquals(1.0, d.intensity());
        assertNull(parse("sphere { }").environment());
        // A PNG map is sRGB-decoded, as textures are.
        Environment png = parse("environment { file \"grid.png\" }").environment();
        int code = new java.awt.Color(javax.imageio.ImageIO.read(Path.of("textures/grid.png").toFile()).getRGB(0, 0)).getGreen();
        assertEquals(TextureCache.srgbToLinear(code / 255.0), png.map().texel(0, 0, 0, 1), 1e-6);
    }

    @Test
    void errorsAreLocated() throws IOException {
        assertEquals("t.dat:1:15: unknown property 'intensty' in environment (did you mean 'intensity'?)",
                firstLine(error("environment { intensty 2 file \"sky.hdr\" }")));
        assertTrue(error("environment { rotate 3 }").startsWith("t.dat:1:1: "), error("environment { rotate 3 }"));
        assertTrue(error("environment { rotate 3 }").contains("file"), error("environment { rotate 3 }"));
        assertEquals("t.dat:1:41: environment intensity must be between 0 and 100, found 200.0",
                error("environment { file \"sky.hdr\"  rotate 3  intensity 200 }"));
        assertTrue(error("environment { file \"sky.hdr\" }\nenvironment { file \"sky.hdr\" }")
                .startsWith("t.dat:2:1: environment is already defined at 1:1"));
        String missing = error("environment { file \"nosuch.hdr\" }");
        assertTrue(missing.startsWith("t.dat:1:20: environment image 'nosuch.hdr' not found"), missing);

        Path bad = dir.resolve("bad.hdr");
        Files.write(bad, "#?RADIANCE\n\n+Y 4 +X 8\n".getBytes(StandardCharsets.US_ASCII));
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse("environment { file \"bad.hdr\" }", "t.dat", dir));
        assertEquals("t.dat:1:20: cannot read environment image 'bad.hdr': unsupported Radiance HDR orientation at line 3: '+Y 4 +X 8'"
                + " (only -Y height +X width, rows top-down, is read)", e.getMessage());
    }

    @Test
    void lightAndSamplesMakeItALightAndBadValuesAreLocated() {
        Environment lit = parse("environment { file \"sky.hdr\"  light true  samples 16 }").environment();
        assertTrue(lit.isLight());
        assertEquals(16, lit.samples());
        Environment one = parse("environment { file \"sky.hdr\"  light true }").environment();
        assertTrue(one.isLight());
        assertEquals(1, one.samples());
        assertTrue(!parse("environment { file \"sky.hdr\" }").environment().isLight(), "not a light by default");
        assertTrue(!parse("environment { file \"sky.hdr\"  light false }").environment().isLight());
        assertTrue(parse("environment { file \"sky.hdr\"  light true }").build().environmentLight() != null, "built when frozen");

        assertEquals("t.dat:1:43: environment samples must be 1..1024, found 0",
                error("environment { file \"sky.hdr\"  light true  samples 0 }"));
        assertEquals("t.dat:1:43: environment samples must be 1..1024, found 1025",
                error("environment { file \"sky.hdr\"  light true  samples 1025 }"));
        assertEquals("t.dat:1:31: environment samples needs 'light true' (an environment that is not a light sends no shadow rays)",
                error("environment { file \"sky.hdr\"  samples 4 }"));
        assertEquals("t.dat:1:31: unknown property 'ligth' in environment (did you mean 'light'?)",
                firstLine(error("environment { file \"sky.hdr\"  ligth true }")));
        assertTrue(error("environment { file \"sky.hdr\"  light 1 }").startsWith("t.dat:1:"), error("environment { file \"sky.hdr\"  light 1 }"));
    }

    /**
     * The light's sampling tables (8 bytes a texel) are checked where the statement asks for
     * them: a grey 1024 x 512 PNG takes a little less heap as an image than its tables do, so a
     * budget between the two reads the image and refuses the light, at 'light'.
     */
    @Test
    void theLightsTablesAreCheckedAtItsStatement() throws IOException {
        java.awt.image.BufferedImage grey = new java.awt.image.BufferedImage(1024, 512, java.awt.image.BufferedImage.TYPE_BYTE_GRAY);
        javax.imageio.ImageIO.write(grey, "png", dir.resolve("grey.png").toFile());
        String text = "environment { file \"grey.png\"\n  light true }";
        // The tables: 8 * (1025 * 512 + 513) + 8 * (2 * 512 + 1 + 5 * 1024) = 4,251,664 bytes.
        try (lt.spindulys.limits.HeapBudget.Scope cap = lt.spindulys.limits.HeapBudget.cap(4_251_000)) {
            assertTrue(!SceneParser.parse("environment { file \"grey.png\" }", "t.dat", dir).environment().isLight(), "the image alone fits");
            SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(text, "t.dat", dir));
            assertTrue(e.getMessage().startsWith("t.dat:2:3: the environment light's sampling tables for the 1024x512 map needs 4"), e.getMessage());
        }
        assertTrue(SceneParser.parse(text, "t.dat", dir).environment().isLight(), "fits without the cap");
    }

    private static String firstLine(String s) {
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }

    @Test
    void backgroundAndVisibleIntensitySetWhatCameraRaysSee() {
        Environment plain = parse("environment { file \"sky.hdr\"  intensity 2 }").environment();
        assertTrue(plain.isBackground());
        assertEquals(2, plain.visibleIntensity());
        Environment hidden = parse("environment { file \"sky.hdr\"  light true  background false }").environment();
        assertTrue(!hidden.isBackground() && hidden.isLight());
        assertEquals(0.3, parse("environment { file \"sky.hdr\"  visibleintensity 0.3 }").environment().visibleIntensity());
    }

    @Test
    void visibleIntensityIsRefusedWhenTheBackgroundIsHidden() {
        assertEquals("t.dat:1:49: visibleintensity scales what camera rays see of the environment, but 'background false' (at 1:31)"
                + " hides it from them: give one of them", error("environment { file \"sky.hdr\"  background false  visibleintensity 0.3 }"));
        String negative = error("environment { file \"sky.hdr\"  visibleintensity -1 }");
        assertTrue(negative.startsWith("t.dat:1:31: environment visibleintensity must be between 0 and"), negative);
    }
}
