package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.math.Color;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.Cylinder;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.scene.Triangle;

/** The parser builds exactly the objects, settings, materials, camera and lights a scene text describes. */
class SceneParserTest {
    private static SceneBuilder parse(String text) {
        return SceneParser.parse(text, "test.dat", Path.of("."));
    }

    private static final String FULL = """
            # every statement once, most keys given
            settings {
              width 320  height 200
              samples 4  maxdepth 5
              mincontribution 0.01
              background 0.1 0.2 0.3
              ambient 0.5            # one number = grey
              encoding srgb
              seed -7
            }
            camera { eye 0 2 -6  lookat 0 1 0  up 0 0 1  fov 60 }
            light { position 5 10 -5  color 1 0.9 0.8  intensity 2  falloff inverse-square }
            light { position 0 5 0 }
            material glass {
              color 0.9 1 0.95  ka 0  kd 0.1  ks 0.8  shininess 100
              kr 0.1  kt 0.9  ior 1.5  beta 0.2 0.1 0  filter 0.5 0.6 0.7  fresnel true
            }
            material matte { }
            sphere {
              center 0 1 0  radius 0.5
              translate 1 2 3  rotate y 90  scale 2
              material glass  name "ball \\"one\\" \\\\ end"
            }
            plane { }
            plane { normal 0 0 2  offset 4  material matte }
            box { min 1 1 1  max -1 0 -2  rotate 1 0 0 30  scale 1 2 3 }
            cylinder { base 0 0 0  top 0 2 0 }
            triangle {
              vertices 0 0 0  1 0 0  0 1 0
              material { color 1 0 0  kd 0.7 }
            }
            """;

    @Test
    void settingsCameraAndLights() {
        SceneBuilder b = parse(FULL);
        assertEquals(RenderSettings.builder().size(320, 200).samplesPerPixel(4).maxDepth(5).minContribution(0.01)
                .background(new Color(0.1, 0.2, 0.3)).ambient(Color.grey(0.5)).srgb(true).seed(-7).build(), b.settings());
        PinholeCamera cam = assertInstanceOf(PinholeCamera.class, b.camera());
        assertEquals(new Vec3(0, 2, -6), cam.eye());
        assertEquals(new Vec3(0, 1, 0), cam.lookAt());
        assertEquals(new Vec3(0, 0, 1), cam.up());
        assertEquals(60, cam.fovDegrees());
        assertEquals(List.of(
                new PointLight(new Vec3(5, 10, -5), new Color(1, 0.9, 0.8), 2, PointLight.Falloff.INVERSE_SQUARE),
                new PointLight(new Vec3(0, 5, 0), Color.WHITE, 1, PointLight.Falloff.NONE)), b.lights());
    }

    @Test
    void namedMaterials() {
        SceneBuilder b = parse(FULL);
        Material g = b.material("glass");
        assertEquals("glass", g.name());
        assertEquals(new Color(0.9, 1, 0.95), g.color());
        assertEquals(0, g.ka());
        assertEquals(0.1, g.kd());
        assertEquals(0.8, g.ks());
        assertEquals(100, g.shininess());
        assertEquals(0.1, g.kr());
        assertEquals(0.9, g.kt());
        assertEquals(1.5, g.ior());
        assertEquals(new Color(0.2, 0.1, 0), g.beta());
        assertEquals(new Color(0.5, 0.6, 0.7), g.filter());
        assertTrue(g.fresnel());

        // An empty block keeps every default of Material.builder().
        Material m = b.material("matte"), d = Material.builder().build();
        assertEquals("matte", m.name());
        assertEquals(d.color(), m.color());
        assertEquals(d.filter(), m.filter());
        assertEquals(d.beta(), m.beta());
        assertEquals(List.of(d.ka(), d.kd(), d.ks(), d.shininess(), d.kr(), d.kt(), d.ior()),
                List.of(m.ka(), m.kd(), m.ks(), m.shininess(), m.kr(), m.kt(), m.ior()));
        assertEquals(d.fresnel(), m.fresnel());
    }

    @Test
    void objectsInOrderWithTheirValues() {
        SceneBuilder b = parse(FULL);
        List<GObject> objs = b.objects();
        assertEquals(6, objs.size());

        Sphere s = assertInstanceOf(Sphere.class, objs.get(0));
        assertEquals(new Vec3(0, 1, 0), s.center());
        assertEquals(0.5, s.radius());
        assertSame(b.material("glass"), s.material());
        assertEquals("ball \"one\" \\ end", s.name());
        assertEquals(Transform.translate(1, 2, 3).then(Transform.rotateY(90)).then(Transform.scale(2, 2, 2)), s.transform());

        Plane p0 = assertInstanceOf(Plane.class, objs.get(1));
        assertEquals(Vec3.Y, p0.normal());
        assertEquals(0, p0.offset());
        assertNull(p0.material(), "no material given: the scene default applies when built");
        assertTrue(p0.transform().isIdentity());
        assertEquals("plane", p0.name());

        Plane p1 = assertInstanceOf(Plane.class, objs.get(2));
        assertEquals(Vec3.Z, p1.normal());
        assertEquals(2, p1.offset());
        assertSame(b.material("matte"), p1.material());

        Box box = assertInstanceOf(Box.class, objs.get(3));
        assertEquals(new Vec3(-1, 0, -2), box.min());
        assertEquals(new Vec3(1, 1, 1), box.max());
        assertEquals(Transform.rotate(Vec3.X, 30).then(Transform.scale(1, 2, 3)), box.transform());

        Cylinder c = assertInstanceOf(Cylinder.class, objs.get(4));
        assertEquals(Vec3.ZERO, c.base());
        assertEquals(new Vec3(0, 2, 0), c.top());
        assertEquals(1, c.radius(), "radius defaults to 1");

        Triangle t = assertInstanceOf(Triangle.class, objs.get(5));
        Material inline = t.material();
        assertNull(inline.name());
        assertEquals(new Color(1, 0, 0), inline.color());
        assertEquals(0.7, inline.kd());
        assertEquals(Material.builder().build().ka(), inline.ka());
    }

    @Test
    void defaultsWhenNothingIsGiven() {
        SceneBuilder b = parse("# nothing but a comment\n\n");
        assertEquals(RenderSettings.DEFAULT, b.settings());
        assertNull(b.camera());
        assertTrue(b.lights().isEmpty());
        assertTrue(b.objects().isEmpty());

        b = parse("sphere { }  camera { eye 1 2 3  lookat 0 0 0 }");
        Sphere s = (Sphere) b.objects().get(0);
        assertEquals(Vec3.ZERO, s.center());
        assertEquals(1, s.radius());
        PinholeCamera cam = (PinholeCamera) b.camera();
        assertEquals(Vec3.Y, cam.up());
        assertEquals(45, cam.fovDegrees());
    }

    @Test
    void settingsKeysOverrideOnlyWhatTheyName() {
        SceneBuilder b = parse("settings { height 100  encoding linear }");
        assertEquals(RenderSettings.builder().height(100).build(), b.settings());
        assertEquals(lt.spindulys.scene.AcceleratorKind.BVH, b.settings().accelerator());
        for (var kind : lt.spindulys.scene.AcceleratorKind.values()) {
            assertEquals(kind, parse("settings { accelerator " + kind.keyword() + " }").settings().accelerator());
        }
    }

    @Test
    void filterAndItsWidthAreSettings() {
        RenderSettings s = parse("settings { filter blackman-harris }").settings();
        assertEquals(lt.spindulys.camera.PixelFilter.BLACKMAN_HARRIS, s.filter());
        assertEquals(1.5, s.pixelFilterWidth());
        RenderSettings m = parse("settings { filterwidth 3  filter mitchell }").settings();
        assertEquals(lt.spindulys.camera.PixelFilter.MITCHELL, m.filter());
        assertEquals(3, m.pixelFilterWidth());
        assertEquals(lt.spindulys.camera.PixelFilter.BOX, parse("settings { width 10 }").settings().filter());
        SceneException bad = assertThrows(SceneException.class, () -> parse("settings { filter lanczos }"));
        assertTrue(bad.getMessage().contains("expected box, gaussian, blackman-harris or mitchell for 'filter', found 'lanczos'"), bad.getMessage());
        SceneException wide = assertThrows(SceneException.class, () -> parse("settings { filterwidth 40 }"));
        assertTrue(wide.getMessage().contains("filterwidth must be 0 (the filter's default) or from 0.1 to 16 pixels, found 40.0"), wide.getMessage());
    }

    @Test
    void adaptiveSamplingSettingsAndTheirOneLineErrors() {
        RenderSettings s = parse("settings { samples 256  noisethreshold 0.01 }").settings();
        assertEquals(0.01, s.noiseThreshold());
        assertTrue(s.adaptiveSampling());
        assertEquals(64, s.adaptiveMinSamples(), "Cycles' default: max(4, ceil(16 / 0.01^0.3))");
        assertEquals(32, parse("settings { samples 256  noisethreshold 0.1 }").settings().adaptiveMinSamples());
        assertEquals(16, parse("settings { samples 16  noisethreshold 0.01 }").settings().adaptiveMinSamples(), "at most the samples");
        assertEquals(8, parse("settings { samples 16  noisethreshold 0.01  minsamples 8 }").settings().adaptiveMinSamples());
        assertFalse(parse("settings { samples 16 }").settings().adaptiveSampling());
        assertEquals(EnumSet.of(Aov.NOISE), parse("settings { aov noise }").settings().aovs());
        String[][] cases = {
                {"settings { noisethreshold -0.5 }", "test.dat:1:12: noisethreshold must be 0 (no adaptive sampling) or a relative error up to 1, found -0.5"},
                {"settings { minsamples 70000 }", "test.dat:1:12: minsamples must be 0 (the default) or between 1 and 65536, found 70000"},
                {"settings { samples 16\n  noisethreshold 0.01  minsamples 32 }", "test.dat:2:24: minsamples 32 is more than samples 16 (expected at most the samples per pixel)"},
                {"settings { samples 16  timesteps 2  noisethreshold 0.01 }",
                        "test.dat:1:37: noisethreshold 0.01 needs timesteps 1, found 2 (adaptive sampling stops a pixel on all its samples at once)"},
                {"settings { samples 16  timesteps 2  aov noise }", "test.dat:1:37: the noise pass needs timesteps 1, found 2"},
        };
        for (String[] c : cases) {
            SceneException e = assertThrows(SceneException.class, () -> parse(c[0]), c[0]);
            assertEquals(c[1], e.getMessage(), c[0]);
        }
    }

    @Test
    void aovListEndsAtTheNextKeyOrTheBrace() {
        assertEquals(Set.of(), parse("settings { width 10 }").settings().aovs());
        RenderSettings s = parse("settings { aov object depth  width 10 }").settings();
        assertEquals(EnumSet.of(Aov.DEPTH, Aov.OBJECT), s.aovs());
        assertEquals(10, s.width());
        assertEquals(EnumSet.of(Aov.NORMAL, Aov.DEPTH, Aov.OBJECT), parse("settings { width 10 aov normal depth object}").settings().aovs());
        assertEquals(EnumSet.complementOf(EnumSet.of(Aov.NOISE)), parse("settings { width 10 aov normal depth object albedo}").settings().aovs());
        assertEquals(RenderSettings.builder().aovs(EnumSet.of(Aov.NORMAL)).build(), parse("settings { aov normal }").settings());
    }

    @Test
    void transformsComposeInTheOrderWritten() {
        GObject a = parse("sphere { translate 1 0 0  rotate z 90 }").objects().get(0);
        GObject b = parse("sphere { rotate z 90  translate 1 0 0 }").objects().get(0);
        // Moved to x=1, then turned about the origin onto the y axis; or turned in place, then moved.
        assertVecEquals(new Vec3(0, 1, 0), a.transform().point(Vec3.ZERO));
        assertVecEquals(new Vec3(1, 0, 0), b.transform().point(Vec3.ZERO));

        GObject r = parse("sphere { rotate x 10  rotate 0 0 2 90  rotate x 20  scale 1 2 3  scale 2 }").objects().get(0);
        assertEquals(Transform.rotateX(10).then(Transform.rotate(Vec3.Z, 90)).then(Transform.rotateX(20))
                .then(Transform.scale(1, 2, 3)).then(Transform.scale(2, 2, 2)), r.transform());
    }

    @Test
    void lexicalForms() {
        // CRLF and lone CR line ends, tabs, comments glued to values, every number form, names with . and -.
        String text = "material glass.v2-b {\r\n\tkd .5 ks 5. ka +0.25\rkr -1.5e-3e0 }";
        SceneException e = assertThrows(SceneException.class, () -> parse(text));
        assertEquals("test.dat:3:4: malformed number '-1.5e-3e0'", e.getMessage());

        SceneBuilder b = parse("material glass.v2-b {\r\n\tkd .5 ks 5.#comment\rka +0.25 kr 1.5E-3 }\n"
                + "sphere{material glass.v2-b name\"\"}");
        Material m = b.material("glass.v2-b");
        assertEquals(0.5, m.kd());
        assertEquals(5, m.ks());
        assertEquals(0.25, m.ka());
        assertEquals(0.0015, m.kr());
        assertSame(m, b.objects().get(0).material());
        assertEquals("", b.objects().get(0).name());
    }

    @Test
    void positionsCountTabsAsOneColumnAndCrLfAsOneLineEnd() {
        SceneException e = assertThrows(SceneException.class, () -> parse("sphere {\r\n\tradius -1 }"));
        assertEquals(2, e.line());
        assertEquals(2, e.column());
        e = assertThrows(SceneException.class, () -> parse("\uFEFFsphere { radus 1 }"));
        assertEquals("test.dat:1:10: unknown property 'radus' in sphere (did you mean 'radius'?)", e.getMessage());
    }

    @Test
    void fileNameIsOptional() {
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse("box { }", null, null));
        assertEquals("<input>:1:1: box needs 'min' and 'max'", e.getMessage());
    }

    @Test
    void readsAFileAndResolvesMeshPathsAgainstItsFolder(@TempDir Path dir) throws IOException {
        Path scenes = Files.createDirectories(dir.resolve("scenes"));
        Path f = scenes.resolve("room.dat");
        Files.writeString(f, "sphere { radius 2 }\nmesh { file \"../models/bunny.obj\" }\n");
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(f));
        assertEquals(f + ":2:13: mesh file '../models/bunny.obj' not found (looked in "
                + dir.toAbsolutePath().resolve("models/bunny.obj") + ")", e.getMessage());

        Files.writeString(f, "sphere { radius 2 }\n");
        SceneBuilder b = SceneParser.parse(f);
        assertEquals(2, ((Sphere) b.objects().get(0)).radius());
    }

    @Test
    void refusesAFileThatIsNotUtf8(@TempDir Path dir) throws IOException {
        Path f = dir.resolve("latin1.dat");
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        bytes.writeBytes("sphere {\n  name \"caf".getBytes(StandardCharsets.US_ASCII));
        bytes.write(0xE9); // é in ISO-8859-1
        bytes.writeBytes("\" }\n".getBytes(StandardCharsets.US_ASCII));
        Files.write(f, bytes.toByteArray());
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(f));
        assertEquals(f + ":2:12: the file is not UTF-8 text: byte 0xE9 cannot be decoded", e.getMessage());

        Files.writeString(f, "sphere { name \"café\" }", StandardCharsets.UTF_8);
        assertEquals("café", SceneParser.parse(f).objects().get(0).name());
    }

    @Test
    void builderRefusalsKeepTheirCause() {
        SceneException e = assertThrows(SceneException.class, () -> parse("sphere { radius -1 }"));
        assertInstanceOf(IllegalArgumentException.class, e.getCause());
    }

    @Test
    void suggestionsUseEditDistanceWithSwaps() {
        assertEquals(1, SceneGrammar.editDistance("shpere", "sphere"));
        assertEquals(2, SceneGrammar.editDistance("radus", "radiuss"));
        assertEquals("sphere", SceneGrammar.nearest("shpere", SceneGrammar.statementNames()));
        assertEquals("ka", SceneGrammar.nearest("kq", SceneGrammar.MATERIAL.keyNames()));
        // Too far, or as far as the word is long: no suggestion rather than a random one.
        assertNull(SceneGrammar.nearest("teapot", SceneGrammar.statementNames()));
        assertNull(SceneGrammar.nearest("qq", SceneGrammar.MATERIAL.keyNames()));
    }

    @Test
    void grammarTableIsConsistent() {
        for (SceneGrammar.Block blk : SceneGrammar.STATEMENTS) {
            assertEquals(blk.keys().size(), blk.keyNames().stream().distinct().count(), blk.keyword() + " has a key twice");
            for (SceneGrammar.Key k : blk.keys()) {
                assertFalse(k.required() && k.defaultValue() != null, k.name() + " is required yet has a default");
                assertEquals(k.kind() == SceneGrammar.Kind.CHOICE || k.kind() == SceneGrammar.Kind.CHOICES, !k.choices().isEmpty(), k.name());
            }
        }
    }

    private static void assertVecEquals(Vec3 expected, Vec3 actual) {
        assertTrue(expected.minus(actual).length() < 1e-12, "expected " + expected + " but was " + actual);
    }
}
