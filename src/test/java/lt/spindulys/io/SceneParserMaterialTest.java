package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material;
import lt.spindulys.material.Material.Model;
import lt.spindulys.math.Color;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Noise;

/** The material block's two models: principled keys, emission, the refusal of the other model's keys and channels, and where errors point. */
class SceneParserMaterialTest {
    private static Material material(String text, String name) {
        return SceneParser.parse(text, "t.dat", Path.of("scenes")).material(name);
    }

    private static String error(String text) {
        return assertThrows(SceneException.class, () -> SceneParser.parse(text, "t.dat", Path.of("scenes"))).getMessage();
    }

    @Test
    void aPrincipledBlockParsesToItsValues() {
        Material gold = material("material gold { model principled  color 1 0.78 0.34  metallic 1  roughness 0.25 }", "gold");
        assertEquals(Model.PRINCIPLED, gold.model());
        assertEquals(new Color(1, 0.78, 0.34), gold.color());
        assertEquals(List.of(1.0, 0.25, 0.0, 1.5), List.of(gold.metallic(), gold.roughness(), gold.transmission(), gold.ior()));
        assertEquals("gold", gold.name());

        Material glass = material("material glass { model principled color 1 1 1 transmission 1 roughness 0 ior 1.45 }", "glass");
        assertEquals(List.of(0.0, 0.0, 1.0, 1.45), List.of(glass.metallic(), glass.roughness(), glass.transmission(), glass.ior()));
        assertTrue(glass.isTransparent());

        // The same as the builder makes it, derived Whitted terms included.
        Material built = Material.builder().model(Model.PRINCIPLED).color(new Color(1, 0.78, 0.34)).metallic(1).roughness(0.25).build();
        assertEquals(List.of(built.ka(), built.kd(), built.ks(), built.shininess(), built.kr(), built.kt(), built.fresnel()),
                List.of(gold.ka(), gold.kd(), gold.ks(), gold.shininess(), gold.kr(), gold.kt(), gold.fresnel()));
    }

    @Test
    void theOrderOfTheKeysDoesNotMatter() {
        Material late = material("material m { roughness 0.3  metallic 0.5  model principled }", "m");
        assertEquals(Model.PRINCIPLED, late.model());
        assertEquals(List.of(0.5, 0.3), List.of(late.metallic(), late.roughness()));
        // Inline, too, and 'model whitted' said outright is the default.
        assertEquals(Model.WHITTED, material("material w { ks 0.5  model whitted }", "w").model());
    }

    @Test
    void aWhittedKeyInAPrincipledBlockIsAnErrorAtTheKey() {
        assertEquals("t.dat:1:44: 'ks' belongs to model whitted, not to a model principled material",
                error("material m { model principled  metallic 1  ks 0.5 }"));
        // Before 'model' as after it.
        assertEquals("t.dat:2:3: 'shininess' belongs to model whitted, not to a model principled material",
                error("material m {\n  shininess 40\n  model principled }"));
        // In an inline material too.
        assertEquals("t.dat:1:38: 'fresnel' belongs to model whitted, not to a model principled material",
                error("sphere { material { model principled fresnel true } }"));
    }

    @Test
    void aPrincipledKeyInAWhittedBlockIsAnErrorAtTheKey() {
        String message = error("material m { color 1 0 0  roughness 0.2 }");
        assertEquals("t.dat:1:27: 'roughness' belongs to model principled, not to a model whitted material"
                + " (a material is whitted unless it gives 'model principled')", message);
        assertTrue(error("material m { model whitted  metallic 1 }").startsWith("t.dat:1:29: 'metallic' belongs to model principled"));
        assertTrue(error("material m { transmission 1 }").startsWith("t.dat:1:14: 'transmission' belongs to model principled"));
    }

    @Test
    void aChannelOfTheOtherModelIsAnErrorAtTheChannel() {
        String noise = "texture n { pattern noise }\n";
        assertEquals("t.dat:2:57: channel specular belongs to model whitted, not to a model principled material",
                error(noise + "material m { model principled  map { texture n  channel specular } }"));
        assertTrue(error(noise + "material m { map { texture n  channel roughness } }")
                .startsWith("t.dat:2:39: channel roughness belongs to model principled, not to a model whitted material"));
    }

    @Test
    void roughnessAndMetallicMapsBind() {
        Material m = material("texture n { pattern noise }\n"
                + "material m { model principled  map { texture n  channel roughness }  map { texture n  channel metallic  mapping planar } }", "m");
        assertInstanceOf(Noise.class, m.texture(Channel.ROUGHNESS));
        assertNotNull(m.texture(Channel.METALLIC));
        assertEquals(m.texture(Channel.ROUGHNESS), m.texture(Channel.METALLIC));
    }

    @Test
    void emissionOnEitherModel() {
        Material w = material("material lamp { emission 4 4 4 }", "lamp");
        assertEquals(Model.WHITTED, w.model());
        assertEquals(Color.grey(4), w.emission());
        assertEquals(0.9, w.kd()); // everything else the Whitted default
        assertEquals(Color.grey(2), material("material lamp { emission 2 }", "lamp").emission());
        assertEquals(new Color(1, 2, 3), material("material lamp { model principled  emission 1 2 3 }", "lamp").emission());
        assertEquals("t.dat:1:17: emission must have components between 0 and 100, found (101.0, 0.0, 0.0)",
                error("material lamp { emission 101 0 0 }"));
        assertEquals("t.dat:1:30: expected 1 or 3 numbers for 'emission', found '}'",
                error("material lamp { emission 1 2 }"));
    }

    @Test
    void rangesAndChoicesAreReportedWhereWritten() {
        assertEquals("t.dat:1:32: roughness must be between 0 and 1, found 1.5",
                error("material m { model principled  roughness 1.5 }"));
        assertEquals("t.dat:1:20: expected whitted or principled for 'model', found 'principle' (did you mean 'principled'?)",
                error("material m { model principle }"));
        // A base colour is a reflectance: reported at 'color'.
        assertEquals("t.dat:1:32: color of a principled material must have components between 0 and 1, found (2.0, 2.0, 2.0)",
                error("material m { model principled  color 2 }"));
        // kr + kt still at the later of the two.
        assertTrue(error("material m { kt 0.7  kr 0.5 }").startsWith("t.dat:1:22: kr + kt must be at most 1"));
    }
}
