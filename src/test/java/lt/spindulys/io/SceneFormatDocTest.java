package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.math.Color;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.GObject;
import lt.spindulys.material.Material;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;

/**
 * docs/scene-format.md and the grammar table cannot drift apart: each statement has a section whose
 * key table lists exactly the keys the parser accepts, and every example in the document parses.
 */
class SceneFormatDocTest {
    private static final Path DOC = Path.of("docs/scene-format.md");
    private static final Pattern KEY_ROW = Pattern.compile("^\\| `([A-Za-z_][A-Za-z0-9_.-]*)` \\|", Pattern.MULTILINE);
    private static final Pattern DAT_BLOCK = Pattern.compile("```dat\\n(.*?)```", Pattern.DOTALL);

    private static String doc() throws IOException {
        return Files.readString(DOC);
    }

    /** The text of the "### heading" section, up to the next heading of level 2 or 3. */
    private static String section(String doc, String heading) {
        int start = doc.indexOf("\n### " + heading + "\n");
        assertTrue(start >= 0, "docs/scene-format.md has no section '### " + heading + "'");
        Matcher end = Pattern.compile("\\n##+ ").matcher(doc);
        int stop = end.find(start + 1) ? end.start() : doc.length();
        return doc.substring(start, stop);
    }

    private static Set<String> keyRows(String section) {
        Set<String> keys = new LinkedHashSet<>();
        Matcher m = KEY_ROW.matcher(section);
        while (m.find()) keys.add(m.group(1));
        return keys;
    }

    private static List<String> names(List<SceneGrammar.Key> keys) {
        List<String> out = new ArrayList<>();
        for (SceneGrammar.Key k : keys) out.add(k.name());
        return out;
    }

    @Test
    void everyStatementAndKeyIsDocumentedAndNothingElse() throws IOException {
        String doc = doc();
        for (SceneGrammar.Block b : SceneGrammar.STATEMENTS) {
            List<String> own = names(b.keys());
            if (b.category().isObject()) own.removeAll(names(SceneGrammar.OBJECT_COMMON));
            assertEquals(new LinkedHashSet<>(own), keyRows(section(doc, "`" + b.keyword() + "`")), "keys of " + b.keyword());
        }
        assertEquals(new LinkedHashSet<>(names(SceneGrammar.OBJECT_COMMON)), keyRows(section(doc, "Common object keys")));
        // No section documents a statement the parser does not know.
        Matcher h = Pattern.compile("^### `([a-z]+)`$", Pattern.MULTILINE).matcher(doc);
        while (h.find()) assertTrue(SceneGrammar.statement(h.group(1)) != null, "documented statement " + h.group(1) + " is unknown");
    }

    /** The texture binding block nested in materials is not a statement; its keys have a section of their own. */
    @Test
    void textureBindingKeysAreDocumented() throws IOException {
        assertEquals(new LinkedHashSet<>(names(SceneGrammar.MAP.keys())), keyRows(section(doc(), "Texture bindings (`map`)")));
    }

    /** The motion block nested in objects is not a statement either. */
    @Test
    void motionKeysAreDocumented() throws IOException {
        assertEquals(new LinkedHashSet<>(names(SceneGrammar.MOTION.keys())), keyRows(section(doc(), "Motion (`motion`)")));
    }

    /** The keys, key pose and turntable blocks of an animation are not statements either. */
    @Test
    void animationBlockKeysAreDocumented() throws IOException {
        String doc = doc();
        assertEquals(new LinkedHashSet<>(names(SceneGrammar.KEYS.keys())), keyRows(section(doc, "Keys (`keys`)")));
        assertEquals(new LinkedHashSet<>(names(SceneGrammar.KEY.keys())), keyRows(section(doc, "Key poses (`key`)")));
        assertEquals(new LinkedHashSet<>(names(SceneGrammar.TURNTABLE.keys())), keyRows(section(doc, "Turntable (`turntable`)")));
    }

    @Test
    void everyExampleParses() throws IOException {
        Matcher m = DAT_BLOCK.matcher(doc());
        int examples = 0;
        while (m.find()) {
            examples++;
            String text = m.group(1);
            try {
                SceneParser.parse(text, "example.dat", Path.of("docs"));
            } catch (SceneException e) {
                // The examples name model files that are not shipped; everything before that must be valid.
                assertTrue((text.contains("mesh") || text.contains("subdiv")) && e.getMessage().contains("mesh file"),
                        "example fails: " + e.getMessage() + "\n" + text);
            }
        }
        assertTrue(examples >= 12, "found only " + examples + " examples");
    }

    /** The file of "The same scene in Java" and the code shown next to it make the same objects. */
    @Test
    void javaRouteMatchesTheFile() throws IOException {
        String doc = doc();
        Matcher m = DAT_BLOCK.matcher(doc.substring(doc.indexOf("## The same scene in Java")));
        assertTrue(m.find());
        SceneBuilder f = SceneParser.parse(m.group(1), "example.dat", Path.of("docs"));

        // The code from the document.
        SceneBuilder b = new SceneBuilder()
                .settings(RenderSettings.builder().size(400, 300).samplesPerPixel(4).build())
                .camera(new PinholeCamera(new Vec3(0, 2, -6), new Vec3(0, 1, 0), Vec3.Y, 45))
                .light(new PointLight(new Vec3(5, 10, -5), Color.WHITE, 1, PointLight.Falloff.NONE));
        b.defineMaterial("glass", Material.builder().color(Color.WHITE).kd(0.1).ks(0.8).shininess(100)
                .kr(0.1).kt(0.9).ior(1.5).name("glass").build());
        b.add(new Sphere(new Vec3(0, 1, 0), 1).material(b.material("glass")));
        b.add(new Plane(Vec3.Y, 0));
        b.add(new Box(new Vec3(-1, 0, -1), new Vec3(1, 1, 1))
                .transform(Transform.rotateY(30))
                .transform(Transform.translate(3, 0, 2))
                .material(Material.builder().color(new Color(0.8, 0.2, 0.2)).build()));

        assertEquals(b.settings(), f.settings());
        PinholeCamera bc = (PinholeCamera) b.camera(), fc = (PinholeCamera) f.camera();
        assertEquals(List.of(bc.eye(), bc.lookAt(), bc.up(), bc.fovDegrees()), List.of(fc.eye(), fc.lookAt(), fc.up(), fc.fovDegrees()));
        assertEquals(b.lights(), f.lights());
        assertSameMaterial(b.material("glass"), f.material("glass"));
        assertEquals(b.objects().size(), f.objects().size());
        for (int i = 0; i < b.objects().size(); i++) {
            GObject x = b.objects().get(i), y = f.objects().get(i);
            assertEquals(x.getClass(), y.getClass());
            assertEquals(x.transform(), y.transform());
            assertEquals(x.name(), y.name());
            if (x.material() == null) assertEquals(null, y.material());
            else assertSameMaterial(x.material(), y.material());
        }
        Sphere s = assertInstanceOf(Sphere.class, f.objects().get(0));
        assertEquals(List.of(new Vec3(0, 1, 0), 1.0), List.of(s.center(), s.radius()));
        Plane p = assertInstanceOf(Plane.class, f.objects().get(1));
        assertEquals(List.of(Vec3.Y, 0.0), List.of(p.normal(), p.offset()));
        Box box = assertInstanceOf(Box.class, f.objects().get(2));
        assertEquals(List.of(new Vec3(-1, 0, -1), new Vec3(1, 1, 1)), List.of(box.min(), box.max()));
        assertFalse(box.transform().isIdentity());
    }

    private static void assertSameMaterial(Material a, Material b) {
        assertEquals(List.of(String.valueOf(a.name()), a.color(), a.filter(), a.beta(), a.ka(), a.kd(), a.ks(), a.shininess(), a.kr(), a.kt(), a.ior(), a.fresnel()),
                List.of(String.valueOf(b.name()), b.color(), b.filter(), b.beta(), b.ka(), b.kd(), b.ks(), b.shininess(), b.kr(), b.kt(), b.ior(), b.fresnel()));
    }
}
