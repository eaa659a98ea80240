package lt.spindulys.plugin.raytrace;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.OutputPlugins;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.render.RenderJob;
import lt.spindulys.render.RenderResult;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.PointLight;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Checker;
import lt.spindulys.texture.Cylindrical;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.Planar;
import lt.spindulys.texture.Spherical;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.Uv;

class RayTracePluginTest {
    private static final Path RESOURCES = Path.of("src/test/resources/plugin/raytrace");

    @TempDir Path dir;

    /** The cube of cube.obj, as a host would build it: same vertices and faces, a sharp crease on edge 2-6. */
    static ControlMesh cube() {
        double[] p = {-1, -1, -1, 1, -1, -1, 1, 1, -1, -1, 1, -1, -1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1};
        return ControlMesh.builder(p, quads(), faces()).crease(2, 6, ControlMesh.INFINITELY_SHARP).source("cube").build();
    }

    /** The cube of small-cube.obj. */
    static ControlMesh smallCube() {
        double a = 1.75, b = 3.25, l = -0.75, h = 0.75;
        double[] p = {a, l, l, b, l, l, b, h, l, a, h, l, a, l, h, b, l, h, b, h, h, a, h, h};
        return ControlMesh.builder(p, quads(), faces()).source("small cube").build();
    }

    private static int[] quads() { return new int[] {4, 4, 4, 4, 4, 4}; }

    private static int[] faces() { return new int[] {0, 3, 2, 1, 4, 5, 6, 7, 0, 4, 7, 3, 1, 2, 6, 5, 0, 1, 5, 4, 3, 7, 6, 2}; }

    static List<DisplayedSurface> surfaces() {
        return List.of(new DisplayedSurface("cube", cube(), DisplayedSurface.Scheme.CATMULL_CLARK, 2),
                new DisplayedSurface("small cube", smallCube(), DisplayedSurface.Scheme.CATMULL_CLARK, 1));
    }

    static PluginView view() {
        return new PluginView(new Vec3(1.5, 2.5, -6), new Vec3(1.2, 0, 0), Vec3.Y, 40, 640, 480);
    }

    /** The options of by-hand.dat. */
    static Map<String, String> handOptions() {
        Map<String, String> o = new HashMap<>();
        o.put("width", "64");
        o.put("height", "48");
        o.put("samples", "1");
        o.put("lighting", "headlight");
        o.put("floor", "none");
        o.put("surface.0.rendering", "host-level");
        o.put("surface.1.rendering", "adaptive");
        return o;
    }

    private static PluginResult run(Map<String, String> options, Path out, PluginProgress progress) throws Exception {
        return new RayTracePlugin().run(new PluginRequest(surfaces(), view(), options, out, progress));
    }

    @Test
    void serviceLoaderFindsThePlugin() {
        List<OutputPlugin> all = OutputPlugins.available();
        assertTrue(all.stream().anyMatch(p -> p instanceof RayTracePlugin), "found: " + all);
        assertEquals(Set.of("obj", "raytrace"), new HashSet<>(all.stream().map(OutputPlugin::id).toList()), "both of the library's plugins");
        OutputPlugin p = OutputPlugins.find("raytrace").orElseThrow();
        assertEquals("Ray tracer", p.name());
        assertEquals(List.of("jpg", "png", "tga"), p.fileExtensions());
    }

    @Test
    void surfacesHandedOverRenderBitIdenticallyToTheSameSceneWrittenByHand() throws Exception {
        Path viaPlugin = dir.resolve("plugin.png"), byHand = dir.resolve("hand.png");
        run(handOptions(), viaPlugin, PluginProgress.NONE);
        RenderResult hand = RenderJob.of(RESOURCES.resolve("by-hand.dat")).output(byHand).run();
        assertArrayEquals(Files.readAllBytes(byHand), Files.readAllBytes(viaPlugin), "the plugin's PNG is the hand-written scene's, byte for byte");
        // And the frames themselves, as doubles, from the builder the plugin makes.
        RenderResult built = RenderJob.of(RayTraceOptions.resolve(surfaces(), view(), handOptions()).scene().toBuilder(new TextureCache())).run();
        assertArrayEquals(hand.frame().data(), built.frame().data());
        assertNotEquals(pixel(viaPlugin, 0, 0), pixel(viaPlugin, 20, 24), "the picture shows something");
    }

    @Test
    void theSavedSceneReadBackRendersBitIdenticallyToThePluginsPicture() throws Exception {
        Path texture = dir.resolve("textures").resolve("grid.png");
        Files.createDirectories(texture.getParent());
        BufferedImage img = new BufferedImage(8, 8, BufferedImage.TYPE_INT_RGB);
        for (int y = 0; y < 8; y++) for (int x = 0; x < 8; x++) img.setRGB(x, y, (x + y) % 2 == 0 ? 0xE0C080 : 0x306090);
        ImageIO.write(img, "png", texture.toFile());
        Map<String, String> o = new HashMap<>();
        o.put("width", "48");
        o.put("height", "36");
        o.put("samples", "2");
        o.put("lighting", "studio");
        o.put("floor", "checker");
        o.put("background", "0.3 0.1 0.05");
        o.put("save-scene", "true");
        o.put("identify", "true");
        o.put("surface.0.material", "transparent");
        o.put("surface.0.attenuation", "0.5");
        o.put("surface.0.tint", "0.9 0.95 0.8");
        o.put("surface.0.rendering", "adaptive");
        o.put("surface.1.material", "mirror");
        o.put("surface.1.rendering", "host-level");
        o.put("surface.1.shading", "flat");
        o.put("surface.1.texture", texture.toString());
        o.put("surface.1.mapping", "planar");
        Path out = dir.resolve("scene.tga");
        PluginResult r = run(o, out, PluginProgress.NONE);
        Path dat = dir.resolve("scene.dat");
        assertEquals(List.of(out, dir.resolve("scene.surfaces.png"), dat, dir.resolve("scene.0-cube.obj"), dir.resolve("scene.1-small_cube.obj")), r.files());
        String text = Files.readString(dat);
        assertTrue(text.contains("image \"textures/grid.png\""), "the texture named relative to the scene:\n" + text);
        Path again = dir.resolve("again.tga");
        RenderJob.of(dat).output(again).run();
        assertArrayEquals(Files.readAllBytes(out), Files.readAllBytes(again), "the saved scene renders the plugin's picture, byte for byte");
        // Each surface's default (limit) rendering also survives the round trip.
        Map<String, String> limit = new HashMap<>(handOptions());
        limit.remove("surface.0.rendering");
        limit.remove("surface.1.rendering");
        limit.put("save-scene", "true");
        Path limitOut = dir.resolve("limit.png");
        run(limit, limitOut, PluginProgress.NONE);
        Path limitAgain = dir.resolve("limit-again.png");
        assertTrue(Files.readString(dir.resolve("limit.dat")).contains("subdiv { file \"limit.0-cube.obj\"  level 2  positions limit"));
        RenderJob.of(dir.resolve("limit.dat")).output(limitAgain).run();
        assertArrayEquals(Files.readAllBytes(limitOut), Files.readAllBytes(limitAgain));
    }

    @Test
    void oddSurfaceNamesSurviveTheSavedSceneAndTheLegend() throws Exception {
        String odd = "a \"quoted\" \\ name \u00e9\nsecond line " + "x".repeat(200);
        List<DisplayedSurface> shown = List.of(new DisplayedSurface(odd, cube(), DisplayedSurface.Scheme.CATMULL_CLARK, 1));
        Map<String, String> o = Map.of("width", "16", "height", "12", "samples", "1", "save-scene", "true", "identify", "true");
        Path out = dir.resolve("odd.png");
        PluginResult r = new RayTracePlugin().run(new PluginRequest(shown, view(), o, out, PluginProgress.NONE));
        String text = Files.readString(dir.resolve("odd.dat"));
        assertTrue(text.contains("name \"a \\\"quoted\\\" \\\\ name \u00e9 second line x"), text);
        Path again = dir.resolve("odd-again.png");
        RenderJob.of(dir.resolve("odd.dat")).output(again).run();
        assertArrayEquals(Files.readAllBytes(out), Files.readAllBytes(again));
        assertTrue(r.files().get(3).getFileName().toString().startsWith("odd.0-a__quoted___"), r.files().toString());
        BufferedImage id = ImageIO.read(dir.resolve("odd.surfaces.png").toFile());
        assertTrue(id.getWidth() < 16 + 6 * 80, "the legend shows a long name cut: " + id.getWidth());
    }

    @Test
    void everyFileExtensionIsWritten() throws Exception {
        for (String ext : List.of("jpg", "png", "tga")) {
            Path out = dir.resolve("out." + ext);
            PluginResult r = run(handOptions(), out, PluginProgress.NONE);
            assertEquals(List.of(out), r.files());
            assertTrue(Files.size(out) > 100, ext);
        }
        BufferedImage jpg = ImageIO.read(dir.resolve("out.jpg").toFile());
        assertEquals(64, jpg.getWidth());
        assertEquals(48, jpg.getHeight());
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> run(handOptions(), dir.resolve("out.bmp"), PluginProgress.NONE));
        assertTrue(e.getMessage().contains(".jpg, .png or .tga"), e.getMessage());
        assertFalse(Files.exists(dir.resolve("out.bmp")));
    }

    @Test
    void defaultsComeFromTheViewAndTheSurfaces() {
        List<PluginOption> o = new RayTracePlugin().options(surfaces(), view());
        assertEquals("640", option(o, "width").defaultValue());
        assertEquals("480", option(o, "height").defaultValue());
        assertEquals("cube", option(o, "surface.0.material").group());
        assertEquals("small cube", option(o, "surface.1.material").group());
        assertEquals("limit", option(o, "surface.0.rendering").defaultValue());
        assertEquals("checker", option(o, "floor").defaultValue(), "the eye is above the surfaces");
        assertEquals("spherical", option(o, "surface.0.mapping").defaultValue(), "no texture coordinates: a projection");
        List<DisplayedSurface> polyhedron = List.of(new DisplayedSurface("cage", cube(), DisplayedSurface.Scheme.NONE, 0));
        List<PluginOption> p = new RayTracePlugin().options(polyhedron, view());
        assertEquals("host-level", option(p, "surface.0.rendering").defaultValue());
        assertEquals("flat", option(p, "surface.0.shading").defaultValue());
        // The host's shading decides: facets of a subdivided surface stay facets at the host's level,
        // and a control mesh the host shades smoothly is shaded smoothly.
        List<DisplayedSurface> facets = List.of(new DisplayedSurface("cage", cube(), DisplayedSurface.Scheme.CATMULL_CLARK, 2,
                DisplayedSurface.Shading.FLAT));
        List<PluginOption> f = new RayTracePlugin().options(facets, view());
        assertEquals("host-level", option(f, "surface.0.rendering").defaultValue());
        assertEquals("flat", option(f, "surface.0.shading").defaultValue());
        List<DisplayedSurface> roundCage = List.of(new DisplayedSurface("cage", cube(), DisplayedSurface.Scheme.NONE, 0,
                DisplayedSurface.Shading.SMOOTH));
        List<PluginOption> r = new RayTracePlugin().options(roundCage, view());
        assertEquals("host-level", option(r, "surface.0.rendering").defaultValue());
        assertEquals("smooth", option(r, "surface.0.shading").defaultValue());
        PluginView below = new PluginView(new Vec3(0, -5, -5), Vec3.ZERO, Vec3.Y, 40, 64, 48);
        assertEquals("none", option(new RayTracePlugin().options(surfaces(), below), "floor").defaultValue());
        // Every option's default resolves (the whole default scene builds).
        SceneBuilder b = RayTraceOptions.resolve(surfaces(), view(), Map.of()).scene().toBuilder(new TextureCache());
        b.build();
    }

    private static PluginOption option(List<PluginOption> options, String key) {
        return options.stream().filter(o -> o.key().equals(key)).findFirst().orElseThrow(() -> new AssertionError("no option " + key));
    }

    @Test
    void imageOptionsReachTheSettingsAndCamera() {
        Map<String, String> v = new HashMap<>(Map.of("width", "80", "height", "30", "samples", "9", "background", "0.1 0.2 0.3"));
        SceneBuilder b = builder(v);
        RenderSettings s = b.settings();
        assertEquals(80, s.width());
        assertEquals(30, s.height());
        assertEquals(9, s.samplesPerPixel());
        assertEquals(new Color(0.1, 0.2, 0.3), s.background());
        assertTrue(s.srgb());
        PinholeCamera c = assertInstanceOf(PinholeCamera.class, b.camera());
        assertEquals(view().eye(), c.eye());
        assertEquals(view().target(), c.lookAt());
        assertEquals(view().up(), c.up());
        assertEquals(40, c.fovDegrees());
    }

    @Test
    void lightingPresetsReachTheLights() {
        assertEquals(List.of(new PointLight(view().eye(), Color.WHITE, 1, PointLight.Falloff.NONE)), builder(Map.of("lighting", "headlight")).lights());
        List<PointLight> studio = builder(Map.of("lighting", "studio")).lights();
        assertEquals(3, studio.size());
        Vec3 centre = new Vec3(1.125, 0, 0);
        for (PointLight l : studio) assertTrue(l.position().minus(centre).length() > 3, "outside the surfaces: " + l);
        List<PointLight> sun = builder(Map.of("lighting", "sun")).lights();
        assertEquals(1, sun.size());
        assertTrue(sun.get(0).position().y() > 10, "high above: " + sun.get(0));
    }

    @Test
    void floorOptionReachesThePlane() {
        List<GObject> none = builder(Map.of("floor", "none")).objects();
        assertEquals(2, none.size());
        Plane plain = assertInstanceOf(Plane.class, builder(Map.of("floor", "plain")).objects().get(2));
        assertEquals(Vec3.Y, plain.normal());
        assertTrue(plain.offset() < -1 && plain.offset() > -1.01, "just under the cube: " + plain.offset());
        assertEquals(null, plain.material().texture(Channel.DIFFUSE));
        Plane checker = assertInstanceOf(Plane.class, builder(Map.of("floor", "checker")).objects().get(2));
        assertInstanceOf(Checker.class, checker.material().texture(Channel.DIFFUSE));
    }

    @Test
    void materialOptionsReachEachSurface() {
        Map<String, String> v = new HashMap<>();
        v.put("surface.0.material", "transparent");
        v.put("surface.0.ior", "1.33");
        v.put("surface.0.tint", "0.9 1 0.8");
        v.put("surface.0.attenuation", "0.25");
        v.put("surface.1.material", "mirror");
        v.put("surface.1.reflectivity", "0.6");
        v.put("surface.1.color", "0.5 0.6 0.7");
        List<GObject> o = builder(v).objects();
        Material glass = o.get(0).material();
        assertTrue(glass.kt() > 0);
        assertEquals(1.33, glass.ior());
        assertEquals(new Color(0.9, 1, 0.8), glass.filter());
        assertEquals(Color.grey(0.25), glass.beta());
        assertTrue(glass.fresnel());
        Material mirror = o.get(1).material();
        assertEquals(0.6, mirror.kr());
        assertEquals(new Color(0.5, 0.6, 0.7), mirror.color());
        Material opaque = builder(Map.of("surface.0.color", "0.2 0.3 0.4")).objects().get(0).material();
        assertEquals(new Color(0.2, 0.3, 0.4), opaque.color());
        assertEquals(0, opaque.kt());
        assertEquals(0, opaque.kr());
    }

    @Test
    void textureOptionsReachTheMaterial() throws IOException {
        Path image = dir.resolve("grid.png");
        BufferedImage img = new BufferedImage(4, 4, BufferedImage.TYPE_INT_RGB);
        img.setRGB(1, 1, 0xFF0000);
        ImageIO.write(img, "png", image.toFile());
        Map<String, Class<?>> expected = Map.of("planar", Planar.class, "spherical", Spherical.class, "cylindrical", Cylindrical.class);
        for (Map.Entry<String, Class<?>> e : expected.entrySet()) {
            Material m = builder(Map.of("surface.1.texture", image.toString(), "surface.1.mapping", e.getKey())).objects().get(1).material();
            assertInstanceOf(ImageTexture.class, m.texture(Channel.DIFFUSE));
            assertInstanceOf(e.getValue(), m.mapping(Channel.DIFFUSE));
            assertEquals(Color.WHITE, m.color(), "the texture shows as it is");
        }
        // uv needs texture coordinates: a cube with them takes it.
        ControlMesh withUvs = ControlMesh.builder(cube().positions(), quads(), faces())
                .uvs(new double[] {0, 0, 1, 0, 1, 1, 0, 1}, new int[] {0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3}).build();
        List<DisplayedSurface> one = List.of(new DisplayedSurface("unwrapped", withUvs, DisplayedSurface.Scheme.CATMULL_CLARK, 1));
        assertEquals("uv", option(RayTraceOptions.options(one, view()), "surface.0.mapping").defaultValue());
        Material uv = RayTraceOptions.resolve(one, view(), Map.of("surface.0.texture", image.toString())).scene()
                .toBuilder(new TextureCache()).objects().get(0).material();
        assertInstanceOf(Uv.class, uv.mapping(Channel.DIFFUSE));
    }

    @Test
    void renderingAndShadingOptionsReachTheSurfaces() {
        Map<String, String> v = new HashMap<>();
        v.put("surface.0.rendering", "host-level");
        v.put("surface.0.shading", "flat");
        v.put("surface.1.rendering", "adaptive");
        List<GObject> o = builder(v).objects();
        SubdivisionSurface host = assertInstanceOf(SubdivisionSurface.class, o.get(0));
        assertEquals(2, host.level());
        assertFalse(host.isSmooth());
        AdaptiveSubdivisionSurface adaptive = assertInstanceOf(AdaptiveSubdivisionSurface.class, o.get(1));
        assertEquals(AdaptiveSubdivisionSurface.Method.COMBINED, adaptive.method());
        assertEquals(1.0, adaptive.target());
        assertEquals(-1, adaptive.fixedLevel());
        assertTrue(adaptive.isSmooth());
        // The limit surface: the host's level with the vertices at their limit positions.
        SubdivisionSurface limit = assertInstanceOf(SubdivisionSurface.class, builder(Map.of("surface.0.rendering", "limit")).objects().get(0));
        assertEquals(2, limit.level());
        assertEquals(SubdivisionSurface.Positions.LIMIT, limit.positions());
        assertEquals(SubdivisionSurface.Positions.REFINED, host.positions());
        // A polyhedron at the host's level is its control mesh.
        List<DisplayedSurface> cage = List.of(new DisplayedSurface("cage", cube(), DisplayedSurface.Scheme.NONE, 0));
        SubdivisionSurface flat = assertInstanceOf(SubdivisionSurface.class,
                RayTraceOptions.resolve(cage, view(), Map.of()).scene().toBuilder(new TextureCache()).objects().get(0));
        assertEquals(0, flat.level());
        assertFalse(flat.isSmooth());
        // Its limit surface is refined a few levels: at level 0 it would be the cage shrunk.
        SubdivisionSurface cageLimit = assertInstanceOf(SubdivisionSurface.class,
                RayTraceOptions.resolve(cage, view(), Map.of("surface.0.rendering", "limit")).scene().toBuilder(new TextureCache()).objects().get(0));
        assertEquals(RayTraceOptions.LIMIT_LEVEL_OF_A_POLYHEDRON, cageLimit.level());
        assertEquals(SubdivisionSurface.Positions.LIMIT, cageLimit.positions());
    }

    @Test
    void aHostLevelTooLargeToRefineWholeIsRenderedByTheCombinedMethodAtThatLevel() {
        // A 32 x 32 grid of quads at level 8: 4096 corners, 4096 * 4^7 = 67 million faces, past SubdivisionSurface.MAX_FACES.
        int n = 32;
        double[] p = new double[3 * (n + 1) * (n + 1)];
        for (int j = 0, k = 0; j <= n; j++) for (int i = 0; i <= n; i++) { p[k++] = i; p[k++] = 0; p[k++] = j; }
        int[] sizes = new int[n * n], corners = new int[4 * n * n];
        for (int j = 0, f = 0; j < n; j++) {
            for (int i = 0; i < n; i++, f++) {
                sizes[f] = 4;
                int a = j * (n + 1) + i;
                corners[4 * f] = a;
                corners[4 * f + 1] = a + n + 1;
                corners[4 * f + 2] = a + n + 2;
                corners[4 * f + 3] = a + 1;
            }
        }
        ControlMesh grid = ControlMesh.builder(p, sizes, corners).build();
        List<DisplayedSurface> shown = List.of(new DisplayedSurface("grid", grid, DisplayedSurface.Scheme.CATMULL_CLARK, 8));
        SceneDescription d = RayTraceOptions.resolve(shown, view(), Map.of("surface.0.rendering", "host-level")).scene();
        assertEquals("level 8 (combined method: too large to refine whole)", d.surfaces().get(0).renderedAs());
        AdaptiveSubdivisionSurface s = assertInstanceOf(AdaptiveSubdivisionSurface.class, d.toBuilder(new TextureCache()).objects().get(0));
        assertEquals(8, s.fixedLevel());
        assertTrue(d.toText(List.of("grid.obj"), dir, "test").contains("subdiv { file \"grid.obj\"  method combined  level 8\n"));
        // Limit positions need uniform refinement: too large for it, the limit is approximated to half-pixel edges.
        SceneDescription limit = RayTraceOptions.resolve(shown, view(), Map.of("surface.0.rendering", "limit")).scene();
        assertEquals("limit surface (adaptive, 0.5 px edges: level 8 is too large to refine whole)", limit.surfaces().get(0).renderedAs());
        AdaptiveSubdivisionSurface a = assertInstanceOf(AdaptiveSubdivisionSurface.class, limit.toBuilder(new TextureCache()).objects().get(0));
        assertEquals(0.5, a.target());
        assertEquals(-1, a.fixedLevel());
    }

    private static SceneBuilder builder(Map<String, String> values) {
        return RayTraceOptions.resolve(surfaces(), view(), values).scene().toBuilder(new TextureCache());
    }

    @Test
    void badValuesGiveOneLineNamingTheOption() throws IOException {
        Path out = dir.resolve("bad.png");
        Map<String, String> cases = new HashMap<>();
        cases.put("width", "Image width (width) must be between 1 and 32768, found 0");
        cases.put("samples", "Samples per pixel (samples) must be a whole number, found 'many'");
        cases.put("surface.1.ior", "Index of refraction (surface.1.ior) must be between 1.0 and 5.0, found 0.5");
        cases.put("surface.0.tint", "Tint (surface.0.tint) must be three numbers r g b between 0 and 1, found '1 1'");
        cases.put("lighting", "Lighting (lighting) must be one of studio, headlight, sun, found 'disco'");
        cases.put("surface.0.texture", "Texture image (surface.0.texture) names no file: '");
        Map<String, String> values = Map.of("width", "0", "samples", "many", "surface.1.ior", "0.5", "surface.0.tint", "1 1",
                "lighting", "disco", "surface.0.texture", dir.resolve("missing.png").toString());
        for (Map.Entry<String, String> c : cases.entrySet()) {
            Map<String, String> o = new HashMap<>(handOptions());
            o.put(c.getKey(), values.get(c.getKey()));
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> run(o, out, PluginProgress.NONE));
            assertTrue(e.getMessage().startsWith(c.getValue()), e.getMessage());
            assertFalse(e.getMessage().contains("\n"), e.getMessage());
        }
        Map<String, String> huge = new HashMap<>(handOptions());
        huge.put("width", "32768");
        huge.put("height", "32768");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> run(huge, out, PluginProgress.NONE));
        assertTrue(e.getMessage().startsWith("Image width (width) and height (height): the 32768x32768 frame needs "), e.getMessage());
        Map<String, String> unknown = new HashMap<>(handOptions());
        unknown.put("surface.0.colour", "1 0 0");
        e = assertThrows(IllegalArgumentException.class, () -> run(unknown, out, PluginProgress.NONE));
        assertTrue(e.getMessage().startsWith("unknown option 'surface.0.colour'"), e.getMessage());
        // A texture that is not an image, and uv mapping on a surface without texture coordinates.
        Path notImage = Files.writeString(dir.resolve("notes.png"), "not a picture");
        Map<String, String> broken = new HashMap<>(handOptions());
        broken.put("surface.1.texture", notImage.toString());
        e = assertThrows(IllegalArgumentException.class, () -> run(broken, out, PluginProgress.NONE));
        assertTrue(e.getMessage().startsWith("Texture image (surface.1.texture) of surface 'small cube' cannot be used: "), e.getMessage());
        broken.put("surface.1.mapping", "uv");
        e = assertThrows(IllegalArgumentException.class, () -> run(broken, out, PluginProgress.NONE));
        assertTrue(e.getMessage().startsWith("Texture mapping (surface.1.mapping) is uv, but surface 'small cube' has no texture coordinates"), e.getMessage());
        assertFalse(Files.exists(out));
        try (Stream<Path> left = Files.list(dir)) {
            assertEquals(List.of(notImage), left.toList(), "nothing else written");
        }
    }

    @Test
    void anUnwritableOutputFailsBeforeRendering() {
        Map<String, String> o = new HashMap<>(handOptions());
        o.put("save-scene", "true");
        int[] reports = {0};
        PluginProgress counting = new PluginProgress() {
            @Override public void progress(double fraction, String stage) { reports[0]++; }
            @Override public boolean isCancelled() { return false; }
        };
        IOException e = assertThrows(IOException.class, () -> run(o, dir.resolve("missing").resolve("out.jpg"), counting));
        assertTrue(e.getMessage().contains("missing"), e.getMessage());
        assertEquals(0, reports[0], "nothing rendered");
    }

    @Test
    void aCancelledRenderWritesNothingAndKeepsAnExistingFile() throws Exception {
        for (int cancelAfter : new int[] {0, 1, 3}) {
            Path out = Files.writeString(dir.resolve("keep" + cancelAfter + ".png"), "old content");
            Map<String, String> o = new HashMap<>(handOptions());
            o.put("identify", "true");
            o.put("save-scene", "true");
            java.util.concurrent.atomic.AtomicInteger asked = new java.util.concurrent.atomic.AtomicInteger();
            PluginProgress cancelling = new PluginProgress() {
                @Override public void progress(double fraction, String stage) { }
                @Override public boolean isCancelled() { return asked.getAndIncrement() >= cancelAfter; }
            };
            assertThrows(CancellationException.class, () -> run(o, out, cancelling));
            assertEquals("old content", Files.readString(out));
        }
        try (Stream<Path> left = Files.list(dir)) {
            assertEquals(3, left.count(), "only the three old files");
        }
    }

    @Test
    void aCancelWhileTheFilesAreWrittenStillWritesNothing() throws Exception {
        Path out = Files.writeString(dir.resolve("late.png"), "old content");
        Map<String, String> o = new HashMap<>(handOptions());
        o.put("identify", "true");
        o.put("save-scene", "true");
        // The user cancels just after the picture is encoded, before the other files are.
        java.util.concurrent.atomic.AtomicBoolean writing = new java.util.concurrent.atomic.AtomicBoolean();
        java.util.concurrent.atomic.AtomicInteger askedWhileWriting = new java.util.concurrent.atomic.AtomicInteger();
        PluginProgress late = new PluginProgress() {
            @Override public void progress(double fraction, String stage) { if (stage.equals("writing")) writing.set(true); }
            @Override public boolean isCancelled() { return writing.get() && askedWhileWriting.incrementAndGet() >= 2; }
        };
        assertThrows(CancellationException.class, () -> run(o, out, late));
        assertEquals("old content", Files.readString(out));
        try (Stream<Path> left = Files.list(dir)) {
            assertEquals(List.of(out), left.toList(), "no other file, no temporary file");
        }
    }

    @Test
    void aPreviewComesFirstThenTheFinalPicture() throws Exception {
        List<int[]> sizes = new ArrayList<>();
        List<Boolean> last = new ArrayList<>();
        List<int[]> pixels = new ArrayList<>();
        List<Double> fractions = new ArrayList<>();
        PluginProgress p = new PluginProgress() {
            @Override public synchronized void progress(double fraction, String stage) { fractions.add(fraction); }
            @Override public boolean isCancelled() { return false; }
            @Override public synchronized void preview(int width, int height, int[] argb, boolean isLast) {
                sizes.add(new int[] {width, height});
                last.add(isLast);
                pixels.add(argb);
            }
        };
        Path out = dir.resolve("p.png");
        // Previews at every tile: the coarse one, one per tile of the 64 x 48 picture (16-pixel tiles), the final picture.
        new RayTracePlugin(0).run(new PluginRequest(surfaces(), view(), handOptions(), out, p));
        assertEquals(1 + 4 * 3 + 1, last.size());
        assertArrayEquals(new int[] {16, 12}, sizes.get(0));
        for (int i = 1; i < sizes.size(); i++) {
            assertArrayEquals(new int[] {64, 48}, sizes.get(i));
            assertEquals(i == sizes.size() - 1, last.get(i));
        }
        BufferedImage written = ImageIO.read(out.toFile());
        int[] picture = written.getRGB(0, 0, 64, 48, null, 0, 64);
        assertArrayEquals(picture, pixels.get(pixels.size() - 1), "the final preview is the written picture");
        assertArrayEquals(picture, pixels.get(pixels.size() - 2), "the last tile completes it");
        // The first tile preview is the coarse preview scaled up, but for one tile of the picture (where they differ).
        int[] first = pixels.get(1), coarse = pixels.get(0);
        int differ = 0;
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                if (first[y * 64 + x] != coarse[(y / 4) * 16 + x / 4]) {
                    differ++;
                    assertEquals(picture[y * 64 + x], first[y * 64 + x]);
                }
            }
        }
        assertTrue(differ <= 16 * 16, differ + " pixels, at most one tile");
        assertTrue(fractions.contains(1.0));
        for (double f : fractions) assertTrue(f >= 0 && f <= 1, "fraction " + f);
        // At the default pace a small picture goes straight from the coarse preview to the final one.
        last.clear();
        run(handOptions(), dir.resolve("q.png"), p);
        assertEquals(Boolean.FALSE, last.get(0));
        assertEquals(Boolean.TRUE, last.get(last.size() - 1));
    }

    @Test
    void theIdentificationImageColoursSurfacesDistinctlyWithALegend() throws Exception {
        Map<String, String> o = new HashMap<>(handOptions());
        o.put("identify", "true");
        o.put("floor", "plain");
        Path out = dir.resolve("id.png");
        PluginResult r = run(o, out, PluginProgress.NONE);
        Path id = dir.resolve("id.surfaces.png");
        assertEquals(List.of(out, id), r.files());
        assertTrue(r.summary().startsWith("64 x 48, 1 sample, "), r.summary());
        BufferedImage img = ImageIO.read(id.toFile());
        // The picture region: the object pass of the same view, surface i in colour(i).
        RenderResult pass = RenderJob.of(RayTraceOptions.resolve(surfaces(), view(), o).scene().toBuilder(new TextureCache()))
                .settings(s -> s.toBuilder().aovs(Set.of(Aov.OBJECT)).build()).run();
        Set<Integer> seen = new HashSet<>();
        for (int y = 0; y < 48; y++) {
            for (int x = 0; x < 64; x++) {
                int objectId = pass.passes().orElseThrow().objectId(x, y);
                int expected = objectId < 0 ? IdentificationImage.BACKGROUND : objectId < 2 ? IdentificationImage.colour(objectId) : IdentificationImage.FLOOR;
                assertEquals(expected, img.getRGB(x, y) & 0xFFFFFF, "pixel " + x + "," + y);
                seen.add(expected);
            }
        }
        assertEquals(Set.of(IdentificationImage.FLOOR, IdentificationImage.colour(0), IdentificationImage.colour(1)), seen,
                "both surfaces and the floor show (the view looks down: the floor hides the background)");
        assertNotEquals(IdentificationImage.colour(0), IdentificationImage.colour(1));
        // The legend: a swatch and two lines per surface, in the built-in font.
        String[] lines = {"cube: Catmull-Clark, level 2", "rendered as level 2", "small cube: Catmull-Clark, level 1", "rendered as adaptive (1 px edges)"};
        int textWidth = Stream.of(lines).mapToInt(l -> BitmapFont.width(l, 1)).max().orElseThrow();
        assertEquals(Math.max(64, 4 + 7 + 4 + textWidth + 4), img.getWidth(), "the panel widens for text longer than the picture");
        assertEquals(48 + 4 + 2 * 20 + 4, img.getHeight());
        for (int i = 0; i < 2; i++) {
            int top = 48 + 4 + 20 * i;
            assertEquals(IdentificationImage.colour(i), img.getRGB(4 + 3, top + 3) & 0xFFFFFF, "swatch " + i);
            int[] expected = new int[img.getWidth() * 16];
            java.util.Arrays.fill(expected, IdentificationImage.PANEL);
            BitmapFont.draw(expected, img.getWidth(), 15, 0, lines[2 * i], IdentificationImage.TEXT, 1);
            BitmapFont.draw(expected, img.getWidth(), 15, 9, lines[2 * i + 1], IdentificationImage.TEXT, 1);
            for (int y = 0; y < 16; y++) {
                for (int x = 15; x < img.getWidth(); x++) {
                    assertEquals(expected[y * img.getWidth() + x], img.getRGB(x, top + y) & 0xFFFFFF, "legend of surface " + i + " at " + x + "," + y);
                }
            }
        }
    }

    @Test
    void paletteColoursAreDistinctAndNeverNeutral() {
        Set<Integer> seen = new HashSet<>(List.of(IdentificationImage.BACKGROUND, IdentificationImage.FLOOR, IdentificationImage.PANEL, IdentificationImage.TEXT));
        for (int i = 0; i < 64; i++) assertTrue(seen.add(IdentificationImage.colour(i)), "colour " + i + " is new");
    }

    private static int pixel(Path png, int x, int y) throws IOException {
        return ImageIO.read(png.toFile()).getRGB(x, y);
    }
}
