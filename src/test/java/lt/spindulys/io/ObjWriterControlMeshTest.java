package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.SubdivTags;

/** Control meshes written with their tags read back through {@link ObjReader#readSubdiv} as equal meshes. */
class ObjWriterControlMeshTest {

    /** Every OpenSubdiv regression shape under src/test/resources/subdiv. */
    static Stream<String> shapes() throws IOException, URISyntaxException {
        Path dir = Path.of(ObjWriterControlMeshTest.class.getClassLoader().getResource("subdiv/OPENSUBDIV-LICENSE.txt").toURI()).getParent();
        List<String> names = new ArrayList<>();
        try (Stream<Path> files = Files.list(dir)) {
            files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".obj.gz")).sorted().forEach(names::add);
        }
        assertTrue(names.size() >= 40, "the corpus is present: " + names.size());
        return names.stream();
    }

    private static String resource(String name) {
        try (InputStream in = new GZIPInputStream(ObjWriterControlMeshTest.class.getClassLoader().getResourceAsStream("subdiv/" + name))) {
            return new String(in.readAllBytes(), StandardCharsets.US_ASCII);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String write(ControlMesh m, String name) throws IOException {
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ObjWriter.write(m, name, "written by a test", out);
        return out.toString(StandardCharsets.UTF_8);
    }

    @ParameterizedTest
    @MethodSource("shapes")
    void openSubdivShapesRoundTrip(String file) throws IOException {
        ControlMesh original = ObjReader.parseSubdiv(resource(file), file).toControlMesh();
        ControlMesh back = ObjReader.parseSubdiv(write(original, file), "back.obj").toControlMesh();
        assertSameMesh(original, back);
        assertSameRefinement(original, back, 2);
    }

    @Test
    void theShapesCarryTagsOfEveryKind() throws Exception {
        // The round trip above covers tags only if the corpus has them; name the shapes that do.
        ControlMesh creases = shape("catmark_cube_creases1.obj.gz"), corners = shape("catmark_cube_corner3.obj.gz"),
                holes = shape("catmark_hole_test1.obj.gz"), uvs = shape("catmark_fvar_bound2.obj.gz"), fvar = shape("catmark_cubes_semisharp.obj.gz"), chaikin = shape("catmark_chaikin1.obj.gz"),
                tris = shape("catmark_smoothtris1.obj.gz");
        assertTrue(creases.tags().creaseCount() > 0);
        assertTrue(corners.tags().corners().length > 0);
        assertTrue(holes.tags().holes().length > 0);
        assertNotNull(uvs.uvs());
        assertNotEquals(SubdivOptions.FaceVarying.ALL, fvar.options().fvar());
        assertEquals(SubdivOptions.Creasing.CHAIKIN, chaikin.options().creasing());
        assertEquals(SubdivOptions.Triangles.SMOOTH, tris.options().triangles());
    }

    private static ControlMesh shape(String file) {
        return ObjReader.parseSubdiv(resource(file), file).toControlMesh();
    }

    /** A mesh with every tag and option away from its default, mixed face sizes, a uv seam and awkward numbers. */
    static ControlMesh everyTag() {
        // A 3x2 grid of quads, with a triangle and a pentagon added along one side.
        double[] p = {
            0, 0, 0, 1, 0, 0.1, 2, 0, -0.0, 3, 0, 1e-300,
            0, 1, 0, 1, 1, Math.PI, 2, 1, 0.3, 3, 1, -2.5e14,
            0, 2, 0, 1, 2, 123456789012345.0, 2, 2, Double.MIN_VALUE, 3, 2, 1.0 / 3,
            4, 0.5, 0, 4, 1.5, 0, 4, 2.5, 0.7};
        int[] sizes = {4, 4, 4, 4, 4, 4, 3, 5};
        int[] fv = {0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 4, 5, 9, 8, 5, 6, 10, 9, 6, 7, 11, 10, 3, 12, 7, 7, 12, 13, 14, 11};
        // UVs: one per vertex, except that faces 2 and 5 get their own copies (a seam).
        int nv = p.length / 3;
        double[] uv = new double[2 * (nv + 4)];
        for (int v = 0; v < nv; v++) {
            uv[2 * v] = p[3 * v] / 4;
            uv[2 * v + 1] = p[3 * v + 1] / 3 + 0.1;
        }
        for (int k = 0; k < 4; k++) {
            uv[2 * (nv + k)] = 0.9 + 0.01 * k;
            uv[2 * (nv + k) + 1] = 0.7 - 0.1 * k;
        }
        int[] fuv = fv.clone();
        fuv[8] = nv; fuv[9] = nv + 1; fuv[10] = nv + 2; fuv[11] = nv + 3;
        return ControlMesh.builder(p, sizes, fv)
                .uvs(uv, fuv)
                .crease(1, 5, 2.5f)
                .crease(5, 6, 0.1f)
                .crease(6, 10, ControlMesh.INFINITELY_SHARP)
                .crease(1, 5, 1.7f) // a later crease on the same edge replaces the first
                .corner(0, 3f)
                .corner(11, 0.3f)
                .corner(0, 4.25f)
                .hole(3)
                .hole(7)
                .options(new SubdivOptions(SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.FaceVarying.CORNERS_PLUS2,
                        SubdivOptions.Creasing.CHAIKIN, SubdivOptions.Triangles.SMOOTH))
                .source("every tag")
                .build();
    }

    @Test
    void aMeshWithEveryTagRoundTrips() throws IOException {
        ControlMesh m = everyTag();
        String text = write(m, "every\ntag");
        assertTrue(text.startsWith("# written by a test\no every tag\nv 0 0 0\n"), text);
        assertTrue(text.contains("\nf 1/1 2/2 6/6 5/5\n"), "face-varying corners v/vt");
        assertTrue(text.contains("\nf 3/16 4/17 8/18 7/19\n"), "the seam face has its own uv indices");
        assertTrue(text.contains("\nt crease 2/1/0 1 5 2.5\n"));
        assertTrue(text.contains("\nt crease 2/1/0 5 6 0.1\n"));
        assertTrue(text.contains("\nt crease 2/1/0 6 10 10\n"));
        assertTrue(text.contains("\nt corner 1/1/0 11 0.3\n"));
        assertTrue(text.contains("\nt hole 1/0/0 7\n"));
        assertTrue(text.endsWith("t interpolateboundary 1/0/0 1\nt facevaryinginterpolateboundary 1/0/0 3\n"
                + "t creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 smooth\n"), text);
        ControlMesh back = ObjReader.parseSubdiv(text, "back.obj").toControlMesh();
        assertSameMesh(m, back);
        for (int level = 0; level <= 3; level++) assertSameRefinement(m, back, level);
    }

    @Test
    void defaultOptionsAreWrittenToo() throws IOException {
        ControlMesh quad = ControlMesh.builder(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, new int[] {4}, new int[] {0, 1, 2, 3}).build();
        String text = write(quad, null);
        assertEquals("# written by a test\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"
                + "t interpolateboundary 1/0/0 2\nt facevaryinginterpolateboundary 1/0/0 5\n"
                + "t creasemethod 0/0/1 normal\nt smoothtriangles 0/0/1 catmark\n", text);
        assertSameMesh(quad, ObjReader.parseSubdiv(text, "q.obj").toControlMesh());
    }

    @Test
    void aLoopOrBilinearSchemeIsWrittenAndReadsBack() throws IOException {
        // Two triangles, so that the Loop scheme can take them too.
        ControlMesh.Builder b = ControlMesh.builder(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, new int[] {3, 3}, new int[] {0, 1, 2, 0, 2, 3})
                .crease(0, 2, 2.5f);
        for (SubdivOptions.Scheme scheme : SubdivOptions.Scheme.values()) {
            ControlMesh m = b.options(SubdivOptions.DEFAULT.withScheme(scheme).withCreasing(SubdivOptions.Creasing.CHAIKIN)).build();
            String text = write(m, null);
            String options = "t interpolateboundary 1/0/0 2\nt facevaryinginterpolateboundary 1/0/0 5\n"
                    + "t creasemethod 0/0/1 chaikin\nt smoothtriangles 0/0/1 catmark\n";
            // Catmull-Clark files stay as OpenSubdiv writes them: no scheme tag.
            assertTrue(text.endsWith("t crease 2/1/0 0 2 2.5\n" + (scheme == SubdivOptions.Scheme.CATMARK ? "" : "t scheme 0/0/1 " + scheme.keyword() + "\n")
                    + options), text);
            ControlMesh back = ObjReader.parseSubdiv(text, "back.obj").toControlMesh();
            assertEquals(scheme, back.options().scheme());
            assertSameMesh(m, back);
        }
    }

    @Test
    void everySharpnessReadsBackAsTheSameFloat() {
        SplittableRandom r = new SplittableRandom(17);
        for (int i = 0; i < 200_000; i++) {
            float s = i % 2 == 0 ? Float.intBitsToFloat(r.nextInt(0x3f000000, 0x41300000)) // 0.5 to 11
                    : Float.intBitsToFloat(r.nextInt(1, 0x7f000000));                     // any positive finite
            if (s > 1e15f) continue; // above the reader's bound: written as infinitely sharp (below)
            String t = ObjWriter.sharpness(s);
            assertEquals(s, (float) Double.parseDouble(t), t);
        }
        assertEquals("0", ObjWriter.sharpness(-2f), "negative sharpness is smooth");
        assertEquals("10", ObjWriter.sharpness(Float.POSITIVE_INFINITY));
        assertEquals("10", ObjWriter.sharpness(1e30f));
        assertEquals("0.1", ObjWriter.sharpness(0.1f));
    }

    @Test
    void numbersAnObjFileCannotHoldAreRefusedBeforeWriting() {
        ControlMesh far = ControlMesh.builder(new double[] {0, 0, 0, 1, 0, 0, 1, 2e15, 0}, new int[] {3}, new int[] {0, 1, 2}).source("far").build();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> ObjWriter.write(far, null, null, out));
        assertEquals("far: vertex 2 has the number 2.0E15, beyond the 1e15 an OBJ file may hold", e.getMessage());
        assertEquals(0, out.size(), "nothing written");
    }

    @Test
    void progressRunsFromZeroToOneAndCanStopTheWriting() throws IOException {
        ControlMesh m = everyTag();
        List<Double> seen = new ArrayList<>();
        ObjWriter.write(m, null, null, new ByteArrayOutputStream(), seen::add);
        assertEquals(0.0, seen.get(0));
        assertEquals(1.0, seen.get(seen.size() - 1));
        class Stop extends RuntimeException {}
        assertThrows(Stop.class, () -> ObjWriter.write(m, null, null, new ByteArrayOutputStream(), f -> { throw new Stop(); }));
    }

    static void assertSameMesh(ControlMesh a, ControlMesh b) {
        assertArrayEquals(bits(a.positions()), bits(b.positions()), "positions");
        assertArrayEquals(a.faceSizes(), b.faceSizes(), "face sizes");
        assertArrayEquals(a.faceVertices(), b.faceVertices(), "face vertices");
        assertEquals(a.uvs() == null, b.uvs() == null, "uvs present");
        if (a.uvs() != null) {
            assertArrayEquals(bits(a.uvs()), bits(b.uvs()), "uvs");
            assertArrayEquals(a.faceUvIndices(), b.faceUvIndices(), "uv indices");
        }
        SubdivTags s = a.tags(), t = b.tags();
        assertArrayEquals(s.creases(), t.creases(), "creases");
        assertArrayEquals(s.creaseSharpness(), t.creaseSharpness(), "crease sharpness");
        assertArrayEquals(s.corners(), t.corners(), "corners");
        assertArrayEquals(s.cornerSharpness(), t.cornerSharpness(), "corner sharpness");
        assertArrayEquals(s.holes(), t.holes(), "holes");
        assertEquals(a.options(), b.options(), "options");
    }

    static void assertSameRefinement(ControlMesh a, ControlMesh b, int level) {
        RefinedMesh ra = CatmullClark.refine(a, level), rb = CatmullClark.refine(b, level);
        assertArrayEquals(bits(ra.positions()), bits(rb.positions()), "refined positions at level " + level);
        assertArrayEquals(bits(ra.limitPositions()), bits(rb.limitPositions()), "limit positions at level " + level);
        assertArrayEquals(ra.faceVertices(), rb.faceVertices(), "refined faces at level " + level);
        for (int f = 0; f < ra.faceCount(); f++) assertEquals(ra.isHole(f), rb.isHole(f), "hole " + f + " at level " + level);
        if (ra.uvs() != null) assertArrayEquals(bits(ra.uvs()), bits(rb.uvs()), "refined uvs at level " + level);
    }

    private static long[] bits(double[] a) {
        long[] out = new long[a.length];
        for (int i = 0; i < a.length; i++) out[i] = Double.doubleToRawLongBits(a[i]);
        return out;
    }
}
