package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.IntStream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.cli.Main;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.Images;

/**
 * The ranges of the scene's numbers (lt.spindulys.math.Ranges) keep every pixel finite: scenes
 * made of values at the very ends of those ranges (brightest lights, on and next to surfaces;
 * largest colours and coefficients; deepest mirror paths; the largest coordinates and scales;
 * the tiniest scenes) render through the command line to a .pfm whose every value is a finite
 * float. Fixed worst cases first, then random scenes drawn from the extremes.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class FinitePixelsTest {
    @TempDir Path dir;

    /** Renders {@code scene} to a .pfm through the command line and checks every value is a finite float. */
    private void assertFinite(String scene, String label) throws IOException {
        Path file = dir.resolve("s.dat"), out = dir.resolve("s.pfm");
        Files.deleteIfExists(out);
        Files.writeString(file, scene);
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        int status = Main.run(new String[] {file.toString(), "-o", out.toString(), "--threads", "1", "--quiet"},
                new PrintStream(new ByteArrayOutputStream()), new PrintStream(err, true, StandardCharsets.UTF_8));
        assertEquals(0, status, label + ": " + err.toString(StandardCharsets.UTF_8) + "\n" + scene);
        FrameBuffer fb = Images.read(out);
        double[] d = fb.data();
        for (int i = 0; i < d.length; i++) {
            int p = i / 3;
            int x = p % fb.width(), y = p / fb.width();
            assertTrue(Float.isFinite((float) d[i]), label + ": pixel " + x + "," + y + " is " + d[i] + "\n" + scene);
        }
    }

    /** The brightest allowed lights, on and a hair away from mirror and diffuse surfaces, 64 bounces between mirrors. */
    @Test
    void brightestLightsOnSurfacesBetweenMirrors() throws IOException {
        StringBuilder s = new StringBuilder("""
                settings { width 25 height 19 maxdepth 64 mincontribution 0 ambient 100 background 100 }
                camera { eye 0 0 -3 lookat 0 0 0 }
                material mirror { color 100 ka 10 kd 10 ks 10 shininess 1e6 kr 1 }
                material bright { color 100 ka 10 kd 10 ks 10 shininess 0 }
                plane { normal 0 1 0 offset -1 material mirror }
                plane { normal 0 -1 0 offset -1 material mirror }
                sphere { center 0 0 0 radius 0.5 material bright }
                """);
        // On the surfaces exactly, and just off them: the centre pixel's ray (odd width and height,
        // one sample at the pixel centre) hits the sphere at 0 0 -0.5, a hair from the last light.
        String[] at = {"0 -1 0", "0 1 0", "0 0 -0.5", "0 -0.9999999999999999 0", "0.3 1 0.2", "0 0 -0.5000000000000001", "0 0 -0.50000000001"};
        for (String p : at) {
            s.append("light { position ").append(p).append("  color 100  intensity 1e15  falloff inverse-square }\n");
            s.append("light { position ").append(p).append("  color 100  intensity 1e15 }\n");
        }
        assertFinite(s.toString(), "mirrors");
    }

    /** As many lights as the total allows, all at full intensity and colour, around a glowing, textured sphere. */
    @Test
    void largestLightTotal() throws IOException {
        StringBuilder s = new StringBuilder("""
                settings { width 8 height 6 ambient 100 background 100 }
                texture glow { pattern marble  color1 100 100 100  color2 -100 -100 -100 }
                material m { color 100 ka 10 kd 10 ks 10 shininess 1
                             map { texture glow  channel emission }  map { texture glow  channel diffuse }
                             map { texture glow  channel specular }  map { texture glow  channel bump  strength 1e15 } }
                sphere { radius 1 material m }
                """);
        for (int i = 0; i < 1000; i++) {
            double a = i * 0.7;
            s.append(String.format(Locale.ROOT, "light { position %.17g %.17g %.17g  color 100  intensity 1e15  falloff %s }%n",
                    Math.cos(a), Math.sin(a) * 0.5, -Math.sin(a * 1.3), i % 2 == 0 ? "inverse-square" : "none"));
        }
        assertFinite(s.toString(), "light total");
    }

    /**
     * Principled materials at the ends of their ranges (their derived Whitted terms at theirs: ks
     * 10, shininess 1e6 or 0), with the largest emission plus the largest emission texture, under
     * the brightest lights between mirrors.
     */
    @Test
    void principledMaterialsAtTheirExtremes() throws IOException {
        StringBuilder s = new StringBuilder("""
                settings { width 25 height 19 maxdepth 64 mincontribution 0 ambient 100 background 100 }
                camera { eye 0 0 -3 lookat 0 0 0 }
                texture glow { pattern marble  color1 100 100 100  color2 -100 -100 -100 }
                material mirror { model principled  color 1  metallic 1  roughness 0  emission 100
                                  map { texture glow  channel emission }  map { texture glow  channel diffuse } }
                material glass { model principled  color 1  transmission 1  roughness 0  ior 1e15  emission 100
                                 map { texture glow  channel emission }  map { texture glow  channel roughness } }
                material rough { model principled  color 1  metallic 1  roughness 1  ior 1e-15  emission 100
                                 map { texture glow  channel metallic }  map { texture glow  channel transparency } }
                plane { normal 0 1 0 offset -1 material mirror }
                plane { normal 0 -1 0 offset -1 material mirror }
                sphere { center -0.6 0 0 radius 0.5 material glass }
                sphere { center 0.6 0 0 radius 0.5 material rough }
                """);
        for (String p : new String[] {"0 -1 0", "0 0 -0.5", "0.6 0 -0.5000000000000001"}) {
            s.append("light { position ").append(p).append("  color 100  intensity 1e15  falloff inverse-square }\n");
            s.append("light { position ").append(p).append("  color 100  intensity 1e15 }\n");
        }
        assertFinite(s.toString(), "principled");
    }

    /** Coordinates, sizes and scales at their largest: a world some 1e30 across. */
    @Test
    void largestCoordinatesAndScales() throws IOException {
        String scene = """
                settings { width 16 height 12 maxdepth 8 ambient 100 background 100 }
                camera { eye -1e15 1e15 -1e15 lookat 1e15 -1e15 1e15 up 0 1 0 }
                material m { color 100 ka 10 kd 10 ks 10 kr 0.5 kt 0.5 fresnel true ior 1e15 beta 1e-15 }
                sphere { center 1e15 1e15 1e15 radius 1e15 scale 1e15 material m }
                box { min -1e15 -1e15 -1e15 max 1e15 1e15 1e15 translate 1e15 0 0 scale 1e15 material m }
                plane { normal 1e15 1 1e-15 offset 1e15 material m }
                cylinder { base -1e15 0 0 top 1e15 0 0 radius 1e15 material m }
                triangle { vertices -1e15 -1e15 1e15  1e15 -1e15 1e15  0 1e15 -1e15 material m }
                light { position 1e15 1e15 -1e15  color 100  intensity 1e15  falloff inverse-square }
                light { position -1e15 -1e15 -1e15  color 100  intensity 1e15 }
                """;
        assertFinite(scene, "largest");
    }

    /** The tiniest scene: objects 1e-15 across seen from 1e-14 away, shrunk by a further 1e-15. */
    @Test
    void tinyScene() throws IOException {
        String scene = """
                settings { width 16 height 12 maxdepth 16 ambient 100 background 100 }
                camera { eye 0 0 -1e-14 lookat 0 0 0 }
                material m { color 100 ka 10 kd 10 ks 10 kr 0.5 kt 0.5 ior 1.5 beta 1e15 }
                sphere { radius 1e-15 material m }
                sphere { center 0 0 1e-15 radius 1 scale 1e-15 material m }
                box { min -1e-300 -1e-300 -1e-300 max 1e-300 1e-300 1e-300 material m }
                light { position 0 0 -1e-15  color 100  intensity 1e15  falloff inverse-square }
                light { position 1e-300 0 0  color 100  intensity 1e15  falloff inverse-square }
                """;
        assertFinite(scene, "tiny");
    }

    static IntStream seeds() { return IntStream.range(0, 24); }

    /** Random scenes whose every number is drawn from the ends of its range (or a typical value). */
    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void randomExtremeScenes(int seed) throws IOException {
        Random r = new Random(seed);
        StringBuilder s = new StringBuilder();
        double geo = pickD(r, 1e15, 1e-15, 1, 1e10);
        s.append(String.format(Locale.ROOT, "settings { width 10 height 8 maxdepth %d mincontribution %s ambient %s background %s }%n",
                r.nextInt(65), pickD(r, 0.001, 0.01, 0.1), colour(r), colour(r)));
        s.append(String.format(Locale.ROOT, "camera { eye 0 0 %s lookat 0 0 0 fov %s }%n", num(-4 * Math.min(geo, 2.5e14)), pickD(r, 1e-10, 179.99, 45)));
        s.append(String.format(Locale.ROOT, "texture t { pattern %s  color1 %s  color2 %s }%n",
                pick(r, "checker", "noise", "marble", "wood"), signedColour(r), signedColour(r)));
        double kr = pickD(r, 0, 1, 0.5, 0.999), kt = Math.min(1 - kr, pickD(r, 0, 1, 0.5));
        s.append(String.format(Locale.ROOT, "material m { color %s ka %s kd %s ks %s shininess %s kr %s kt %s ior %s filter %s beta %s fresnel %s%n",
                colour(r), coeff(r), coeff(r), coeff(r), pickD(r, 0, 1e6, 20), num(kr), num(kt), pickD(r, 1e-15, 1e15, 1.5, 1),
                pick(r, "1", "0", "0.5 1 0"), pick(r, "0", "1e15", "1e-15", "0.1"), r.nextBoolean()));
        for (String channel : new String[] {"diffuse", "specular", "reflection", "transparency", "emission", "bump"}) {
            if (r.nextBoolean()) {
                s.append("  map { texture t  channel ").append(channel).append(channel.equals("bump") ? "  strength " + pick(r, "1e15", "-1e15", "1e-15") : "").append(" }\n");
            }
        }
        s.append("}\n");
        String size = num(geo);
        s.append("sphere { radius ").append(size).append(" material m }\n");
        s.append("box { min -").append(size).append(" -").append(size).append(" ").append(size)
                .append(" max ").append(size).append(" ").append(size).append(" ").append(num(2 * Math.min(geo, 5e14))).append(" material m }\n");
        s.append("plane { normal 0 1 0 offset ").append(num(-geo)).append(" material m }\n");
        s.append("sphere { radius 1 scale ").append(pick(r, "1e15", "1e-15", "1")).append(" translate 0 ").append(size).append(" 0 material m }\n");
        int lights = 1 + r.nextInt(12);
        for (int i = 0; i < lights; i++) {
            // On a surface, at the centre, or out in space.
            String p = pick(r, "0 0 0", "0 " + num(-geo) + " 0", num(geo) + " 0 0", "0 0 " + num(-geo), "0 " + num(geo) + " " + num(-geo));
            s.append(String.format(Locale.ROOT, "light { position %s  color %s  intensity %s  falloff %s }%n",
                    p, colour(r), pickD(r, 1e15, 1e12, 1, 0), pick(r, "none", "inverse-square")));
        }
        assertFinite(s.toString(), "seed " + seed);
    }

    @SafeVarargs
    private static <T> T pick(Random r, T... choices) { return choices[r.nextInt(choices.length)]; }

    private static double pickD(Random r, double... choices) { return choices[r.nextInt(choices.length)]; }

    private static String num(double v) { return Double.toString(v).replace("E", "e"); }

    private static String colour(Random r) { return pick(r, "100", "0", "1", "100 0 100", "1e-15"); }

    private static String signedColour(Random r) { return pick(r, "100", "-100", "0", "1", "-100 100 0"); }

    private static String coeff(Random r) { return pick(r, "10", "0", "1"); }
}
