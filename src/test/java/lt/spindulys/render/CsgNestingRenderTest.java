package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.cli.Main;
import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.Bool;

/**
 * CSG nested as deep as allowed ({@link Bool#MAX_NESTING} levels) parses, builds and renders, on
 * the test's own thread (parse, build) and the renderer's (rays), exactly like the same solid
 * written as one flat block.
 */
class CsgNestingRenderTest {
    private static final String HEAD = "settings { width 40  height 30  samples 1 }\n"
            + "camera { eye 0 1 -9  lookat 0 0 0  fov 40 }\nlight { position -4 6 -6 }\n";

    /** Sphere i of the union: a cloud of overlapping spheres in [-2, 2]^3. */
    private static String sphere(int i) {
        double x = (i * 37 % 41) / 10.0 - 2, y = (i * 53 % 43) / 10.5 - 2, z = (i * 29 % 47) / 11.5 - 2;
        return "sphere { center " + x + " " + y + " " + z + "  radius 0.35 }\n";
    }

    @Test
    void deepestNestingRendersLikeTheFlatBlock() throws Exception {
        int levels = Bool.MAX_NESTING;
        StringBuilder nested = new StringBuilder(HEAD), flat = new StringBuilder(HEAD);
        nested.append("union {\n".repeat(levels)).append(sphere(0));
        flat.append("union {\n").append(sphere(0));
        for (int i = 1; i <= levels; i++) {
            nested.append(sphere(i)).append("}\n");
            flat.append(sphere(i));
        }
        flat.append("}\n");
        double[] deep = Renderer.render(SceneParser.parse(nested.toString(), "nested.dat", null).build(), 2, ProgressListener.NONE).frame().data();
        double[] one = Renderer.render(SceneParser.parse(flat.toString(), "flat.dat", null).build(), 2, ProgressListener.NONE).frame().data();
        int lit = 0;
        for (double d : one) if (d > 0) lit++;
        assertTrue(lit > one.length / 10, "the solid covers part of the image");
        assertArrayEquals(one, deep);
    }

    @Test
    void deepestAlternatingNestingRendersThroughTheCommandLine(@TempDir Path dir) throws Exception {
        int levels = Bool.MAX_NESTING;
        StringBuilder b = new StringBuilder(HEAD);
        for (int i = 0; i < levels; i++) b.append(i % 2 == 0 ? "difference" : "intersection").append(" {\n");
        b.append("sphere { }\nsphere { center 0.5 0 0 }\n");
        for (int i = levels - 1; i >= 0; i--) {
            b.append(i % 2 == 0 ? "sphere { center 0 0 -1  radius 0.5 }\n" : "box { min -2 -2 -2  max 2 2 2 }\n").append("}\n");
        }
        Path scene = dir.resolve("deep.dat"), out = dir.resolve("deep.png");
        Files.writeString(scene, b);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new String[] {scene.toString(), "-o", out.toString(), "--quiet"},
                new PrintStream(new ByteArrayOutputStream(), true, StandardCharsets.UTF_8), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals("", err.toString(StandardCharsets.UTF_8));
        assertEquals(0, status);
        assertTrue(Files.size(out) > 0);
    }
}
