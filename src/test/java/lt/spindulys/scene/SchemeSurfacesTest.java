package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.function.Function;
import java.util.function.Supplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.image.Aov;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.render.RenderResult;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.PatchRefiner;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivOptions.Scheme;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Checker;
import lt.spindulys.texture.Uv;
import lt.spindulys.trace.Hit;
import lt.spindulys.trace.TraceContext;

/**
 * Loop and bilinear surfaces in the renderer (issue 19), built through the public builder API
 * from small cages of their own (an icosahedron, a creased octahedron, an open sheet with UVs, a
 * cube): the uniform surface's triangles and heap check, the adaptive methods at a fixed level
 * render the uniform surface's passes, the view-dependent tessellation is watertight (rays from
 * inside always hit it, random edge levels stitch without a crack), eager, lazy and combined
 * images are identical, and CSG, textures on refined UVs, motion blur and instancing work on them
 * as on Catmull-Clark surfaces ({@link AdaptiveSubdivisionTest}; {@link AdaptiveSchemesTest} runs
 * that test's fixed-level and crack tests on OpenSubdiv's Loop and bilinear shapes).
 */
class SchemeSurfacesTest {
    // ---- cages ----

    private static SubdivOptions options(Scheme s) { return SubdivOptions.DEFAULT.withScheme(s); }

    /** The icosahedron on the unit sphere: closed, valence 5 everywhere. */
    static ControlMesh icosahedron(Scheme s) {
        MeshData m = TestMeshes.icosphere(0, 1);
        return ControlMesh.builder(m.positions(), m.faceSizes(), m.vertexIndex()).options(options(s)).source("icosahedron").build();
    }

    /**
     * An octahedron (valence 4), stretched along y, with its equator infinitely sharp, one
     * semi-sharp edge from the top and a sharp corner at the bottom: closed.
     */
    static ControlMesh creasedOctahedron(Scheme s) {
        double[] p = {1, 0, 0, 0, 1.4, 0, 0, 0, 1, -1, 0, 0, 0, -1.4, 0, 0, 0, -1};
        int[] fv = {0, 1, 2, 2, 1, 3, 3, 1, 5, 5, 1, 0, 0, 2, 4, 2, 3, 4, 3, 5, 4, 5, 0, 4};
        int[] sizes = {3, 3, 3, 3, 3, 3, 3, 3};
        ControlMesh.Builder b = ControlMesh.builder(p, sizes, fv).options(options(s)).source("creased octahedron");
        b.crease(0, 2, ControlMesh.INFINITELY_SHARP).crease(2, 3, ControlMesh.INFINITELY_SHARP)
                .crease(3, 5, ControlMesh.INFINITELY_SHARP).crease(5, 0, ControlMesh.INFINITELY_SHARP);
        b.crease(1, 2, 1.5f).corner(4, ControlMesh.INFINITELY_SHARP);
        return b.build();
    }

    /** An open, wavy n x n sheet of triangles (two per grid square) with UVs over [0,1]^2: a boundary with corners. */
    static ControlMesh sheet(Scheme s, int n) {
        double[] p = new double[3 * (n + 1) * (n + 1)], uv = new double[2 * (n + 1) * (n + 1)];
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                int v = j * (n + 1) + i;
                double x = (double) i / n, y = (double) j / n;
                p[3 * v] = 2 * x - 1;
                p[3 * v + 1] = 2 * y - 1;
                p[3 * v + 2] = 0.25 * Math.sin(5 * x + 1) * Math.cos(4 * y);
                uv[2 * v] = x;
                uv[2 * v + 1] = y;
            }
        }
        int[] fv = new int[6 * n * n], sizes = new int[2 * n * n];
        java.util.Arrays.fill(sizes, 3);
        for (int j = 0, k = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i, b = a + 1, c = a + n + 2, d = a + n + 1;
                // Alternate diagonals, so the vertices have valences 4, 6 and 8 (irregular for Loop).
                if ((i + j) % 2 == 0) {
                    fv[k++] = a; fv[k++] = b; fv[k++] = c; fv[k++] = a; fv[k++] = c; fv[k++] = d;
                } else {
                    fv[k++] = a; fv[k++] = b; fv[k++] = d; fv[k++] = b; fv[k++] = c; fv[k++] = d;
                }
            }
        }
        return ControlMesh.builder(p, sizes, fv).uvs(uv, fv.clone()).options(options(s)).source("sheet").build();
    }

    /** The unit cube's quads. */
    static ControlMesh cube(Scheme s) {
        MeshData m = TestMeshes.cube();
        return ControlMesh.builder(m.positions(), m.faceSizes(), m.vertexIndex()).options(options(s)).source("cube").build();
    }

    static ControlMesh cage(String name) {
        String[] w = name.split(" ");
        Scheme s = Scheme.ofKeyword(w[0]);
        return switch (w[1]) {
            case "icosahedron" -> icosahedron(s);
            case "octahedron" -> creasedOctahedron(s);
            case "sheet" -> sheet(s, 4);
            case "cube" -> cube(s);
            default -> throw new IllegalArgumentException(name);
        };
    }

    // ---- scenes ----

    /** A scene of the objects {@code make} gives, seen from the front, above and to the left, lit, with depth and normal passes. */
    static Scene scene(int w, int h, double distance, Vec3 from, double fov, AdaptiveSettings a, RenderSettings.Builder settings, GObject... objects) {
        SceneBuilder b = new SceneBuilder();
        b.settings(settings.size(w, h).aovs(Set.of(Aov.DEPTH, Aov.NORMAL)).adaptive(a).build());
        Vec3 eye = from.normalized().times(distance);
        b.camera(new PinholeCamera(eye, Vec3.ZERO, Vec3.Y, fov));
        b.light(new PointLight(new Vec3(-5, 8, -9), Color.WHITE));
        for (GObject o : objects) b.add(o);
        return b.build();
    }

    static Scene scene(int w, int h, AdaptiveSettings a, GObject... objects) {
        return scene(w, h, 3.6, new Vec3(-0.45, 0.55, -1), 40, a, RenderSettings.builder(), objects);
    }

    static AdaptiveSubdivisionSurface adaptive(ControlMesh c, String method, int level) {
        // The power-of-two path: exactly the uniform refinement's triangles at a fixed level, which these tests compare with.
        AdaptiveSubdivisionSurface s = new AdaptiveSubdivisionSurface(c, method(method), true).levels(AdaptiveSubdivisionSurface.Levels.EDGE);
        return s.level(level);
    }

    static AdaptiveSubdivisionSurface.Method method(String word) {
        for (AdaptiveSubdivisionSurface.Method m : AdaptiveSubdivisionSurface.Method.values()) if (m.word().equals(word)) return m;
        throw new IllegalArgumentException(word);
    }

    static void assertSameImages(RenderResult expected, RenderResult actual, String what) {
        AdaptiveSubdivisionTest.assertSamePasses(expected, actual, what);
        BufferedImage a = expected.image(), b = actual.image();
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) fail(what + ": pixel (" + x + ", " + y + ") differs");
            }
        }
    }

    // ---- the uniform surface ----

    @Test
    void uniformLoopSurfacesHaveFourTrianglesPerTriangleAndKeepTheirBoundary() {
        SubdivisionSurface ico = new SubdivisionSurface(icosahedron(Scheme.LOOP), 3);
        assertEquals(20 * 64, ico.triangleCount(), "one triangle per refined Loop face");
        assertTrue(ico.isClosed());
        assertEquals(0, ico.boundaryEdgeCount());
        SubdivisionSurface sheet = new SubdivisionSurface(sheet(Scheme.LOOP, 4), 2);
        assertEquals(32 * 16, sheet.triangleCount());
        assertEquals(16, sheet.boundaryEdgeCount(), "the control mesh's boundary edges");
        // Bilinear: quads after the first level, two triangles each; the limit is the cage itself.
        SubdivisionSurface bil = new SubdivisionSurface(icosahedron(Scheme.BILINEAR), 2, true, SubdivisionSurface.Positions.LIMIT);
        assertEquals(2 * 60 * 4, bil.triangleCount());
        // Loop's limit surface lies strictly inside the unit icosahedron's circumsphere, bilinear's on its faces.
        double[] lp = new SubdivisionSurface(icosahedron(Scheme.LOOP), 2, true, SubdivisionSurface.Positions.LIMIT).triangleData().positions();
        double inradius = 0.7946544722917661; // of the unit icosahedron: its faces' distance from the centre
        for (int i = 0; i < lp.length; i += 3) {
            double r = Math.sqrt(lp[i] * lp[i] + lp[i + 1] * lp[i + 1] + lp[i + 2] * lp[i + 2]);
            assertTrue(r < 1 && r > 0.5, "a Loop limit point at radius " + r);
        }
        double[] bp = bil.triangleData().positions();
        for (int i = 0; i < bp.length; i += 3) {
            double r = Math.sqrt(bp[i] * bp[i] + bp[i + 1] * bp[i + 1] + bp[i + 2] * bp[i + 2]);
            assertTrue(r >= inradius - 1e-12 && r <= 1 + 1e-12, "a bilinear point off the cage, at radius " + r);
        }
    }

    /**
     * The level check counts a Loop surface's refined triangles at Loop's own figure per face,
     * below a quad's: under a heap cap between the two needs, Loop's level 5 of the icosahedron
     * (20,480 triangles) is built, Catmull-Clark's of the same cage (15,360 quads) refused.
     */
    @Test
    void theLevelCheckCountsLoopTrianglesAtTheirOwnCost() {
        assertTrue(SubdivisionSurface.bytesPerFace(Scheme.LOOP, false) < SubdivisionSurface.BYTES_PER_FACE);
        assertEquals(SubdivisionSurface.BYTES_PER_FACE, SubdivisionSurface.bytesPerFace(Scheme.BILINEAR, false));
        long loop = 20480 * SubdivisionSurface.bytesPerFace(Scheme.LOOP, false), quads = 15360 * SubdivisionSurface.BYTES_PER_FACE;
        assertTrue(loop < quads);
        try (lt.spindulys.limits.HeapBudget.Scope cap = lt.spindulys.limits.HeapBudget.cap((loop + quads) / 2)) {
            assertEquals(20480, new SubdivisionSurface(icosahedron(Scheme.LOOP), 5).triangleCount());
            IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                    () -> new SubdivisionSurface(icosahedron(Scheme.CATMARK), 5));
            assertTrue(e.getMessage().contains("subdivision level 5 of this mesh (15360 faces"), e.getMessage());
        }
    }

    /** The scene file's check counts alike: under the same cap a Loop subdiv is refined uniformly, not handed to the combined method. */
    @Test
    void aSceneFilesLoopLevelIsCheckedAtLoopsCost(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir) throws java.io.IOException {
        MeshData m = TestMeshes.icosphere(0, 1);
        StringBuilder obj = new StringBuilder();
        double[] p = m.positions();
        for (int i = 0; i < p.length; i += 3) obj.append("v ").append(p[i]).append(' ').append(p[i + 1]).append(' ').append(p[i + 2]).append('\n');
        int[] vi = m.vertexIndex();
        for (int i = 0; i < vi.length; i += 3) obj.append("f ").append(vi[i] + 1).append(' ').append(vi[i + 1] + 1).append(' ').append(vi[i + 2] + 1).append('\n');
        java.nio.file.Files.writeString(dir.resolve("ico.obj"), obj);
        long loop = 20480 * SubdivisionSurface.bytesPerFace(Scheme.LOOP, false), quads = 15360 * SubdivisionSurface.BYTES_PER_FACE;
        for (String scheme : List.of("loop", "catmark")) {
            SceneBuilder b;
            try (lt.spindulys.limits.HeapBudget.Scope cap = lt.spindulys.limits.HeapBudget.cap((loop + quads) / 2)) {
                b = lt.spindulys.io.SceneParser.parse("subdiv { file \"ico.obj\"  scheme " + scheme + "  level 5 }\n", "schemes.dat", dir);
            }
            GObject o = b.objects().get(0);
            // Catmull-Clark's level does not fit whole: the combined method renders it instead.
            assertEquals(scheme.equals("loop") ? SubdivisionSurface.class : AdaptiveSubdivisionSurface.class, o.getClass(), scheme);
        }
    }

    // ---- at a fixed level, every adaptive path gives the uniform surface ----

    /**
     * Cages beside {@link AdaptiveSchemesTest}'s OpenSubdiv shapes: semi-sharp and infinitely
     * sharp creases with a corner, an open sheet with UVs and irregular valences, and a triangle
     * cage under bilinear (quads from triangles); with the variants that test leaves out (8
     * threads, the last two patches).
     */
    static Stream<Arguments> fixedLevelCages() {
        return Stream.of(Arguments.of("loop octahedron", 3), Arguments.of("loop sheet", 2), Arguments.of("bilinear icosahedron", 2));
    }

    @ParameterizedTest(name = "{0} at level {1}")
    @MethodSource("fixedLevelCages")
    void everyMethodAtAFixedLevelGivesTheUniformSurfacesPasses(String cage, int level) {
        ControlMesh c = cage(cage);
        RenderResult expected = AdaptiveSubdivisionTest.render(scene(48, 36, AdaptiveSettings.DEFAULT, new SubdivisionSurface(c, level)), 2);
        AdaptiveSubdivisionSurface probe = adaptive(c, "lazy", level);
        long[] bytes = AdaptiveSubdivisionTest.patchBytes(probe, level);
        long all = bytes[1], one = bytes[0];
        record V(String method, AdaptiveSettings a, int threads, String what) {}
        for (V v : List.of(new V("lazy", AdaptiveSettings.DEFAULT, 1, "lazy, 1 thread"),
                new V("lazy", AdaptiveSettings.DEFAULT, 8, "lazy, 8 threads"),
                new V("lazy", AdaptiveSettings.DEFAULT.withCache(one), 2, "lazy, a cache of one patch"),
                new V("lazy", AdaptiveSettings.DEFAULT.withLastTwoPatches(true), 2, "lazy, the last two patches"),
                new V("combined", new AdaptiveSettings(all + all / 2, all, false, Double.NaN), 2, "combined, half pinned"),
                new V("projected", AdaptiveSettings.DEFAULT, 2, "projected"))) {
            Scene s = scene(48, 36, v.a(), adaptive(c, v.method(), level));
            AdaptiveSubdivisionTest.assertSamePasses(expected, AdaptiveSubdivisionTest.render(s, v.threads()), cage + " at level " + level + ", " + v.what());
        }
    }

    /**
     * The projected method's eager mesh is counted at one triangle per refined Loop face: with
     * exactly the room that count needs, it stays eager (counted as two per face, as for quads,
     * it would not fit and turn combined).
     */
    @Test
    void aLoopSurfaceStaysEagerWithExactlyTheRoomItsTrianglesNeed() {
        ControlMesh c = icosahedron(Scheme.LOOP);
        int level = 3;
        long patches = AdaptiveSubdivisionTest.patchBytes(adaptive(c, "projected", level), level)[1];
        long triangles = 20L << (2 * level);
        long need = patches + triangles * AdaptiveTessellation.FLAT_BYTES_PER_TRIANGLE, cache = 1 << 20;
        for (long room : new long[] {need, need - 1}) {
            Scene s = scene(8, 6, new AdaptiveSettings(cache + room, cache, false, Double.NaN), adaptive(c, "projected", level));
            String stats = AdaptiveSubdivisionTest.surface(s).statistics();
            if (room == need) assertTrue(stats.contains("; eager " + triangles + " triangles"), stats);
            else assertTrue(stats.contains("as combined"), stats);
        }
    }

    // ---- the view-dependent tessellation ----

    /** A scene with the camera 1.7 radii from the centre, so that edge levels differ. */
    static Scene closeUp(GObject o, AdaptiveSettings a) {
        return scene(160, 120, 1.9, new Vec3(0.35, 0.25, -1), 70, a, RenderSettings.builder(), o);
    }

    static AdaptiveSubdivisionSurface viewDependent(ControlMesh c, String method) {
        return new AdaptiveSubdivisionSurface(c, method(method), true).levels(AdaptiveSubdivisionSurface.Levels.EDGE).target(4).maxLevel(6);
    }

    static Stream<Arguments> closedLoopSurfaces() {
        return Stream.of(Arguments.of("loop icosahedron", "lazy"), Arguments.of("loop icosahedron", "projected"),
                Arguments.of("loop octahedron", "lazy"), Arguments.of("loop octahedron", "combined"), Arguments.of("bilinear cube", "lazy"));
    }

    /** pbrt-v4's watertightness property at mixed levels: seeded rays from points inside the closed surface all hit it. */
    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("closedLoopSurfaces")
    void raysFromInsideAClosedSurfaceAtMixedLevelsAllHitIt(String cage, String method) {
        Scene s = closeUp(viewDependent(cage(cage), method), AdaptiveSettings.DEFAULT);
        AdaptiveSubdivisionSurface surface = AdaptiveSubdivisionTest.surface(s); // the scene's copy, frozen
        int[] range = AdaptiveSubdivisionTest.assertMixedLevels(surface, 1);
        assertTrue(surface.isClosed(), cage + " is closed");
        int n = 100_000;
        String[] first = new String[1];
        int missed = AdaptiveSubdivisionTest.raysFromInsideMissing(s, 0, 0, 0, 1, cage.hashCode() * 31L + method.hashCode(), n, first);
        assertEquals(0, missed, cage + " (" + method + ", edge levels " + range[0] + ".." + range[1] + "): " + missed + " of " + n
                + " rays from inside missed, the first " + first[0]);
        AdaptiveSubdivisionTest.assertCrackFree(surface.tessellation(), cage + " at its view's levels");
    }

    /**
     * Random levels per control edge (each face at its edges' largest, corners at the least edge
     * level around them): the patches, joined and welded, close the surface without a crack.
     */
    @ParameterizedTest(name = "{0}")
    @MethodSource("closedCages")
    void patchesAtRandomEdgeLevelsStitchWithoutACrack(String cage) {
        ControlMesh c = cage(cage);
        PatchRefiner r = new PatchRefiner(c);
        SplittableRandom rnd = new SplittableRandom(cage.hashCode());
        for (int trial = 0; trial < 6; trial++) {
            int[] edgeLevel = new int[r.edgeCount()];
            for (int e = 0; e < edgeLevel.length; e++) edgeLevel[e] = rnd.nextInt(5);
            MeshData[] parts = new MeshData[r.faceCount()];
            for (int f = 0; f < r.faceCount(); f++) {
                int n = r.faceSize(f), level = 0;
                int[] el = new int[n], cl = new int[n];
                for (int k = 0; k < n; k++) {
                    el[k] = edgeLevel[r.faceEdge(f, k)];
                    level = Math.max(level, el[k]);
                    cl[k] = r.vertexLevel(f, k, edgeLevel);
                }
                parts[f] = r.refine(f, level, el, cl, true);
            }
            MeshData welded = AdaptiveTessellation.weld(AdaptiveTessellation.join(parts, cage, null, null));
            AdaptiveSubdivisionTest.assertCrackFree(welded, cage + ", trial " + trial);
        }
    }

    static Stream<String> closedCages() {
        return Stream.of("loop icosahedron", "loop octahedron", "bilinear icosahedron", "bilinear cube");
    }

    /** At view-dependent levels, the eager, lazy and combined (part pinned) tessellations render the same image and passes. */
    @ParameterizedTest(name = "{0}")
    @MethodSource("closedCages")
    void eagerLazyAndCombinedImagesAreIdentical(String cage) {
        ControlMesh c = cage(cage);
        Function<String, AdaptiveSubdivisionSurface> make = m -> new AdaptiveSubdivisionSurface(c, method(m), true)
                .levels(AdaptiveSubdivisionSurface.Levels.EDGE).target(3).maxLevel(5);
        Scene es = scene(64, 48, 1.9, new Vec3(0.35, 0.25, -1), 60, AdaptiveSettings.DEFAULT, RenderSettings.builder(), make.apply("projected"));
        AdaptiveSubdivisionSurface eager = AdaptiveSubdivisionTest.surface(es);
        RenderResult e = AdaptiveSubdivisionTest.render(es, 2);
        assertTrue(eager.statistics().contains("eager"), eager.statistics());
        AdaptiveSubdivisionTest.assertMixedLevels(eager, 1);
        for (String m : List.of("lazy", "combined")) {
            AdaptiveSubdivisionSurface s = make.apply(m);
            // The combined method with room for only some patches pinned: the rest lazy.
            AdaptiveSettings a = m.equals("combined") ? new AdaptiveSettings((64L << 20) + (256 << 10), 64L << 20, false, Double.NaN) : AdaptiveSettings.DEFAULT;
            Scene ls = scene(64, 48, 1.9, new Vec3(0.35, 0.25, -1), 60, a, RenderSettings.builder(), s);
            RenderResult l = AdaptiveSubdivisionTest.render(ls, 2);
            if (m.equals("combined")) {
                String stats = AdaptiveSubdivisionTest.surface(ls).statistics();
                Matcher pinned = Pattern.compile("; (\\d+) patches eager").matcher(stats);
                assertTrue(pinned.find() && Integer.parseInt(pinned.group(1)) > 0 && Integer.parseInt(pinned.group(1)) < c.faceCount(),
                        "some patches pinned, the rest lazy: " + stats);
            }
            assertSameImages(e, l, cage + ", " + m);
        }
    }

    // ---- everything else keeps working on Loop and bilinear surfaces ----

    /** The uniform and lazy versions of a scene (objects from {@code make}, given a maker of the surface), equal in image and passes. */
    static void assertLazyRendersAsUniform(ControlMesh c, int level, RenderSettings.Builder settings, Function<Supplier<GObject>, List<GObject>> make,
                                           String what) {
        RenderResult u = AdaptiveSubdivisionTest.render(scene(48, 36, 3.6, new Vec3(-0.45, 0.55, -1), 40, AdaptiveSettings.DEFAULT, settings,
                make.apply(() -> new SubdivisionSurface(c, level)).toArray(GObject[]::new)), 2);
        RenderResult l = AdaptiveSubdivisionTest.render(scene(48, 36, 3.6, new Vec3(-0.45, 0.55, -1), 40, AdaptiveSettings.DEFAULT, settings,
                make.apply(() -> adaptive(c, "lazy", level)).toArray(GObject[]::new)), 2);
        assertSameImages(u, l, what);
    }

    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.EnumSource(value = Scheme.class, names = {"LOOP", "BILINEAR"})
    void csgWithAnOperandOfTheSchemeEqualsTheUniformOneAndCutsIt(Scheme scheme) {
        ControlMesh c = icosahedron(scheme);
        for (Bool.Op op : Bool.Op.values()) {
            assertLazyRendersAsUniform(c, 3, RenderSettings.builder(),
                    s -> List.of(new Bool(op, List.of(s.get(), new Sphere(new Vec3(-0.5, 0.6, -0.5), 0.6)))), op + " with a sphere");
        }
        // Rays from inside the difference of two such surfaces (uniform minus lazy) always hit it, and the cut removes a real piece.
        SubdivisionSurface a = new SubdivisionSurface(c, 3);
        AdaptiveSubdivisionSurface b = adaptive(c, "lazy", 3);
        b.transform(Transform.scale(0.7, 0.7, 0.7)).transform(Transform.translate(0.5, 0.3, -0.2));
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(a, b));
        Scene s = scene(8, 6, AdaptiveSettings.DEFAULT, d);
        SplittableRandom rnd = new SplittableRandom(7);
        TraceContext ctx = new TraceContext();
        Hit hit = new Hit();
        int tried = 0, escaped = 0, removed = 0;
        while (tried < 3000) {
            double x = rnd.nextDouble(-0.7, 0.7), y = rnd.nextDouble(-0.7, 0.7), z = rnd.nextDouble(-0.7, 0.7);
            if (x * x + y * y + z * z > 0.49) continue; // inside the surface (Loop's and the cage's radius > 0.7 everywhere)
            double bx = (x - 0.5) / 0.7, by = (y - 0.3) / 0.7, bz = (z + 0.2) / 0.7;
            double rb = Math.sqrt(bx * bx + by * by + bz * bz);
            if (rb < 0.7) { removed++; continue; } // inside the cutter, so not in the result
            if (rb < 1) continue; // near the cutter's surface: not sure which side
            tried++;
            double dx = rnd.nextDouble(-1, 1), dy = rnd.nextDouble(-1, 1), dz = rnd.nextDouble(-1, 1), l = Math.sqrt(dx * dx + dy * dy + dz * dz);
            Ray ray = new Ray().set(x, y, z, dx / l, dy / l, dz / l, 0, Double.POSITIVE_INFINITY);
            hit.reset(ray.tMax);
            if (!s.intersect(ray, hit, ctx)) escaped++;
        }
        assertEquals(0, escaped, "rays from inside the difference that escaped");
        assertTrue(removed > 100, "the cutter removes a real piece: " + removed);
    }

    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.EnumSource(value = Scheme.class, names = {"LOOP", "BILINEAR"})
    void aCheckerOnTheRefinedUvsEqualsTheUniformOne(Scheme scheme) {
        ControlMesh c = sheet(scheme, 4);
        Material checker = Material.builder().color(Color.WHITE)
                .texture(Channel.DIFFUSE, new Checker(new Color(1, 0.1, 0.1), new Color(0.1, 0.1, 1), 8, false), new Uv(1, 1)).build();
        assertLazyRendersAsUniform(c, 3, RenderSettings.builder(), s -> List.of(s.get().material(checker)), "checker on UVs");
        // The texture follows the refined UVs: both colours show, in runs (not per-pixel noise).
        RenderResult u = AdaptiveSubdivisionTest.render(scene(48, 36, 3.6, new Vec3(0, 0.2, -1), 40, AdaptiveSettings.DEFAULT, RenderSettings.builder(),
                new SubdivisionSurface(c, 3).material(checker)), 2);
        int red = 0, blue = 0;
        for (int y = 0; y < 36; y++) {
            for (int x = 0; x < 48; x++) {
                int rgb = u.image().getRGB(x, y), r = (rgb >> 16) & 255, b = rgb & 255;
                if (r > 2 * b + 20) red++;
                if (b > 2 * r + 20) blue++;
            }
        }
        assertTrue(red > 100 && blue > 100, "both checker colours show: " + red + " red, " + blue + " blue pixels");
    }

    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.EnumSource(value = Scheme.class, names = {"LOOP", "BILINEAR"})
    void aMovingSurfaceEqualsTheUniformOne(Scheme scheme) {
        Motion m = Motion.of(new Vec3(1, 1, 1), Vec3.Y, 25, new Vec3(0.7, 0.2, 0), Vec3.ZERO, Double.NaN, Double.NaN);
        assertLazyRendersAsUniform(creasedOctahedron(scheme), 3, RenderSettings.builder().samplesPerPixel(4).shutter(0, 1),
                s -> List.of(s.get().motion(m)), "motion blur");
    }

    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.EnumSource(value = Scheme.class, names = {"LOOP", "BILINEAR"})
    void instancesShareOneTessellationBuiltOncePerFace(Scheme scheme) {
        ControlMesh c = icosahedron(scheme);
        List<GObject> two = new ArrayList<>();
        AdaptiveSubdivisionSurface first = adaptive(c, "lazy", 3);
        first.transform(Transform.scale(0.6, 0.6, 0.6)).transform(Transform.translate(-0.7, 0, 0));
        AdaptiveSubdivisionSurface second = first.instance();
        second.transform(Transform.scale(0.6, 0.6, 0.6)).transform(Transform.rotateY(30)).transform(Transform.translate(0.8, 0, 0.3));
        two.add(first);
        two.add(second);
        Scene s = scene(48, 36, AdaptiveSettings.DEFAULT, two.toArray(GObject[]::new));
        AdaptiveSubdivisionTest.render(s, 1);
        List<String> lines = s.adaptiveStatistics();
        assertEquals(1, lines.size(), "one tessellation for both instances: " + lines);
        Matcher m = Pattern.compile("patches (\\d+) built, (\\d+) hits").matcher(lines.get(0));
        assertTrue(m.find(), lines.get(0));
        assertTrue(Integer.parseInt(m.group(1)) <= 20, "each of the icosahedron's 20 faces refined at most once for both instances: " + lines.get(0));
        assertTrue(Long.parseLong(m.group(2)) > 500, "the second instance's rays hit the first's patches: " + lines.get(0));
        // The uniform surface's instances render the same.
        SubdivisionSurface u = new SubdivisionSurface(c, 3);
        u.transform(Transform.scale(0.6, 0.6, 0.6)).transform(Transform.translate(-0.7, 0, 0));
        SubdivisionSurface ui = u.instance();
        ui.transform(Transform.scale(0.6, 0.6, 0.6)).transform(Transform.rotateY(30)).transform(Transform.translate(0.8, 0, 0.3));
        Scene su = scene(48, 36, AdaptiveSettings.DEFAULT, u, ui);
        AdaptiveSubdivisionSurface f2 = adaptive(c, "lazy", 3);
        f2.transform(Transform.scale(0.6, 0.6, 0.6)).transform(Transform.translate(-0.7, 0, 0));
        AdaptiveSubdivisionSurface s2 = f2.instance();
        s2.transform(Transform.scale(0.6, 0.6, 0.6)).transform(Transform.rotateY(30)).transform(Transform.translate(0.8, 0, 0.3));
        assertSameImages(AdaptiveSubdivisionTest.render(su, 2), AdaptiveSubdivisionTest.render(scene(48, 36, AdaptiveSettings.DEFAULT, f2, s2), 2),
                "two instances");
    }
}
