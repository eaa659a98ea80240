package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;

import lt.spindulys.material.Material;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Cylindrical;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.Planar;
import lt.spindulys.texture.Spherical;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.TexturePoint;
import lt.spindulys.texture.Uv;

/** Texture statements and material bindings become the textures and mappings they describe. */
class SceneParserTextureTest {
    private static final Path SCENES = Path.of("scenes");

    private static SceneBuilder parse(String text) {
        return SceneParser.parse(text, "t.dat", SCENES);
    }

    @Test
    void bindingsReachTheMaterial() {
        SceneBuilder b = parse("""
                texture grid { image "../textures/grid.png"  filter nearest  wrap clamp }
                texture rings { pattern wood  scale 3 }
                material m { color 1 1 1
                  map { texture grid  channel diffuse  mapping spherical  axis 0 0 1  reference 1 0 0 }
                  map { texture rings  channel bump  mapping planar  scale 2 0.5  strength -0.25 }
                  map { texture rings  channel specular  mapping cylindrical }
                  map { texture grid  channel emission }
                }
                """);
        Material m = b.material("m");
        assertInstanceOf(ImageTexture.class, m.texture(Channel.DIFFUSE));
        assertInstanceOf(Spherical.class, m.mapping(Channel.DIFFUSE));
        assertInstanceOf(Planar.class, m.mapping(Channel.BUMP));
        assertInstanceOf(Cylindrical.class, m.mapping(Channel.SPECULAR));
        assertInstanceOf(Uv.class, m.mapping(Channel.EMISSION));
        assertSame(m.texture(Channel.BUMP), m.texture(Channel.SPECULAR));
        assertSame(m.texture(Channel.DIFFUSE), m.texture(Channel.EMISSION));
        assertNull(m.texture(Channel.REFLECTION));
        assertEquals(-0.25, m.bumpStrength());

        // The planar mapping got its scale per axis: one repeat over 2 units along x, 0.5 along -z.
        TexturePoint tp = new TexturePoint();
        m.mapping(Channel.BUMP).map(0, 0, new double[3], new double[3], new double[] {1, 7, -0.25}, tp);
        assertEquals(0.5, tp.u, 1e-12);
        assertEquals(0.5, tp.v, 1e-12);
    }

    @Test
    void anImageIsLoadedOncePerParse() {
        SceneBuilder b = parse("""
                texture a { image "../textures/grid.png" }
                texture b { image "models/../../textures/grid.png"  filter nearest }
                material m { map { texture a }  map { texture b  channel emission } }
                """);
        Material m = b.material("m");
        ImageTexture a = (ImageTexture) m.texture(Channel.DIFFUSE), c = (ImageTexture) m.texture(Channel.EMISSION);
        assertSame(a.image(), c.image());
        assertNotSame(a, c);
    }

    /** A mesh's OBJ vt coordinates reach the texture through the uv mapping: an emissive quad shows the texel at its (u, v). */
    @Test
    void objTextureCoordinatesReachTheTexture(@org.junit.jupiter.api.io.TempDir Path dir) throws Exception {
        // Every corner has the same vt, so the whole quad shows the texture at (0.8, 0.3).
        java.nio.file.Files.writeString(dir.resolve("quad.obj"), "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0.8 0.3\nf 1/1 2/1 3/1 4/1\n");
        java.nio.file.Files.copy(Path.of("textures/grid.png"), dir.resolve("grid.png"));
        SceneBuilder b = SceneParser.parse("""
                settings { width 1  height 1  ambient 0 }
                camera { eye 0 0 -3  lookat 0 0 0  fov 10 }
                texture grid { image "grid.png"  filter nearest }
                mesh { file "quad.obj"  material { ka 0  kd 0  map { texture grid  channel emission } } }
                """, "t.dat", dir);
        var image = lt.spindulys.render.Renderer.render(b.build(), 1, lt.spindulys.render.ProgressListener.NONE).frame();
        Texture grid = b.objects().get(0).material().texture(Channel.EMISSION);
        double[] expected = colourAt(grid, 0.8, 0.3);
        for (int c = 0; c < 3; c++) assertEquals(expected[c], image.get(0, 0, c), 1e-9);
        assertNotEquals(colourAt(grid, 0.2, 0.3)[0], expected[0], 1e-3); // the u matters
    }

    @Test
    void inlineMaterialsBindTexturesToo() {
        SceneBuilder b = parse("""
                texture c { pattern checker  scale 4  color1 1 0 0  color2 0 0 1  solid true }
                sphere { material { map { texture c } } }
                """);
        Material m = b.objects().get(0).material();
        assertNotNull(m.texture(Channel.DIFFUSE));
        assertInstanceOf(Uv.class, m.mapping(Channel.DIFFUSE));
    }

    @Test
    void everyPatternMakesATextureThatVaries() {
        for (String pattern : SceneGrammar.PATTERNS) {
            for (String solid : new String[] {"false", "true"}) {
                SceneBuilder b = parse("texture t { pattern " + pattern + "  solid " + solid + " }\nmaterial m { map { texture t } }");
                Texture t = b.material("m").texture(Channel.DIFFUSE);
                double[] a = colourAt(t, 0.13, 0.27), c = colourAt(t, 1.61, 0.88);
                assertNotEquals(a[0] + a[1] + a[2], c[0] + c[1] + c[2], 1e-9, pattern + " solid " + solid + " is constant");
            }
        }
    }

    private static double[] colourAt(Texture t, double s, double r) {
        TexturePoint p = new TexturePoint();
        p.u = s; p.v = r; p.x = s * 2; p.y = r * 3; p.z = (s + r) * 1.7;
        double[] rgb = new double[3];
        t.evaluate(p, rgb);
        return rgb;
    }
}
