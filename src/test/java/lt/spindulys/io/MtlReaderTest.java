package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Dissolve;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.TexturePoint;
import lt.spindulys.texture.Uniform;
import lt.spindulys.texture.Wrap;

/** The .mtl parser: every key and how it maps to the Whitted model or, with the physically based keys, the principled one, and bad input with its location. */
class MtlReaderTest {
    @TempDir Path dir;
    private final TextureCache cache = new TextureCache();

    @BeforeEach
    void texture() throws IOException {
        BufferedImage img = new BufferedImage(2, 2, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, 0xff0000);
        img.setRGB(1, 1, 0x00ff00);
        ImageIO.write(img, "png", dir.resolve("tex.png").toFile());
    }

    private Map<String, Material> parse(String text) {
        return MtlReader.parse(text, "m.mtl", dir, cache);
    }

    private static void assertColor(Color expected, Color actual) {
        assertEquals(expected.r(), actual.r(), 1e-12);
        assertEquals(expected.g(), actual.g(), 1e-12);
        assertEquals(expected.b(), actual.b(), 1e-12);
    }

    @Test
    void colourKeysMapToTheWhittedTerms() {
        Map<String, Material> m = parse("""
                # a comment line
                newmtl plain
                Kd 0.5 0.25 1   # diffuse colour
                Ka 0.3 0.3 0.6
                Ks 0.6 0.3 0.0
                Ns 50
                illum 2
                newmtl grey
                Kd 0.4
                newmtl defaults
                """);
        assertEquals(List.of("plain", "grey", "defaults"), List.copyOf(m.keySet()), "in the order defined");
        Material plain = m.get("plain");
        assertEquals("plain", plain.name());
        assertColor(new Color(0.5, 0.25, 1), plain.color());
        assertEquals(1, plain.kd());
        assertEquals(0.4, plain.ka(), 1e-12, "ka: the mean of Ka");
        assertEquals(0.3, plain.ks(), 1e-12, "ks: the mean of Ks");
        assertEquals(50, plain.shininess());
        assertEquals(0, plain.kr());
        assertEquals(0, plain.kt());
        assertFalse(plain.fresnel());
        assertColor(Color.grey(0.4), m.get("grey").color());
        Material d = m.get("defaults");
        assertColor(Color.grey(0.8), d.color());
        assertEquals(0.1, d.ka(), "the model's default ka without Ka");
        assertEquals(0, d.ks());
        assertFalse(d.isTextured());
    }

    @Test
    void illumModelsTurnTermsOn() {
        Map<String, Material> m = parse("""
                newmtl matte
                Ks 0.5
                illum 1
                newmtl mirror
                Ks 0.5
                illum 3
                newmtl fresnel
                Ks 0.4
                illum 5
                newmtl glass
                Ks 0.2
                d 0.1
                Ni 1.5
                Tf 0.9 0.8 0.7
                illum 7
                newmtl water
                Tr 0.8
                Ni 1.33
                illum 6
                newmtl noRefraction
                Ks 0.3
                d 0.5
                Ni 1.5
                illum 4
                newmtl constant
                Kd 0.2 0.4 0.6
                illum 0
                """);
        assertEquals(0, m.get("matte").ks(), "illum 1: no highlight");
        assertEquals(0.5, m.get("mirror").kr(), 1e-12, "illum 3: reflection weighted by Ks");
        assertFalse(m.get("mirror").fresnel());
        assertTrue(m.get("fresnel").fresnel());
        assertEquals(0.4, m.get("fresnel").kr(), 1e-12);
        Material glass = m.get("glass");
        assertEquals(0.9, glass.kt(), 1e-12, "kt = 1 - d");
        assertEquals(0.1, glass.kr(), 1e-12, "kr: Ks's mean, at most what transmission leaves");
        assertEquals(1.5, glass.ior());
        assertTrue(glass.fresnel());
        assertColor(new Color(0.9, 0.8, 0.7), glass.filter());
        Material water = m.get("water");
        assertEquals(0.8, water.kt(), 1e-12, "Tr is 1 - d");
        assertEquals(1.33, water.ior());
        assertFalse(water.fresnel());
        Material four = m.get("noRefraction");
        assertEquals(1, four.ior(), "illum 4 is transparent without refraction");
        assertEquals(0.5, four.kt(), 1e-12);
        assertEquals(0.3, four.kr(), 1e-12);
        Material constant = m.get("constant");
        assertEquals(0, constant.kd());
        assertEquals(0, constant.ka());
        Uniform glow = assertInstanceOf(Uniform.class, constant.texture(Channel.EMISSION), "illum 0 shows Kd as it is: emitted");
        double[] rgb = new double[3];
        glow.evaluate(new TexturePoint(), rgb);
        assertEquals(0.6, rgb[2], 1e-12);
    }

    @Test
    void emissionAndKeywordCase() {
        Map<String, Material> m = parse("NEWMTL lamp\nKE 1 0.5 0\nkd 0 0 0\nnewmtl dark\nKe 0 0 0\n");
        assertInstanceOf(Uniform.class, m.get("lamp").texture(Channel.EMISSION));
        assertColor(Color.BLACK, m.get("lamp").color());
        assertNull(m.get("dark").texture(Channel.EMISSION), "a black Ke emits nothing");
        // A Whitted .mtl material keeps Ke as an emission texture, as before, not as the material's emission.
        assertEquals(Material.Model.WHITTED, m.get("lamp").model());
        assertColor(Color.BLACK, m.get("lamp").emission());
        double[] rgb = new double[3];
        m.get("lamp").texture(Channel.EMISSION).evaluate(new TexturePoint(), rgb);
        assertEquals(List.of(1.0, 0.5, 0.0), List.of(rgb[0], rgb[1], rgb[2]));
    }

    @Test
    void physicallyBasedKeysMakeAPrincipledMaterial() {
        // As an exporter writes it: the Whitted statements beside the extension's are read but not used.
        Map<String, Material> m = parse("newmtl gold\nNs 250\nKa 1 1 1\nKd 1 0.78 0.34\nKs 0.5 0.5 0.5\nKe 0.1 0.2 0.3\nNi 1.45\nd 1\nillum 2\n"
                + "Pr 0.25\nPm 1\nmap_Ks tex.png\n"
                + "newmtl rough\nPr 0.8\n"
                + "newmtl metal\nPm 0.5\n"
                + "newmtl glass\nKd 1 1 1\nPr 0\nd 0.25\nTf 1 0.5 1\n");
        Material gold = m.get("gold");
        assertEquals(Material.Model.PRINCIPLED, gold.model());
        assertColor(new Color(1, 0.78, 0.34), gold.color());
        assertEquals(List.of(1.0, 0.25, 0.0, 1.45), List.of(gold.metallic(), gold.roughness(), gold.transmission(), gold.ior()));
        assertColor(new Color(0.1, 0.2, 0.3), gold.emission());
        assertNull(gold.texture(Channel.EMISSION), "Ke is the principled material's own emission");
        assertNull(gold.texture(Channel.SPECULAR), "map_Ks is a Whitted channel");
        Material rough = m.get("rough");
        assertEquals(List.of(0.0, 0.8, 0.0, 1.5), List.of(rough.metallic(), rough.roughness(), rough.transmission(), rough.ior()));
        assertColor(Color.grey(0.8), rough.color());
        assertEquals(List.of(0.5, 0.5), List.of(m.get("metal").metallic(), m.get("metal").roughness()));
        Material glass = m.get("glass");
        assertEquals(0.75, glass.transmission(), 1e-12);
        assertEquals(0.0, glass.roughness());
        assertColor(new Color(1, 0.5, 1), glass.filter());
    }

    @Test
    void physicallyBasedMapsBindTheirChannels() {
        Map<String, Material> m = parse("newmtl a\nmap_Pr tex.png\nmap_Pm -s 2 tex.png\nmap_d tex.png\nd 0.5\n"
                + "newmtl b\nPr 0.5\nmap_Pr tex.png\n");
        Material a = m.get("a");
        assertEquals(Material.Model.PRINCIPLED, a.model());
        assertInstanceOf(ImageTexture.class, a.texture(Channel.ROUGHNESS));
        assertInstanceOf(ImageTexture.class, a.texture(Channel.METALLIC));
        assertInstanceOf(Dissolve.class, a.texture(Channel.TRANSPARENCY));
        // A map alone gives the value, the material's is 1; transmission is 1 and the map dissolves it.
        assertEquals(List.of(1.0, 1.0, 1.0), List.of(a.roughness(), a.metallic(), a.transmission()));
        assertEquals(0.5, m.get("b").roughness());
    }

    @Test
    void mapsBindImageTexturesWithTheirOptions() {
        Map<String, Material> m = parse("""
                newmtl textured
                d 0.5
                map_Kd -s 2 3 -o 0.5 0.25 -clamp on tex.png
                map_Ks tex.png
                map_d -o 0.1 tex.png
                map_Bump -bm 0.3 tex.png
                newmtl bumped
                bump tex.png
                """);
        Material t = m.get("textured");
        ImageTexture diffuse = assertInstanceOf(ImageTexture.class, t.texture(Channel.DIFFUSE));
        assertEquals(Wrap.CLAMP, diffuse.wrap());
        assertEquals(Wrap.REPEAT, ((ImageTexture) t.texture(Channel.SPECULAR)).wrap());
        assertNotNull(t.texture(Channel.SPECULAR));
        TexturePoint p = new TexturePoint();
        double[] zero = {0, 0, 0}, one = {1, 0, 0};
        t.mapping(Channel.DIFFUSE).map(1, 1, one, one, zero, p);
        assertEquals(2.5, p.u, 1e-12, "-s scales, then -o moves");
        assertEquals(3.25, p.v, 1e-12);
        t.mapping(Channel.TRANSPARENCY).map(0, 0, one, one, zero, p);
        assertEquals(0.1, p.u, 1e-12);
        assertEquals(0, p.v, 1e-12, "-o with one number moves u only");
        assertInstanceOf(Dissolve.class, t.texture(Channel.TRANSPARENCY), "map_d is an opacity: its transparency is 1 - d map");
        assertEquals(1, t.kt(), "the dissolve map gives the transparency");
        assertNotNull(t.texture(Channel.BUMP));
        assertEquals(0.3, t.bumpStrength());
        assertEquals(1, m.get("bumped").bumpStrength());
        assertNotNull(m.get("bumped").texture(Channel.BUMP));
        assertEquals(1, cache.size(), "one image, loaded once through the cache");
    }

    @Test
    void readsAFileAndResolvesTexturesBesideIt() throws IOException {
        Path sub = Files.createDirectories(dir.resolve("lib"));
        Files.copy(dir.resolve("tex.png"), sub.resolve("t.png"));
        Path mtl = sub.resolve("a.mtl");
        Files.writeString(mtl, "\uFEFFnewmtl a\r\nmap_Kd t.png\r\n");
        Map<String, Material> m = MtlReader.read(mtl, cache);
        assertNotNull(m.get("a").texture(Channel.DIFFUSE));
        SceneException e = assertThrows(SceneException.class, () -> MtlReader.read(dir.resolve("none.mtl"), cache));
        assertTrue(e.getMessage().startsWith(dir.resolve("none.mtl") + ": material library not found"), e.getMessage());
    }

    static List<org.junit.jupiter.params.provider.Arguments> badInput() {
        return List.of(
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKx 1\n", "2:1: unknown material statement 'Kx' (did you mean 'Kd'?) (supported: newmtl, Kd, Ka, Ks, Ns, d, Tr, Tf, Ni, Ke, illum, map_Kd, map_Ks, map_d, map_Bump, bump, Pr, Pm, map_Pr, map_Pm)"),
                org.junit.jupiter.params.provider.Arguments.of("Kd 1 1 1\n", "1:1: 'Kd' before any 'newmtl' (a material's statements follow its newmtl line)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl\n", "1:7: expected a material name after 'newmtl', found end of line"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nnewmtl b\nnewmtl a\n", "3:8: material 'a' defined twice (first on line 1)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd 1 x 1\n", "2:6: expected a number for 'Kd', found 'x'"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd 1 1\n", "2:7: expected 1 or 3 numbers for 'Kd', found 2"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd 1 1 1 1\n", "2:10: unexpected '1' after the colour of 'Kd' (expected 1 or 3 numbers)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd" + " 1".repeat(100_000) + "\n", "2:10: unexpected '1' after the colour of 'Kd' (expected 1 or 3 numbers)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd 200\n", "2:4: 'Kd' must be between 0 and 100, found 200"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKa spectral ka.rfl\n", "2:4: 'Ka spectral' is not supported; give r g b (or one number for grey)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKs\n", "2:3: expected 1 or 3 numbers for 'Ks', found end of line"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nNs -1\n", "2:4: 'Ns' must be between 0 and 1e6, found -1"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nNs 10 20\n", "2:7: unexpected '20' after the value of 'Ns'"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nd 1.5\n", "2:3: 'd' must be between 0 and 1, found 1.5"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nd -halo 0.5\n", "2:3: 'd -halo' is not supported (a dissolve that depends on the viewing angle); give d alone"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nd 0.5\nTr 0.5\n", "3:1: 'Tr' given twice for material 'a' (first on line 2); Tr is 1 - d, give one of them"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd 1\nKd 0\n", "3:1: 'Kd' given twice for material 'a' (first on line 2)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nillum 11\n", "2:7: expected an illumination model 0 to 9 for 'illum', found 11"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nillum 2.5\n", "2:7: expected an illumination model 0 to 9 for 'illum', found '2.5'"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nillum 10\n", "2:7: illum 10 (shadows cast onto invisible surfaces) is not supported; expected 0 to 9"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nNi 0\nillum 7\n", "2:1: Ni must be above 0 for illum 7 (it refracts), found 0.0"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nillum 0\nKe 1 1 1\n", "3:1: illum 0 (a constant colour, Kd) cannot have Ke: give illum 1 or 2 for a lit surface"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_Ka tex.png\n", "2:1: 'map_Ka' is not supported (the diffuse map, map_Kd, also drives the ambient term); supported: newmtl, Kd, Ka, Ks, Ns, d, Tr, Tf, Ni, Ke, illum, map_Kd, map_Ks, map_d, map_Bump, bump, Pr, Pm, map_Pr, map_Pm"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_Kd -blendu off tex.png\n", "2:8: texture option '-blendu' is not supported (supported: -o, -s, -clamp)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_Kd -bm 2 tex.png\n", "2:8: '-bm' (the bump multiplier) applies to map_Bump and bump only"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_Kd -s 0 1 tex.png\n", "2:8: '-s' scales must be above 0, found 0.0 1.0"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_Kd -clamp maybe tex.png\n", "2:15: expected on or off after '-clamp', found 'maybe'"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_Kd -o\n", "2:10: expected 1 to 3 numbers (u, v, w) after '-o'"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nmap_d -o 1 2\n", "2:13: expected a texture file name for 'map_d', found end of line"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nTf 1 2 1\n", "2:6: 'Tf' must be between 0 and 1, found 2"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nPr 1.5\n", "2:4: 'Pr' must be between 0 and 1, found 1.5"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nPm -0\nPm 1\n", "3:1: 'Pm' given twice for material 'a' (first on line 2)"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nKd 2 1 1\nPm 1\n",
                        "2:1: Kd must be between 0 and 1 for a physically based material (Pr, Pm), found (2.0, 1.0, 1.0): a base colour is a reflectance"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nNi 0\nPr 0.2\n", "2:1: Ni must be above 0 for a physically based material (Pr, Pm), found 0.0"),
                org.junit.jupiter.params.provider.Arguments.of("newmtl a\nPs 0.5\n",
                        "2:1: 'Ps' is not supported (the principled material has no sheen, clearcoat or anisotropy; of the physically based keys Pr, Pm, map_Pr and map_Pm are read); supported: newmtl, Kd, Ka, Ks, Ns, d, Tr, Tf, Ni, Ke, illum, map_Kd, map_Ks, map_d, map_Bump, bump, Pr, Pm, map_Pr, map_Pm"));
    }

    @ParameterizedTest
    @MethodSource("badInput")
    void badInputIsLocated(String text, String expected) {
        SceneException e = assertThrows(SceneException.class, () -> parse(text));
        assertEquals("m.mtl:" + expected, e.getMessage());
    }

    @Test
    void aMissingTextureIsLocatedAtItsName() {
        SceneException e = assertThrows(SceneException.class, () -> parse("newmtl a\nmap_Kd -clamp on  no such.png\n"));
        assertTrue(e.getMessage().startsWith("m.mtl:2:19: texture image 'no such.png' not found"), e.getMessage());
        assertEquals(2, e.line());
        assertEquals(19, e.column());
    }

    @Test
    void anUnreadableTextureIsLocatedAtItsName() throws IOException {
        Files.writeString(dir.resolve("bad.png"), "not an image");
        SceneException e = assertThrows(SceneException.class, () -> parse("newmtl a\nbump bad.png\n"));
        assertTrue(e.getMessage().startsWith("m.mtl:2:6: cannot read texture image 'bad.png': "), e.getMessage());
    }
}
