package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

import lt.spindulys.scene.AcceleratorKind;
import lt.spindulys.image.Aov;
import lt.spindulys.math.Color;
import lt.spindulys.camera.PixelFilter;

/** The settings' builder: defaults, changed copies, and each value checked where it is given. */
class RenderSettingsTest {
    @Test
    void defaultsAreTheDocumentedValues() {
        RenderSettings d = RenderSettings.DEFAULT;
        assertEquals(List.of(640, 480, 1, 8, 0.001, Color.BLACK, Color.WHITE, false, 0L, AcceleratorKind.DEFAULT, Set.of(), 0.0, 1.0, 1,
                        IntegratorKind.WHITTED, 0.0, PixelFilter.BOX, 0.0, 1.0),
                List.of(d.width(), d.height(), d.samplesPerPixel(), d.maxDepth(), d.minContribution(), d.background(), d.ambient(),
                        d.srgb(), d.seed(), d.accelerator(), d.aovs(), d.shutterOpen(), d.shutterClose(), d.timeSteps(),
                        d.integrator(), d.clamp(), d.filter(), d.filterWidth(), d.pixelFilterWidth()));
        assertEquals(d, RenderSettings.builder().build());
        assertEquals(d, d.toBuilder().build());
    }

    @Test
    void everyValueReachesTheSettings() {
        RenderSettings s = RenderSettings.builder().size(320, 200).samplesPerPixel(16).maxDepth(3).minContribution(0.25)
                .background(Color.grey(0.5)).ambient(new Color(0.1, 0.2, 0.3)).srgb(true).seed(-9).accelerator(AcceleratorKind.OCTREE)
                .aovs(EnumSet.of(Aov.OBJECT, Aov.DEPTH)).shutter(0.25, 0.75).timeSteps(4).integrator(IntegratorKind.PATH).clamp(10)
                .filter(PixelFilter.MITCHELL).filterWidth(3).noiseThreshold(0.05).minSamples(8).denoise(true).build();
        assertEquals(new RenderSettings(320, 200, 16, 3, 0.25, Color.grey(0.5), new Color(0.1, 0.2, 0.3), true, -9, AcceleratorKind.OCTREE,
                EnumSet.of(Aov.DEPTH, Aov.OBJECT), 0.25, 0.75, 4, AdaptiveSettings.DEFAULT, IntegratorKind.PATH, 10, PixelFilter.MITCHELL, 3,
                0.05, 8, true), s);
        assertEquals(s, s.toBuilder().build());
        assertEquals(200, RenderSettings.builder().width(7).height(200).build().height());
        assertEquals(7, RenderSettings.builder().width(7).height(200).build().width());
    }

    @Test
    void aChangedCopyLeavesTheOriginal() {
        RenderSettings a = RenderSettings.builder().size(100, 50).build();
        RenderSettings.Builder b = a.toBuilder();
        RenderSettings c = b.samplesPerPixel(9).build();
        assertEquals(1, a.samplesPerPixel());
        assertEquals(9, c.samplesPerPixel());
        assertEquals(100, c.width());
        assertNotEquals(a, c);
        // The builder goes on from where it was; settings already built do not change.
        assertEquals(3, b.maxDepth(3).build().maxDepth());
        assertEquals(8, c.maxDepth());
    }

    @Test
    void passesAreCopiedWhenGiven() {
        Set<Aov> passes = EnumSet.of(Aov.NORMAL);
        RenderSettings.Builder b = RenderSettings.builder().aovs(passes);
        passes.add(Aov.DEPTH);
        RenderSettings s = b.build();
        assertEquals(Set.of(Aov.NORMAL), s.aovs());
        assertThrows(UnsupportedOperationException.class, () -> s.aovs().add(Aov.DEPTH));
    }

    /** Each refusal comes from the call that gave the value, worded as the constructor words it. */
    @Test
    void valuesAreCheckedWhereTheyAreGiven() {
        RenderSettings.Builder b = RenderSettings.builder();
        refused("width must be between 1 and 32768, found 0", () -> b.size(0, 10));
        refused("height must be between 1 and 32768, found 32769", () -> b.size(10, 32769));
        refused("width must be between 1 and 32768, found -1", () -> b.width(-1));
        refused("height must be between 1 and 32768, found 0", () -> b.height(0));
        refused("samples per pixel must be between 1 and 65536, found 0", () -> b.samplesPerPixel(0));
        refused("maxdepth must be between 0 and 64, found 65", () -> b.maxDepth(65));
        refused("mincontribution must be in [0, 1), found 1.0", () -> b.minContribution(1));
        refused("mincontribution must be in [0, 1), found NaN", () -> b.minContribution(Double.NaN));
        refused("background is missing", () -> b.background(null));
        refused("ambient must have components between 0 and 100, found (101.0, 101.0, 101.0)", () -> b.ambient(Color.grey(101)));
        refused("timesteps must be between 1 and 65536, found 0", () -> b.timeSteps(0));
        assertThrows(IllegalArgumentException.class, () -> b.shutter(1, 0));
        assertThrows(IllegalArgumentException.class, () -> b.shutter(0, Double.POSITIVE_INFINITY));
        assertThrows(NullPointerException.class, () -> b.accelerator(null));
        assertThrows(NullPointerException.class, () -> b.aovs(null));
        assertThrows(NullPointerException.class, () -> b.integrator(null));
        refused("clamp must be 0 (none) or a positive value up to 100, found -1.0", () -> b.clamp(-1));
        refused("clamp must be 0 (none) or a positive value up to 100, found NaN", () -> b.clamp(Double.NaN));
        assertThrows(NullPointerException.class, () -> b.filter(null));
        refused("filterwidth must be 0 (the filter's default) or from 0.1 to 16 pixels, found 0.05", () -> b.filterWidth(0.05));
        refused("filterwidth must be 0 (the filter's default) or from 0.1 to 16 pixels, found NaN", () -> b.filterWidth(Double.NaN));
        refused("filterwidth must be 0 (the filter's default) or from 0.1 to 16 pixels, found 17.0", () -> b.filterWidth(17));
        // A refused value leaves the builder as it was.
        assertEquals(RenderSettings.DEFAULT, b.build());
        // The constructor words a refusal as the builder does.
        refused("width must be between 1 and 32768, found 0", () -> new RenderSettings(0, 1, 1, 0, 0, Color.BLACK, Color.BLACK, false, 0,
                AcceleratorKind.DEFAULT, Set.of(), 0, 1, 1, AdaptiveSettings.DEFAULT, IntegratorKind.DEFAULT, 0, null, 0, 0, 0, false));
    }

    @Test
    void integratorsAreNamedByTheirKeywords() {
        assertEquals(List.of("whitted", "path"), IntegratorKind.keywords());
        assertEquals(IntegratorKind.PATH, IntegratorKind.fromKeyword("path"));
        refused("unknown integrator 'photon' (expected one of whitted, path)", () -> IntegratorKind.fromKeyword("photon"));
    }

    @Test
    void filtersAreNamedByTheirKeywordsAndWidthsDefaultPerFilter() {
        assertEquals(List.of("box", "gaussian", "blackman-harris", "mitchell"), PixelFilter.keywords());
        assertEquals(PixelFilter.BLACKMAN_HARRIS, PixelFilter.fromKeyword("blackman-harris"));
        refused("unknown filter 'lanczos' (expected one of box, gaussian, blackman-harris, mitchell)", () -> PixelFilter.fromKeyword("lanczos"));
        RenderSettings b = RenderSettings.builder().filter(PixelFilter.BLACKMAN_HARRIS).build();
        assertEquals(1.5, b.pixelFilterWidth());
        assertEquals(4, b.toBuilder().filter(PixelFilter.MITCHELL).build().pixelFilterWidth());
        assertEquals(2.5, b.toBuilder().filterWidth(2.5).build().pixelFilterWidth());
        assertEquals(1, RenderSettings.DEFAULT.pixelFilterWidth());
    }

    @Test
    void theDefaultFilterFollowsTheIntegratorUnlessOneIsChosen() {
        RenderSettings whitted = RenderSettings.DEFAULT.toBuilder().samplesPerPixel(16).build();
        assertFalse(whitted.filterChosen());
        assertEquals(PixelFilter.BOX, whitted.filter());
        assertEquals(1, whitted.pixelFilterWidth());
        RenderSettings path = whitted.toBuilder().integrator(IntegratorKind.PATH).build();
        assertEquals(PixelFilter.BLACKMAN_HARRIS, path.filter());
        assertEquals(1.5, path.pixelFilterWidth());
        // Back to Whitted, a filter left to the default is the box again; a chosen one stays.
        assertEquals(PixelFilter.BOX, path.toBuilder().integrator(IntegratorKind.WHITTED).build().filter());
        RenderSettings chosen = path.toBuilder().filter(PixelFilter.GAUSSIAN).integrator(IntegratorKind.WHITTED).build();
        assertTrue(chosen.filterChosen());
        assertEquals(PixelFilter.GAUSSIAN, chosen.filter());
        assertEquals(PixelFilter.BOX, path.toBuilder().filter(PixelFilter.BOX).build().filter());
    }

    @Test
    void timeStepsMustDivideTheSamples() {
        RenderSettings s = RenderSettings.builder().samplesPerPixel(6).timeSteps(4).build();
        refused("samples 6 is not a multiple of timesteps 4 (each time step renders samples / timesteps per pixel)", s::checkTimeSteps);
        assertEquals(s.toBuilder().samplesPerPixel(8).build(), s.toBuilder().samplesPerPixel(8).build().checkTimeSteps());
    }

    private static void refused(String message, Executable e) {
        assertEquals(message, assertThrows(IllegalArgumentException.class, e).getMessage());
    }
}
