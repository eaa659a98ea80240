package lt.spindulys.material;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material.Model;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.Uv;

/** The material builder: both models' defaults and ranges, which keys each refuses, toBuilder, and a principled material's derived Whitted terms. */
class MaterialTest {
    private static final Texture GREY = (p, rgb) -> { rgb[0] = rgb[1] = rgb[2] = 0.5; };
    private static final double EPS = 1e-12;

    private static Material.Builder principled() { return Material.builder().model(Model.PRINCIPLED); }

    private static String refusal(Material.Builder b) {
        return assertThrows(IllegalArgumentException.class, b::build).getMessage();
    }

    @Test
    void whittedDefaultsAreTheThesisOnes() {
        Material m = Material.builder().build();
        assertEquals(Model.WHITTED, m.model());
        assertEquals(List.of(Color.grey(0.8), Color.WHITE, Color.BLACK, Color.BLACK), List.of(m.color(), m.filter(), m.beta(), m.emission()));
        assertEquals(List.of(0.1, 0.9, 0.0, 20.0, 0.0, 0.0, 1.0), List.of(m.ka(), m.kd(), m.ks(), m.shininess(), m.kr(), m.kt(), m.ior()));
        assertFalse(m.fresnel());
        assertEquals(List.of(0.0, 0.5, 0.0), List.of(m.metallic(), m.roughness(), m.transmission()));
    }

    @Test
    void principledDefaultsAndItsIor() {
        Material m = principled().build();
        assertEquals(Model.PRINCIPLED, m.model());
        assertEquals(List.of(0.0, 0.5, 0.0, 1.5), List.of(m.metallic(), m.roughness(), m.transmission(), m.ior()));
        assertEquals(Color.BLACK, m.emission());
        assertEquals(1.33, principled().ior(1.33).build().ior());
        // Given before the model is chosen, ior is still the given one; not given, the model's default.
        assertEquals(1.33, Material.builder().ior(1.33).model(Model.PRINCIPLED).build().ior());
        assertEquals(1.0, principled().model(Model.WHITTED).build().ior());
    }

    @Test
    void rangesOfTheNewKeys() {
        assertEquals("metallic must be between 0 and 1, found -0.1",
                assertThrows(IllegalArgumentException.class, () -> principled().metallic(-0.1)).getMessage());
        assertEquals("roughness must be between 0 and 1, found 1.5",
                assertThrows(IllegalArgumentException.class, () -> principled().roughness(1.5)).getMessage());
        assertEquals("transmission must be between 0 and 1, found NaN",
                assertThrows(IllegalArgumentException.class, () -> principled().transmission(Double.NaN)).getMessage());
        assertEquals("emission must have components between 0 and 100, found (0.0, 101.0, 0.0)",
                assertThrows(IllegalArgumentException.class, () -> Material.builder().emission(new Color(0, 101, 0))).getMessage());
        assertThrows(IllegalArgumentException.class, () -> Material.builder().emission(new Color(-1, 0, 0)));
        assertThrows(IllegalArgumentException.class, () -> Material.builder().model(null));
        // Both ends are allowed.
        Material m = principled().metallic(1).roughness(0).transmission(1).emission(Color.grey(100)).build();
        assertEquals(List.of(1.0, 0.0, 1.0), List.of(m.metallic(), m.roughness(), m.transmission()));
    }

    @Test
    void aPrincipledColourIsAReflectance() {
        assertEquals("color of a principled material must have components between 0 and 1, found (2.0, 0.5, 0.5)",
                refusal(principled().color(new Color(2, 0.5, 0.5))));
        assertEquals(new Color(2, 0.5, 0.5), Material.builder().color(new Color(2, 0.5, 0.5)).build().color());
    }

    @Test
    void whittedKeysAreRefusedInAPrincipledMaterialWhateverTheOrder() {
        String expected = "'ks' belongs to model whitted, not to a model principled material";
        assertEquals(expected, refusal(principled().ks(0.5)));
        assertEquals(expected, refusal(Material.builder().ks(0.5).model(Model.PRINCIPLED)));
        for (String key : Model.WHITTED.ownKeys()) {
            Material.Builder b = principled();
            switch (key) {
                case "ka" -> b.ka(0.1);
                case "kd" -> b.kd(0.9);
                case "ks" -> b.ks(0);
                case "shininess" -> b.shininess(20);
                case "kr" -> b.kr(0);
                case "kt" -> b.kt(0);
                case "fresnel" -> b.fresnel(false);
                default -> throw new AssertionError(key);
            }
            // Even a default value, given, is refused: it says the writer meant the other model.
            assertEquals("'" + key + "' belongs to model whitted, not to a model principled material", refusal(b));
        }
    }

    @Test
    void principledKeysAreRefusedInAWhittedMaterial() {
        String hint = " (a material is whitted unless it gives 'model principled')";
        assertEquals("'metallic' belongs to model principled, not to a model whitted material" + hint, refusal(Material.builder().metallic(1)));
        assertEquals("'roughness' belongs to model principled, not to a model whitted material" + hint, refusal(Material.builder().roughness(0.2)));
        assertEquals("'transmission' belongs to model principled, not to a model whitted material" + hint,
                refusal(principled().transmission(1).model(Model.WHITTED)));
        // The first one given is named.
        assertTrue(refusal(Material.builder().roughness(0.2).metallic(1)).startsWith("'roughness'"));
    }

    @Test
    void channelsOfTheOtherModelAreRefused() {
        assertEquals("channel specular belongs to model whitted, not to a model principled material",
                refusal(principled().texture(Channel.SPECULAR, GREY, new Uv(1, 1))));
        assertEquals("channel reflection belongs to model whitted, not to a model principled material",
                refusal(principled().texture(Channel.REFLECTION, GREY, new Uv(1, 1))));
        assertTrue(refusal(Material.builder().texture(Channel.ROUGHNESS, GREY, new Uv(1, 1)))
                .startsWith("channel roughness belongs to model principled, not to a model whitted material"));
        assertTrue(refusal(Material.builder().texture(Channel.METALLIC, GREY, new Uv(1, 1))).startsWith("channel metallic belongs to model principled"));
        // The channels both take.
        for (Channel c : List.of(Channel.DIFFUSE, Channel.TRANSPARENCY, Channel.EMISSION, Channel.BUMP)) {
            principled().texture(c, GREY, new Uv(1, 1)).build();
            Material.builder().texture(c, GREY, new Uv(1, 1)).build();
        }
        principled().texture(Channel.ROUGHNESS, GREY, new Uv(1, 1)).texture(Channel.METALLIC, GREY, new Uv(1, 1)).build();
    }

    @Test
    void sharedKeysApplyToBoth() {
        for (Model model : Model.values()) {
            Material m = Material.builder().model(model).color(Color.grey(0.5)).ior(1.2).beta(0.3).filter(new Color(1, 0.5, 0.25))
                    .emission(new Color(4, 3, 2)).build();
            assertEquals(new Color(4, 3, 2), m.emission());
            assertEquals(Color.grey(0.3), m.beta());
            assertEquals(1.2, m.ior());
            assertNull(model.refusal("color"));
            assertNull(model.refusal("emission"));
            assertNull(model.refusal("map"));
        }
    }

    @Test
    void toBuilderRoundTripsBothModels() {
        Material gold = principled().name("gold").color(new Color(1, 0.78, 0.34)).metallic(1).roughness(0.25).ior(1.7)
                .filter(new Color(1, 0.5, 1)).beta(0.2).emission(new Color(0.1, 0.2, 0.3))
                .texture(Channel.ROUGHNESS, GREY, new Uv(1, 1)).build();
        assertSameMaterial(gold, gold.toBuilder().build());
        Material glass = Material.builder().name("glass").color(Color.WHITE).kd(0.1).ks(0.8).shininess(100).kr(0.1).kt(0.9).ior(1.5)
                .fresnel(true).filter(new Color(0.9, 1, 0.9)).emission(Color.grey(2)).texture(Channel.SPECULAR, GREY, new Uv(1, 1)).build();
        assertSameMaterial(glass, glass.toBuilder().build());
        // The given values travel, not the derived ones: a principled material with only a colour
        // becomes a Whitted one with the Whitted defaults, its ior the Whitted default again.
        Material plain = principled().color(Color.grey(0.5)).build();
        Material whitted = plain.toBuilder().model(Model.WHITTED).build();
        assertEquals(List.of(0.1, 0.9, 0.0, 20.0, 0.0, 0.0, 1.0),
                List.of(whitted.ka(), whitted.kd(), whitted.ks(), whitted.shininess(), whitted.kr(), whitted.kt(), whitted.ior()));
        assertEquals(Color.WHITE, whitted.filter());
        // A given principled key keeps it principled: switching would have to drop it.
        assertTrue(refusal(gold.toBuilder().model(Model.WHITTED)).startsWith("'metallic' belongs to model principled"));
        // Changing the builder leaves the material alone.
        gold.toBuilder().roughness(1).build();
        assertEquals(0.25, gold.roughness());
    }

    private static void assertSameMaterial(Material a, Material b) {
        assertEquals(List.of(String.valueOf(a.name()), a.model(), a.color(), a.filter(), a.beta(), a.emission(), a.ka(), a.kd(), a.ks(), a.shininess(),
                        a.kr(), a.kt(), a.ior(), a.fresnel(), a.metallic(), a.roughness(), a.transmission(), a.bumpStrength()),
                List.of(String.valueOf(b.name()), b.model(), b.color(), b.filter(), b.beta(), b.emission(), b.ka(), b.kd(), b.ks(), b.shininess(),
                        b.kr(), b.kt(), b.ior(), b.fresnel(), b.metallic(), b.roughness(), b.transmission(), b.bumpStrength()));
        for (Channel c : Channel.values()) {
            assertSame(a.texture(c), b.texture(c));
            assertSame(a.mapping(c), b.mapping(c));
        }
    }

    /** Defaults: roughness 0.5 (alpha 0.25), ior 1.5 (F0 0.04), grey 0.8, a dielectric. */
    @Test
    void derivedTermsOfThePlainPrincipledSurface() {
        Material m = principled().build();
        assertEquals(1, m.kd(), EPS);
        assertEquals(0.1, m.ka(), EPS);
        assertEquals(30, m.shininess(), EPS);           // 2 / 0.25^2 - 2
        assertEquals(0.04 / (4 * 0.0625), m.ks(), EPS);  // F0 / (4 alpha^2)
        assertEquals(0.5 * 0.04, m.kr(), EPS);           // (1 - r) F0
        assertEquals(0, m.kt());
        assertFalse(m.fresnel());
        assertFalse(m.isTransparent());
        assertEquals(Color.grey(0.8), m.color());
        assertEquals(0.8, m.filter().r(), EPS);
    }

    @Test
    void derivedTermsOfGold() {
        Material m = principled().color(new Color(1, 0.78, 0.34)).metallic(1).roughness(0.25).build();
        double mean = (1 + 0.78 + 0.34) / 3;
        assertEquals(0.25, m.kd(), EPS);                    // only the rough metal's share, in its colour
        assertEquals(0.025, m.ka(), EPS);
        assertEquals(510, m.shininess(), 1e-9);             // 2 / 0.0625^2 - 2
        assertEquals(Ranges.MAX_COEFFICIENT, m.ks());       // mean / (4 * 0.0039) = 45, capped
        assertEquals(0.75 * mean, m.kr(), EPS);
        assertEquals(0, m.kt());
    }

    @Test
    void derivedTermsOfClearGlass() {
        Material m = principled().color(Color.WHITE).transmission(1).roughness(0).ior(1.5).build();
        assertEquals(0, m.kd());
        assertEquals(0, m.ka());
        assertEquals(Ranges.MAX_SHININESS, m.shininess());  // a mirror-sharp highlight
        assertEquals(Ranges.MAX_COEFFICIENT, m.ks());
        assertEquals(0, m.kr());                            // glass reflects through Fresnel from kt
        assertEquals(1, m.kt());
        assertTrue(m.fresnel());
        assertTrue(m.isTransparent());
        assertEquals(Color.WHITE, m.filter());
        // Tinted glass: the filter takes the base colour.
        assertEquals(new Color(0.5, 0.25, 1), principled().color(new Color(1, 0.5, 1)).transmission(1).filter(new Color(0.5, 0.5, 1)).build().filter());
    }

    @Test
    void derivedTermsOfARoughMetalAndABlackDielectricOfIorOne() {
        Material rough = principled().color(Color.grey(0.6)).metallic(1).roughness(1).build();
        assertEquals(0, rough.shininess());
        assertEquals(0.6 / 4, rough.ks(), EPS);
        assertEquals(0, rough.kr());
        assertEquals(1, rough.kd(), EPS);
        // ior 1 reflects nothing (F0 0): no highlight at all, even at roughness 0 (not 0 / 0).
        Material none = principled().ior(1).roughness(0).build();
        assertEquals(0, none.ks());
        assertEquals(0, none.kr());
    }

    /** Over a grid of every parameter, the derived terms stay in the Whitted ranges and kr + kt at most 1. */
    @Test
    void derivedTermsStayInRange() {
        double[] unit = {0, 1e-9, 0.03, 0.25, 0.5, 0.9, 1};
        double[] iors = {1e-3, 0.5, 1, 1.33, 1.5, 2.4, 1e15};
        Color[] colours = {Color.BLACK, Color.grey(0.5), Color.WHITE, new Color(1, 0, 0.2)};
        int n = 0;
        for (double m : unit) for (double r : unit) for (double t : unit) for (double ior : iors) for (Color c : colours) {
            Material x = principled().metallic(m).roughness(r).transmission(t).ior(ior).color(c).build();
            String at = "m " + m + " r " + r + " t " + t + " ior " + ior + " " + c;
            assertTrue(x.kr() + x.kt() <= 1, at + ": kr + kt " + (x.kr() + x.kt()));
            assertTrue(x.kr() >= 0 && x.kr() <= 1 && x.kt() >= 0 && x.kt() <= 1, at);
            for (double k : new double[] {x.ka(), x.kd(), x.ks()}) assertTrue(k >= 0 && k <= Ranges.MAX_COEFFICIENT, at + ": " + k);
            assertTrue(x.shininess() >= 0 && x.shininess() <= Ranges.MAX_SHININESS, at + ": shininess " + x.shininess());
            assertTrue(x.filter().isNonNegative() && x.filter().max() <= 1, at);
            assertEquals(x.kt() > 0, x.fresnel(), at);
            n++;
        }
        assertEquals(7 * 7 * 7 * 7 * 4, n);
    }

    @Test
    void keywordsOfTheModels() {
        assertEquals(List.of("whitted", "principled"), Model.keywords());
        assertEquals(Model.PRINCIPLED, Model.fromKeyword("principled"));
        assertThrows(IllegalArgumentException.class, () -> Model.fromKeyword("Principled"));
        assertTrue(Model.PRINCIPLED.owns(Channel.ROUGHNESS) && Model.WHITTED.owns(Channel.SPECULAR) && !Model.WHITTED.owns(Channel.DIFFUSE));
    }
}
