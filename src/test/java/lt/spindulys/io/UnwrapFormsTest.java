package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.render.ProgressListener;
import lt.spindulys.render.Renderer;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * The two forms of a Workframe unwrap lead to the same surface: one point per corner and points
 * with faces refine (and render) alike where an unwrap can be written in both, and points with
 * faces are OpenSubdiv's face-varying data, refining as an OBJ file with the same shared
 * {@code vt}.
 */
class UnwrapFormsTest {
    @TempDir Path dir;

    private static final Path CUBE_DAT = Path.of("scenes/models/cube.dat"), CUBE_TEX = Path.of("scenes/models/cube.tex"),
            CUBE_POINTS = Path.of("scenes/models/cube-points.tex"), NET_TEX = Path.of("src/test/resources/unwrap/cube-net.tex"),
            NET_OBJ = Path.of("src/test/resources/unwrap/cube-net.obj");

    private static SubdivInput cube(Path tex, SubdivOptions.FaceVarying mode) throws IOException {
        SubdivInput in = SubdivInput.of(WorkframeReader.readMesh(CUBE_DAT));
        in = WorkframeReader.readTex(tex, in.mesh()).applyTo(in);
        return in.withOptions(in.options().withFaceVarying(mode));
    }

    /** The one-point-per-corner text of an unwrap: its corners, face after face. */
    private static String cornerForm(Unwrap u) {
        double[] c = u.cornerUvs();
        StringBuilder s = new StringBuilder().append(c.length / 2).append('\n');
        for (int i = 0; i < c.length; i += 2) s.append(c[i]).append(' ').append(c[i + 1]).append('\n');
        return s.toString();
    }

    /** Same positions, faces and, corner by corner, bit-identical refined UVs. */
    private static void assertSameRefinement(SubdivInput a, SubdivInput b, int level) {
        RefinedMesh ra = CatmullClark.refine(a.toControlMesh(), level), rb = CatmullClark.refine(b.toControlMesh(), level);
        assertArrayEquals(ra.positions(), rb.positions());
        assertArrayEquals(ra.faceVertices(), rb.faceVertices());
        double[] ua = ra.uvs(), ub = rb.uvs();
        int[] fa = ra.faceUvs(), fb = rb.faceUvs();
        assertNotNull(fa);
        assertEquals(fa.length, fb.length);
        for (int c = 0; c < fa.length; c++) {
            assertEquals(ua[2 * fa[c]], ub[2 * fb[c]], "u of refined corner " + c);
            assertEquals(ua[2 * fa[c] + 1], ub[2 * fb[c] + 1], "v of refined corner " + c);
        }
    }

    @ParameterizedTest
    @EnumSource(SubdivOptions.FaceVarying.class)
    void theCubeAtlasRefinesAlikeInBothForms(SubdivOptions.FaceVarying mode) throws IOException {
        SubdivInput corners = cube(CUBE_TEX, mode), points = cube(CUBE_POINTS, mode);
        // The points file lists the atlas as a grid, not corner by corner: the indices differ.
        assertFalse(java.util.Arrays.equals(corners.mesh().uvIndex(), points.mesh().uvIndex()));
        assertSameRefinement(corners, points, 3);
    }

    @ParameterizedTest
    @EnumSource(SubdivOptions.FaceVarying.class)
    void aSharedPointNetRefinesAlikeInBothForms(SubdivOptions.FaceVarying mode) throws IOException {
        SubdivInput points = cube(NET_TEX, mode);
        MeshData m = points.mesh();
        Unwrap perCorner = WorkframeReader.parseTex(cornerForm(WorkframeReader.readTex(NET_TEX, m)), "net-corners.tex", m);
        assertFalse(perCorner.hasOwnFaces());
        SubdivInput corners = perCorner.applyTo(SubdivInput.of(WorkframeReader.readMesh(CUBE_DAT)));
        corners = corners.withOptions(corners.options().withFaceVarying(mode));
        assertSameRefinement(points, corners, 3);
    }

    @ParameterizedTest
    @EnumSource(SubdivOptions.FaceVarying.class)
    void aSharedPointUnwrapRefinesLikeTheObjWithVt(SubdivOptions.FaceVarying mode) throws IOException {
        SubdivInput tex = cube(NET_TEX, mode);
        SubdivInput obj = ObjReader.readSubdiv(NET_OBJ);
        obj = obj.withOptions(obj.options().withFaceVarying(mode));
        // The same face-varying data: 14 points, each corner's index as the OBJ's vt.
        assertEquals(14, tex.mesh().uvs().length / 2);
        assertArrayEquals(obj.mesh().uvs(), tex.mesh().uvs());
        assertArrayEquals(obj.mesh().uvIndex(), tex.mesh().uvIndex());
        assertSameRefinement(obj, tex, 3);
        RefinedMesh a = CatmullClark.refine(obj.toControlMesh(), 2), b = CatmullClark.refine(tex.toControlMesh(), 2);
        assertArrayEquals(a.uvs(), b.uvs());
        assertArrayEquals(a.faceUvs(), b.faceUvs());
    }

    @Test
    void pointsKeepTheirOwnSeamsWhereValuesAgree() throws IOException {
        // Face 2 of the net gets its own copy of point 5 (same u v): a seam the per-corner form,
        // which welds equal values at a vertex, cannot express; the OBJ with a duplicated vt can.
        String net = Files.readString(NET_TEX);
        String dup = net.replace("14 6\n", "15 6\n").replace("4 8 9 5 4\n", "4 8 9 14 4\n")
                .replace("0.0 0.6666666666666666 0\n", "0.0 0.6666666666666666 0\n0.5 0.3333333333333333 0\n");
        assertNotEquals(net, dup);
        String obj = Files.readString(NET_OBJ).replace("vt 0.0 0.6666666666666666\n", "vt 0.0 0.6666666666666666\nvt 0.5 0.3333333333333333\n")
                .replace("f 1/9 2/10 6/6 5/5", "f 1/9 2/10 6/15 5/5");
        MeshData m = WorkframeReader.readMesh(CUBE_DAT);
        SubdivInput tex = WorkframeReader.parseTex(dup, "dup.tex", m).applyTo(SubdivInput.of(m));
        SubdivInput fromObj = ObjReader.parseSubdiv(obj, "dup.obj");
        SubdivInput welded = SubdivInput.of(m).withCornerUvs(WorkframeReader.parseUnwrap(dup, "dup.tex", m));
        assertEquals(15, tex.mesh().uvs().length / 2);
        assertArrayEquals(fromObj.mesh().uvIndex(), tex.mesh().uvIndex());
        assertEquals(14, welded.mesh().uvs().length / 2, "per corner, the copy welds back");
        for (SubdivOptions.FaceVarying mode : SubdivOptions.FaceVarying.values()) {
            assertSameRefinement(fromObj.withOptions(fromObj.options().withFaceVarying(mode)), tex.withOptions(tex.options().withFaceVarying(mode)), 2);
        }
        // Smooth UVs (no linear interpolation) see the seam: the refinement differs from the welded one.
        SubdivOptions smooth = tex.options().withFaceVarying(SubdivOptions.FaceVarying.NONE);
        RefinedMesh seam = CatmullClark.refine(tex.withOptions(smooth).toControlMesh(), 2);
        RefinedMesh none = CatmullClark.refine(welded.withOptions(smooth).toControlMesh(), 2);
        assertFalse(java.util.Arrays.equals(cornerValues(seam), cornerValues(none)), "the seam changes the refined UVs");
    }

    @Test
    void aPointNoFaceUsesChangesNothing() throws IOException {
        String net = Files.readString(NET_TEX);
        String extra = net.replace("14 6\n", "15 6\n").replace("0.0 0.6666666666666666 0\n", "0.0 0.6666666666666666 0\n0.9 0.9 0\n");
        assertNotEquals(net, extra);
        MeshData m = WorkframeReader.readMesh(CUBE_DAT);
        SubdivInput with = WorkframeReader.parseTex(extra, "extra.tex", m).applyTo(SubdivInput.of(m));
        assertEquals(15, with.mesh().uvs().length / 2);
        for (SubdivOptions.FaceVarying mode : SubdivOptions.FaceVarying.values()) {
            assertSameRefinement(cube(NET_TEX, mode), with.withOptions(with.options().withFaceVarying(mode)), 2);
        }
    }

    private static double[] cornerValues(RefinedMesh r) {
        int[] f = r.faceUvs();
        double[] out = new double[2 * f.length];
        for (int c = 0; c < f.length; c++) {
            out[2 * c] = r.uvs()[2 * f[c]];
            out[2 * c + 1] = r.uvs()[2 * f[c] + 1];
        }
        return out;
    }

    /** A small textured scene of the cube with the given unwrap. */
    private static String scene(String tex) {
        return """
                settings { width 48  height 36  samples 1  ambient 0.3 0.3 0.3 }
                camera { eye 0 3.2 -9.5  lookat 0 0 0  fov 30 }
                light { position 6 9 -8  intensity 0.9 }
                texture dice { image "../textures/dice.png" }
                material die { color 1 1 1  map { texture dice } }
                subdiv { file "models/cube.dat"  level 2  uv "models/%s"  uvinterpolation none  material die  rotate y 40  rotate x -20 }
                """.formatted(tex);
    }

    @Test
    void bothFormsRenderBitIdentically() throws InterruptedException {
        Path scenes = Path.of("scenes").toAbsolutePath();
        FrameBuffer a = Renderer.render(SceneParser.parse(scene("cube.tex"), "a.dat", scenes).build(), 2, ProgressListener.NONE).frame();
        FrameBuffer b = Renderer.render(SceneParser.parse(scene("cube-points.tex"), "b.dat", scenes).build(), 2, ProgressListener.NONE).frame();
        assertArrayEquals(a.data(), b.data());
        double sum = 0;
        for (double v : a.data()) sum += v;
        assertTrue(sum > 0, "the picture is not black");
    }

    @Test
    void theShippedSceneRendersAsWithTheCornerForm() throws Exception {
        // scenes/tex-subdiv-cube.dat reads its middle cube's unwrap in the points form: the
        // picture (and so its golden) is the one the corner form gives.
        Path file = Path.of("scenes/tex-subdiv-cube.dat");
        String text = Files.readString(file);
        assertTrue(text.contains("uv \"models/cube-points.tex\""));
        Path scenes = Path.of("scenes").toAbsolutePath();
        FrameBuffer[] frames = new FrameBuffer[2];
        String[] texts = {text, text.replace("cube-points.tex", "cube.tex")};
        for (int i = 0; i < 2; i++) {
            var b = SceneParser.parse(texts[i], file.toString(), scenes);
            b.settings(b.settings().toBuilder().size(96, 72).samplesPerPixel(1).build());
            frames[i] = Renderer.render(b.build(), 2, ProgressListener.NONE).frame();
        }
        assertArrayEquals(frames[1].data(), frames[0].data());
    }

    @Test
    void aSceneNamesTheUnwrapsLineAndColumn() throws IOException {
        Files.copy(CUBE_DAT, dir.resolve("cube.dat"));
        Files.writeString(dir.resolve("bad.tex"), Files.readString(CUBE_POINTS).replace("4  16 17 23 22", "4  16 17 24 22"));
        String text = "subdiv { file \"cube.dat\"  uv \"bad.tex\" }\n";
        SceneException e = assertThrows(SceneException.class, () -> SceneParser.parse(text, "s.dat", dir));
        assertEquals(dir.resolve("bad.tex") + ":35:10: face 5 uses texture point 24, out of range (the unwrap has 24 points, numbered from 0)", e.getMessage());
    }
}
