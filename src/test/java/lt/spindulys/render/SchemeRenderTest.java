package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.SubdivOptions;

/** Loop and bilinear surfaces rendered from scenes: as themselves, in CSG, moving and instanced. */
class SchemeRenderTest {
    @TempDir Path dir;

    @BeforeEach
    void icosahedron() throws IOException {
        try (InputStream in = new java.util.zip.GZIPInputStream(SchemeRenderTest.class.getResourceAsStream("/subdiv/loop_icosahedron.obj.gz"))) {
            Files.write(dir.resolve("ico.obj"), in.readAllBytes());
        }
    }

    private Scene scene(String objects) {
        return SceneParser.parse("settings { width 32  height 24  samples 2 }\ncamera { eye 0 0.5 -4  lookat 0 0 0  fov 45 }\n"
                + "light { position -3 5 -6 }\n" + objects, "s.dat", dir).build();
    }

    private static double[] render(Scene s) throws InterruptedException {
        return Renderer.render(s, 2, ProgressListener.NONE).frame().data();
    }

    private double[] render(String objects) throws InterruptedException {
        return render(scene(objects));
    }

    @Test
    void theThreeSchemesRenderThreeSurfaces() throws InterruptedException {
        double[] loop = render("subdiv { file \"ico.obj\"  level 2  scheme loop }");
        double[] catmark = render("subdiv { file \"ico.obj\"  level 2  scheme catmark }");
        double[] bilinear = render("subdiv { file \"ico.obj\"  level 2  scheme bilinear }");
        double[] empty = render("");
        assertFalse(Arrays.equals(loop, empty), "the Loop surface is in the picture");
        assertFalse(Arrays.equals(loop, catmark));
        assertFalse(Arrays.equals(loop, bilinear));
        assertFalse(Arrays.equals(catmark, bilinear));
        // Bilinear refinement splits the faces in their own planes: flat shaded, the same picture as the cage's (to rounding).
        assertArrayEquals(render("subdiv { file \"ico.obj\"  level 0  scheme bilinear  shading flat }"),
                render("subdiv { file \"ico.obj\"  level 2  scheme bilinear  shading flat }"), 1e-9, "bilinear refinement keeps the cage's facets");
    }

    @Test
    void aLoopSurfaceIsACsgSolidMovesAndIsInstanced() throws InterruptedException {
        String loop = "subdiv { file \"ico.obj\"  level 2  scheme loop }";
        Scene csg = scene("difference { " + loop + "  sphere { center 0 0.3 -0.8  radius 0.5 } }");
        Bool d = assertInstanceOf(Bool.class, csg.objects().get(0));
        SubdivisionSurface operand = assertInstanceOf(SubdivisionSurface.class, d.operands().get(0));
        assertEquals(SubdivOptions.Scheme.LOOP, operand.refined().controlMesh().options().scheme());
        assertTrue(operand.isClosed(), "a closed Loop surface has an inside");
        double[] plain = render(loop), cut = render(csg);
        assertFalse(Arrays.equals(plain, cut), "the sphere cuts into the Loop surface");
        // Cutting with a sphere that misses the surface leaves the picture as it was.
        assertArrayEquals(plain, render("difference { " + loop + "  sphere { center 5 5 5  radius 0.1 } }"));

        double[] moving = render("subdiv { file \"ico.obj\"  level 2  scheme loop  motion { translate 0.6 0 0 } }");
        assertFalse(Arrays.equals(plain, moving), "motion blur moves the Loop surface");

        Scene two = scene(loop + "\nsubdiv { file \"ico.obj\"  level 2  scheme loop  translate 1.5 0 0 }");
        SubdivisionSurface a = (SubdivisionSurface) two.objects().get(0), b = (SubdivisionSurface) two.objects().get(1);
        assertSame(a.refined(), b.refined(), "the second placement is an instance");
        assertFalse(Arrays.equals(plain, render(two)));
    }
}
