package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.Environment;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.TextureImage;

/**
 * The path tracer on everything a scene can hold at once, and its clamp. A scene with every kind
 * of light (point, rectangle, disc, sphere, the environment), CSG, a procedural texture, glass, a
 * mirror, a moving object and depth of field renders finite, non-negative pixels with a plausible
 * brightness; and the clamp bounds what one sample's indirect light brings, as the scene format
 * documents, while leaving direct light alone.
 */
class PathRobustnessTest {
    /** Every light kind, CSG, a texture, glass, a mirror, motion blur and depth of field; path traced. */
    static final String KITCHEN_SINK = """
            settings { width 29  height 19  samples 8  integrator path  maxdepth 8  seed 7 }
            camera { eye 0 1.5 -5  lookat 0 0.5 0  aperture 0.05 }
            light { position -2 4 -2  intensity 6  falloff inverse-square }
            rectlight { center 2 4 -3  normal 0 -1 0  tangent 1 0 0  width 1  height 1  intensity 4  onesided true }
            disclight { center -1 3 1  normal 0 -1 0  radius 0.4  intensity 5 }
            spherelight { center 1.5 2.5 1  radius 0.3  intensity 6 }
            texture tiles { pattern checker  scale 4  color1 0.9 0.1 0.1  color2 0.1 0.1 0.9 }
            material floor { color 1 1 1  kd 0.8  map { texture tiles  mapping planar  axis 0 1 0 } }
            plane { normal 0 1 0  material floor }
            sphere { center -1 0.5 0  radius 0.5  material { color 0.9 0.6 0.2  kd 0.7  ks 0.3  shininess 40 }  motion { direction 1 0 0  speed 0.3 } }
            difference { box { min 0.5 0 -0.5  max 1.5 1 0.5 }  sphere { center 1.5 1 -0.5  radius 0.6 }  material { color 0.2 0.7 0.3 } }
            sphere { center 0 0.4 -1.2  radius 0.4  material { color 1 1 1  kd 0  kt 1  ior 1.5  fresnel true } }
            sphere { center -2 0.6 1.5  radius 0.6  material { color 1 1 1  kd 0  kr 1 } }
            """;

    static TextureImage uniformSky(double v) {
        int w = 8, h = 4;
        double[] rgb = new double[3 * w * h];
        Arrays.fill(rgb, v);
        return TextureImage.fromLinear(w, h, rgb);
    }

    /** The kitchen-sink scene with settings text replaced as given, under a dim uniform sky that is a light. */
    static SceneBuilder kitchenSink(String settingsFrom, String settingsTo) {
        String text = KITCHEN_SINK.replace(settingsFrom, settingsTo);
        return SceneParser.parse(text, "kitchen-sink.dat", Path.of("."))
                .environment(new Environment(uniformSky(0.2), 0, 1, true, 1));
    }

    private static double mean(FrameBuffer fb) {
        double sum = 0;
        for (double v : fb.data()) sum += v;
        return sum / fb.data().length;
    }

    private static void assertFiniteAndNonNegative(FrameBuffer fb, String what) {
        double[] d = fb.data();
        for (int i = 0; i < d.length; i++) {
            assertTrue(Double.isFinite(d[i]) && d[i] >= 0, what + ": value " + i + " (pixel " + (i / 3) % fb.width() + "," + (i / 3) / fb.width() + ") is " + d[i]);
        }
    }

    /**
     * Finite and non-negative everywhere; brighter with indirect light than with direct light
     * alone (indirect light only adds), and neither dark nor absurd: the lights give the lit
     * floor irradiance of order 1, so the mean must lie well inside (0.02, 5).
     */
    @Test
    void everyFeatureAtOnceRendersFinitePlausiblePixels() throws Exception {
        FrameBuffer full = RenderJob.of(kitchenSink("", "")).threads(2).run().frame();
        FrameBuffer direct = RenderJob.of(kitchenSink("maxdepth 8", "maxdepth 0")).threads(2).run().frame();
        assertFiniteAndNonNegative(full, "maxdepth 8");
        assertFiniteAndNonNegative(direct, "maxdepth 0");
        double m = mean(full), md = mean(direct);
        assertTrue(m > 0.02 && m < 5, "mean " + m);
        assertTrue(m > md, "indirect light adds to direct light: " + m + " against " + md);
    }

    /**
     * A floor lit only through a bounce: a one-sided rectangle light faces up at a white ceiling
     * and shows the floor its dark back, and the camera sees only the floor. All the light any
     * sample brings is then indirect (it reached the camera off floor and ceiling), so the scene
     * format's promise, that the clamp is the largest value one sample's indirect light brings to
     * a pixel, bounds every pixel by the clamp itself. The clamp must also cost energy here (the
     * bounce is bright), and the image without it must exceed the clamp somewhere, or the test
     * would prove nothing.
     */
    @Test
    void theClampBoundsEveryPixelLitOnlyIndirectly() throws Exception {
        double clamp = 0.05;
        String scene = """
                settings { width 24  height 16  samples 16  integrator path  maxdepth 3  seed 3 CLAMP }
                camera { eye 0 0.9 -2  lookat 0 0 0  fov 40 }
                rectlight { center 0 1 0  normal 0 1 0  tangent 1 0 0  width 0.5  height 0.5  intensity 200  onesided true }
                plane { normal 0 1 0  material { color 1 1 1  kd 0.8 } }
                plane { normal 0 -1 0  offset -2  material { color 1 1 1  kd 0.8 } }
                """;
        FrameBuffer free = RenderJob.of(SceneParser.parse(scene.replace("CLAMP", ""), "bounce.dat", Path.of("."))).threads(2).run().frame();
        FrameBuffer clamped = RenderJob.of(SceneParser.parse(scene.replace("CLAMP", "clamp " + clamp), "bounce.dat", Path.of("."))).threads(2).run().frame();
        assertFiniteAndNonNegative(free, "unclamped");
        assertFiniteAndNonNegative(clamped, "clamped");
        double freeMax = Arrays.stream(free.data()).max().orElseThrow(), clampedMax = Arrays.stream(clamped.data()).max().orElseThrow();
        assertTrue(freeMax > 2 * clamp, "the scene must be bright enough for the clamp to matter: largest unclamped value " + freeMax);
        assertTrue(mean(clamped) < mean(free), "the clamp removes energy: " + mean(clamped) + " against " + mean(free));
        assertTrue(clampedMax <= clamp * (1 + 1e-12), "no pixel lit only indirectly exceeds the clamp " + clamp + ": largest " + clampedMax);
    }

    /** Direct light (at most one bounce before the camera) is never clamped: at maxdepth 0 the clamp changes no bit. */
    @Test
    void theClampLeavesDirectLightAlone() throws Exception {
        FrameBuffer free = RenderJob.of(kitchenSink("maxdepth 8", "maxdepth 0")).threads(2).run().frame();
        FrameBuffer clamped = RenderJob.of(kitchenSink("maxdepth 8", "maxdepth 0  clamp 0.01")).threads(2).run().frame();
        assertTrue(Arrays.stream(free.data()).max().orElseThrow() > 0.01, "the direct light must exceed the clamp somewhere");
        assertArrayEquals(free.data(), clamped.data());
    }
}
