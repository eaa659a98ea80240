package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.AovFrame;
import lt.spindulys.io.SceneParser;
import lt.spindulys.math.Bounds;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.RenderResult;
import lt.spindulys.render.Renderer;
import lt.spindulys.subdiv.PatchRefiner;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;

/**
 * The adaptive subdivision surface against the uniform one, and its own promises (issue 16's
 * tests): at a fixed level every method, cache size, policy and thread count renders the uniform
 * surface's depth and normal passes; the view-dependent tessellation is watertight (rays from
 * inside always hit it), its visible edges are about the target length, and its welded mesh has
 * no crack; CSG, motion blur, instancing and face-varying UVs keep working on it.
 */
class AdaptiveSubdivisionTest {
    /** Where the OpenSubdiv reference shapes are unpacked (they are stored gzipped among the test resources). */
    @TempDir static Path shapes;

    static final Path MODELS = Path.of("scenes/models").toAbsolutePath();

    @BeforeAll
    static void unpackShapes() throws IOException {
        for (String s : REFERENCE_SHAPES) {
            try (InputStream in = new GZIPInputStream(AdaptiveSubdivisionTest.class.getResourceAsStream("/subdiv/" + s + ".obj.gz"))) {
                Files.write(shapes.resolve(s + ".obj"), in.readAllBytes());
            }
        }
    }

    /** OpenSubdiv's shapes used here: holes, boundary rules, creases (uniform and Chaikin), corners, n-gons, smooth triangles, darts. */
    static final String[] REFERENCE_SHAPES = {"catmark_hole_test1", "catmark_edgeonly", "catmark_edgecorner", "catmark_cube_creases2",
        "catmark_chaikin1", "catmark_cube_corner3", "catmark_nonquads", "catmark_smoothtris1", "catmark_dart_edgecorner", "catmark_fvar_bound1"};

    static Path file(String name) {
        return name.startsWith("catmark_") ? shapes.resolve(name + ".obj") : MODELS.resolve(name);
    }

    // ---- scenes ----

    /**
     * The thesis's power-of-two levels, which give exactly the uniform refinement's triangles at a
     * fixed level (the default, integer rates, evaluates grids on the limit surface instead:
     * {@link GridTessellationTest}); these tests check that exactness, so they ask for it.
     */
    static final String POWER_OF_TWO = "levels edge";

    /** The lazy method on the power-of-two path. */
    static final String LAZY_POWER_OF_TWO = "method lazy  " + POWER_OF_TWO;

    /** A frame around an object: the camera looks at the centre of its bounds from a direction that sees three sides. */
    record Frame(Vec3 centre, double radius) {
        String camera(double distance, Vec3 from, double fov) {
            Vec3 eye = centre.plus(from.normalized().times(distance * radius));
            return String.format(Locale.ROOT, "camera { eye %.17g %.17g %.17g  lookat %.17g %.17g %.17g  fov %s }%n",
                    eye.x(), eye.y(), eye.z(), centre.x(), centre.y(), centre.z(), fov);
        }
    }

    private static final Map<String, Frame> FRAMES = new HashMap<>();

    /** The object's bounds at level 0, as a uniform surface places them. */
    static synchronized Frame frame(String file) {
        return FRAMES.computeIfAbsent(file, k -> {
            Scene s = parse("subdiv { file \"" + file(file) + "\"  level 0 }\n").build();
            Bounds b = s.objects().get(0).bounds();
            Vec3 min = new Vec3(b.minX(), b.minY(), b.minZ()), max = new Vec3(b.maxX(), b.maxY(), b.maxZ());
            return new Frame(min.plus(max).times(0.5), max.minus(min).length() / 2);
        });
    }

    static SceneBuilder parse(String text) {
        return SceneParser.parse(text, "adaptive-test.dat", MODELS);
    }

    /** One object seen from the front, above and to the left, with its depth and normal passes. */
    static String sceneText(String file, String keys, int w, int h) {
        Frame f = frame(file);
        return String.format(Locale.ROOT, "settings { width %d  height %d  aov depth normal }%n", w, h)
                + f.camera(2.8, new Vec3(-0.45, 0.55, -1), 40)
                + "light { position -5 8 -9 }\n"
                + "subdiv { file \"" + file(file) + "\" " + keys + " }\n";
    }

    static Scene build(String text, AdaptiveSettings a) {
        SceneBuilder b = parse(text);
        b.settings(b.settings().toBuilder().adaptive(a).build());
        return b.build();
    }

    static RenderResult render(Scene s, int threads) {
        try {
            return Renderer.render(s, threads, ProgressListener.NONE);
        } catch (InterruptedException e) {
            throw new AssertionError(e);
        }
    }

    /** Depth and normal passes equal to 1e-9 of the depth and of the (unit) normal at every pixel. */
    static void assertSamePasses(RenderResult expected, RenderResult actual, String what) {
        AovFrame e = expected.passes().orElseThrow(), a = actual.passes().orElseThrow();
        int hits = 0;
        for (int y = 0; y < e.height(); y++) {
            for (int x = 0; x < e.width(); x++) {
                double de = e.depth(x, y), da = a.depth(x, y);
                if (Double.isFinite(de)) hits++;
                if (!(de == da || Math.abs(de - da) <= 1e-9 * Math.abs(de))) {
                    fail(what + ": depth at (" + x + ", " + y + ") is " + da + ", the uniform surface's " + de);
                }
                for (int c = 0; c < 3; c++) {
                    double ne = e.normal(x, y, c), na = a.normal(x, y, c);
                    if (!(ne == na || Math.abs(ne - na) <= 1e-9)) {
                        fail(what + ": normal " + "xyz".charAt(c) + " at (" + x + ", " + y + ") is " + na + ", the uniform surface's " + ne);
                    }
                }
            }
        }
        assertTrue(hits > e.width() * e.height() / 40, what + ": the object fills too little of the frame to compare (" + hits + " pixels)");
    }

    /** The largest bytes of one patch of the surface at a fixed level, and all of them together. */
    static long[] patchBytes(AdaptiveSubdivisionSurface s, int level) {
        PatchRefiner r = s.refiner();
        long max = 0, sum = 0;
        for (int f = 0; f < r.faceCount(); f++) {
            if (r.isHole(f)) continue;
            long b = r.patchBytes(f, level, s.isSmooth());
            max = Math.max(max, b);
            sum += b;
        }
        return new long[] {max, sum};
    }

    // ---- at a fixed level, every path gives the uniform surface ----

    static Stream<Arguments> fixedLevelMeshes() {
        return Stream.of(
                Arguments.of("cube.dat", 3, ""),                        // closed quads, valence-3 corners
                Arguments.of("dodecahedron.dat", 2, ""),                // closed pentagons
                Arguments.of("tetrahedron.obj", 3, "shading flat"),     // closed triangles, flat facets
                Arguments.of("house.dat", 2, ""),                       // pentagons and quads
                Arguments.of("bowl.dat", 3, ""),                        // open: a boundary rim
                Arguments.of("sheet.obj", 2, "boundary edge-only"),     // open sheet, the other boundary rule
                Arguments.of("crease-cube.obj", 3, ""),                 // infinitely sharp and semi-sharp creases, a corner
                Arguments.of("catmark_hole_test1", 2, ""),              // holes
                Arguments.of("catmark_edgeonly", 2, ""),
                Arguments.of("catmark_edgecorner", 2, ""),
                Arguments.of("catmark_cube_creases2", 3, ""),
                Arguments.of("catmark_chaikin1", 2, ""),                // Chaikin creasing
                Arguments.of("catmark_cube_corner3", 2, ""),
                Arguments.of("catmark_nonquads", 2, ""),                // n-gons and triangles, open
                Arguments.of("catmark_smoothtris1", 2, ""),             // the smooth-triangle rule
                Arguments.of("catmark_dart_edgecorner", 2, ""),
                Arguments.of("catmark_fvar_bound1", 2, ""));
    }

    record Variant(String method, AdaptiveSettings settings, int threads, String what) {}

    /**
     * Every method at a fixed level with caches that keep every patch, and the combined method
     * with room for about half the patches eager (caches that keep few are the next test's: a
     * ray reaches the one-ring boxes of most faces of a small mesh, so there every ray refines
     * again, which costs too much at this frame size).
     */
    @ParameterizedTest(name = "{0} at level {1}")
    @MethodSource("fixedLevelMeshes")
    void everyMethodGivesTheUniformSurfacesPasses(String file, int level, String keys) {
        long[] bytes = patchBytes(file, level, keys);
        long all = bytes[1];
        AdaptiveSettings d = AdaptiveSettings.DEFAULT;
        assertMethodsGiveTheUniformPasses(file, level, keys, 48, 36, List.of(
                new Variant("lazy", d, 1, "lazy, 64 MiB cache, 1 thread"),
                new Variant("lazy", d, 8, "lazy, 64 MiB cache, 8 threads"),
                new Variant("combined", new AdaptiveSettings(all + all / 2, all, false, Double.NaN), 2, "combined, half pinned, 2 threads"),
                new Variant("combined", d, 8, "combined, all pinned, 8 threads"),
                new Variant("projected", d, 2, "projected, 2 threads"),
                // Too little memory for the eager mesh: the projected method becomes combined.
                new Variant("projected", new AdaptiveSettings(all + bytes[0], all, false, Double.NaN), 2, "projected without room, 2 threads")));
    }

    /**
     * Caches that keep almost nothing: one patch, none (1 byte), and the thesis's last two patches
     * per thread. Every ray then refines most faces its boxes reach again, so smaller frames.
     */
    @ParameterizedTest(name = "{0} at level {1}")
    @MethodSource("lt.spindulys.scene.AdaptiveSubdivisionTest#tinyCacheMeshes")
    void tinyCachesGiveTheUniformSurfacesPasses(String file, int level, String keys) {
        long onePatch = patchBytes(file, level, keys)[0];
        AdaptiveSettings d = AdaptiveSettings.DEFAULT;
        assertMethodsGiveTheUniformPasses(file, level, keys, 24, 18, List.of(
                new Variant("lazy", d.withCache(onePatch), 1, "lazy, cache of one patch, 1 thread"),
                new Variant("lazy", d.withCache(onePatch), 8, "lazy, cache of one patch, 8 threads"),
                new Variant("lazy", d.withCache(1), 2, "lazy, cache of 1 byte (nothing kept), 2 threads"),
                new Variant("lazy", d.withLastTwoPatches(true), 1, "lazy, the last two patches, 1 thread"),
                new Variant("lazy", d.withLastTwoPatches(true), 8, "lazy, the last two patches, 8 threads"),
                new Variant("combined", new AdaptiveSettings(3 * onePatch, onePatch, false, Double.NaN), 2, "combined, two patches pinned, one cached, 2 threads")));
    }

    static Stream<Arguments> tinyCacheMeshes() {
        return Stream.of(Arguments.of("cube.dat", 2, ""), Arguments.of("bowl.dat", 2, ""), Arguments.of("catmark_nonquads", 1, ""),
                Arguments.of("crease-cube.obj", 2, ""), Arguments.of("catmark_hole_test1", 1, ""));
    }

    static void assertMethodsGiveTheUniformPasses(String file, int level, String keys, int w, int h, List<Variant> variants) {
        String uniform = sceneText(file, "level " + level + " " + keys, w, h);
        RenderResult expected = render(build(uniform, AdaptiveSettings.DEFAULT), 2);
        for (Variant v : variants) {
            Scene s = build(sceneText(file, "method " + v.method() + "  " + POWER_OF_TWO + "  level " + level + " " + keys, w, h), v.settings());
            assertSamePasses(expected, render(s, v.threads()), file + " at level " + level + ", " + v.what());
        }
    }

    /** The largest bytes of one patch of the surface at a fixed level, and of all of them together. */
    static long[] patchBytes(String file, int level, String keys) {
        Scene probe = build(sceneText(file, "method lazy  level " + level + " " + keys, 8, 6), AdaptiveSettings.DEFAULT);
        return patchBytes(surface(probe), level);
    }

    // ---- the view-dependent tessellation ----

    /** A scene whose camera is close to one side of the object (eye 1.7 radii from its centre), so edge levels differ. */
    static String closeUp(String file, String keys, int w, int h) {
        Frame f = frame(file);
        return String.format(Locale.ROOT, "settings { width %d  height %d }%n", w, h)
                + f.camera(1.7, new Vec3(0.35, 0.25, -1), 70)
                + "subdiv { file \"" + file(file) + "\" " + keys + " }\n";
    }

    static AdaptiveSubdivisionSurface surface(Scene s) {
        return assertInstanceOf(AdaptiveSubdivisionSurface.class, s.objects().get(0));
    }

    /** The least and largest edge level of a built surface, checked to differ by at least {@code spread}. */
    static int[] assertMixedLevels(AdaptiveSubdivisionSurface s, int spread) {
        int lo = Integer.MAX_VALUE, hi = 0;
        for (int l : s.edgeLevels()) { lo = Math.min(lo, l); hi = Math.max(hi, l); }
        assertTrue(hi - lo >= spread, s + ": edge levels " + lo + ".." + hi + " should differ by at least " + spread);
        return new int[] {lo, hi};
    }

    static Stream<Arguments> closedSurfaces() {
        return Stream.of(Arguments.of("dodecahedron.dat", "lazy"), Arguments.of("dodecahedron.dat", "projected"),
                Arguments.of("crease-cube.obj", "lazy"), Arguments.of("crease-cube.obj", "projected"),
                Arguments.of("catmark_cube_creases2", "combined"));
    }

    /**
     * pbrt-v4's watertightness property: rays from points inside a closed surface must all hit it.
     * 250,000 seeded rays per case, five cases: more than 10^6 in all, at mixed levels.
     */
    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("closedSurfaces")
    void raysFromInsideAClosedSurfaceAtMixedLevelsAllHitIt(String file, String method) {
        // maxlevel 5 keeps the near side's patches small enough for the test's time.
        Scene s = build(closeUp(file, "method " + method + "  " + POWER_OF_TWO + "  target 4  maxlevel 6", 160, 120),
                AdaptiveSettings.DEFAULT);
        int[] range = assertMixedLevels(surface(s), 1);
        Frame f = frame(file);
        int n = 250_000;
        String[] first = new String[1];
        int missed = raysFromInsideMissing(s, f.centre().x(), f.centre().y(), f.centre().z(), f.radius(), file.hashCode() * 31L + method.hashCode(), n, first);
        assertEquals(0, missed, file + " (" + method + ", edge levels " + range[0] + ".." + range[1] + "): " + missed + " of " + n
                + " rays from inside missed the surface, the first " + first[0]);
    }

    /**
     * Of n seeded rays from points within a tenth of {@code radius} of a centre inside a closed
     * surface, in uniform directions, those that do not hit it within 10 radii; the first such
     * ray goes to {@code first[0]}.
     */
    static int raysFromInsideMissing(Scene s, double cx, double cy, double cz, double radius, long seed, int n, String[] first) {
        SplittableRandom rnd = new SplittableRandom(seed);
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit hit = new Hit();
        int missed = 0;
        for (int i = 0; i < n; i++) {
            // A point within a tenth of the radius of the centre (inside these convex-ish shapes), a uniform direction.
            double ox, oy, oz;
            do {
                ox = rnd.nextDouble(-1, 1); oy = rnd.nextDouble(-1, 1); oz = rnd.nextDouble(-1, 1);
            } while (ox * ox + oy * oy + oz * oz > 1);
            double r = 0.1 * radius;
            double dx = rnd.nextDouble(-1, 1), dy = rnd.nextDouble(-1, 1), dz = rnd.nextDouble(-1, 1), l = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (!(l > 1e-3 && l <= 1)) { i--; continue; }
            ray.set(cx + r * ox, cy + r * oy, cz + r * oz, dx / l, dy / l, dz / l, 0, Double.POSITIVE_INFINITY);
            if (!s.intersect(ray, hit, ctx) || !(hit.t > 0 && hit.t < 10 * radius)) {
                if (missed++ == 0) first[0] = ray.toString();
            }
        }
        return missed;
    }

    /** Welded tessellations at mixed levels: every edge of a closed surface is shared by exactly two triangles. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("lt.spindulys.scene.AdaptiveSubdivisionTest#closedMeshes")
    void theWeldedTessellationOfAClosedSurfaceIsCrackFree(String file) {
        Scene s = build(closeUp(file, "method lazy  " + POWER_OF_TWO + "  target 4  maxlevel 6", 160, 120), AdaptiveSettings.DEFAULT);
        AdaptiveSubdivisionSurface surface = surface(s);
        assertMixedLevels(surface, 1);
        assertTrue(surface.isClosed(), file + " is closed");
        assertCrackFree(surface.tessellation(), file);
    }

    static Stream<String> closedMeshes() {
        return Stream.of("cube.dat", "dodecahedron.dat", "tetrahedron.obj", "house.dat", "crease-cube.obj", "catmark_cube_creases2",
                "catmark_chaikin1", "catmark_smoothtris1", "catmark_cube_corner3");
    }

    /** Every undirected edge of the mesh's faces is used by exactly two faces, in opposite directions. */
    static void assertCrackFree(MeshData m, String what) {
        Map<Long, int[]> uses = new HashMap<>();
        int[] sizes = m.faceSizes(), vi = m.vertexIndex();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int k = 0; k < sizes[f]; k++) {
                int a = vi[c + k], b = vi[c + (k + 1) % sizes[f]];
                int[] u = uses.computeIfAbsent(((long) Math.min(a, b) << 32) | Math.max(a, b), key -> new int[2]);
                u[a < b ? 0 : 1]++;
            }
        }
        int bad = 0;
        String example = null;
        for (Map.Entry<Long, int[]> e : uses.entrySet()) {
            int[] u = e.getValue();
            if (u[0] != 1 || u[1] != 1) {
                if (bad++ == 0) {
                    int a = (int) (e.getKey() >>> 32), b = (int) (long) e.getKey();
                    double[] p = m.positions();
                    example = String.format(Locale.ROOT, "(%g %g %g)-(%g %g %g) used %d and %d times", p[3 * a], p[3 * a + 1], p[3 * a + 2],
                            p[3 * b], p[3 * b + 1], p[3 * b + 2], u[0], u[1]);
                }
            }
        }
        assertEquals(0, bad, what + ": " + bad + " of " + uses.size() + " edges are not shared by exactly two triangles, e.g. " + example);
    }

    // ---- per-edge levels: projected edges of the rendered tessellation ----

    /**
     * How much longer than the target a visible edge of the tessellation may project. A level
     * bounds its control edge's projection conservatively (nearest distance, no foreshortening),
     * but the refined surface is not the control mesh halved: pieces follow the limit curve,
     * neighbouring longer edges pull on them, the limit surface may come closer to the eye than
     * the cage, and a stitched triangle next to a coarser edge spans that edge's longer piece from
     * the finer interior. One level too few would show as about 2; the measured worst cases
     * (printed) are well below 1.5, as for the control-edge test in adaptive/EdgeLevelsTest.
     */
    static final double TOLERANCE = 1.5;

    static Stream<Arguments> levelScenes() {
        return Stream.of(Arguments.of("dodecahedron.dat", 4.0, ""), Arguments.of("sheet.obj", 3.0, ""), Arguments.of("crease-cube.obj", 4.0, ""),
                // Loop halves its edges too: the same levels reach the target on its triangles.
                Arguments.of("loop_icosahedron.obj", 3.0, "scheme loop"));
    }

    @ParameterizedTest(name = "{0}, target {1} px {2}")
    @MethodSource("levelScenes")
    void visibleEdgesOfTheTessellationProjectToAboutTheTarget(String file, double target, String keys) {
        int w = 320, h = 240;
        String text = closeUp(file, String.format(Locale.ROOT, "method lazy  %s  target %s  %s", POWER_OF_TWO, target, keys), w, h);
        Scene s = build(text, AdaptiveSettings.DEFAULT);
        AdaptiveSubdivisionSurface surface = surface(s);
        int[] range = assertMixedLevels(surface, 1);
        PinholeCamera cam = assertInstanceOf(PinholeCamera.class, s.camera());
        Projector proj = new Projector(cam, w, h);
        MeshData m = surface.tessellation();
        double[] p = m.positions();
        int[] sizes = m.faceSizes(), vi = m.vertexIndex();
        TraceContext ctx = new TraceContext();
        Ray ray = new Ray();
        Hit hit = new Hit();
        double worst = 0;
        int checked = 0;
        Vec3 eye = cam.eye();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int k = 0; k < sizes[f]; k++) {
                int a = vi[c + k], b = vi[c + (k + 1) % sizes[f]];
                if (a > b) continue; // each edge once (the other triangle has it reversed)
                double[] pa = proj.project(p[3 * a], p[3 * a + 1], p[3 * a + 2]), pb = proj.project(p[3 * b], p[3 * b + 1], p[3 * b + 2]);
                if (!proj.inImage(pa) || !proj.inImage(pb)) continue;
                // Visible: the ray from the eye to the edge's midpoint reaches it first.
                double mx = (p[3 * a] + p[3 * b]) / 2 - eye.x(), my = (p[3 * a + 1] + p[3 * b + 1]) / 2 - eye.y(), mz = (p[3 * a + 2] + p[3 * b + 2]) / 2 - eye.z();
                double dist = Math.sqrt(mx * mx + my * my + mz * mz);
                ray.set(eye.x(), eye.y(), eye.z(), mx / dist, my / dist, mz / dist, 0, Double.POSITIVE_INFINITY);
                if (s.intersect(ray, hit, ctx) && hit.t < dist * (1 - 1e-7)) continue;
                double px = Math.hypot(pb[0] - pa[0], pb[1] - pa[1]);
                worst = Math.max(worst, px / target);
                checked++;
            }
        }
        System.out.printf(Locale.ROOT, "AdaptiveSubdivisionTest: %s %s at target %s px, edge levels %d..%d, %d visible tessellation edges, longest %.3f x the target%n",
                file, keys, target, range[0], range[1], checked, worst);
        assertTrue(checked >= 200, "enough visible edges: " + checked);
        assertTrue(worst <= TOLERANCE, file + ": a visible edge projects to " + worst + " x the target");
    }

    // ---- everything else keeps working on a lazy surface ----

    /** A scene around the cube with {@code objects} ({@code METHOD} in them replaced), and a light. */
    static String cubeScene(String settings, String objects, String method) {
        Frame f = frame("cube.dat");
        return "settings { width 48  height 36  aov depth normal " + settings + " }\n" + f.camera(3.2, new Vec3(-0.45, 0.55, -1), 40)
                + "light { position -5 8 -9 }\n" + objects.replace("CUBE", "\"" + file("cube.dat") + "\"").replace("METHOD", method) + "\n";
    }

    /** The lazy and uniform scenes' images and passes, equal. */
    static RenderResult[] assertLazyRendersAsUniform(String settings, String objects, String what) {
        RenderResult u = render(build(cubeScene(settings, objects, ""), AdaptiveSettings.DEFAULT), 2);
        RenderResult l = render(build(cubeScene(settings, objects, LAZY_POWER_OF_TWO), AdaptiveSettings.DEFAULT), 2);
        assertSamePasses(u, l, what);
        java.awt.image.BufferedImage a = u.image(), b = l.image();
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) fail(what + ": pixel (" + x + ", " + y + ") differs from the uniform surface's");
            }
        }
        return new RenderResult[] {u, l};
    }

    @Test
    void csgWithALazyOperandEqualsTheUniformOne() {
        assertLazyRendersAsUniform("", "difference { subdiv { file CUBE  level 2  METHOD }  sphere { center -0.6 0.7 -0.6  radius 0.75 } }",
                "difference");
        assertLazyRendersAsUniform("", "intersection { subdiv { file CUBE  level 2  METHOD }  sphere { center 0.2 0.1 -0.1  radius 1.05 } }",
                "intersection");
    }

    @Test
    void aMovingLazySurfaceEqualsTheUniformOne() {
        assertLazyRendersAsUniform("samples 4  shutter 0 1",
                "subdiv { file CUBE  level 2  METHOD  motion { translate 0.7 0.2 0  rotate y 25 } }", "motion blur");
    }

    @Test
    void faceVaryingUvsWithATextureEqualTheUniformOnes() {
        Path dice = Path.of("textures/dice.png").toAbsolutePath();
        assertLazyRendersAsUniform("", "texture dice { image \"" + dice + "\" }\nmaterial die { color 1 1 1  map { texture dice  mapping uv } }\n"
                + "subdiv { file CUBE  uv \"" + file("cube.tex") + "\"  level 3  METHOD  material die }", "uvs and a texture");
    }

    @Test
    void instancesShareOneTessellationBuiltOncePerFace() {
        String two = "subdiv { file CUBE  level 2  METHOD  scale 0.6  translate -0.7 0 0 }\nsubdiv { file CUBE  level 2  METHOD  scale 0.6  rotate y 30  translate 0.8 0 0.3 }";
        assertLazyRendersAsUniform("", two, "two instances");
        Scene s = build(cubeScene("", two, LAZY_POWER_OF_TWO), AdaptiveSettings.DEFAULT);
        render(s, 1);
        List<String> lines = s.adaptiveStatistics();
        assertEquals(1, lines.size(), "one tessellation for both instances: " + lines);
        Matcher m = Pattern.compile("patches (\\d+) built, (\\d+) hits").matcher(lines.get(0));
        assertTrue(m.find(), lines.get(0));
        assertEquals(6, Integer.parseInt(m.group(1)), "each of the cube's 6 faces refined once for both instances: " + lines.get(0));
        assertTrue(Long.parseLong(m.group(2)) > 1000, "the second instance's rays hit the first's patches: " + lines.get(0));
    }

    @Test
    void statsListPatchesHitsMissesEvictionsPeakAndLevels() throws IOException {
        Path scene = shapes.resolve("stats.dat"), out = shapes.resolve("stats.png");
        Files.writeString(scene, cubeScene("", "subdiv { file CUBE  METHOD  target 2 }", LAZY_POWER_OF_TWO));
        java.io.ByteArrayOutputStream o = new java.io.ByteArrayOutputStream(), e = new java.io.ByteArrayOutputStream();
        int status = lt.spindulys.cli.Main.run(new String[] {scene.toString(), "-o", out.toString(), "--stats", "--quiet", "--threads", "2"},
                new java.io.PrintStream(o, true, java.nio.charset.StandardCharsets.UTF_8), new java.io.PrintStream(e, true, java.nio.charset.StandardCharsets.UTF_8));
        assertEquals(0, status, e.toString(java.nio.charset.StandardCharsets.UTF_8));
        String line = o.toString(java.nio.charset.StandardCharsets.UTF_8).lines().filter(l -> l.startsWith("subdiv ")).findFirst().orElseThrow();
        assertTrue(Pattern.compile("^subdiv .*cube\\.dat: lazy, 6 faces, face levels [0-9: ]+; patches \\d+ built, \\d+ hits, \\d+ misses, \\d+ evictions.*, peak [0-9.]+ [KMG]?i?B.*; levels [0-9: ]+")
                .matcher(line).find(), line);
    }

    /** A pinhole camera's projection, from its public view (the frame its constructor builds). */
    static final class Projector {
        final double[] e, r, u, f;
        final double tanHalf, aspect;
        final int w, h;

        Projector(PinholeCamera c, int w, int h) {
            this.w = w;
            this.h = h;
            aspect = (double) w / h;
            e = new double[] {c.eye().x(), c.eye().y(), c.eye().z()};
            Vec3 fw = c.lookAt().minus(c.eye()).normalized();
            Vec3 rt = fw.cross(c.up()).normalized();
            Vec3 up = rt.cross(fw);
            f = new double[] {fw.x(), fw.y(), fw.z()};
            r = new double[] {rt.x(), rt.y(), rt.z()};
            u = new double[] {up.x(), up.y(), up.z()};
            tanHalf = Math.tan(Math.toRadians(c.fovDegrees()) / 2);
        }

        /** Pixel coordinates (x right, y down) of a point, or null behind the eye. */
        double[] project(double x, double y, double z) {
            double dx = x - e[0], dy = y - e[1], dz = z - e[2];
            double depth = dx * f[0] + dy * f[1] + dz * f[2];
            if (!(depth > 0)) return null;
            double sx = (dx * r[0] + dy * r[1] + dz * r[2]) / depth, sy = (dx * u[0] + dy * u[1] + dz * u[2]) / depth;
            return new double[] {(sx / (tanHalf * aspect) + 1) / 2 * w, (1 - sy / tanHalf) / 2 * h};
        }

        boolean inImage(double[] p) { return p != null && p[0] >= 0 && p[0] <= w && p[1] >= 0 && p[1] <= h; }
    }
}
