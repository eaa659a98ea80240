package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

import lt.spindulys.subdiv.SubdivOptions;

/**
 * Adaptive subdivision of Loop and bilinear surfaces, with issue 16's tests as
 * {@link AdaptiveSubdivisionTest} runs them for Catmull-Clark: at a fixed level every method
 * renders the uniform surface's passes, and the view-dependent tessellation is crack-free.
 */
class AdaptiveSchemesTest {
    @TempDir static Path shapes;

    static final String[] SHAPES = {"loop_cube_creases1", "loop_icosahedron", "loop_triangle_edgecorner", "loop_fvar_bound1", "bilinear_nonquads1"};

    @BeforeAll
    static void unpack() throws IOException {
        for (String s : SHAPES) {
            try (InputStream in = new GZIPInputStream(AdaptiveSchemesTest.class.getResourceAsStream("/subdiv/" + s + ".obj.gz"))) {
                Files.write(shapes.resolve(s + ".obj"), in.readAllBytes());
            }
        }
    }

    /** A reference shape's file (absolute, so the adaptive test's helpers take it as it is), or a model's name. */
    static String file(String name) {
        return name.contains("_") ? shapes.resolve(name + ".obj").toString() : name;
    }

    static Stream<Arguments> fixedLevel() {
        return Stream.of(
                Arguments.of("loop_icosahedron", 3, "scheme loop"),
                Arguments.of("loop_cube_creases1", 2, "scheme loop"),
                Arguments.of("loop_triangle_edgecorner", 2, "scheme loop"),
                Arguments.of("loop_fvar_bound1", 2, "scheme loop"),
                Arguments.of("cube.dat", 2, "scheme bilinear"),
                Arguments.of("bilinear_nonquads1", 2, "scheme bilinear"));
    }

    @ParameterizedTest(name = "{0} at level {1}, {2}")
    @MethodSource("fixedLevel")
    void everyMethodGivesTheUniformSurfacesPasses(String name, int level, String keys) {
        String file = file(name);
        long[] bytes = AdaptiveSubdivisionTest.patchBytes(file, level, keys);
        long all = bytes[1];
        AdaptiveSettings d = AdaptiveSettings.DEFAULT;
        AdaptiveSubdivisionTest.assertMethodsGiveTheUniformPasses(file, level, keys, 48, 36, List.of(
                new AdaptiveSubdivisionTest.Variant("lazy", d, 2, "lazy, 2 threads"),
                new AdaptiveSubdivisionTest.Variant("lazy", d.withCache(bytes[0]), 2, "lazy, cache of one patch, 2 threads"),
                new AdaptiveSubdivisionTest.Variant("combined", new AdaptiveSettings(all + all / 2, all, false, Double.NaN), 2, "combined, half pinned"),
                new AdaptiveSubdivisionTest.Variant("projected", d, 2, "projected")));
    }

    static Stream<Arguments> closed() {
        return Stream.of(Arguments.of("tetrahedron.obj", "scheme loop"), Arguments.of("loop_icosahedron", "scheme loop"),
                Arguments.of("loop_cube_creases1", "scheme loop"), Arguments.of("cube.dat", "scheme bilinear"));
    }

    @ParameterizedTest(name = "{0}, {1}")
    @MethodSource("closed")
    void theWeldedTessellationAtMixedLevelsIsCrackFree(String name, String keys) {
        String file = file(name);
        Scene s = AdaptiveSubdivisionTest.build(AdaptiveSubdivisionTest.closeUp(file, AdaptiveSubdivisionTest.LAZY_POWER_OF_TWO + "  target 4  maxlevel 6  " + keys, 160, 120),
                AdaptiveSettings.DEFAULT);
        AdaptiveSubdivisionSurface surface = AdaptiveSubdivisionTest.surface(s);
        assertEquals(SubdivOptions.Scheme.valueOf(keys.substring(7).toUpperCase(java.util.Locale.ROOT)), surface.control().options().scheme());
        AdaptiveSubdivisionTest.assertMixedLevels(surface, 1);
        assertTrue(surface.isClosed(), file + " is closed");
        AdaptiveSubdivisionTest.assertCrackFree(surface.tessellation(), file);
    }
}
