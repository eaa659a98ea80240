package lt.spindulys.plugin;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Vec3;

class PluginOptionTest {
    private final List<PluginOption> options = List.of(
            PluginOption.integer("samples", "Samples per pixel", "Image", 4, 1, 1024, "rays per pixel"),
            PluginOption.number("ior", "Index of refraction", "cube", 1.5, 1, 4, "glass is 1.5"),
            PluginOption.choice("material", "Material", "cube", "opaque", List.of("opaque", "transparent", "mirror"), "the look"),
            PluginOption.of("floor", "Floor", "Scene", PluginOption.Kind.BOOLEAN, "true", "a floor under the surfaces"),
            PluginOption.of("color", "Colour", "cube", PluginOption.Kind.COLOR, "0.8 0.4 0.2", "its colour"),
            PluginOption.of("texture", "Texture", "cube", PluginOption.Kind.FILE, "", "an image"));

    @Test
    void validValuesPass() {
        assertNull(PluginOption.check(options, Map.of("samples", "16", "ior", "1.33", "material", "mirror", "floor", "false",
                "color", "0 1 0.5", "texture", "")));
        assertNull(PluginOption.check(options, Map.of()));
    }

    @Test
    void eachKindSaysWhatIsWrong() {
        assertEquals("Samples per pixel (samples) must be between 1 and 1024, found 0", PluginOption.check(options, Map.of("samples", "0")));
        assertEquals("Samples per pixel (samples) must be a whole number, found '1.5'", PluginOption.check(options, Map.of("samples", "1.5")));
        assertEquals("Index of refraction (ior) must be a number, found 'Infinity'", PluginOption.check(options, Map.of("ior", "Infinity")));
        assertEquals("Index of refraction (ior) must be between 1.0 and 4.0, found 0.5", PluginOption.check(options, Map.of("ior", "0.5")));
        assertEquals("Material (material) must be one of opaque, transparent, mirror, found 'glass'", PluginOption.check(options, Map.of("material", "glass")));
        assertEquals("Floor (floor) must be true or false, found 'yes'", PluginOption.check(options, Map.of("floor", "yes")));
        assertEquals("Colour (color) must be three numbers r g b between 0 and 1, found '1 2 3'", PluginOption.check(options, Map.of("color", "1 2 3")));
        assertTrue(PluginOption.check(options, Map.of("texture", "/no/such/file.png")).startsWith("Texture (texture) names no file"));
        assertTrue(PluginOption.check(options, Map.of("sample", "4")).startsWith("unknown option 'sample'; expected one of: samples, ior"));
    }

    @Test
    void aDefaultMustBeValid() {
        assertThrows(IllegalArgumentException.class, () -> PluginOption.integer("n", "N", "g", 0, 1, 2, ""));
        assertThrows(IllegalArgumentException.class, () -> PluginOption.choice("c", "C", "g", "x", List.of("a"), ""));
    }

    @Test
    void theViewIsChecked() {
        assertThrows(IllegalArgumentException.class, () -> new PluginView(Vec3.ZERO, Vec3.ZERO, Vec3.Y, 45, 10, 10));
        assertThrows(IllegalArgumentException.class, () -> new PluginView(Vec3.ZERO, Vec3.Y, Vec3.Y, 45, 10, 10));
        assertThrows(IllegalArgumentException.class, () -> new PluginView(Vec3.ZERO, Vec3.X, Vec3.Y, 180, 10, 10));
        assertThrows(IllegalArgumentException.class, () -> new PluginView(Vec3.ZERO, Vec3.X, Vec3.Y, 45, 0, 10));
    }

    @Test
    void anOptionMayMatterOnlyForSomeValuesOfAnother() {
        PluginOption material = PluginOption.choice("material", "Material", "cube", "opaque", List.of("opaque", "transparent", "mirror"), "the look");
        PluginOption ior = PluginOption.number("ior", "Index of refraction", "cube", 1.5, 1, 4, "").onlyWhen("material", "transparent");
        List<PluginOption> all = List.of(material, ior);
        assertEquals("material", ior.when());
        assertFalse(ior.applies(all, Map.of()), "the default material is opaque");
        assertTrue(ior.applies(all, Map.of("material", "transparent")));
        assertTrue(material.applies(all, Map.of()), "no condition");
        // Its value is still checked whether or not it matters.
        assertEquals("Index of refraction (ior) must be a number, found 'x'", PluginOption.check(all, Map.of("ior", "x")));
        assertThrows(IllegalArgumentException.class, () -> material.onlyWhen("ior"));
        assertThrows(IllegalArgumentException.class, () -> new PluginOption("k", "K", "g", PluginOption.Kind.TEXT, "", List.of(), 0, 0, "", "other", List.of()));
    }
}
