package lt.spindulys.io;

import lt.spindulys.scene.TestMeshes;
import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivTags;

/** OpenSubdiv's t tags read by {@link ObjReader#readSubdiv}: values, options, and every malformed form with its location. */
class ObjReaderSubdivTest {
    static final String CUBE = TestMeshes.CUBE_OBJ;

    private static SubdivTags tags(String tagLines) {
        return ObjReader.parseSubdiv(CUBE + tagLines, "cube.obj").tags();
    }

    @Test
    void plainReadingStillSkipsTagsEvenMalformedOnes() {
        MeshData m = ObjReader.parse(CUBE + "t crease 2/1/0 0 1\nt nonsense\n", "cube.obj");
        assertEquals(6, m.faceCount());
        assertEquals(8, m.vertexCount());
    }

    @Test
    void creasesWithOneSharpnessForAllOrOnePerPair() {
        SubdivTags t = tags("t crease 4/1/0 0 1 1 2 2.5\nt crease 4/2/0 2 3 3 0 1 10\n");
        assertArrayEquals(new int[] {0, 1, 1, 2, 2, 3, 3, 0}, t.creases());
        assertArrayEquals(new float[] {2.5f, 2.5f, 1f, 10f}, t.creaseSharpness());
        assertEquals(4, t.creaseCount());
    }

    @Test
    void sharpnessIsKeptAsAFloatLikeOpenSubdiv() {
        SubdivTags t = tags("t corner 1/1/0 6 0.7\n");
        assertEquals(0.7f, t.cornerSharpness()[0]);
        assertNotEquals(0.7, (double) t.cornerSharpness()[0]);
    }

    @Test
    void cornersHolesAndOptions() {
        SubdivTags t = tags("""
                t corner 3/1/0 0 1 2 3
                t corner 2/2/0 6 7 1.5 10
                t hole 2/0/0 1 3
                t interpolateboundary 1/0/0 1
                t facevaryinginterpolateboundary 1/0/0 3
                t creasemethod 0/0/1 chaikin
                t smoothtriangles 0/0/1 smooth
                """);
        assertArrayEquals(new int[] {0, 1, 2, 6, 7}, t.corners());
        assertArrayEquals(new float[] {3, 3, 3, 1.5f, 10}, t.cornerSharpness());
        assertArrayEquals(new int[] {1, 3}, t.holes());
        assertEquals(new SubdivOptions(SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.FaceVarying.CORNERS_PLUS2,
                SubdivOptions.Creasing.CHAIKIN, SubdivOptions.Triangles.SMOOTH), t.options());
    }

    @Test
    void everyIntegerOfTheBoundaryTagsMapsToItsMode() {
        SubdivOptions.Boundary[] boundary = {SubdivOptions.Boundary.NONE, SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.Boundary.EDGE_ONLY};
        for (int i = 0; i < 3; i++) assertEquals(boundary[i], tags("t interpolateboundary 1/0/0 " + i + "\n").options().boundary());
        for (int i = 0; i < 6; i++) {
            assertEquals(SubdivOptions.FaceVarying.values()[i], tags("t facevaryinginterpolateboundary 1/0/0 " + i + "\n").options().fvar());
        }
        assertEquals(SubdivOptions.Creasing.UNIFORM, tags("t creasemethod 0/0/1 chaikin\nt creasemethod 0/0/1 normal\n").options().creasing(), "the last tag wins");
        assertEquals(SubdivOptions.Triangles.CATMARK, tags("t smoothtriangles 0/0/1 catmark\n").options().triangles());
        assertEquals(SubdivOptions.DEFAULT, tags("").options());
    }

    @Test
    void theSchemeTagChoosesCatmarkLoopOrBilinear() {
        assertEquals(SubdivOptions.Scheme.CATMARK, tags("").options().scheme(), "no tag: Catmull-Clark, as OpenSubdiv's shape files mean");
        for (SubdivOptions.Scheme s : SubdivOptions.Scheme.values()) {
            assertEquals(SubdivOptions.DEFAULT.withScheme(s), tags("t scheme 0/0/1 " + s.keyword() + "\n").options());
        }
        SubdivOptions o = tags("t creasemethod 0/0/1 chaikin\nt scheme 0/0/1 bilinear\nt scheme 0/0/1 loop\n").options();
        assertEquals(SubdivOptions.Scheme.LOOP, o.scheme(), "the last tag wins");
        assertEquals(SubdivOptions.Creasing.CHAIKIN, o.creasing(), "the scheme leaves the other options as they are");
    }

    @Test
    void aLoopFileWithAQuadIsRefusedNamingTheFileTheFaceAndItsSize() {
        SubdivInput in = ObjReader.parseSubdiv("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4 2\nt scheme 0/0/1 loop\n", "tri.obj");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, in::toControlMesh);
        assertEquals("tri.obj: face 1 has 4 corners; the Loop scheme needs triangles", e.getMessage());
        // The same faces under the other schemes are fine.
        assertEquals(2, in.withOptions(in.options().withScheme(SubdivOptions.Scheme.BILINEAR)).toControlMesh().faceCount());
    }

    @Test
    void hierarchicalEditsAreReadAndIgnoredLikeFarDoes() {
        SubdivTags t = tags("t vertexedit 4/2/3 1 0 1 0 0.5 1 add P value\nt faceedit 2/0/1 1 0 hole\nt vertexedit 0/0/0\n");
        assertEquals(List.of("vertexedit", "faceedit"), t.ignored());
        assertEquals(0, t.creaseCount());
    }

    @Test
    void tagsMayComeBeforeTheVerticesTheyName() {
        SubdivInput in = ObjReader.parseSubdiv("t crease 2/1/0 0 1 3\n" + CUBE, "cube.obj");
        assertArrayEquals(new int[] {0, 1}, in.tags().creases());
    }

    @Test
    void texturedFacesBecomeFaceVaryingUvs() {
        String text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
        SubdivInput in = ObjReader.parseSubdiv(text, "quad.obj");
        assertArrayEquals(new int[] {0, 1, 2, 3}, in.mesh().uvIndex());
        RefinedMesh r = CatmullClark.refine(in.toControlMesh(), 1);
        assertNotNull(r.uvs());
        assertEquals(4 * r.faceCount(), r.faceUvs().length);
    }

    /** A malformed tagged OBJ and the "line:column: message" it must give. */
    record Bad(String name, String text, String expected) {
        @Override public String toString() { return name; }
    }

    static Stream<Bad> malformed() {
        return Stream.of(
                new Bad("unknown tag", "t creese 2/1/0 0 1 1\n", "15:3: unknown tag 'creese' (did you mean 'crease'?) (known: crease, corner, hole, "
                        + "interpolateboundary, facevaryinginterpolateboundary, facevaryingpropagatecorners, creasemethod, smoothtriangles, scheme, vertexedit, edgeedit, faceedit)"),
                new Bad("no tag name", "t\n", "15:2: expected a tag name after 't', found end of line"),
                new Bad("counts missing", "t crease 0 1 1\n", "15:10: expected the argument counts nints/nfloats/nstrings (such as 2/1/0) after 't crease', found '0'"),
                new Bad("counts malformed", "t crease 2/1 0 1 1\n", "15:10: expected the argument counts nints/nfloats/nstrings (such as 2/1/0) after 't crease', found '2/1'"),
                new Bad("odd crease indices", "t crease 3/1/0 0 1 2 1\n", "15:10: tag 'crease' takes vertex pairs and one sharpness for all pairs or one per pair (such as 2/1/0 or 4/2/0), found 3/1/0"),
                new Bad("crease sharpness count", "t crease 4/3/0 0 1 1 2 1 1 1\n", "15:10: tag 'crease' takes vertex pairs and one sharpness for all pairs or one per pair (such as 2/1/0 or 4/2/0), found 4/3/0"),
                new Bad("corner without sharpness", "t corner 1/0/0 3\n", "15:10: tag 'corner' takes vertices and one sharpness for all or one per vertex (such as 1/1/0 or 3/3/0), found 1/0/0"),
                new Bad("hole with a float", "t hole 1/1/0 3 1\n", "15:8: tag 'hole' takes face indices only (such as 1/0/0 or 3/0/0), found 1/1/0"),
                new Bad("boundary with two ints", "t interpolateboundary 2/0/0 1 1\n", "15:23: tag 'interpolateboundary' takes one integer (1/0/0), found 2/0/0"),
                new Bad("creasemethod as int", "t creasemethod 1/0/0 1\n", "15:16: tag 'creasemethod' takes one string (0/0/1), found 1/0/0"),
                new Bad("too few integers", "t crease 4/1/0 0 1 2\n", "15:21: expected integer 4 of 4 (its counts 4/1/0 say 4 integers, 1 float and 0 strings) of tag 'crease', found end of line"),
                new Bad("float for an index", "t crease 2/1/0 0 1.5 2\n", "15:18: expected integer 2 of 2 (its counts 2/1/0 say 2 integers, 1 float and 0 strings) of tag 'crease', found '1.5'"),
                new Bad("missing sharpness", "t crease 2/1/0 0 1 # sharp\n", "15:20: expected a number for sharpness 1 of 1 of tag 'crease' (its counts 2/1/0 say 2 integers, 1 float and 0 strings), found a comment"),
                new Bad("word for sharpness", "t corner 1/1/0 0 sharp\n", "15:18: expected a number for sharpness 1 of 1 of tag 'corner' (its counts 1/1/0 say 1 integer, 1 float and 0 strings), found 'sharp'"),
                new Bad("negative sharpness", "t crease 2/1/0 0 1 -2\n", "15:20: crease sharpness must not be negative, found -2"),
                new Bad("too many arguments", "t hole 1/0/0 1 2\n", "15:16: unexpected '2' after the arguments of tag 'hole' (its counts 1/0/0 say 1 integer, 0 floats and 0 strings)"),
                new Bad("missing string", "t smoothtriangles 0/0/1\n", "15:24: expected string 1 of 1 of tag 'smoothtriangles' (its counts 0/0/1 say 0 integers, 0 floats and 1 string), found end of line"),
                new Bad("boundary out of range", "t interpolateboundary 1/0/0 3\n", "15:29: expected 0 (none), 1 (edge and corner) or 2 (edge only) for tag 'interpolateboundary', found 3"),
                new Bad("fvar out of range", "t facevaryinginterpolateboundary 1/0/0 6\n", "15:40: expected 0 (none), 1 (corners only), 2 (corners plus1), "
                        + "3 (corners plus2), 4 (boundaries) or 5 (all) for tag 'facevaryinginterpolateboundary', found 6"),
                new Bad("unknown crease method", "t creasemethod 0/0/1 chaikn\n", "15:22: expected normal or chaikin for tag 'creasemethod', found 'chaikn' (did you mean 'chaikin'?)"),
                new Bad("unknown triangle rule", "t smoothtriangles 0/0/1 loop\n", "15:25: expected catmark or smooth for tag 'smoothtriangles', found 'loop'"),
                new Bad("unknown scheme", "t scheme 0/0/1 lop\n", "15:16: expected catmark, loop or bilinear for tag 'scheme', found 'lop' (did you mean 'loop'?)"),
                new Bad("scheme as int", "t scheme 1/0/0 2\n", "15:10: tag 'scheme' takes one string (0/0/1), found 1/0/0"),
                new Bad("scheme misspelt", "t schem 0/0/1 loop\n", "15:3: unknown tag 'schem' (did you mean 'scheme'?) (known: crease, corner, hole, "
                        + "interpolateboundary, facevaryinginterpolateboundary, facevaryingpropagatecorners, creasemethod, smoothtriangles, scheme, vertexedit, edgeedit, faceedit)"),
                new Bad("crease vertex out of range", "t crease 2/1/0 0 8 1\n", "15:18: crease vertex 8 out of range (the file has 8 vertices; tag indices count from 0)"),
                new Bad("negative crease vertex", "t crease 2/1/0 -1 0 1\n", "15:16: crease vertex -1 out of range (the file has 8 vertices; tag indices count from 0)"),
                new Bad("crease not an edge", "t crease 2/1/0 0 6 1\n", "15:16: crease 0 6 is not an edge of the mesh (no face has vertices 0 and 6 next to each other; tag indices count from 0)"),
                new Bad("crease to itself", "t crease 2/1/0 3 3 1\n", "15:18: crease from vertex 3 to itself (a crease is an edge: two different vertices)"),
                new Bad("corner out of range", "\n\nt corner 2/1/0 0 12 5\n", "17:18: corner vertex 12 out of range (the file has 8 vertices; tag indices count from 0)"),
                new Bad("hole out of range", "t hole 2/0/0 5 6\n", "15:16: hole face 6 out of range (the file has 6 faces; tag indices count from 0)"),
                new Bad("uvs on some faces only", "vt 0 0\nf 1/1 2/1 3/1\n", "16:1: face has texture coordinates, but the face on line 9 has none (a subdivision surface needs them on every face or none)"));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("malformed")
    void malformedTagsNameFileLineAndColumn(Bad c) {
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.parseSubdiv(CUBE + c.text(), "cube.obj"));
        assertEquals("cube.obj:" + c.expected(), e.getMessage());
    }

    @Test
    void facesWithoutUvsAfterOnesWithThemAreAlsoRefused() {
        String text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nf 1/1 2/1 3/1\nf 2 4 3\n";
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.parseSubdiv(text, "m.obj"));
        assertEquals("m.obj:7:1: face has no texture coordinates, but the face on line 6 has (a subdivision surface needs them on every face or none)", e.getMessage());
    }

    @Test
    void missingFileIsReported() {
        Path p = Path.of("no/such/mesh.obj");
        SceneException e = assertThrows(SceneException.class, () -> ObjReader.readSubdiv(p));
        assertTrue(e.getMessage().startsWith("no/such/mesh.obj: OBJ file not found"), e.getMessage());
    }

    // ---- OpenSubdiv's own shapes ----

    /** OpenSubdiv's regression shapes and reference data, gzipped in the test resources (subdiv/). */
    private static Path shapes() throws Exception {
        java.net.URL url = ObjReaderSubdivTest.class.getClassLoader().getResource("subdiv/OPENSUBDIV-LICENSE.txt");
        assertNotNull(url, "test resources subdiv/ not on the class path");
        return Path.of(url.toURI()).getParent();
    }

    private static String gunzip(Path p) throws IOException {
        try (var in = new java.util.zip.GZIPInputStream(Files.newInputStream(p))) {
            return new String(in.readAllBytes(), java.nio.charset.StandardCharsets.US_ASCII);
        }
    }

    @TestFactory
    Stream<DynamicTest> readsOpenSubdivShapes() throws Exception {
        // The regression shapes are those with reference levels (a test-made variant has none):
        // all 122 of them, 87 Catmull-Clark, 31 Loop and 4 bilinear.
        List<Path> objs;
        try (Stream<Path> s = Files.list(shapes())) {
            objs = s.filter(p -> p.toString().endsWith(".obj.gz"))
                    .filter(p -> Files.exists(p.resolveSibling(p.getFileName().toString().replaceAll("\\.obj\\.gz$", ".L1.txt.gz"))))
                    .sorted().toList();
        }
        assertEquals(122, objs.size(), "regression shapes with reference data");
        return objs.stream().map(p -> DynamicTest.dynamicTest(p.getFileName().toString(), () -> readsOpenSubdivShapeAsFarDoes(p)));
    }

    /**
     * A regression shape of OpenSubdiv reads, with the options, crease, corner and hole counts
     * and ignored tags that the reference data's header says Far applied.
     */
    private static void readsOpenSubdivShapeAsFarDoes(Path obj) throws IOException {
        String name = obj.getFileName().toString().replaceAll("\\.obj\\.gz$", "");
        List<String> header = gunzip(obj.resolveSibling(name + ".L1.txt.gz")).lines().filter(l -> l.startsWith("#")).toList();
        SubdivInput in = ObjReader.parseSubdiv(gunzip(obj), name + ".obj");
        SubdivTags t = in.tags();

        Map<String, String> option = new java.util.HashMap<>();
        int creases = 0, corners = 0, holes = 0;
        List<String> ignored = new ArrayList<>();
        Pattern count = Pattern.compile("# tag applied: (crease|corner|hole): \\d+ tag\\(s\\), (\\d+) ");
        for (String l : header) {
            String[] w = l.split("\\s+");
            if (l.startsWith("# option ")) option.put(w[2], w[3]);
            Matcher m = count.matcher(l);
            if (m.lookingAt()) {
                int n = Integer.parseInt(m.group(2));
                switch (m.group(1)) {
                    case "crease" -> creases = n;
                    case "corner" -> corners = n;
                    default -> holes = n;
                }
            }
            if (l.startsWith("# tag IGNORED: t ") && !ignored.contains(w[4])) ignored.add(w[4]);
        }
        SubdivOptions o = t.options();
        assertEquals(option.get("VtxBoundaryInterpolation"), "VTX_BOUNDARY_" + o.boundary());
        assertEquals(option.get("FVarLinearInterpolation"), "FVAR_LINEAR_" + o.fvar());
        assertEquals(option.get("CreasingMethod"), "CREASE_" + o.creasing());
        assertEquals(option.get("TriangleSubdivision"), "TRI_SUB_" + o.triangles());
        assertEquals(creases, t.creaseCount(), "creased edges");
        assertEquals(corners, t.corners().length, "corners");
        assertEquals(holes, t.holes().length, "holes");
        assertEquals(ignored, t.ignored());
        assertTrue(in.mesh().faceCount() > 0);
    }
}
