package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.ObjReader;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.Subdivision;

/** {@code render subdivide}, run in-process through {@link Main#run}. */
class SubdivideCommandTest {
    @TempDir Path dir;

    private static final Path CUBE_DAT = Path.of("scenes/models/cube.dat"), CUBE_TEX = Path.of("scenes/models/cube.tex");

    private static CliTest.Run run(String... args) {
        return CliTest.run(args);
    }

    private static RefinedMesh expected(int level, boolean uv) throws IOException {
        MeshData m = WorkframeReader.readMesh(CUBE_DAT);
        SubdivInput in = SubdivInput.of(m);
        if (uv) in = in.withCornerUvs(WorkframeReader.readUnwrap(CUBE_TEX, m));
        return CatmullClark.refine(in.toControlMesh(), level);
    }

    @Test
    void writesTheRefinedMeshAsObj() throws IOException {
        Path out = dir.resolve("cube2.obj");
        CliTest.Run r = run("subdivide", CUBE_DAT.toString(), "--level", "2", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        RefinedMesh e = expected(2, false);
        MeshData m = ObjReader.read(out);
        assertArrayEquals(e.positions(), m.positions(), "positions read back exactly");
        assertArrayEquals(e.faceSizes(), m.faceSizes());
        assertArrayEquals(e.faceVertices(), m.vertexIndex());
        assertNull(m.uvs());
        assertNull(m.normals());
        assertTrue(Files.readString(out).startsWith("# Catmull-Clark subdivision of cube.dat at level 2"));
    }

    @Test
    void limitPositionsNormalsAndUvs() throws IOException {
        Path out = dir.resolve("cube1.obj");
        CliTest.Run r = run("subdivide", CUBE_DAT.toString(), "--limit", "--uv", CUBE_TEX.toString(), "--level", "1", "--output", out.toString());
        assertEquals(0, r.status(), r.err());
        RefinedMesh e = expected(1, true);
        MeshData m = ObjReader.read(out);
        assertArrayEquals(e.limitPositions(), m.positions());
        assertArrayEquals(e.limitNormals(), m.normals());
        assertArrayEquals(e.uvs(), m.uvs());
        assertArrayEquals(e.faceUvs(), m.uvIndex());
        assertArrayEquals(e.faceVertices(), m.normalIndex(), "one normal per vertex");
    }

    @Test
    void holesAreLeftOutAndIgnoredTagsNoted() throws IOException {
        Path in = dir.resolve("holed.obj");
        Files.writeString(in, Files.readString(Path.of("scenes/models/crease-cube.obj")) + "t hole 1/0/0 2\nt vertexedit 0/0/0\n");
        Path out = dir.resolve("holed1.obj");
        CliTest.Run r = run("subdivide", in.toString(), "--level", "1", "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals(in + ": note: tag 'vertexedit' is ignored (OpenSubdiv's Far does not apply it either)" + System.lineSeparator(), r.err());
        MeshData m = ObjReader.read(out);
        assertEquals(24 - 4, m.faceCount());
    }

    @Test
    void helpIsPrinted() {
        CliTest.Run r = run("subdivide", "--help");
        assertEquals(0, r.status());
        assertTrue(r.out().startsWith("usage: render subdivide MESH.obj|MESH.dat --level N -o OUT.obj"), r.out());
        assertTrue(run("--help").out().contains("render subdivide"), "the main help mentions it");
    }

    @Test
    void badUsageIsOneLineExitsTwoAndWritesNothing() throws IOException {
        String in = CUBE_DAT.toString(), out = dir.resolve("o.obj").toString();
        String[][] cases = {
                {"render: subdivide needs --level N or --scene SCENE.dat (see render subdivide --help)", "subdivide", in, "-o", out},
                {"render: subdivide needs an output file: -o OUT.obj (see render subdivide --help)", "subdivide", in, "--level", "1"},
                {"render: no mesh given to subdivide (see render subdivide --help)", "subdivide", "--level", "1", "-o", out},
                {"render: --level must be between 0 and 8, found 9", "subdivide", in, "--level", "9", "-o", out},
                {"render: --level expects a whole number, found 'two'", "subdivide", in, "--level", "two", "-o", out},
                {"render: option --level needs a value", "subdivide", in, "--level"},
                {"render: unknown option '--levle' for subdivide (see render subdivide --help)", "subdivide", in, "--levle", "1", "-o", out},
                {"render: the output of subdivide must be an .obj file, found '" + dir.resolve("o.ply") + "'", "subdivide", in, "--level", "1", "-o", dir.resolve("o.ply").toString()},
                {"render: the mesh to subdivide must be an .obj or a .dat file, found 'cube.ply'", "subdivide", "cube.ply", "--level", "1", "-o", out},
                {"render: more than one mesh given: '" + in + "' and 'x.obj'", "subdivide", in, "x.obj", "--level", "1", "-o", out},
                {"render: cannot write '" + dir.resolve("no/o.obj") + "': directory '" + dir.resolve("no") + "' does not exist", "subdivide", in, "--level", "1", "-o", dir.resolve("no/o.obj").toString()},
        };
        for (String[] c : cases) {
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            CliTest.Run r = run(args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(c[0] + System.lineSeparator(), r.err(), String.join(" ", args));
        }
        try (Stream<Path> files = Files.list(dir)) {
            assertEquals(0, files.count(), "nothing written");
        }
    }

    @Test
    void badInputNamesTheFileAndLeavesAnExistingOutput() throws IOException {
        Path out = dir.resolve("keep.obj");
        Files.writeString(out, "old");
        Path bad = dir.resolve("bad.obj");
        Files.writeString(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 1 x\n");
        Path badTex = dir.resolve("bad.tex");
        Files.writeString(badTex, "23\n" + "0 0\n".repeat(23));
        Path missing = dir.resolve("missing.dat");
        String[][] cases = {
                {bad + ":5:20: expected a number for sharpness 1 of 1 of tag 'crease' (its counts 2/1/0 say 2 integers, 1 float and 0 strings), found 'x'",
                        "subdivide", bad.toString(), "--level", "1", "-o", out.toString()},
                {badTex + ":1:1: the unwrap has 23 corners but the mesh " + CUBE_DAT + " has 24 face corners (one 'u v' per corner, face after face)",
                        "subdivide", CUBE_DAT.toString(), "--uv", badTex.toString(), "--level", "1", "-o", out.toString()},
                {missing + ": mesh file not found (looked in " + missing.toAbsolutePath() + ")", "subdivide", missing.toString(), "--level", "1", "-o", out.toString()},
        };
        for (String[] c : cases) {
            String[] args = java.util.Arrays.copyOfRange(c, 1, c.length);
            CliTest.Run r = run(args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(c[0] + System.lineSeparator(), r.err());
        }
        assertEquals("old", Files.readString(out), "existing output untouched");
        try (Stream<Path> files = Files.list(dir)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().endsWith(".tmp")), "no temporary file left");
        }
    }

    // ---- the scheme: the file's t scheme tag, or --scheme ----

    /** A tetrahedron's four triangles (Loop can take them), with a crease and the given tag lines. */
    private Path tetrahedron(String tags) throws IOException {
        Path p = dir.resolve("tet.obj");
        Files.writeString(p, "v 1 1 1\nv -1 -1 1\nv -1 1 -1\nv 1 -1 -1\nf 1 2 3\nf 1 4 2\nf 1 3 4\nf 2 4 3\nt crease 2/1/0 0 1 2\n" + tags);
        return p;
    }

    private static RefinedMesh refined(Path obj, SubdivOptions.Scheme scheme, int level) throws IOException {
        SubdivInput in = ObjReader.readSubdiv(obj);
        return Subdivision.refine(in.withOptions(in.options().withScheme(scheme)).toControlMesh(), level);
    }

    @Test
    void theFilesSchemeTagOrSchemeOptionChoosesTheRules() throws IOException {
        Path tet = tetrahedron("t scheme 0/0/1 loop\n");
        Path out = dir.resolve("tet2.obj");
        record Case(String[] extra, SubdivOptions.Scheme scheme, String name) {}
        for (Case c : new Case[] {
            new Case(new String[0], SubdivOptions.Scheme.LOOP, "Loop"),
            new Case(new String[] {"--scheme", "bilinear"}, SubdivOptions.Scheme.BILINEAR, "bilinear"),
            new Case(new String[] {"--scheme", "catmark"}, SubdivOptions.Scheme.CATMARK, "Catmull-Clark"),
            new Case(new String[] {"--scheme", "loop"}, SubdivOptions.Scheme.LOOP, "Loop"),
        }) {
            String[] args = Stream.concat(Stream.of("subdivide", tet.toString(), "--level", "2", "-o", out.toString()), Stream.of(c.extra()))
                    .toArray(String[]::new);
            CliTest.Run r = run(args);
            assertEquals(0, r.status(), r.err());
            RefinedMesh e = refined(tet, c.scheme(), 2);
            SubdivInput back = ObjReader.readSubdiv(out);
            assertArrayEquals(e.positions(), back.mesh().positions(), String.join(" ", args));
            assertArrayEquals(e.faceSizes(), back.mesh().faceSizes());
            assertArrayEquals(e.faceVertices(), back.mesh().vertexIndex());
            assertEquals(c.scheme(), back.options().scheme(), "the output keeps its scheme: " + String.join(" ", args));
            String text = Files.readString(out);
            assertTrue(text.startsWith("# " + c.name() + " subdivision of tet.obj at level 2"), text.lines().findFirst().orElse(""));
            // Loop splits each triangle into four triangles; the others make quads (three per triangle at the first level).
            int size = c.scheme() == SubdivOptions.Scheme.LOOP ? 3 : 4;
            for (int s : back.mesh().faceSizes()) assertEquals(size, s, String.join(" ", args));
            assertEquals(c.scheme() == SubdivOptions.Scheme.LOOP ? 4 * 16 : 4 * 3 * 4, back.mesh().faceCount());
        }
        // The schemes give three different surfaces.
        double[] loop = refined(tet, SubdivOptions.Scheme.LOOP, 2).positions(), bilinear = refined(tet, SubdivOptions.Scheme.BILINEAR, 2).positions(),
                catmark = refined(tet, SubdivOptions.Scheme.CATMARK, 2).positions();
        assertFalse(java.util.Arrays.equals(bilinear, catmark));
        assertFalse(java.util.Arrays.equals(loop, catmark));
        // Bilinear refinement stays on the cage: every vertex of the first face's children lies in its plane (x - y - z = -1 through 1 1 1, -1 -1 1, -1 1 -1).
        RefinedMesh flat = refined(tet, SubdivOptions.Scheme.BILINEAR, 2);
        int[] fv = flat.faceVertices();
        double[] p = flat.positions();
        for (int c = 0; c < 4 * 4; c++) {
            int v = fv[c];
            assertEquals(-1, p[3 * v] - p[3 * v + 1] - p[3 * v + 2], 1e-12, "vertex " + v + " of the first face's children");
        }
    }

    @Test
    void aUniformLoopStatementOfASceneIsWrittenWithItsScheme() throws IOException {
        Path tet = tetrahedron("");
        Path scene = dir.resolve("tet.dat");
        Files.writeString(scene, "camera { eye 0 0 -5  lookat 0 0 0 }\nsubdiv { file \"tet.obj\"  level 2  scheme loop }\n");
        Path out = dir.resolve("tet-scene.obj");
        CliTest.Run r = run("subdivide", tet.toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        String text = Files.readString(out);
        assertTrue(text.startsWith("# Loop subdivision of tet.obj at level 2 as tet.dat renders it"), text.lines().findFirst().orElse(""));
        SubdivInput back = ObjReader.readSubdiv(out);
        assertEquals(SubdivOptions.Scheme.LOOP, back.options().scheme());
        assertArrayEquals(refined(tet, SubdivOptions.Scheme.LOOP, 2).positions(), back.mesh().positions());
    }

    @Test
    void badSchemesAreRefused() throws IOException {
        String out = dir.resolve("o.obj").toString();
        Path tet = tetrahedron("");
        CliTest.Run r = run("subdivide", tet.toString(), "--level", "1", "--scheme", "lop", "-o", out);
        assertEquals(2, r.status());
        assertEquals("render: --scheme expects catmark, loop or bilinear, found 'lop'" + System.lineSeparator(), r.err());
        r = run("subdivide", tet.toString(), "--level", "1", "--scheme");
        assertEquals(2, r.status());
        assertEquals("render: option --scheme needs a value" + System.lineSeparator(), r.err());
        // Loop on the cube's quads: the face and its size, exit status 2, nothing written.
        r = run("subdivide", CUBE_DAT.toString(), "--level", "1", "--scheme", "loop", "-o", out);
        assertEquals(2, r.status(), r.err());
        assertEquals(CUBE_DAT + ": face 0 has 4 corners; the Loop scheme needs triangles" + System.lineSeparator(), r.err());
        Path quadLoop = dir.resolve("quad.obj");
        Files.writeString(quadLoop, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3\nf 2 5 3 4\nt scheme 0/0/1 loop\n");
        r = run("subdivide", quadLoop.toString(), "--level", "1", "-o", out);
        assertEquals(2, r.status(), r.err());
        assertEquals(quadLoop + ": face 1 has 4 corners; the Loop scheme needs triangles" + System.lineSeparator(), r.err());
        assertEquals(0, run("subdivide", quadLoop.toString(), "--level", "1", "--scheme", "bilinear", "-o", out).status(), "--scheme overrides the tag");
        Files.delete(Path.of(out));
        try (Stream<Path> files = Files.list(dir)) {
            assertTrue(files.noneMatch(p -> p.getFileName().toString().startsWith("o.")), "nothing written for the refusals");
        }
    }

    // ---- --scene: the tessellation a scene renders ----

    /** A scene beside a copy of the cube and its unwrap, the camera close to one corner so that levels differ per edge. */
    private Path cubeScene(String subdivs) throws IOException {
        Files.copy(CUBE_DAT, dir.resolve("cube.dat"));
        Files.copy(CUBE_TEX, dir.resolve("cube.tex"));
        Path scene = dir.resolve("close.dat");
        Files.writeString(scene, "settings { width 160  height 120 }\ncamera { eye 0.9 1.1 -2.6  lookat 0 0 0  fov 60 }\n" + subdivs);
        return scene;
    }

    /** Every edge of the faces is used by exactly two faces, once in each direction. */
    static void assertCrackFree(MeshData m) {
        java.util.Map<Long, int[]> uses = new java.util.HashMap<>();
        int[] sizes = m.faceSizes(), vi = m.vertexIndex();
        for (int f = 0, c = 0; f < sizes.length; c += sizes[f], f++) {
            for (int k = 0; k < sizes[f]; k++) {
                int a = vi[c + k], b = vi[c + (k + 1) % sizes[f]];
                uses.computeIfAbsent(((long) Math.min(a, b) << 32) | Math.max(a, b), key -> new int[2])[a < b ? 0 : 1]++;
            }
        }
        long bad = uses.values().stream().filter(u -> u[0] != 1 || u[1] != 1).count();
        assertEquals(0, bad, bad + " of " + uses.size() + " edges are not shared by exactly two faces");
    }

    @Test
    void sceneWritesTheAdaptiveTessellationCrackFree() throws IOException {
        // The power-of-two levels: no triangles of no area, so crack-free as written.
        Path scene = cubeScene("subdiv { file \"cube.dat\"  uv \"cube.tex\"  method lazy  levels edge  target 6  maxlevel 5 }\n");
        Path out = dir.resolve("adaptive.obj");
        CliTest.Run r = run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err());
        MeshData m = ObjReader.read(out);
        assertCrackFree(m);
        assertNotNull(m.uvs(), "vt written");
        assertNotNull(m.normals(), "vn written");
        for (int size : m.faceSizes()) assertEquals(3, size);
        // The same triangles the scene renders, at mixed levels.
        lt.spindulys.scene.Scene built = lt.spindulys.io.SceneParser.parse(scene).build();
        lt.spindulys.scene.AdaptiveSubdivisionSurface s = (lt.spindulys.scene.AdaptiveSubdivisionSurface) built.objects().get(0);
        MeshData t = s.tessellation();
        assertArrayEquals(t.positions(), m.positions(), "positions read back exactly");
        assertArrayEquals(t.vertexIndex(), m.vertexIndex());
        int[] levels = s.edgeLevels();
        assertTrue(java.util.Arrays.stream(levels).min().getAsInt() < java.util.Arrays.stream(levels).max().getAsInt(),
                "mixed levels: " + java.util.Arrays.toString(levels));
        String text = Files.readString(out);
        assertTrue(text.startsWith("# tessellation of cube.dat as close.dat renders it (" + scene + ":3:1, method lazy)"), text.substring(0, 200));
        assertTrue(text.contains("# control edges per level: level "), "levels histogram");
        assertTrue(text.contains(" " + m.faceCount() + " triangles"), "triangle count");
    }

    /**
     * The rates' grids (the default): welded, every edge of the closed cube is shared by exactly
     * two triangles once any triangles of no area (where a grid is snapped to a coarser edge's
     * points) are left out; and the written mesh is the one the scene renders.
     */
    @Test
    void sceneWritesTheRateTessellationCrackFree() throws IOException {
        Path scene = cubeScene("subdiv { file \"cube.dat\"  uv \"cube.tex\"  method lazy  levels rate  target 6  maxlevel 5 }\n");
        Path out = dir.resolve("rates.obj");
        CliTest.Run r = run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        MeshData m = ObjReader.read(out);
        for (int size : m.faceSizes()) assertEquals(3, size);
        assertNotNull(m.normals(), "vn written");
        lt.spindulys.scene.Scene built = lt.spindulys.io.SceneParser.parse(scene).build();
        lt.spindulys.scene.AdaptiveSubdivisionSurface s = (lt.spindulys.scene.AdaptiveSubdivisionSurface) built.objects().get(0);
        String stats = s.statistics();
        assertTrue(stats.contains("edge rates "), stats);
        MeshData t = s.tessellation();
        assertArrayEquals(t.positions(), m.positions(), "positions read back exactly");
        assertArrayEquals(t.vertexIndex(), m.vertexIndex());
        // Rates that differ from edge to edge, so faces are snapped to coarser neighbours.
        java.util.regex.Matcher rates = java.util.regex.Pattern.compile("edge rates (\\d+)-(\\d+)").matcher(stats);
        assertTrue(rates.find() && Integer.parseInt(rates.group(1)) < Integer.parseInt(rates.group(2)), "mixed rates: " + stats);
        double[] p = m.positions();
        int[] vi = m.vertexIndex();
        java.util.List<Integer> keep = new java.util.ArrayList<>();
        for (int c = 0; c < vi.length; c += 3) {
            int a = 3 * vi[c], b = 3 * vi[c + 1], d = 3 * vi[c + 2];
            double ux = p[b] - p[a], uy = p[b + 1] - p[a + 1], uz = p[b + 2] - p[a + 2], wx = p[d] - p[a], wy = p[d + 1] - p[a + 1], wz = p[d + 2] - p[a + 2];
            if (uy * wz - uz * wy != 0 || uz * wx - ux * wz != 0 || ux * wy - uy * wx != 0) keep.add(c);
        }
        int[] sizes = new int[keep.size()], kept = new int[3 * keep.size()];
        java.util.Arrays.fill(sizes, 3);
        for (int k = 0; k < keep.size(); k++) System.arraycopy(vi, keep.get(k), kept, 3 * k, 3);
        assertCrackFree(new MeshData(p, null, null, sizes, kept, null, null, null, null, null));
    }

    @Test
    void instancesShareOneTessellationAndDifferentOptionsAreNoted() throws IOException {
        Path scene = cubeScene("subdiv { file \"cube.dat\"  method projected  target 4  maxlevel 4 }\n"
                + "subdiv { file \"cube.dat\"  method projected  target 4  maxlevel 4  translate 3 0 0 }\n");
        Path out = dir.resolve("two.obj");
        CliTest.Run r = run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("", r.err(), "instances: one tessellation, nothing to say");
        assertCrackFree(ObjReader.read(out));

        Files.writeString(scene, Files.readString(scene) + "subdiv { file \"cube.dat\"  method lazy  target 12 }\n");
        r = run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        assertEquals("note: 3 subdiv statements of " + scene + " refine " + dir.resolve("cube.dat") + " with different options; writing the tessellation of the first ("
                + scene + ":3:1), not of " + scene + ":5:1" + System.lineSeparator(), r.err());
    }

    @Test
    void aUniformSubdivWritesItsUniformRefinement() throws IOException {
        Path scene = cubeScene("sphere { }\nsubdiv { file \"cube.dat\"  level 2 }\n");
        Path out = dir.resolve("uniform.obj");
        CliTest.Run r = run("subdivide", dir.resolve("cube.dat").toString(), "--scene", scene.toString(), "-o", out.toString());
        assertEquals(0, r.status(), r.err());
        RefinedMesh e = expected(2, false);
        MeshData m = ObjReader.read(out);
        assertArrayEquals(e.positions(), m.positions());
        assertArrayEquals(e.faceVertices(), m.vertexIndex());
        assertTrue(Files.readString(out).startsWith("# Catmull-Clark subdivision of cube.dat at level 2 as close.dat renders it"));
    }

    @Test
    void sceneRefusals() throws IOException {
        Path scene = cubeScene("subdiv { file \"cube.dat\"  method lazy }\n");
        Path out = dir.resolve("x.obj");
        String mesh = dir.resolve("cube.dat").toString();
        record Bad(String[] args, String message) {}
        for (Bad b : new Bad[] {
            new Bad(new String[] {"subdivide", mesh, "--scene", scene.toString(), "--level", "2", "-o", out.toString()},
                    "render: --level and --scene exclude each other: the scene's subdiv statement chooses the levels"),
            new Bad(new String[] {"subdivide", mesh, "--scene", scene.toString(), "--limit", "-o", out.toString()},
                    "render: --limit goes with --level, not --scene (the scene's tessellation is written as it renders it)"),
            new Bad(new String[] {"subdivide", mesh, "--scene", scene.toString(), "--scheme", "loop", "-o", out.toString()},
                    "render: --scheme goes with --level, not --scene (the scene's subdiv statement chooses the scheme)"),
            new Bad(new String[] {"subdivide", mesh, "-o", out.toString()}, "render: subdivide needs --level N or --scene SCENE.dat (see render subdivide --help)"),
            new Bad(new String[] {"subdivide", CUBE_DAT.toString(), "--scene", scene.toString(), "-o", out.toString()},
                    "render: " + scene + " has no subdiv statement whose file is " + CUBE_DAT + " (its subdiv files: " + mesh + ")"),
            new Bad(new String[] {"subdivide", mesh, "--scene", dir.resolve("none.dat").toString(), "-o", out.toString()},
                    dir.resolve("none.dat") + ": scene file not found"),
        }) {
            CliTest.Run r = run(b.args());
            assertEquals(2, r.status(), r.err());
            assertEquals(b.message() + System.lineSeparator(), r.err());
            assertFalse(Files.exists(out), "nothing written");
        }
        // Bad input in the scene: the parser's one-line located error.
        Files.writeString(scene, "subdiv { file \"cube.dat\"  method lazzy }\n");
        CliTest.Run r = run("subdivide", mesh, "--scene", scene.toString(), "-o", out.toString());
        assertEquals(2, r.status(), r.err());
        assertEquals(scene + ":1:34: expected uniform, projected, lazy or combined for 'method', found 'lazzy' (did you mean 'lazy'?)" + System.lineSeparator(), r.err());
        assertFalse(Files.exists(out));
    }
}
