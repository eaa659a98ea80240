package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.io.SceneParser;
import lt.spindulys.material.Material;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.SceneBuilder;

/**
 * Principled materials under the Whitted integrator: emission shows exactly, lit scenes render
 * finite and lit, and a principled material renders exactly as the Whitted material of its derived
 * terms does.
 */
class PrincipledMaterialRenderTest {
    private static FrameBuffer render(SceneBuilder b) throws InterruptedException {
        return Renderer.render(b.build(), 2, ProgressListener.NONE).frame();
    }

    private static SceneBuilder parse(String text) {
        return SceneParser.parse(text, "t.dat", Path.of("scenes"));
    }

    /**
     * A sphere filling the view with no lights, ambient or background: every pixel is exactly the
     * emission (its reflections see the black background; a glass one would also see its own far side).
     */
    @Test
    void anEmissiveSphereWithoutLightsShowsItsEmission() throws InterruptedException {
        for (String material : new String[] {
                "model principled  color 0.5 0.5 0.5  metallic 1  roughness 0.1  emission 0.25 0.5 0.75",
                "model principled  color 0.3 0.3 0.3  emission 0.25 0.5 0.75",
                "emission 0.25 0.5 0.75"}) {
            FrameBuffer f = render(parse("settings { width 3  height 3  samples 2  ambient 0  background 0 }\n"
                    + "camera { eye 0 0 -5  lookat 0 0 0  fov 5 }\n"
                    + "sphere { radius 1  material { " + material + " } }\n"));
            for (int y = 0; y < 3; y++) {
                for (int x = 0; x < 3; x++) {
                    assertArrayEquals(new double[] {0.25, 0.5, 0.75}, new double[] {f.get(x, y, 0), f.get(x, y, 1), f.get(x, y, 2)},
                            material + " at " + x + "," + y);
                }
            }
        }
    }

    private static final String LIT = """
            settings { width 48  height 24  samples 1  maxdepth 6 }
            camera { eye 0 1.5 -6  lookat 0 0.7 0  fov 40 }
            light { position 4 8 -6 }
            material gold  { model principled  color 1 0.78 0.34  metallic 1  roughness 0.25 }
            material clear { model principled  color 1 1 1  transmission 1  roughness 0  ior 1.5 }
            material paint { model principled  color 0.2 0.3 0.8 }
            material floor { model principled  color 0.7 0.7 0.7  roughness 0.8 }
            sphere { center -2.2 1 0  radius 1  material gold }
            sphere { center 0 1 0  radius 1  material clear }
            sphere { center 2.2 1 0  radius 1  material paint }
            plane { material floor }
            """;

    @Test
    void aLitPrincipledSceneRendersFiniteAndLit() throws InterruptedException {
        FrameBuffer f = render(parse(LIT));
        double sum = 0;
        for (double v : f.data()) {
            assertTrue(Double.isFinite(v) && v >= 0, "pixel value " + v);
            sum += v;
        }
        assertTrue(sum / f.data().length > 0.05, "mean " + sum / f.data().length);
        // Seen along +z, +x is on the image's left: the blue paint there is blue, the gold on the
        // right more red than blue (its colour shows through the rough metal's diffuse share).
        int row = 24 / 2 - 1;
        double[] paint = rgbAround(f, 9, row), gold = rgbAround(f, 35, row);
        assertTrue(paint[2] > paint[0], "paint " + java.util.Arrays.toString(paint));
        assertTrue(gold[0] > gold[2], "gold " + java.util.Arrays.toString(gold));
    }

    private static double[] rgbAround(FrameBuffer f, int x, int y) {
        return new double[] {f.get(x, y, 0), f.get(x, y, 1), f.get(x, y, 2)};
    }

    /** The Whitted integrator sees nothing of a principled material but its derived terms. */
    @Test
    void rendersAsTheWhittedMaterialOfItsDerivedTerms() throws InterruptedException {
        SceneBuilder principled = parse(LIT), whitted = parse(LIT);
        for (GObject o : whitted.objects()) o.material(whittedTwin(o.material()));
        FrameBuffer a = render(principled), b = render(whitted);
        assertArrayEquals(b.data(), a.data());
        assertEquals(Material.Model.WHITTED, whitted.objects().get(0).material().model());
    }

    private static Material whittedTwin(Material m) {
        return Material.builder().color(m.color()).ka(m.ka()).kd(m.kd()).ks(m.ks()).shininess(m.shininess()).kr(m.kr()).kt(m.kt())
                .ior(m.ior()).fresnel(m.fresnel()).filter(m.filter()).beta(m.beta()).emission(m.emission()).build();
    }
}
