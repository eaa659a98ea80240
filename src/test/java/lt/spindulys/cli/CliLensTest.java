package lt.spindulys.cli;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.image.Images;
import lt.spindulys.scene.SceneBuilder;

/** --aperture and --focus override the scene's camera. */
class CliLensTest {
    @TempDir Path dir;

    private static final String SCENE = """
            settings { width 24 height 16 samples 4 }
            camera { eye 0 1 -4 lookat 0 0.5 0 %s }
            light { position 3 5 -4 }
            plane { normal 0 1 0 material { color 0.8 0.8 0.8 } }
            sphere { center 0 0.5 0 radius 0.5 material { color 1 0 0 } }
            sphere { center 1 0.5 3 radius 0.5 material { color 0 0 1 } }
            """;

    private double[] render(String cameraKeys, String... options) throws IOException {
        Path scene = dir.resolve("s.dat"), out = dir.resolve("s.pfm");
        Files.writeString(scene, SCENE.formatted(cameraKeys));
        String[] args = new String[options.length + 4];
        args[0] = scene.toString(); args[1] = "-o"; args[2] = out.toString(); args[3] = "--quiet";
        System.arraycopy(options, 0, args, 4, options.length);
        CliTest.Run r = CliTest.run(args);
        assertEquals(0, r.status(), r.err());
        return Images.read(out).data();
    }

    @Test
    void optionsGiveTheSameImageAsTheSceneKeys() throws IOException {
        double[] fromFile = render("aperture 0.2 focus 3");
        assertArrayEquals(fromFile, render("", "--aperture", "0.2", "--focus", "3"), 0.0);
        assertArrayEquals(fromFile, render("aperture 0.5 focuspoint 0 0 9", "--aperture", "0.2", "--focus", "3"), 0.0);
        assertFalse(java.util.Arrays.equals(fromFile, render("")), "the lens blurs");
    }

    @Test
    void apertureZeroIsThePinhole() throws IOException {
        assertArrayEquals(render(""), render("aperture 0.3 focus 2", "--aperture", "0"), 0.0);
    }

    @Test
    void aSceneWithoutCameraGetsTheDefaultOneWithTheLens() {
        ThinLensCamera c = SceneBuilder.DEFAULT_CAMERA.withLens(0.1, null);
        assertEquals(SceneBuilder.DEFAULT_CAMERA, c.view());
        assertEquals(5, c.focusDistance(), 1e-12);
        assertEquals(0.1, c.aperture());
    }

    @Test
    void badLensValuesAreOneLineAndExitTwo() throws IOException {
        Path scene = dir.resolve("s.dat");
        Files.writeString(scene, SCENE.formatted(""));
        String[][] cases = {
                {"render: --aperture must be a finite number at least 0, found -1", "--aperture", "-1"},
                {"render: --aperture expects a number, found 'wide'", "--aperture", "wide"},
                {"render: --focus must be a finite number greater than 0, found 0", "--focus", "0"},
                {"render: --focus must be a finite number greater than 0, found Infinity", "--focus", "Infinity"},
                {"render: --focus must be at most 1e15, found 1e300", "--focus", "1e300"},
                {"render: --aperture must be at most 1e15, found 2e15", "--aperture", "2e15"},
                {"render: option --focus needs a value", "--focus"},
        };
        for (String[] c : cases) {
            String[] args = new String[c.length];
            args[0] = scene.toString();
            System.arraycopy(c, 1, args, 1, c.length - 1);
            CliTest.Run r = CliTest.run(args);
            assertEquals(2, r.status(), String.join(" ", args));
            assertEquals(c[0] + System.lineSeparator(), r.err(), String.join(" ", args));
        }
    }

    @Test
    void anOrthographicCameraRefusesALens() throws IOException {
        Path scene = dir.resolve("ortho.dat");
        Files.writeString(scene, SCENE.formatted("projection orthographic  width 3"));
        for (String option : new String[] {"--aperture", "--focus"}) {
            CliTest.Run r = CliTest.run(scene.toString(), "-o", dir.resolve("o.png").toString(), option, "0.2");
            assertEquals(2, r.status(), r.err());
            assertEquals("render: " + option + ": an orthographic camera has no lens: aperture and focus need a perspective camera"
                    + System.lineSeparator(), r.err());
        }
    }

    @Test
    void helpListsTheLensOptions() {
        String help = CliTest.run("--help").out();
        assertTrue(help.contains("--aperture R") && help.contains("--focus D"), help);
    }
}
